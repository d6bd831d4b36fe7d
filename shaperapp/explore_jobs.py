"""Long explore computations off the GUI thread: a map of many designs, or an optimization.

Each job is a QObject whose ``run`` executes on its own QThread. It works in chunks, reports
progress and checks a cancel flag between chunks, so the window stays
responsive and Cancel takes effect within one chunk. Results travel back
through queued signals; the view never touches a job's data while it runs.
Every number comes from ``core.sweep`` / ``core.optimize``.
"""
from __future__ import annotations

import threading
from dataclasses import dataclass
import numpy as np
from PySide6.QtCore import QObject, QThread, Signal

from core.dynamics import MassProperties
from core.errors import DesignError
from core.optimize import Cancelled, Optimum, objective_of, optimize
from core.spec import Spec
from core.sweep import evaluate

# Figures a map can show: key → (objective it equals, needs loads, needs the rod variant).
FIGURES = {
    "pressure-angle": ("pressure-angle", False, True),
    "accel": ("accel", False, False),
    "v-work": (None, False, False),
    "v-return": (None, False, False),
    "peak-torque": ("peak-torque", True, False),
    "flywheel": ("flywheel", True, False),
}


@dataclass(frozen=True)
class MapResult:
    """A grid of designs over two parameters: figures (ny, nx) and why cells are invalid."""

    x_name: str
    y_name: str
    x: np.ndarray                      # (nx,) values of the x parameter
    y: np.ndarray                      # (ny,)
    figures: dict[str, np.ndarray]     # figure key → (ny, nx), NaN where invalid
    valid: np.ndarray                  # (ny, nx) bool
    errors: list[DesignError | None]   # row-major, None where valid


def figure_values(evaluation, key: str) -> np.ndarray:
    """One figure of every design: the worst value over the speeds (see ``core.optimize``)."""
    objective = FIGURES[key][0]
    if objective is not None:
        values = objective_of(evaluation, objective)
        return np.where(np.isfinite(values), values, np.nan)
    name = "v_work_max_m_s" if key == "v-work" else "v_return_max_m_s"
    return np.max(evaluation.figures[name], axis=-1)


class MapJob(QObject):
    """Evaluate an nx × ny grid of designs, a few rows at a time."""

    progress = Signal(int, int)         # rows done, rows in all
    finished = Signal(object)           # MapResult
    failed = Signal(object)             # the DesignError, or None for lack of memory
    cancelled = Signal()

    def __init__(self, spec: Spec, x_name: str, x: np.ndarray, y_name: str, y: np.ndarray,
                 rpms, masses: MassProperties | None, rows_per_chunk: int = 4) -> None:
        super().__init__()
        self.spec, self.x_name, self.x, self.y_name, self.y = spec, x_name, x, y_name, y
        self.rpms, self.masses, self.rows = rpms, masses, max(1, rows_per_chunk)
        self.stop = threading.Event()

    def run(self) -> None:
        try:
            keys = [k for k, (_, loads, rod) in FIGURES.items()
                    if (self.masses is not None or not loads)]
            figures = {k: np.full((self.y.size, self.x.size), np.nan) for k in keys}
            valid = np.zeros((self.y.size, self.x.size), dtype=bool)
            errors: list[DesignError | None] = []
            for start in range(0, self.y.size, self.rows):
                if self.stop.is_set():
                    self.cancelled.emit()
                    return
                rows = self.y[start:start + self.rows]
                yy, xx = np.meshgrid(rows, self.x, indexing="ij")
                ev = evaluate(self.spec, {self.x_name: xx.ravel(), self.y_name: yy.ravel()},
                              self.rpms, self.masses)
                part = slice(start, start + rows.size)
                valid[part] = ev.valid.reshape(rows.size, self.x.size)
                for key in keys:
                    if key == "pressure-angle" and ev.peaks.pressure_max is None:
                        continue
                    figures[key][part] = figure_values(ev, key).reshape(rows.size, self.x.size)
                errors += [ev.error(i) for i in range(rows.size * self.x.size)]
                self.progress.emit(min(start + rows.size, self.y.size), self.y.size)
            self.finished.emit(MapResult(self.x_name, self.y_name, self.x, self.y, figures,
                                         valid, errors))
        except DesignError as exc:
            self.failed.emit(exc)
        except MemoryError:
            self.failed.emit(None)


class OptimizeJob(QObject):
    """Run ``core.optimize.optimize``; Cancel stops it before its next batch."""

    progress = Signal(int, int)
    finished = Signal(object)           # Optimum
    failed = Signal(object)             # the DesignError, or None for lack of memory
    cancelled = Signal()

    def __init__(self, spec: Spec, bounds: dict[str, tuple[float, float]], objective: str,
                 rpms, masses: MassProperties | None) -> None:
        super().__init__()
        self.spec, self.bounds, self.objective = spec, bounds, objective
        self.rpms, self.masses = rpms, masses
        self.stop = threading.Event()

    def run(self) -> None:
        try:
            best: Optimum = optimize(self.spec, self.bounds, self.objective, self.rpms,
                                     self.masses, should_stop=self.stop.is_set)
        except Cancelled:
            self.cancelled.emit()
            return
        except DesignError as exc:
            self.failed.emit(exc)
            return
        except MemoryError:
            self.failed.emit(None)
            return
        self.finished.emit(best)


class _Worker(QThread):
    """A thread that runs one job's ``run`` and ends (no event loop). The job stays a
    GUI-thread object, so its signals reach GUI-thread receivers queued."""

    def __init__(self, job: QObject, parent: QObject) -> None:
        super().__init__(parent)
        self.job = job

    def run(self) -> None:
        self.job.run()  # type: ignore[attr-defined]


class JobRunner(QObject):
    """Runs one job at a time on a worker thread; a new job cancels the previous one.

    ``ended(job)`` is emitted on the GUI thread when a job's thread has finished.
    Connect a job's own signals to bound methods of GUI-thread objects (never to
    lambdas, which would run on the worker thread).
    """

    ended = Signal(object)

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._threads: dict[QThread, QObject] = {}
        self._job: QObject | None = None

    @property
    def job(self) -> QObject | None:
        """The job running now (None once cancelled or ended)."""
        return self._job

    def start(self, job: QObject) -> None:
        self.cancel()
        thread = _Worker(job, self)
        thread.finished.connect(self._thread_finished)
        self._threads[thread] = job
        self._job = job
        thread.start()

    def _thread_finished(self) -> None:
        thread = self.sender()
        job = self._threads.pop(thread, None)  # type: ignore[arg-type]
        if job is self._job:
            self._job = None
        if isinstance(thread, QThread):
            thread.deleteLater()
        self.ended.emit(job)

    def cancel(self) -> None:
        """Ask the running job to stop; it ends at its next chunk."""
        if self._job is not None:
            self._job.stop.set()  # type: ignore[attr-defined]
        self._job = None

    def wait(self, msecs: int = 10_000) -> bool:
        """Block until every thread has ended (closing the window, tests)."""
        for job in self._threads.values():
            job.stop.set()  # type: ignore[attr-defined]
        return all(t.wait(msecs) for t in list(self._threads))
