"""``shaper curves``: ram and lever motion over the cycle, as CSV."""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from .common import (add_angle_options, add_design_options, add_speed_options, design_from_args,
                     request_from_args)
from .streaming import write_table

if TYPE_CHECKING:
    import numpy as np

HELP = "ram and lever motion over the cycle, as CSV"
DESCRIPTION = ("Ram displacement, velocity and acceleration, lever angle, angular velocity and "
               "acceleration (and the rod's, for the rod variant) at every crank angle and speed, "
               "as CSV with the units in the column names. Large requests are computed and "
               "written block by block, with progress shown on a terminal.")
EXAMPLES = ("shaper curves --crank 100 --K 1.4 --stroke 300 --rpm 40 60 --step 1 --csv curves.csv",
            "shaper curves --dims 125,275,600,150 --guide 575 --angles 0,90,180,270 --rpm 30")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser)
    add_speed_options(parser)
    add_angle_options(parser, "the curves")
    parser.add_argument("--csv", default="-", metavar="FILE|-",
                        help="output file, or - for stdout (default)")


def run(args: argparse.Namespace) -> int:
    from core.files.io import curve_table
    from core.linkage.kinematics import solve
    design = design_from_args(args)
    angles, rpms = request_from_args(args)

    def block(phi: np.ndarray, rpm: float):
        return curve_table(solve(design, phi, [rpm]))

    write_table("--csv", args.csv, "computing curves", block, angles, rpms)
    return 0
