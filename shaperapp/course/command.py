"""``shaper course``: the report and every drawing sheet of one design file, into a folder.

Registered through the ``shaper.commands`` entry point like ``report`` and ``drawing``
(it paints with Qt). Everything that can refuse the job (the file's parts, the cam, the
folder, the names, the options) is checked before Qt starts and before the first file is
written: a refusal is one line, exit status 2, and nothing written.
"""
from __future__ import annotations

import argparse
import os
import sys
import time

from core.cli.common import UsageError
from core.cli.notes import say_defaulted
from core.cli.output import OutputError, add_cad_font_option, cad_font_from_args
from core.course_design.plan import PARTS, CourseError, file_names, plan_course, read_document
from core.drawing.paper import PAPERS

from shaperapp.widgets.command_line import (add_cover_options, add_sheet_speed_option,
                                            cover_from_args, design_name, sheet_speed, start_qt)

HELP = "write the whole course design: the report and every drawing sheet, from one design file"
_NAMES = ", ".join(name for _, name in file_names(PARTS, dxf=False))
# What each design-file key the parts need is, for the help: in the order the parts need them.
_KEYS = {"rpm": "the speeds (\"rpm\")", "forces": "the loads (\"forces\")",
         "cam": "the feed cam (\"cam\")", "gear": "the gear pair (\"gear\": z1, z2, module_mm)"}
_NEEDED = list(dict.fromkeys(key for part in PARTS for key in part.needs))
_NEEDS = ", ".join(_KEYS.get(key, f"\"{key}\"") for key in _NEEDED[:-1]) + \
    f" and {_KEYS.get(_NEEDED[-1], _NEEDED[-1])}"
DESCRIPTION = ("The course design (课程设计) of one design file in one folder, with numbered names: "
               f"{_NAMES} (and each sheet's .dxf beside its PDF with --dxf). The design file "
               f"must hold what every file needs: the linkage, {_NEEDS}; without one the command "
               "names it and writes nothing. The folder is made if it is not there (its parent must be); files "
               "of the same names in it are replaced, each atomically, other files are left "
               "alone. Prints each file's path once it is complete. The report is A4 with every "
               "speed, the sheets on --sheet paper at one speed (--rpm-index); Chinese needs a font with Chinese glyphs (fonts-noto-cjk).")
EXAMPLES = ("shaper course --design my.shaper.json -o course",
            "shaper course --design my.shaper.json --lang zh --sheet A2 --dxf --student 张三 "
            "--student-number 2021001 --class 机械2101 --school 机械工程学院 --supervisor 李四 "
            "-o 课程设计")


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--design", required=True, metavar="FILE",
                        help="the design file (saved by the GUI) with the linkage, speeds, loads, cam and "
                             "gear pair")
    parser.add_argument("-o", "--output", required=True, metavar="DIR",
                        help="the folder to write into (made if missing; same-named files are replaced)")
    add_file_options(parser)
    add_sheet_speed_option(parser)
    block = parser.add_argument_group("cover and title blocks (blank when not given, to fill in by hand)")
    block.add_argument("--title", metavar="TEXT", help="design name (default: the design file's name)")
    add_cover_options(block, "the date (default: today, YYYY-MM-DD)")


def add_file_options(parser: argparse.ArgumentParser) -> None:
    """--lang, --sheet, --dxf and --cad-font: how the files are written (shared with ``shaper class``)."""
    parser.add_argument("--lang", choices=("en", "zh", "zh_CN"), default="en",
                        help="language of every file: en, or zh (= zh_CN) (default en)")
    parser.add_argument("--sheet", default="A1", metavar="SIZE",
                        help=f"paper of the drawing sheets, landscape: {', '.join(PAPERS)} (default A1)")
    parser.add_argument("--dxf", action="store_true", help="write each sheet as DXF too, beside its PDF")
    add_cad_font_option(parser)


def paper_of(args: argparse.Namespace) -> str:
    """--sheet's paper, checked (UsageError naming it)."""
    paper = args.sheet.upper()
    if paper not in PAPERS:
        raise UsageError(f"--sheet: {args.sheet!r} is not one of {', '.join(PAPERS)}")
    return paper


def run(args: argparse.Namespace) -> int:
    from .write import Covering
    paper = paper_of(args)
    cover, date = cover_from_args(args)
    doc, keys = read_document(args.design)          # FileFormatError: "--design: …"
    say_defaulted("--design", args.design, doc)
    try:
        course = plan_course(doc, keys, args.design, args.output, dxf=args.dxf)
    except CourseError as exc:
        raise (UsageError if exc.option == "--design" else OutputError)(str(exc)) from None
    covering = Covering(paper, design_name(args), date, cover, speed=sheet_speed(args, len(course.rpms)),
                        cad_font=cad_font_from_args(args, args.dxf))
    there = [os.path.basename(f.path) for f in course.files if os.path.lexists(f.path)]
    if there:       # replaced whole, as documented: said, since the teacher's own may be among them
        print(f"shaper: note: {args.output} holds {len(there)} of these files already, replaced now: "
              f"{', '.join(there)}", file=sys.stderr, flush=True)
    start = time.perf_counter()
    language = start_qt(args.lang)
    from .write import write_course
    try:
        for file in write_course(course, language, covering):
            print(file.path, flush=True)
    except OSError as exc:      # a WriteError: names the file and a plain reason
        raise OutputError(f"--output: {exc}") from None
    print(f"{len(course.files)} files in {time.perf_counter() - start:.1f} s")
    return 0
