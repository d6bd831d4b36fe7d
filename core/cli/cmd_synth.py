"""``shaper synth``: the dimensions synthesized from L1, K and H."""
from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING, Any, Mapping

from core.base.figure_text import figure_text
from .common import add_design_options, design_from_args
from .output import print_json, print_table

if TYPE_CHECKING:
    from core.linkage.geometry import Design

HELP = "synthesize dimensions from L1, K, H"
DESCRIPTION = ("Synthesize the frame distance L2, the lever length L3 and the ram-guide height "
               "from the crank length L1, the time ratio K and the stroke H (the textbook synthesis: the ram's guide through the lever tip's chord).")
EXAMPLES = ("shaper synth --crank 100 --K 1.4 --stroke 300",
            "shaper synth --crank 100 --K 1.4 --stroke 300 --rod-ratio 0.3 --guide sagitta --json")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser, allow_dims=False)
    parser.add_argument("--json", action="store_true", help="print JSON")


def design_summary(design: Design) -> dict[str, Any]:
    """The design's dimensions and what they imply; units in the keys."""
    return {
        "variant": design.variant,
        "theta_deg": math.degrees(design.theta),
        "K": design.time_ratio,
        "stroke_mm": design.stroke,
        "crank_mm": design.crank,
        "frame_mm": design.frame,
        "lever_mm": design.lever,
        "guide_mm": design.guide,
        "h_mm": design.guide_above_crank,
        "rod_mm": design.rod,
        "rod_side": design.rod_side if design.rod is not None else None,
    }


def json_document(args: argparse.Namespace) -> dict[str, Any]:
    """What ``--json`` prints (``shaper class``'s answer key holds it for each student)."""
    return design_summary(design_from_args(args))


def run(args: argparse.Namespace) -> int:
    if args.json:
        print_json(json_document(args))
        return 0
    print_table(dimension_rows(design_from_args(args)))
    return 0


def dimension_rows(design: Design, words: Mapping[str, str] | None = None) -> list[tuple[str, str]]:
    """(label, value) of the dimensions and what they imply, as printed (and in the report).
    ``words`` may rename the variant and rod-side words (a translation)."""
    word = (lambda w: w) if words is None else (lambda w: words.get(w, w))  # noqa: E731
    rows = [("variant", word(design.variant)),
            ("extreme-position angle θ", f"{figure_text('angle', math.degrees(design.theta))}°"),
            ("frame O2O4 L2", f"{figure_text('length', design.frame)} mm"),
            ("lever O4B L3", f"{figure_text('length', design.lever)} mm"),
            ("guide above lever pivot", f"{figure_text('length', design.guide)} mm"),
            ("guide above crank centre h", f"{figure_text('length', design.guide_above_crank)} mm")]
    if design.rod is not None:
        rows.append(("rod BC L4", f"{figure_text('length', design.rod)} mm ({word(design.rod_side)})"))
    rows += [("time ratio K", figure_text("ratio", design.time_ratio)),
             ("stroke H", f"{figure_text('length', design.stroke)} mm")]
    return rows
