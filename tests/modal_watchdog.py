"""A guard against modal dialogs that nobody answers.

Offscreen, a modal dialog that a test did not expect (a QMessageBox.question the test
forgot to patch, an unsaved-changes question while a window closes) waits for a click
that never comes: the suite hangs until CI's time limit, and the log shows only the
test's name. The watchdog looks for a modal window a few times a second; one still
open after ``limit_s`` is rejected, so the test goes on, and its title and text are
kept for the test to fail with.
"""
from __future__ import annotations

import time

from PySide6.QtCore import QObject, QTimer
from PySide6.QtWidgets import QApplication, QDialog, QMessageBox, QProgressDialog, QWidget

POLL_MS = 250


def describe(widget: QWidget) -> str:
    """The dialog's class, title and text, as a test failure names it."""
    text = widget.text() if isinstance(widget, QMessageBox) else ""
    return f"{type(widget).__name__} {widget.windowTitle()!r}: {text!r}"


class ModalWatchdog(QObject):
    """Rejects any modal window left open longer than ``limit_s``; ``closed`` lists them."""

    def __init__(self, limit_s: float) -> None:
        super().__init__()
        self.limit_s = limit_s
        self.closed: list[str] = []
        self._since: tuple[QWidget, float, int] | None = None
        self._timer = QTimer(self, interval=POLL_MS)
        self._timer.timeout.connect(self._check)

    def start(self) -> None:
        self._timer.start()

    def stop(self) -> None:
        self._timer.stop()

    def _check(self) -> None:
        modal = QApplication.activeModalWidget()
        if modal is None:
            self._since = None
            return
        # a progress dialog whose bar has moved since the last look waits for no answer
        moved = modal.value() if isinstance(modal, QProgressDialog) else 0
        if self._since is None or self._since[0] is not modal or self._since[2] != moved:
            self._since = (modal, time.monotonic(), moved)
            return
        if time.monotonic() - self._since[1] >= self.limit_s:
            self.closed.append(describe(modal))
            self._since = None
            if isinstance(modal, QDialog):
                modal.reject()
            else:
                modal.close()
