"""``shaper report``: the design report as an A4 PDF (or HTML), headless.

Registered through the ``shaper.commands`` entry point (it needs Qt, which
``core`` never imports). Every input is validated by core before Qt starts,
so bad input is one line and exit status 2 like every other subcommand.
"""
from __future__ import annotations

import argparse
import errno
from pathlib import Path
from typing import TYPE_CHECKING

from core.files.atomic import atomic_write
from core.cli.cmd_library import library_failure
from core.cli.cmd_library_compare import load_candidates
from core.cli.common import (UsageError, add_design_options, add_load_options, add_speed_options,
                             design_file, number)
from core.cli.output import OutputError
from core.library.store import ENV_VAR, LibraryError
from core.course_design.counts import DEFAULT_COUNT
from core.base.progress import Progress

from shaperapp.widgets.command_line import (MAX_TEXT, add_cover_options, check_output_folder,  # noqa: F401
                                            cover_from_args, cover_text, design_name, diagram_angles,
                                            inputs_from_args, printable_labels, start_qt)

if TYPE_CHECKING:
    from core.space.compare import Candidate

HELP = "write the design report (A4 PDF, or HTML)"
DESCRIPTION = ("The course-design report (设计说明书): inputs, synthesized dimensions and validation "
               "margins, the scheme at both limit positions, s/v/a curves and cycle metrics, the "
               "positions table, velocity/acceleration/force polygons at two positions, torque, "
               "energy, flywheel and motor power, the conventions and formulas, with --compare "
               "or --compare-file a comparison with other designs, and from a --design file its "
               "feed cam and its gear pair (the pair in mesh to scale). Runs without a display. The "
               "Chinese report needs a font with Chinese glyphs (fonts-noto-cjk).")
EXAMPLES = ("shaper report --crank 100 --K 1.4 --stroke 300 --rpm 40 60 --lever-mass 20 "
            "--lever-inertia 1.1 --ram-mass 70 --cut-force 7000 --cut-height 80 -o report.pdf",
            "shaper report --design my.shaper.json --lang zh --diagrams 90,270 -o 说明书.pdf",
            "shaper report --design my.shaper.json --html -o report.html",
            "shaper report --design my.shaper.json --compare base rod-1.6 --compare-file other.shaper.json "
            "-o report.pdf")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser)
    add_speed_options(parser)
    add_load_options(parser, required=False)
    parser.add_argument("-o", "--output", required=True, metavar="FILE",
                        help="the report file to write: .pdf for a PDF, .html or .htm for HTML")
    parser.add_argument("--lang", choices=("en", "zh", "zh_CN"), default="en",
                        help="report language: en, or zh (= zh_CN) for Chinese (default en)")
    parser.add_argument("--positions", metavar="N", default=str(DEFAULT_COUNT),
                        help="number of equally spaced crank positions in the table (default 12)")
    parser.add_argument("--diagrams", metavar="A,B",
                        help="crank angles (degrees) of the two vector-diagram positions (default: "
                             "mid working stroke and mid return stroke)")
    parser.add_argument("--title", metavar="TEXT",
                        help="design name for the title block (default: the design file's name)")
    cover = parser.add_argument_group("cover block (printed blank when not given, to fill in by hand)")
    add_cover_options(cover, "the date on the cover (default: today, YYYY-MM-DD)")
    parser.add_argument("--html", action="store_true",
                        help="insist on HTML (the name must end in .html or .htm)")
    parser.add_argument("--compare", nargs="+", default=[], metavar="NAME",
                        help="add a comparison section: the design beside these library entries "
                             "at the first speed (numbers as 'shaper library compare')")
    parser.add_argument("--compare-file", nargs="+", default=[], metavar="FILE",
                        help="add a comparison section with these design files")
    parser.add_argument("--library", metavar="PATH",
                        help=f"the library of --compare (default: ${ENV_VAR}, else the per-user library)")


def comparison_candidates(args: argparse.Namespace) -> list[Candidate]:
    """The designs of --compare (library) and --compare-file, checked before Qt starts:
    1 to MAX_DESIGNS − 1 of them, no library name twice. LibraryError for the library."""
    from core.space.compare import MAX_DESIGNS
    if not args.compare and not args.compare_file:
        return []
    others, _ = load_candidates(args.library, args.compare, args.compare_file, "--compare-file")
    others = printable_labels(others)
    if len(others) > MAX_DESIGNS - 1:
        option = "--compare" if args.compare else "--compare-file"
        raise UsageError(f"{option}: compare the design with at most {MAX_DESIGNS - 1} others "
                         f"(got {len(others)})")
    names = [c.label for c in others]
    for name in names:
        if names.count(name) > 1:
            raise UsageError(f"--compare: {name!r} is named twice")
    return others


def run(args: argparse.Namespace) -> int:
    try:
        return _run(args)
    except LibraryError as exc:                 # only --compare's library raises it
        return library_failure(exc, args.library, "report", "--compare")


def _run(args: argparse.Namespace) -> int:
    from core.course_design.positions import check_count
    spec, rpms, masses = inputs_from_args(args)
    count = check_count(number("positions", args.positions))
    diagrams = diagram_angles(args)
    others = comparison_candidates(args)
    cover, date = cover_from_args(args)
    title = design_name(args)
    target = Path(args.output)
    try:
        kind = report_kind(args.output, html=args.html)
    except ValueError as exc:
        raise OutputError(f"--output: {exc}") from None
    check_output_folder(args.output)
    language = start_qt(args.lang)
    from .content import Options, build
    from .blocks import Cover
    from core.cam.file import cam_from_dict
    from core.gear.file import gear_from_dict
    doc = design_file(args)         # a design file's feed cam and gear pair go into the report too
    cam = cam_from_dict(doc["cam"]) if doc is not None and doc.get("cam") is not None else None
    gear = gear_from_dict(doc["gear"]) if doc is not None and doc.get("gear") is not None else None
    report = build(spec, rpms, masses, title, date, language,
                   Options(count, diagrams, tuple(others), Cover(**cover), cam, gear))
    try:
        pages = write_report(report, args.output)
    except OSError as exc:      # a WriteError: names the path and a plain reason
        raise OutputError(f"--output: {exc}") from None
    what = "HTML" if kind == "html" else f"PDF, {pages} pages"
    print(f"wrote {target} ({what})")
    return 0


# The file name says what is written: a report is never a PDF under another type's name.
REPORT_TYPES = {".pdf": "pdf", ".html": "html", ".htm": "html"}


def report_kind(path: str, html: bool = False) -> str:
    """"pdf" or "html", from the name's suffix (any case). ValueError with a plain reason
    for another or no suffix, or a PDF name with ``html`` (the CLI's --html) set."""
    suffix = Path(path).suffix.lower()
    kind = REPORT_TYPES.get(suffix)
    if kind is None:
        raise ValueError(f"the file name must end in .pdf, .html or .htm (got {Path(path).name!r})")
    if html and kind != "html":
        raise ValueError(f"--html writes HTML, but {Path(path).name!r} names a PDF; "
                         "name the file .html or leave out --html")
    return kind


def write_report(report, path: str, progress: Progress = Progress()) -> int:
    """Write ``report`` as the type its name says (:func:`report_kind`), atomically: the
    old file or the whole new one (``core.files.atomic``). Returns the PDF's page count (0 for
    HTML). ValueError for a name of another type; OSError (a WriteError) names the path.
    ``progress`` hears of every page; Cancelled (it said stop) before anything is written."""
    from .html import report_html
    from .pdf import pdf_bytes
    if report_kind(path) == "html":
        text = report_html(report)
        progress.done(1.0)
        atomic_write(path, text)
        return 0
    data, pages = pdf_bytes(report, progress=progress)
    if not data:
        raise OSError(errno.EIO, "the PDF writer produced nothing", path)
    atomic_write(path, data)
    return pages
