"""``shaper library list``: the library's entries filtered, sorted and shown as a table.

The one action with a syntax of its own (the filter and sort fields, from
``core.library.query``'s tables, printed by its --help) and a table of its own
(``LIST_COLUMNS``), so it stands beside ``cmd_library`` as check, compare and
refresh do. Notes on stderr say when listed figures are stale or damaged.
"""
from __future__ import annotations

import argparse
import sys
from typing import Callable

from core.library.open import library_exists
from core.library.query import QueryError, parse_filter, sort_sql

from core.linkage.limits import MAX_FILE_SAMPLES
from core.base.figure_text import value_text
from core.space.figures import FIGURES_VERSION
from ..library import Library
from core.base.text import terminal_text
from .common import UsageError, library_path, number, whole_number
from .output import print_json

# (heading, key, a figure?): a figure at its kind's precision (core.base.figure_text.value_text),
# as the GUI's table writes it
LIST_COLUMNS = (("name", "name", False), ("variant", "variant", False), ("K", "K", True),
                ("H mm", "stroke_mm", True), ("θ °", "theta_deg", True),
                ("r/min", "rpm", True), ("v_work_max m/s", "v_work_max_m_s", True),
                ("v_return_max m/s", "v_return_max_m_s", True), ("a_max m/s²", "a_max_m_s2", True),
                ("J_F kg·m²", "flywheel_inertia_kg_m2", True), ("modified", "modified", False))


def filter_help() -> str:
    """The filter and sort syntax, for ``library list --help`` (from core's own tables)."""
    from core.library.query import FIELDS, OPERATORS
    return ("filter (--where): conditions FIELD OP VALUE separated by commas, all must hold.\n"
            f"  OP: {' '.join(OPERATORS)}   (~ contains, ignoring case)\n"
            "  VALUE: a number, or text; \"double quotes\" around text with a comma.\n"
            "  tag=TAG matches one of the tags.\n"
            "sort (--sort) and filter fields:\n  " + _wrap(", ".join(k for k in FIELDS if k != "tag")) + "\n"
            "  short names: K, H, L1, L2, L3, L4, theta, a_max, J_F, crank, frame, lever, rod, "
            "stroke, pressure, flywheel (any letter case)")


def _wrap(text: str, width: int = 76) -> str:
    import textwrap
    return "\n  ".join(textwrap.wrap(text, width))


def list_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--where", metavar="FILTER", default="",
                   help="conditions FIELD OP VALUE separated by commas, e.g. 'K>=1.4,variant=rod,name~cut'")
    p.add_argument("--search", metavar="TEXT", default="", help="text in the name, notes or tags")
    p.add_argument("--sort", metavar="FIELD", default="name",
                   help="sort by a field (default name; the fields are listed below)")
    p.add_argument("--desc", action="store_true", help="sort descending")
    p.add_argument("--rpm", metavar="RPM", help="show per-speed figures at this speed (default: each design's first)")
    p.add_argument("--limit", metavar="N", help="show at most N entries")
    p.add_argument("--json", action="store_true", help="print a JSON array")


def run_list(args: argparse.Namespace, open_library: Callable[..., Library]) -> int:
    """List the entries that match, as a table or JSON; ``open_library(args, create=False)``
    opens the library, only when it exists (listing never creates one)."""
    rpm = number("rpm", args.rpm) if args.rpm is not None else None
    limit = whole_number("--limit", args.limit) if args.limit is not None else None
    try:
        sort_sql(args.sort, args.desc)
    except QueryError as exc:
        raise UsageError(f"--sort: {exc}") from None
    parse_filter(args.where)                # a bad filter is reported even for an empty library
    path = library_path(args.library)
    if not library_exists(path):            # listing never creates a library
        print("[]" if args.json else f"no designs in {path} (it does not exist yet)")
        return 0
    with open_library(args, create=False) as lib:
        rows = lib.query(args.where, search=args.search, sort=args.sort, descending=args.desc,
                         rpm=rpm, limit=limit, documents=True)
    stale = sum(1 for row in rows if row["figures_version"] is not None
                and row["figures_version"] < FIGURES_VERSION)
    if stale:
        print(f"shaper: note: {stale} of the {len(rows)} designs listed "
              f"{'has' if stale == 1 else 'have'} figures an older version computed; "
              "'shaper library refresh' recomputes them", file=sys.stderr)
    fine = sum(1 for row in rows if _too_fine(row))
    damaged = sum(1 for row in rows if row["damaged"]) - fine
    if damaged:
        print(f"shaper: note: {damaged} of the {len(rows)} designs listed {'is' if damaged == 1 else 'are'} "
              "damaged (what cannot be read shows as —); 'shaper library check' says why", file=sys.stderr)
    if fine:
        print(f"shaper: note: {fine} of the {len(rows)} designs listed {'is' if fine == 1 else 'are'} "
              f"too fine for a design file (stored before its limit of {MAX_FILE_SAMPLES} samples, "
              "angles × speeds); 'shaper library check' gives each one's samples and the step "
              "'shaper library export NAME --step DEG -o FILE' needs", file=sys.stderr)
    if args.json:
        print_json(rows)
        return 0
    if not rows:
        print("no designs match" if (args.where or args.search) else f"no designs in {lib.path}")
        return 0
    cells = [[head for head, _, _ in LIST_COLUMNS]]
    for row in rows:
        cells.append(["—" if row[key] is None else value_text(row[key], key) if figure
                      else terminal_text(str(row[key])) for _, key, figure in LIST_COLUMNS])
        if row["damaged"]:
            cells[-1][0] += " (too fine)" if _too_fine(row) else " (damaged)"
    widths = [max(len(r[i]) for r in cells) for i in range(len(LIST_COLUMNS))]
    for r in cells:
        print("  ".join(c.ljust(w) if i in (0, 1, len(r) - 1) else c.rjust(w)
                        for i, (c, w) in enumerate(zip(r, widths))).rstrip())
    return 0


def _too_fine(row) -> bool:
    """Whether the listed entry is whole but finer than a design file holds (its damage's
    kind ``too_fine``: stored before the limit), not damaged."""
    return getattr(row["damaged"], "kind", None) == "too_fine"
