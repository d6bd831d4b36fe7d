"""Every widget deleted when the session ends, while Python still runs, so that a run whose
tests all passed also exits with status 0.

A window a module-scoped fixture closes (tests/gui_helpers.py's ``main_window``) is only
marked for deletion (``deleteLater``); the next module's event loop deletes it. After the
last module no loop runs, so the window (its Python side kept by reference cycles) was
still there at interpreter exit. PySide then deletes every object Python still owns while
it destroys the QApplication, after Python has begun to shut down: a pyqtgraph widget's
destructor re-parents its children, their layout calls a Python override, and shiboken
crashed reporting its error (SIGSEGV in ``PepException_GetArgs``, under
``PySide::destroyQCoreApplication``). pytest had printed "passed", but the process ended by
signal 11, exit status 139, which fails CI: every run of
tests/test_shaperapp/gear/test_gui_gear_laptop.py alone did.

Deleted, not closed: a window left with unsaved changes would ask about them in a modal
dialog that nobody answers at this point.
"""
from __future__ import annotations

import gc
import sys

import pytest


@pytest.hookimpl(trylast=True)
def pytest_sessionfinish(session, exitstatus) -> None:
    """Delete every top-level widget (their children go with them) and the cycles that
    held them, if Qt was used at all."""
    if "PySide6.QtWidgets" not in sys.modules:
        return
    from PySide6.QtCore import QCoreApplication, QEvent
    from PySide6.QtWidgets import QApplication
    app = QApplication.instance()
    if app is None:
        return
    gc.collect()
    for widget in app.topLevelWidgets():
        widget.deleteLater()
    # Outside any event loop a posted deletion waits for one; sent here it is done now.
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    gc.collect()
