"""The busy cursor over a step the GUI thread runs to its end (a sheet written, a folder imported).

A step that keeps the event loop from running for more than about half a second
leaves the window unpainted; the cursor is the one sign the user can still see
that the program is working and not hung. Waits that can be cancelled or that
report progress run elsewhere (``export_process``, the Explore worker).
"""
from __future__ import annotations

from contextlib import contextmanager
from typing import Iterator

from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication


@contextmanager
def busy_cursor() -> Iterator[None]:
    """The wait cursor while the block runs, then the cursor as it was (also on an exception).

    ``sync`` hands the new cursor to the window system before the block starts: without
    it the request waits in the connection's buffer until the event loop runs again,
    which is after the wait it should have announced."""
    QGuiApplication.setOverrideCursor(Qt.CursorShape.WaitCursor)
    QGuiApplication.sync()
    try:
        yield
    finally:
        QGuiApplication.restoreOverrideCursor()


@contextmanager
def arrow_cursor() -> Iterator[None]:
    """The arrow for a question or message asked in the middle of a busy step (a library
    that cannot be written, refused files): the wait cursor over a dialog that waits for
    the user says the opposite of what is happening. Nothing changes outside a busy step."""
    busy = QGuiApplication.overrideCursor() is not None
    if busy:
        QGuiApplication.setOverrideCursor(Qt.CursorShape.ArrowCursor)
    try:
        yield
    finally:
        if busy:
            QGuiApplication.restoreOverrideCursor()
