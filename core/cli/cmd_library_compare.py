"""``shaper library compare``: 2 to 6 designs (library entries and design files) side
by side at one speed, as a table of figures and overlay curves (``core.space.compare``).

``load_candidates`` is shared with ``shaper report --compare``.
"""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Sequence

from core.library.names import file_stem, unique_name
from core.base.errors import DesignError, FileFormatError
from ..library import Library
from .common import UsageError, library_path, note_read_only, number
from .output import write_output

if TYPE_CHECKING:
    from core.space.compare import Candidate


def compare_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("names", metavar="NAME", nargs="*", help="library entries to compare")
    p.add_argument("--file", dest="files", metavar="FILE", action="append", default=[],
                   help="also compare a design file (repeatable)")
    p.add_argument("--rpm", metavar="RPM", help="the common crank speed (default: the first design's first)")
    p.add_argument("--step", metavar="DEG", default="1", help="crank-angle step of the curves (default 1)")
    out = p.add_mutually_exclusive_group()
    out.add_argument("--json", action="store_true", help="print the table as JSON")
    out.add_argument("--csv", metavar="FILE|-", help="write the table as CSV")
    p.add_argument("--curves-csv", metavar="FILE|-", help="write the overlay curves as CSV")


def load_candidates(library: str | None, names: Sequence[str], files: Sequence[str],
                    file_option: str = "--file") -> tuple[list[Candidate], float | None]:
    """Library entries ``names`` (from ``library``, see ``resolve_path``), then design
    ``files`` (labelled by their names, made unique),
    as comparison candidates; and the first one's first speed.

    LibraryError for the library or a missing name; UsageError naming ``file_option``
    for a file that cannot be read."""
    from core.files.io import load_design
    from core.space.compare import Candidate
    candidates: list[Candidate] = []
    first_rpm = None
    if names:
        with Library(library_path(library), create=False) as lib:
            note_read_only(lib)
            for name in names:
                doc = lib.get(name).document(any_step=True)      # a too fine entry compares too
                first_rpm = first_rpm or doc["rpm"][0]
                candidates.append(Candidate(name, doc["spec"], doc["masses"]))
    for path in files:
        try:
            doc = load_design(path)
        except FileFormatError as exc:
            raise UsageError(f"{file_option}: {exc}") from None
        first_rpm = first_rpm or doc["rpm"][0]
        label = unique_name(file_stem(path), [c.label for c in candidates])
        candidates.append(Candidate(label, doc["spec"], doc["masses"]))
    return candidates, first_rpm


def run_compare(args: argparse.Namespace) -> int:
    from core.space.compare import comparison_json, compare, curves_csv_chunks, table_csv
    candidates, first_rpm = load_candidates(args.library, args.names, args.files)
    if not 2 <= len(candidates) <= 6:
        raise UsageError(f"NAME: compare 2 to 6 designs (got {len(candidates)})")
    rpm = number("rpm", args.rpm) if args.rpm is not None else first_rpm
    try:
        result = compare(candidates, rpm, number("step", args.step), curves=bool(args.curves_csv))
    except DesignError as exc:
        if exc.parameter == "designs":
            raise UsageError(f"NAME: {exc.value!r} {exc.allowed}") from None
        raise
    if args.curves_csv:
        write_output("--curves-csv", args.curves_csv, curves_csv_chunks(result))
    if args.json:
        print(comparison_json(result), end="")
    elif args.csv:
        write_output("--csv", args.csv, table_csv(result))
    elif not args.curves_csv or args.curves_csv != "-":
        print_comparison(result)
    return 0


def print_comparison(result) -> None:
    from core.space.compare import difference_text, value_text
    labels = result.labels
    head = ["figure"] + list(labels)
    cells = [head, ["rpm"] + [f"{result.rpm:g}"] * len(labels)]
    for row in result.rows:
        line = [row.key]
        for i, value in enumerate(row.values):
            line.append(value_text(value, row.key) + difference_text(row, i) + (" *" if i in row.best else ""))
        cells.append(line)
    widths = [max(len(r[i]) for r in cells) for i in range(len(head))]
    for r in cells:
        print("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip())
    print(f"\n(differences from {labels[0]!r} in parentheses; * best: lower max |a|, pressure "
          "angle, torques and J_F)")
