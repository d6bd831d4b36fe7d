"""Long explore computations off the GUI thread: a map of many designs, or an optimization.

Each job is plain Python that ``worker.JobRunner`` runs on a worker thread (which never
touches Qt; see there why). It works in chunks, reports progress and checks a cancel flag
between chunks, so the window stays responsive and Cancel takes effect within one chunk.
Results reach the view as the runner's signals, on the GUI thread; the view never touches
a job's data while it runs. Every number comes from ``core.space.sweep`` / ``core.space.optimize``.
"""
from __future__ import annotations

import threading
from dataclasses import dataclass
import numpy as np

from core.forces.masses import MassProperties
from core.base.errors import DesignError
from core.space.optimize import Cancelled, Optimum, objective_of, optimize
from core.linkage.spec import Spec
from core.space.sweep import evaluate
from shaperapp.widgets.worker import Report

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
    """One figure of every design: the worst value over the speeds (see ``core.space.optimize``)."""
    objective = FIGURES[key][0]
    if objective is not None:
        values = objective_of(evaluation, objective)
        return np.where(np.isfinite(values), values, np.nan)
    name = "v_work_max_m_s" if key == "v-work" else "v_return_max_m_s"
    return np.max(evaluation.figures[name], axis=-1)


class MapJob:
    """Evaluate an nx × ny grid of designs, a few rows at a time (``worker.Job``)."""

    def __init__(self, spec: Spec, x_name: str, x: np.ndarray, y_name: str, y: np.ndarray,
                 rpms, masses: MassProperties | None, rows_per_chunk: int = 4) -> None:
        self.spec, self.x_name, self.x, self.y_name, self.y = spec, x_name, x, y_name, y
        self.rpms, self.masses, self.rows = rpms, masses, max(1, rows_per_chunk)
        self.stop = threading.Event()

    def run(self, report: Report) -> None:
        try:
            keys = [k for k, (_, loads, rod) in FIGURES.items()
                    if (self.masses is not None or not loads)]
            figures = {k: np.full((self.y.size, self.x.size), np.nan) for k in keys}
            valid = np.zeros((self.y.size, self.x.size), dtype=bool)
            errors: list[DesignError | None] = []
            for start in range(0, self.y.size, self.rows):
                if self.stop.is_set():
                    report("cancelled")
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
                report("progress", min(start + rows.size, self.y.size), self.y.size)
            report("finished", MapResult(self.x_name, self.y_name, self.x, self.y, figures,
                                         valid, errors))
        except DesignError as exc:
            report("failed", exc)
        except MemoryError:
            report("failed", None)


class OptimizeJob:
    """Run ``core.space.optimize.optimize``; Cancel stops it before its next batch (``worker.Job``)."""

    def __init__(self, spec: Spec, bounds: dict[str, tuple[float, float]], objective: str,
                 rpms, masses: MassProperties | None) -> None:
        self.spec, self.bounds, self.objective = spec, bounds, objective
        self.rpms, self.masses = rpms, masses
        self.stop = threading.Event()

    def run(self, report: Report) -> None:
        try:
            best: Optimum = optimize(self.spec, self.bounds, self.objective, self.rpms,
                                     self.masses, should_stop=self.stop.is_set)
        except Cancelled:
            report("cancelled")
            return
        except DesignError as exc:
            report("failed", exc)
            return
        except MemoryError:
            report("failed", None)
            return
        report("finished", best)
