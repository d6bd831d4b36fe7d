"""A long export on the GUI thread, in slices, under a progress dialog with Cancel.

Why not a worker thread: the report and the sheets are painted by Qt, and the report's
figures are the app's own widgets rendered offscreen, which Qt allows on the GUI thread
only; a Python thread calling into Qt can also deadlock with the GUI thread over the GIL
(``worker.py``). So the job runs here, and at every step it reports (a section, a page,
a file: ``core.base.progress``) the dialog's bar moves and the pending events are processed:
the window repaints, and Cancel is read there. The dialog is window-modal: the window
stays drawn and answers, but takes no edits until the export has ended. The cursor is
the busy one (an arrow with an hourglass) meanwhile.
"""
from __future__ import annotations

from typing import Callable, TypeVar

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QApplication, QProgressDialog, QWidget

from core.base.progress import Progress

T = TypeVar("T")
STEPS = 1000            # the bar's maximum: the job's fraction in thousandths


def run_with_progress(job: Callable[[Progress, Callable[[str], None]], T], title: str, label: str,
                      parent: QWidget | None = None) -> T:
    """``job(progress, say)`` with a progress dialog titled ``title`` saying ``label`` (the
    job may say more: ``say(text)``, e.g. the file being written); what it returns, or what
    it raises (``core.base.progress.Cancelled`` after Cancel). The bar only moves forward and
    ends at its maximum when the job has finished."""
    QGuiApplication.setOverrideCursor(Qt.CursorShape.BusyCursor)
    dialog = None
    try:
        dialog = QProgressDialog(label, QCoreApplication.translate("Progress", "Cancel"), 0, STEPS, parent)
        dialog.setWindowTitle(title)
        dialog.setWindowModality(Qt.WindowModality.WindowModal)
        dialog.setMinimumDuration(0)
        dialog.setAutoClose(False)
        dialog.setAutoReset(False)
        dialog.setValue(0)
        QApplication.processEvents()            # the dialog shows before the first slice
        result = job(Progress(_reporter(dialog), dialog.wasCanceled), dialog.setLabelText)
        dialog.setValue(STEPS)
        return result
    finally:
        QGuiApplication.restoreOverrideCursor()
        if dialog is not None:
            dialog.close()
            dialog.deleteLater()


def _reporter(dialog: QProgressDialog) -> Callable[[float], None]:
    """The job's fraction done onto the bar (forward only), then the pending events: the
    window repaints and a click on Cancel is seen."""
    def report(fraction: float) -> None:
        value = round(fraction * STEPS)
        if value > dialog.value():
            dialog.setValue(value)
        QApplication.processEvents()
    return report
