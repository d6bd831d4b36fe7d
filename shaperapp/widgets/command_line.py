"""What the Qt-based ``shaper`` subcommands (report, drawing) share: a headless Qt
application, quiet Qt messages, one-line text options and the design's name."""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from core.cli.common import UsageError

MAX_TEXT = 200


def cover_text(option: str, value: str | None) -> str:
    """A text option as given: one line of at most MAX_TEXT characters (UsageError)."""
    if value is None:
        return ""
    if any(ch < " " or "\x7f" <= ch < "\xa0" or ch in "\u2028\u2029" for ch in value):
        raise UsageError(f"{option}: must be one line of text without control characters")
    if len(value) > MAX_TEXT:
        raise UsageError(f"{option}: at most {MAX_TEXT} characters (got {len(value)})")
    return value.strip()


def design_file_name(path: str) -> str:
    """A design file's name without its types (.json, .shaper): what titles call the design."""
    name = Path(path).name
    for suffix in (".json", ".shaper"):
        name = name[: -len(suffix)] if name.endswith(suffix) else name
    return name


def design_name(args: argparse.Namespace) -> str:
    """--title, else the design file's name, else ''."""
    if args.title:
        return args.title
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
    qInstallMessageHandler(_quiet)
    return QApplication.instance() or QApplication(sys.argv[:1])
