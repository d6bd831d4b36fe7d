"""``shaper gear``: the gear pair that drives the crank, its shifts, lengths and checks."""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from core.base.errors import DesignError
from .common import UsageError, design_error_text, design_file, number
from .output import (OutputError, add_cad_font_option, add_lang_option, cad_font_from_args, check_target,
                     print_json, print_table, sheet_labels, write_output)

if TYPE_CHECKING:
    from ..gear import GearPair

# The pair's modules are imported where a pair is made or read: ``shaper gear --help`` (and
# ``shaper drawing --help``, which shares the options) prints only the texts below.

HELP = "the gear pair: shifts, centre distance, diameters, contact ratio, checks"
DESCRIPTION = ("The external involute spur pair that drives the crank (pinion z1 on the motor "
               "side), on the GB/T 1356 basic rack: the shift factors given (--x1 --x2), found "
               "from the centre distance (--centre), or by the rule (neither); the working "
               "pressure angle, every diameter, the tooth and tip thicknesses, the contact ratio "
               "and the checks (undercut, tip, contact ratio, root interference), each failing "
               "one with what to change.")
EXAMPLES = ("shaper gear --z1 13 --z2 40 --module 6",
            "shaper gear --z1 12 --z2 12 --module 10 --centre 130 --json",
            "shaper gear --z1 10 --z2 36 --module 5 --x1 0.45 --x2 0.2 --csv gear.csv",
            "shaper gear --z1 13 --z2 40 --module 6 --dxf 啮合图.dxf --lang zh")

# option → (its dest, the GearPairInputs field, the key of a design file's gear object)
OPTIONS = (("--z1", "z1", "z1", "z1"), ("--z2", "z2", "z2", "z2"),
           ("--module", "module", "module_mm", "module_mm"), ("--x1", "x1", "x1", "x1"),
           ("--x2", "x2", "x2", "x2"), ("--centre", "centre", "centre_mm", "centre_mm"),
           ("--pressure-angle", "pressure_angle", "pressure_angle_deg", "pressure_angle_deg"),
           ("--addendum", "addendum", "addendum", "addendum"),
           ("--clearance", "clearance", "clearance", "clearance"),
           ("--tip-limit", "tip_limit", "tip_limit", "tip_limit"),
           ("--contact-limit", "contact_limit", "contact_limit", "contact_limit"))
# a DesignError's parameter → the row of OPTIONS that sets it
_BY_PARAMETER = {row[1]: row for row in OPTIONS}
_BY_PARAMETER.update({"module_mm": OPTIONS[2], "centre_mm": OPTIONS[5],
                      "pressure_angle_deg": OPTIONS[6]})


def configure(parser: argparse.ArgumentParser) -> None:
    add_gear_options(parser)
    out = parser.add_argument_group("output")
    out.add_argument("--json", action="store_true", help="print the results as JSON")
    out.add_argument("--csv", metavar="FILE|-", help="write the results as CSV (one row per "
                     "quantity, units in the names)")
    out.add_argument("--dxf", metavar="FILE", help="write the meshing sheet as DXF, the pair at 1:1 "
                     "in mm (O1 at the origin, O2 on +x), the sheet scaled round it")
    out.add_argument("--sheet", metavar="SIZE", help="paper of the --dxf sheet: A0, A1, A2, A3 "
                     "(default A2)")
    add_cad_font_option(out)
    add_lang_option(out, "the --dxf sheet's texts")


def add_gear_options(parser: argparse.ArgumentParser,
                     title: str = "the gear pair (z1, z2 and the module are required unless "
                                  "--design has a gear)") -> argparse._ArgumentGroup:
    """The pair's options (shared with ``shaper drawing --content gear``); the group."""
    gear = parser.add_argument_group(title)
    gear.add_argument("--z1", metavar="Z", help="teeth of the pinion (motor side), ≥ 5")
    gear.add_argument("--z2", metavar="Z", help="teeth of the gear (on the crank), ≥ 5")
    gear.add_argument("--module", metavar="MM", help="module m, mm (GB/T 1357 first series, "
                      "or any positive value with a note)")
    gear.add_argument("--x1", metavar="X", help="shift factor of the pinion (with --x2)")
    gear.add_argument("--x2", metavar="X", help="shift factor of the gear (with --x1)")
    gear.add_argument("--centre", metavar="MM", help="centre distance a′, mm, instead of the "
                      "shift factors (default with neither: the rule in docs/methods.md)")
    gear.add_argument("--pressure-angle", metavar="DEG", help="pressure angle α, ° (default 20)")
    gear.add_argument("--addendum", metavar="H", help="addendum factor h*a (default 1)")
    gear.add_argument("--clearance", metavar="C", help="clearance factor c* (default 0.25)")
    gear.add_argument("--tip-limit", metavar="K", help="least tip thickness as a factor K of the module: sa ≥ K·m (default 0.25, i.e. 0.25·m = 1.5 mm at m = 6)")
    gear.add_argument("--contact-limit", metavar="E", help="least contact ratio (default 1.2)")
    if not any(a.dest == "design" for a in parser._actions):
        gear.add_argument("--design", metavar="FILE", help="a design file whose \"gear\" object "
                          "gives the values not given here")
    return gear


def _saved(args: argparse.Namespace) -> dict:
    """The ``--design`` file's gear object as inputs keyed like the file, or {}."""
    doc = design_file(args)
    if doc is None or not doc.get("gear"):
        return {}
    from ..gear.file import gear_from_dict, gear_to_dict
    return gear_to_dict(gear_from_dict(doc["gear"]))


def _values(args: argparse.Namespace) -> tuple[dict, dict]:
    """(GearPairInputs fields, where each came from: an option or ``--design (gear.key)``)."""
    saved = _saved(args)
    if getattr(args, "centre", None) is not None:
        saved.update(x1=None, x2=None)         # a′ on the command line wins over saved shifts
    elif getattr(args, "x1", None) is not None or getattr(args, "x2", None) is not None:
        saved.update(centre_mm=None)
    values, sources = {}, {}
    for option, dest, field, key in OPTIONS:
        text = getattr(args, dest, None)
        if text is not None:
            values[field] = number(dest, text)
            sources[field] = option
        elif saved.get(key) is not None:
            values[field] = saved[key]
            sources[field] = f"--design (gear.{key})"
        elif field in ("z1", "z2", "module_mm"):
            raise UsageError(f"{option}: required (or give --design with a gear)")
    if ("x1" in values) != ("x2" in values):
        given, missing = ("--x1", "--x2") if "x1" in values else ("--x2", "--x1")
        raise UsageError(f"{missing}: required with {given} (or give --centre instead)")
    for field in ("z1", "z2"):
        if values[field] == int(values[field]):
            values[field] = int(values[field])
    return values, sources


def pair_from_args(args: argparse.Namespace) -> GearPair:
    """The pair of the options over the ``--design`` file's gear; UsageError naming the option
    (or the file's key) for a bad value."""
    from ..gear import GearPairInputs, design_pair
    sources: dict = {}
    try:
        values, sources = _values(args)
        return design_pair(GearPairInputs(**values))
    except DesignError as exc:
        row = _BY_PARAMETER.get(exc.parameter)
        option = sources.get(row[2], row[0]) if row else None
        raise UsageError(design_error_text(exc, option)) from None


def json_document(args: argparse.Namespace) -> dict:
    """What ``--json`` prints (``shaper class``'s answer key holds it for each student)."""
    from ..gear.table import gear_summary
    return gear_summary(pair_from_args(args))


def run(args: argparse.Namespace) -> int:
    from ..gear.table import gear_summary, summary_csv, summary_rows
    if args.json and args.csv == "-":
        raise UsageError("--json: cannot share stdout with --csv -; write the CSV to a file")
    for option, target in (("--csv", args.csv), ("--dxf", args.dxf)):
        if target is not None:
            check_target(option, target)
    for option, value in (("--sheet", args.sheet), ("--lang", args.lang)):
        if value is not None and args.dxf is None:
            raise UsageError(f"{option}: only with --dxf")
    cad_font = cad_font_from_args(args, args.dxf is not None)
    pair = pair_from_args(args)
    if args.dxf is not None:
        _paper(args)
        labels = sheet_labels(args.lang or "en", "gear")
    summary = gear_summary(pair)
    if args.csv is not None:
        write_output("--csv", args.csv, summary_csv(summary))
    if args.dxf is not None:
        _write_dxf(pair, args, labels, cad_font)
    if args.json:
        print_json(summary)
    elif args.csv != "-":
        print_table(summary_rows(pair))
    return 0


def _paper(args: argparse.Namespace):
    from ..drawing.sheet import PAPERS
    name = (args.sheet or "A2").upper()
    if name not in PAPERS:
        raise UsageError(f"--sheet: {args.sheet!r} is not one of {', '.join(PAPERS)}")
    return PAPERS[name]


def _write_dxf(pair: GearPair, args: argparse.Namespace, labels: dict[str, str] | None,
               cad_font: str) -> None:
    """The meshing sheet in ``labels``' language (English without), as ``shaper drawing
    --content gear`` draws it."""
    from ..drawing.gear_sheet import ENGLISH, gear_sheet   # ezdxf: only when a drawing is asked for
    from ..drawing.sheet_dxf import save_sheet_dxf
    from ..drawing.title_block import TitleBlock
    # the pair on its own, a set of one sheet (the course design's is its fourth, "4/4")
    block = TitleBlock("", f"z {pair.inputs.z1}/{pair.inputs.z2}, m {pair.inputs.module_mm:g}", "", "1/1")
    drawn = gear_sheet(pair, _paper(args), labels=labels or ENGLISH, block=block)
    try:
        save_sheet_dxf(drawn.sheet, args.dxf, cad_font)
    except OSError as exc:          # a WriteError: names the user's path and a plain reason
        raise OutputError(f"--dxf: {exc}") from None
