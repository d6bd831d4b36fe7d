"""What the Qt-based ``shaper`` subcommands (report, drawing) share: a headless Qt
application, quiet Qt messages, one-line text options and the design's name."""
from __future__ import annotations

import argparse
import datetime
import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Sequence

from core.cli.common import UsageError
from core.base.text import UNDECODABLE, UNPRINTABLE

if TYPE_CHECKING:
    from core.space.compare import Candidate

MAX_TEXT = 200


def cover_text(option: str, value: str | None) -> str:
    """A text option as given: one line of at most MAX_TEXT characters of text (UsageError
    naming ``option`` otherwise)."""
    if value is None:
        return ""
    if UNDECODABLE.search(value):
        raise UsageError(f"{option}: must be text; it holds a byte that is not "
                         f"{sys.getfilesystemencoding().upper()}")
    if UNPRINTABLE.search(value):
        raise UsageError(f"{option}: must be one line of text without control characters or noncharacters")
    if len(value) > MAX_TEXT:
        raise UsageError(f"{option}: at most {MAX_TEXT} characters (got {len(value)})")
    return value.strip()


def plain_text(text: str) -> str:
    """A name nobody typed (a file's) as a title can print it: every control character and
    undecodable byte as U+FFFD, at most MAX_TEXT characters (cut with "…"). A file may have
    any name; the sheets, the report and their files take only this."""
    text = UNPRINTABLE.sub("\ufffd", text).strip()
    return text if len(text) <= MAX_TEXT else text[:MAX_TEXT - 1] + "…"


def printable_labels(candidates: Sequence[Candidate]) -> list[Candidate]:
    """Comparison candidates (``core.space.compare.Candidate``) labelled as :func:`plain_text`: a
    file's name with a control character made the comparison's SVG figures unreadable
    (the report failed on a drawing of size 0)."""
    from dataclasses import replace
    return [replace(c, label=plain_text(c.label)) for c in candidates]


# The course design's cover fields: option → (field, help). ``shaper report`` prints them on
# its cover, ``shaper drawing`` in the title block, and the GUI's two dialogs keep them under
# the settings keys "report/<field>": one place, so both ask for the same things alike.
COVER_OPTIONS = {"--student": ("student", "the student's name"),
                 "--student-number": ("number", "the student's number"),
                 "--class": ("group", "the student's class"),
                 "--school": ("school", "the school or department"),
                 "--supervisor": ("supervisor", "the supervising teacher")}
COVER_FIELDS = tuple(field for field, _ in COVER_OPTIONS.values())
COVER_SETTINGS = "report/"           # QSettings key prefix of the remembered cover fields


def add_cover_options(group, date_help: str) -> None:
    """The cover options (COVER_OPTIONS and --date) on an argument group."""
    for option, (_, what) in COVER_OPTIONS.items():
        group.add_argument(option, metavar="TEXT", help=what)
    group.add_argument("--date", metavar="TEXT", help=date_help)


def cover_from_args(args: argparse.Namespace) -> tuple[dict[str, str], str]:
    """The cover fields (field → text) and the date (default today, YYYY-MM-DD), checked."""
    fields = {field: cover_text(option, getattr(args, option[2:].replace("-", "_")))
              for option, (field, _) in COVER_OPTIONS.items()}
    return fields, cover_text("--date", args.date) or datetime.date.today().isoformat()


def design_file_name(path: str) -> str:
    """A design file's name without its types (.json, .shaper): what titles call the design,
    as :func:`plain_text`."""
    name = Path(path).name
    for suffix in (".json", ".shaper"):
        name = name[: -len(suffix)] if name.endswith(suffix) else name
    return plain_text(name)


def inputs_name(spec) -> str:
    """A design without a file or library name is named by its inputs, never "Untitled"."""
    if spec.mode == "synthesis":
        text = f"L1 {spec.crank:g} mm, K {spec.time_ratio:g}, H {spec.stroke:g} mm"
    else:
        text = f"L1 {spec.crank:g} mm, L2 {spec.frame:g} mm, L3 {spec.lever:g} mm"
    if spec.variant == "rod":
        text += f", L4 {spec.rod_length:g} mm" if spec.rod_input == "length" \
            else f", L4/L3 {spec.rod_ratio:g}"
    return text


def design_name(args: argparse.Namespace) -> str:
    """--title (checked: UsageError naming it), else the design file's name (made printable:
    a file's name is never refused as if it were --title), else ''."""
    title = cover_text("--title", args.title)
    if title:
        return title
    return design_file_name(args.design) if args.design else ""


def ensure_headless() -> None:
    """Qt draws offscreen when there is no display (CI, ssh)."""
    if sys.platform.startswith("linux") and not (os.environ.get("DISPLAY")
                                                 or os.environ.get("WAYLAND_DISPLAY")):
        os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")


def _quiet(kind, _context, message) -> None:
    """Qt's platform notes (e.g. the offscreen plugin's) are not for the user; real
    failures surface as exceptions or a missing file."""
    from PySide6.QtCore import QtMsgType
    if kind in (QtMsgType.QtCriticalMsg, QtMsgType.QtFatalMsg):
        print(f"shaper: Qt: {message}", file=sys.stderr)


def application():
    """The running QApplication, or a new one with the plots configured."""
    from PySide6.QtCore import qInstallMessageHandler
    from PySide6.QtWidgets import QApplication
    from shaperapp.widgets.style import configure_plots
    configure_plots()
    from shaperapp.widgets.fonts import prefer_simplified_chinese
    qInstallMessageHandler(_quiet)
    app = QApplication.instance() or QApplication(sys.argv[:1])
    prefer_simplified_chinese()          # before any text is laid out (see its docstring)
    return app


def inputs_from_args(args: argparse.Namespace):
    """The design's inputs, its speeds and its loads (None when none were given), checked."""
    from core.cli.cmd_table import masses_or_none
    from core.cli.common import rpms_from_args, spec_from_args
    from core.linkage.kinematics import check_rpms
    spec = spec_from_args(args)
    design = spec.design()                  # its error first, as every command reports it
    rpms = [float(r) for r in check_rpms(rpms_from_args(args))]
    return spec, rpms, masses_or_none(args, design)


def diagram_angles(args: argparse.Namespace) -> tuple[float, float] | None:
    """--diagrams A,B as two crank angles in degrees, or None when not given."""
    from core.cli.common import number_list
    from core.base.errors import DesignError
    from core.course_design.positions import check_extra
    if args.diagrams is None:
        return None
    values = check_extra(number_list("diagrams", args.diagrams))
    if values.size != 2:
        raise DesignError("diagrams", args.diagrams, "must be two crank angles A,B in degrees")
    return float(values[0]), float(values[1])


def check_output_folder(path: str) -> None:
    """OutputError naming --output when ``path`` cannot be written (its folder missing, a
    folder, a name too long …), with the words of every other writer (``check_target``)."""
    from core.cli.output import check_target
    check_target("--output", path)


def start_qt(lang: str, needs_font: bool = True) -> str:
    """A headless application in the language of --lang; returns that language. With
    ``needs_font``, UsageError naming --lang when no font can write it."""
    ensure_headless()
    application()
    from shaperapp.widgets import i18n
    from shaperapp.widgets.fonts import MissingFontError, report_font
    language = i18n.language_of(lang)
    i18n.set_language(language)
    if needs_font:
        try:
            report_font(language)
        except MissingFontError as exc:
            raise UsageError(f"--lang {lang}: {exc}") from None
    return language


SPEED_OPTION = "--rpm-index"


def add_sheet_speed_option(parser: argparse.ArgumentParser) -> None:
    """--rpm-index N: which of the design's speeds the sheets are drawn at, counted from 1
    as the speeds are listed (--rpm 40 60: 2 is 60 r/min)."""
    parser.add_argument(SPEED_OPTION, metavar="N",
                        help="draw the sheets at the N-th of the design's speeds, counted from 1 in "
                             "the order of --rpm or the design file's \"rpm\" (default 1, the first); "
                             "the title block shows it")


def sheet_speed(args: argparse.Namespace, count: int) -> int:
    """--rpm-index as an index into the design's ``count`` speeds (0-based); UsageError
    naming the option and the number of speeds when it is not one of them."""
    if args.rpm_index is None:
        return 0
    text = str(args.rpm_index).strip()
    speeds = f"the design has {count} speed{'s' if count != 1 else ''}"
    if not text.isdigit() or not 1 <= int(text) <= count:
        raise UsageError(f"{SPEED_OPTION}: must be a whole number 1 to {count}, {speeds} "
                         f"(got {args.rpm_index!r})")
    return int(text) - 1
