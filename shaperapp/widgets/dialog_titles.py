"""Dialogs at least as wide as their title bar's text.

A window manager elides a title that does not fit its dialog: at 1366 × 768 under
openbox "Go to crank angle — Shaper Designer" read "Go to … signer" and the report's
"Export design rep…". Every dialog of the application is widened, when it is shown,
to hold its full title (with the application's name Qt appends) and the title bar's
buttons; a dialog is never made wider than its screen.
"""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QEvent, QObject
from PySide6.QtGui import QFont, QFontMetrics, QGuiApplication
from PySide6.QtWidgets import QDialog, QFileDialog

from .file_dialogs import localize

TITLE_BAR_EXTRA_PX = 140      # the title bar's buttons, icon and margins
TITLE_FONT_SCALE = 1.15       # window managers draw titles in a larger (often bold) font


def title_width(dialog: QDialog) -> int:
    """px the title bar needs for the dialog's full title."""
    title = dialog.windowTitle().replace("[*]", "")
    name = QGuiApplication.applicationDisplayName()
    if name and name not in title:
        title = f"{title} — {name}"
    font = QFont(dialog.font())
    font.setBold(True)
    return int(QFontMetrics(font).horizontalAdvance(title) * TITLE_FONT_SCALE) + TITLE_BAR_EXTRA_PX


def fit_title(dialog: QDialog) -> None:
    need = title_width(dialog)
    screen = dialog.screen()
    if screen is not None:
        need = min(need, screen.availableGeometry().width())
    if dialog.width() < need:
        dialog.setMinimumWidth(need)
        dialog.resize(need, dialog.height())


class _TitleFitter(QObject):
    """Fits every dialog to its title when shown, and puts a file dialog's texts in the
    UI language (``file_dialogs.localize``), also those QFileDialog's static functions make."""

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        # Every event of the application passes here: the cheap type test first (reading
        # event.type() makes a Python enum, about 3 µs, thousands of times per repaint).
        if isinstance(watched, QDialog) and event.type() == QEvent.Type.Show:
            if isinstance(watched, QFileDialog):
                localize(watched)
            fit_title(watched)
        return False


_fitter: _TitleFitter | None = None
_held = False


def hold() -> None:
    """Until :func:`release`, :func:`install` installs nothing. For the application's start:
    the filter sees every event of the application, some 3 000 while the first window is
    built, laid out and painted (5-10 ms of the first paint, issue 43 item 5), and no
    dialog is shown before that paint (``app.main`` releases it then, or before it opens
    a file given on the command line, whose refusal is a dialog)."""
    global _held
    _held = True


def release(app: QCoreApplication) -> None:
    """End :func:`hold` and install the filter on ``app``."""
    global _held
    _held = False
    install(app)


def install(app: QCoreApplication) -> None:
    """Fit every dialog of ``app`` to its title and localize its file dialogs when shown
    (once per application; nothing while held). The window installs it
    (``MainWindow.set_language``): a process that only translates, a headless writer,
    shows no dialog and would pay the filter on every event."""
    global _fitter
    if _held:
        return
    if _fitter is None or _fitter.parent() is not app:
        _fitter = _TitleFitter(app)
        app.installEventFilter(_fitter)


def uninstall() -> None:
    """Take the filter off its application again: for the tests, whose windows come and go
    in one application (``tests/gui_helpers.main_window``), so that a test's events are
    filtered only when its own window installed the filter, whatever ran before it. The
    application itself keeps it to its end."""
    global _fitter
    if _fitter is not None:
        app = _fitter.parent()
        if app is not None:
            app.removeEventFilter(_fitter)
        _fitter.deleteLater()
        _fitter = None
