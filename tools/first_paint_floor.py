"""The start-up floor under shaperapp: ``python tools/first_paint_floor.py``.

Imports what the window cannot start without (PySide6, numpy, pyqtgraph), makes a
QApplication and a main window holding one pyqtgraph plot at 1366 × 768, and prints
the time from this script's start to that window's first paint, measured as
shaperapp's ``--quit-after-show`` measures it. What the real window takes beyond this
is the project's own (issue 24). Only a developer's tool; run it offscreen
(``QT_QPA_PLATFORM=offscreen``) with ``OPENBLAS_NUM_THREADS=1`` as the app sets it.
"""
import gc
import time

START = time.perf_counter()
gc.disable()        # as shaperapp's main does: no automatic collections during start-up

import sys  # noqa: E402

import numpy  # noqa: E402
import pyqtgraph as pg  # noqa: E402
from PySide6.QtCore import QEvent, QObject, QTimer  # noqa: E402
from PySide6.QtWidgets import QApplication, QMainWindow  # noqa: E402


class _FirstPaint(QObject):
    def eventFilter(self, watched, event) -> bool:  # noqa: N802 - Qt's name
        if event.type() == QEvent.Type.Paint:
            watched.removeEventFilter(self)
            QTimer.singleShot(0, _done)
        return False


def _done() -> None:
    print(f"floor: first paint after {(time.perf_counter() - START) * 1000:.0f} ms", flush=True)
    QApplication.instance().quit()


app = QApplication(sys.argv[:1])
window = QMainWindow()
plot = pg.PlotWidget()
plot.plot(numpy.arange(10.0), numpy.arange(10.0) ** 2)
window.setCentralWidget(plot)
window.resize(1366, 768)
watcher = _FirstPaint()
plot.viewport().installEventFilter(watcher)
window.show()
app.exec()
