"""An export written by a child process (``export_child``) while the window goes on.

The window stays usable: the tabs can be browsed and the design edited meanwhile, since
the child works on the snapshot it was given when the export started. A progress dialog
that blocks nothing (non-modal) shows how far the child is, and the busy cursor (an arrow
with an hourglass: working, and still answering) is on until it ends. Cancel asks the
child to stop (SIGTERM: it stops at the next step, the file being made not written) and
kills it if it has not ended within :data:`KILL_AFTER_MS`; the temporary files a killed
child leaves are removed here (``core.files.atomic.remove_stale_temps``), so the target folder
holds only complete files. Why a child and not a thread: see ``export_child``.
"""
from __future__ import annotations

import sys
from typing import Any, Callable

from PySide6.QtCore import QCoreApplication, QEventLoop, QObject, QProcess, QProcessEnvironment, Qt, \
    QTimer, Signal
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QProgressDialog, QWidget

from core.files.atomic import remove_stale_temps

from .export_child import EXIT_CANCELLED, EXIT_DONE, parse_line

STEPS = 1000            # the bar's maximum: the job's fraction in thousandths
KILL_AFTER_MS = 3000    # how long a child asked to stop may take before it is killed
translate = QCoreApplication.translate


class ChildExport(QObject):
    """One export in a child process, from its start to its end (:attr:`ended`).

    ``job`` is :func:`export_child.job_bytes`; ``targets`` the files it may write (their
    stale temporary siblings are removed after a kill), ``saved_as`` the file or folder
    the user chose (what a status line names); ``conclude(self)`` runs once at
    the end, and what it returns is :attr:`result`. After the end, :attr:`state` is
    "done", "cancelled" or "failed", :attr:`files` the files completed, :attr:`error` the
    exception that stopped it (None when it was not the child's own)."""

    progressed = Signal(float)
    ended = Signal()

    def __init__(self, job: bytes, targets: list[str], saved_as: str, title: str, label: str,
                 parent: QWidget | None, conclude: Callable[["ChildExport"], Any]) -> None:
        super().__init__(parent)
        self.saved_as = saved_as
        self.state = "running"
        self.files: list[str] = []
        self.error: BaseException | None = None
        self.result: Any = None
        self.cancelled = False
        self._targets, self._conclude, self._buffer = targets, conclude, b""
        QGuiApplication.setOverrideCursor(Qt.CursorShape.BusyCursor)
        self.dialog = QProgressDialog(label, translate("Progress", "Cancel"), 0, STEPS, parent)
        self.dialog.setWindowTitle(title)
        self.dialog.setWindowModality(Qt.WindowModality.NonModal)
        self.dialog.setMinimumDuration(0)
        self.dialog.setAutoClose(False)
        self.dialog.setAutoReset(False)
        self.dialog.setValue(0)
        self.dialog.canceled.connect(self.cancel)
        self.dialog.show()
        self.process = QProcess(self)
        env = QProcessEnvironment.systemEnvironment()
        env.insert("QT_QPA_PLATFORM", "offscreen")
        self.process.setProcessEnvironment(env)
        # its traceback, if any, goes to the log (the terminal), never to the user
        self.process.setProcessChannelMode(QProcess.ProcessChannelMode.ForwardedErrorChannel)
        self.process.readyReadStandardOutput.connect(self._read)
        self.process.finished.connect(self._finished)
        self.process.errorOccurred.connect(self._failed_to_start)
        self._killer = QTimer(self, singleShot=True, interval=KILL_AFTER_MS)
        self._killer.timeout.connect(self.process.kill)
        self.process.start(sys.executable, ["-m", "shaperapp.widgets.export_child"])
        self.process.write(job)
        self.process.closeWriteChannel()

    def cancel(self) -> None:
        """Stop the child at its next step (killed after :data:`KILL_AFTER_MS`)."""
        if self.state == "running" and not self.cancelled:
            self.cancelled = True
            self.dialog.setLabelText(translate("Progress", "Cancelling…"))
            self.process.terminate()
            self._killer.start()

    def wait(self, timeout_ms: int = 600_000) -> bool:
        """Turn the event loop until the export has ended (scripts and tests); False on
        timeout."""
        if self.state == "running":
            loop = QEventLoop()
            self.ended.connect(loop.quit)
            QTimer.singleShot(timeout_ms, loop.quit)
            loop.exec()
        return self.state != "running"

    def _read(self) -> None:
        self._buffer += bytes(self.process.readAllStandardOutput().data())
        *lines, self._buffer = self._buffer.split(b"\n")
        for raw in lines:
            message = parse_line(raw.decode("utf-8", "replace"))
            if message is None:
                continue
            kind, value = message
            if kind == "progress" and not self.cancelled:
                bar = round(value * STEPS)
                if bar > self.dialog.value():
                    self.dialog.setValue(bar)
                self.progressed.emit(value)
            elif kind == "file":
                self.files.append(value)
            elif kind == "error":
                self.error = value

    def _failed_to_start(self, error: QProcess.ProcessError) -> None:
        if error == QProcess.ProcessError.FailedToStart:
            self._end(None)

    def _finished(self, code: int, status: QProcess.ExitStatus) -> None:
        self._read()
        self._end(code if status == QProcess.ExitStatus.NormalExit else None)

    def _end(self, code: int | None) -> None:
        if self.state != "running":
            return
        self._killer.stop()
        if code == EXIT_DONE:
            self.state = "done"
        elif self.cancelled or code == EXIT_CANCELLED:
            self.state = "cancelled"
        else:
            self.state = "failed"
            if self.error is None:      # it died (killed, out of memory) or never started
                self.error = RuntimeError(translate("Progress", "the export's process stopped "
                                                    "unexpectedly (exit status %1)").replace(
                    "%1", str(code) if code is not None else "–"))
        if code != EXIT_DONE and code not in (EXIT_CANCELLED, 1):
            for target in self._targets:        # a killed child's temporary files
                remove_stale_temps(target)
        QGuiApplication.restoreOverrideCursor()
        self.dialog.hide()
        self.dialog.deleteLater()
        self.result = self._conclude(self)
        self.ended.emit()

