"""``shaper drawing``: the course design's drawing sheets as PDF, SVG or DXF, headless.

Registered through the ``shaper.commands`` entry point like ``report`` (it needs
Qt for the PDF, the SVG and the translations). Every input is checked before Qt
starts and before anything is written: bad input is one line and exit status 2.
"""
from __future__ import annotations

import argparse
from dataclasses import replace
from pathlib import Path

from core.cli.cmd_cam import (OPTIONAL, SHEET, add_cam_options, add_phase_option, cam_from_inputs,
                              cam_inputs_from_args)
from core.cli.cmd_gear import OPTIONS as GEAR_OPTIONS, add_gear_options, pair_from_args
from core.cli.common import UsageError, add_design_options, add_load_options, add_speed_options, number
from core.cli.output import OutputError, add_cad_font_option, cad_font_from_args
from core.drawing.paper import PAPERS
from core.base.errors import DesignError
from core.course_design.counts import DEFAULT_COUNT

from shaperapp.widgets.command_line import (add_cover_options, add_sheet_speed_option,
                                            check_output_folder, cover_from_args, cover_text,
                                            design_name, diagram_angles, inputs_from_args,
                                            sheet_speed, start_qt)

from .content import CONTENTS, DEFAULT_PAPER, SHEET_SUFFIXES, SheetChoice
from .scheme_command import SCHEME, add_scheme_options, write_scheme_file

HELP = "draw the course design's sheets (A0–A3 PDF, SVG or DXF)"
DESCRIPTION = ("The drawing sheets of the course design (图纸): paper after GB/T 14689 with the "
               "border and a title block after GB/T 10609.1. --content motion: the mechanism to a "
               "standard scale at the N positions (thin) and both limit positions (thick) with "
               "the tool's path, the ram's s, v, a over φ at one speed (--rpm-index, default the first, shown in the title block), the velocity and "
               "acceleration polygons at two positions, each with its scale μ, and the main "
               "dimensions. --content forces: the loads and joint forces, the force polygons, the "
               "crank torque, the energy curve and the flywheel. --content cam: the feed cam (the "
               "options of shaper cam, or the --design file's cam) drawn by inversion to a standard "
               "scale, the follower's ψ, ω, α and the pressure angle over the cam angle, and its "
               "figures. --content gear: the gear pair (the options of shaper gear, or the --design "
               "file's gear; no linkage needed) in mesh to a standard scale, with the line of "
               "action, the contact zones and its results, on A2 by default. The file type "
               "follows the name: .pdf, .svg or .dxf (mm, layers by line type). Chinese sheets need a font with Chinese glyphs (fonts-noto-cjk).")
EXAMPLES = ("shaper drawing --crank 100 --K 1.4 --stroke 300 --rpm 40 --sheet A1 "
            "--content motion -o motion.pdf",
            "shaper drawing --design my.shaper.json --lang zh --diagrams 60,240 --student 张三 "
            "--student-number 2021001 --class 机械2101 --school 机械工程学院 --supervisor 李四 "
            "-o 运动分析.dxf",
            "shaper drawing --crank 100 --K 1.4 --stroke 300 --rpm 40 --content cam --arm 120 "
            "--swing 15 --pressure 40 --rise 60 --dwell 10 --return 60 -o cam.pdf",
            "shaper drawing --content gear --z1 13 --z2 40 --module 6 --centre 162 -o gear.pdf")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser)
    add_speed_options(parser)
    add_sheet_speed_option(parser)
    add_load_options(parser, required=False)
    parser.add_argument("-o", "--output", required=True, metavar="FILE",
                        help="the sheet to write: .pdf, .svg or .dxf")
    parser.add_argument("--sheet", metavar="SIZE",
                        help=f"paper, landscape: {', '.join(PAPERS)} (default A1; A2 for gear)")
    parser.add_argument("--content", default="motion", metavar="WHAT",
                        help=f"what the sheet shows: {', '.join(CONTENTS)} (default motion); or "
                             f"{SCHEME}: the mechanism alone at 1:1 with its dimensions, as DXF")
    add_scheme_options(parser)
    add_phase_option(add_cam_options(parser, "with --content cam: the cam, as shaper cam takes it "
                                             "(required unless --design has a cam)"))
    add_gear_options(parser, "with --content gear: the gear pair, as shaper gear takes it "
                             "(required unless --design has a gear)")
    parser.add_argument("--lang", choices=("en", "zh", "zh_CN"), default="en",
                        help="language of the sheet's texts: en, or zh (= zh_CN) (default en)")
    add_cad_font_option(parser)
    parser.add_argument("--positions", metavar="N", default=str(DEFAULT_COUNT),
                        help="number of equally spaced crank positions drawn, 1 to 72 (default 12)")
    parser.add_argument("--diagrams", metavar="A,B",
                        help="crank angles (degrees) of the two polygon positions (default: the "
                             "numbered positions nearest mid working and mid return stroke)")
    block = parser.add_argument_group("title block (GB/T 10609.1; the report's cover options; blank "
                                      "when not given, to fill in by hand)")
    block.add_argument("--title", metavar="TEXT",
                       help="design name (default: the design file's name)")
    add_cover_options(block, "the date (default: today, YYYY-MM-DD)")
    block.add_argument("--drawn-by", dest="student", metavar="TEXT", help="the same as --student")


CAM_WORDS = tuple((option, dest) for option, dest, _ in SHEET + OPTIONAL) + (
    ("--law", "law"), ("--return-law", "return_law"), ("--phase", "phase"))
GEAR_WORDS = tuple((option, dest) for option, dest, _, _ in GEAR_OPTIONS)


def sheet_suffix(path: str) -> str:
    """".pdf", ".svg" or ".dxf" from the name (any case); OutputError otherwise."""
    suffix = Path(path).suffix.lower()
    if suffix not in SHEET_SUFFIXES:
        raise OutputError(f"--output: the file name must end in .pdf, .svg or .dxf "
                          f"(got {Path(path).name!r})")
    return suffix


def choice_from_args(args: argparse.Namespace, speeds: int = 1) -> SheetChoice:
    """Everything the sheet needs from the words, checked (UsageError, DesignError);
    ``speeds`` is how many speeds the design has (--rpm-index picks one)."""
    from core.course_design.positions import check_count
    from core.drawing.motion import MAX_POSITIONS
    paper = (args.sheet or DEFAULT_PAPER.get(args.content, "A1")).upper()
    if paper not in PAPERS:
        raise UsageError(f"--sheet: {args.sheet!r} is not one of {', '.join(PAPERS)}")
    if args.content not in CONTENTS:
        raise UsageError(f"--content: {args.content!r} is not one of {', '.join(CONTENTS)}")
    count = check_count(number("positions", args.positions))
    if count > MAX_POSITIONS:
        raise DesignError("positions", count, f"must be 1 to {MAX_POSITIONS} on a drawing sheet")
    diagrams = diagram_angles(args)
    if args.content == "gear" and args.rpm_index is not None:
        raise UsageError("--rpm-index: the gear sheet is drawn at no speed; leave it out")
    speed = sheet_speed(args, speeds)
    cover, date = cover_from_args(args)
    return SheetChoice(args.content, paper, count, diagrams, design_name(args),
                       cover["student"], date, cover["school"], number=cover["number"],
                       group=cover["group"], supervisor=cover["supervisor"], speed=speed)


def run(args: argparse.Namespace) -> int:
    if args.content == "gear":          # the pair alone: no linkage, speeds or loads
        spec, rpms, masses = None, [], None
    else:
        spec, rpms, masses = inputs_from_args(args)
    if args.content == SCHEME:
        return write_scheme_file(spec.design(), args)
    choice = choice_from_args(args, len(rpms))
    stray = [option for option, dest in CAM_WORDS if getattr(args, dest) is not None]
    if stray and choice.content != "cam":
        raise UsageError(f"{stray[0]}: a cam option, only with --content cam")
    stray = [option for option, dest in GEAR_WORDS if getattr(args, dest) is not None]
    if stray and choice.content != "gear":
        raise UsageError(f"{stray[0]}: a gear option, only with --content gear")
    if choice.content == "gear":
        choice = replace(choice, gear=pair_from_args(args))
    if choice.content == "cam":
        from core.forces.masses import MassProperties
        idle = masses.idle_fraction if masses is not None else MassProperties().idle_fraction
        choice = replace(choice, cam=cam_from_inputs(cam_inputs_from_args(args), spec.design(), idle,
                                                        args))
    suffix = sheet_suffix(args.output)
    target = Path(args.output)
    check_output_folder(args.output)
    cad_font = cad_font_from_args(args, suffix == ".dxf")
    language = start_qt(args.lang, needs_font=suffix != ".dxf")
    from .content import build_sheet
    from .render import write_sheet
    sheet = build_sheet(spec, rpms, masses, choice)
    try:
        write_sheet(sheet, str(target), language, choice.design_name, cad_font)
    except OSError as exc:      # a WriteError: names the path and a plain reason
        raise OutputError(f"--output: {exc}") from None
    print(f"wrote {target} ({choice.paper}, {choice.content}, {suffix[1:].upper()})")
    return 0


def sheet_labels_in(lang: str, part: str) -> dict[str, str]:
    """The words of ``part``'s drawing ("gear": the meshing sheet, "cam": the cam's DXF notes)
    in --lang (en, zh, zh_CN), for ``shaper gear --dxf --lang`` and ``shaper cam --dxf --lang``:
    core draws them but cannot translate (the catalogue is Qt's), so it asks here."""
    start_qt(lang, needs_font=False)           # a DXF names its font, it embeds none
    if part == "cam":
        from shaperapp.cam.words import cam_words
        return cam_words()
    from .gear_labels import gear_labels
    return gear_labels()
