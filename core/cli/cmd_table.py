"""``shaper table``: every quantity at the numbered and special crank positions."""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from core.course_design.counts import DEFAULT_COUNT
from .common import (UsageError, add_design_options, add_load_options, add_speed_options,
                     design_from_args, number, number_list, rpms_from_args)
from .loads import masses_or_none
from .output import print_json, write_output

if TYPE_CHECKING:
    from core.course_design.positions import PositionTable
    from core.linkage.geometry import Design

# Which side of a switch a row at the cut's start or end shows (core.linkage.cut's rule).
CUT_NOTE = ("cut_start and cut_end rows show the cutting side: the cut includes its ends "
            "(with --idle 0, both limit positions)")
HELP = "kinematics and forces at the 12 (or N) crank positions and the special positions"
DESCRIPTION = ("The course-design table: positions 1 … N equally spaced from the limit position "
               "that starts the working stroke, plus both limit positions, the start and end of "
               "the cut (after the idle margin) and the positions of the largest cutting and "
               "return speeds, solved exactly. Columns are those of the curves CSV and, when "
               "loads are given (options or a design file with loads), the dynamics CSV.")
EXAMPLES = ("shaper table --crank 100 --K 1.4 --stroke 300 --rpm 40",
            "shaper table --design my.shaper.json --positions 24 --at 45,100 --csv table.csv",
            "shaper table --crank 100 --K 1.4 --stroke 300 --lever-mass 20 --lever-inertia 1.1 "
            "--ram-mass 70 --cut-force 7000 --cut-height 80 --json")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser)
    add_speed_options(parser)
    parser.add_argument("--positions", metavar="N", default=str(DEFAULT_COUNT),
                        help="number of equally spaced crank positions (default 12)")
    parser.add_argument("--at", metavar="A,B,…", help="extra crank angles to tabulate, degrees")
    add_load_options(parser, required=False)
    out = parser.add_mutually_exclusive_group()
    out.add_argument("--csv", metavar="FILE|-", help="write the table as CSV to FILE or stdout")
    out.add_argument("--json", action="store_true", help="print one JSON object per position and speed")


def table_from_args(args: argparse.Namespace) -> tuple[Design, PositionTable]:
    from core.course_design.positions import position_table, positions
    from core.forces.masses import MassProperties
    design = design_from_args(args)
    rpms = rpms_from_args(args)
    masses = masses_or_none(args, design)
    extra = number_list("at", args.at) if args.at is not None else []
    idle = masses.idle_fraction if masses is not None else MassProperties().idle_fraction
    where = positions(design, number("positions", args.positions), extra, idle)
    return design, position_table(design, where, rpms, masses)


def run(args: argparse.Namespace) -> int:
    if args.json and args.csv is not None:
        raise UsageError("--json: give either --json or --csv")
    from core.course_design.positions import positions_csv, table_records, text_groups
    _, table = table_from_args(args)
    if args.csv is not None:
        write_output("--csv", args.csv, positions_csv(table))
        return 0
    if args.json:
        print_json(table_records(table))
        return 0
    for index, block in enumerate(text_groups(table)):
        title = f"{block.rpm:g} r/min — {block.group}"
        header = ["pos", "name", *block.columns]
        rows = [[str(number or ""), name, *texts] for number, name, texts in block.rows]
        widths = [max(len(r[c]) for r in [header] + rows) for c in range(len(header))]
        print(("\n" if index else "") + title)
        for r in [header] + rows:
            print("  ".join(cell.rjust(w) if c != 1 else cell.ljust(w)
                            for c, (cell, w) in enumerate(zip(r, widths))).rstrip())
        if "cut_force_N" in block.columns:
            print(CUT_NOTE)
    return 0
