"""A run whose tests all passed exits with status 0: the process ends after pytest's last
word without tearing Qt down.

Tearing Qt down after the tests has crashed twice, at two different points, and each crash
turned a green run red:

* At interpreter exit (before 29 November): a window a module-scoped fixture had closed
  (tests/gui_helpers.py's ``main_window``) was only marked for deletion (``deleteLater``),
  and no event loop ran after the last module to delete it. PySide deleted it while it
  destroyed the QApplication, after Python had begun to shut down: a pyqtgraph widget's
  destructor re-parented its children, their layout called a Python override, and shiboken
  crashed reporting its error (SIGSEGV in ``PepException_GetArgs``, under
  ``PySide::destroyQCoreApplication``). pytest had printed "passed", the process ended by
  signal 11, exit status 139: every run of tests/test_shaperapp/gear/test_gui_gear_laptop.py
  alone did.
* In ``pytest_sessionfinish`` (CI, 29 November): the cure for the first, deleting every
  top-level widget there while Python still ran, crashed an xdist worker once in a
  whole-suite run, after its last test and before it reported "finished" ("node down: Not
  properly terminated"); CI's log kept too little of the dump to say which widget.

Neither is a test of the application: how the real window closes and exits is tested on
the application itself (tests/test_shaperapp/window/). So the process leaves once pytest
has written everything, with pytest's own exit status, and Qt's objects are not destroyed
one by one. In an xdist worker this is after the worker's "finished" event has gone to the
controller, which then ignores how the worker's process ends.
"""
from __future__ import annotations

import os
import sys

import pytest

_exit_status: int | None = None


@pytest.hookimpl(trylast=True)
def pytest_sessionfinish(session, exitstatus) -> None:
    """Keep the run's status for the exit below (``pytest_unconfigure`` does not get it)."""
    global _exit_status
    _exit_status = int(exitstatus)


@pytest.hookimpl(trylast=True)
def pytest_unconfigure(config) -> None:
    """After every other plugin's last hook: leave without Qt's teardown, if Qt was used."""
    if _exit_status is None or "PySide6.QtWidgets" not in sys.modules:
        return
    from PySide6.QtWidgets import QApplication
    if QApplication.instance() is None:
        return
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(_exit_status)
