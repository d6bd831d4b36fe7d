"""``shaper drawing``: the course design's drawing sheets as PDF, SVG or DXF, headless.

Registered through the ``shaper.commands`` entry point like ``report`` (it needs
Qt for the PDF, the SVG and the translations). Every input is checked before Qt
starts and before anything is written: bad input is one line and exit status 2.
"""
from __future__ import annotations

import argparse
import datetime
from pathlib import Path

from core.cli.common import UsageError, add_design_options, add_load_options, add_speed_options, number
from core.cli.output import OutputError
from core.drawing.motion import MAX_POSITIONS
from core.drawing.sheet import PAPERS
from core.errors import DesignError
from core.positions import DEFAULT_COUNT, check_count

from shaperapp.widgets.command_line import (check_output_folder, cover_text, design_name,
                                            diagram_angles, inputs_from_args, start_qt)

from .content import CONTENTS, SHEET_SUFFIXES, SheetChoice

HELP = "draw the course design's sheets (A0–A3 PDF, SVG or DXF)"
DESCRIPTION = ("The drawing sheets of the course design (图纸): paper after GB/T 14689 with the "
               "border and a title block after GB/T 10609.1. --content motion: the mechanism to a "
               "standard scale at the N positions (thin) and both limit positions (thick) with "
               "the tool's path, the ram's s, v, a over φ at the first speed, the velocity and "
               "acceleration polygons at two positions, each with its scale μ, and the main "
               "dimensions. The file type follows the name: .pdf, .svg or .dxf (mm, layers by "
               "line type). Chinese sheets need a font with Chinese glyphs (fonts-noto-cjk).")
EXAMPLES = ("shaper drawing --crank 100 --K 1.4 --stroke 300 --rpm 40 --sheet A1 "
            "--content motion -o motion.pdf",
            "shaper drawing --design my.shaper.json --lang zh --diagrams 60,240 -o 运动分析.dxf")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser)
    add_speed_options(parser)
    add_load_options(parser, required=False)
    parser.add_argument("-o", "--output", required=True, metavar="FILE",
                        help="the sheet to write: .pdf, .svg or .dxf")
    parser.add_argument("--sheet", default="A1", metavar="SIZE",
                        help=f"paper, landscape: {', '.join(PAPERS)} (default A1)")
    parser.add_argument("--content", default="motion", metavar="WHAT",
                        help=f"what the sheet shows: {', '.join(CONTENTS)} (default motion)")
    parser.add_argument("--lang", choices=("en", "zh", "zh_CN"), default="en",
                        help="language of the sheet's texts: en, or zh (= zh_CN) (default en)")
    parser.add_argument("--positions", metavar="N", default=str(DEFAULT_COUNT),
                        help="number of equally spaced crank positions drawn, 1 to 72 (default 12)")
    parser.add_argument("--diagrams", metavar="A,B",
                        help="crank angles (degrees) of the two polygon positions (default: the "
                             "numbered positions nearest mid working and mid return stroke)")
    block = parser.add_argument_group("title block (blank when not given)")
    block.add_argument("--title", metavar="TEXT",
                       help="design name (default: the design file's name)")
    block.add_argument("--drawn-by", metavar="TEXT", help="who drew it")
    block.add_argument("--school", metavar="TEXT", help="school or department")
    block.add_argument("--date", metavar="TEXT", help="the date (default: today, YYYY-MM-DD)")


def sheet_suffix(path: str) -> str:
    """".pdf", ".svg" or ".dxf" from the name (any case); OutputError otherwise."""
    suffix = Path(path).suffix.lower()
    if suffix not in SHEET_SUFFIXES:
        raise OutputError(f"--output: the file name must end in .pdf, .svg or .dxf "
                          f"(got {Path(path).name!r})")
    return suffix


def choice_from_args(args: argparse.Namespace) -> SheetChoice:
    """Everything the sheet needs from the words, checked (UsageError, DesignError)."""
    paper = args.sheet.upper()
    if paper not in PAPERS:
        raise UsageError(f"--sheet: {args.sheet!r} is not one of {', '.join(PAPERS)}")
    if args.content not in CONTENTS:
        raise UsageError(f"--content: {args.content!r} is not one of {', '.join(CONTENTS)}")
    if args.content != "motion":
        raise UsageError(f"--content {args.content}: not available yet; use --content motion")
    count = check_count(number("positions", args.positions))
    if count > MAX_POSITIONS:
        raise DesignError("positions", count, f"must be 1 to {MAX_POSITIONS} on a drawing sheet")
    diagrams = diagram_angles(args)
    date = cover_text("--date", args.date) or datetime.date.today().isoformat()
    return SheetChoice(args.content, paper, count, diagrams,
                       cover_text("--title", design_name(args)), cover_text("--drawn-by", args.drawn_by),
                       date, cover_text("--school", args.school))


def run(args: argparse.Namespace) -> int:
    spec, rpms, masses = inputs_from_args(args)
    choice = choice_from_args(args)
    suffix = sheet_suffix(args.output)
    target = Path(args.output)
    check_output_folder(args.output)
    language = start_qt(args.lang, needs_font=suffix != ".dxf")
    from .content import build_sheet
    from .render import write_sheet
    sheet = build_sheet(spec, rpms, masses, choice)
    try:
        write_sheet(sheet, str(target), language, choice.design_name)
    except OSError as exc:      # a WriteError: names the path and a plain reason
        raise OutputError(f"--output: {exc}") from None
    print(f"wrote {target} ({choice.paper}, {choice.content}, {suffix[1:].upper()})")
    return 0
