"""The one model object: current design, its results, and the animation angle.

Widgets read from it and call its setters; it emits a signal only when a
value really changes. A parameter change recomputes the whole cycle once;
the animation only moves an index into the precomputed arrays.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np
from PySide6.QtCore import QObject, Signal

from core.dynamics import (Dynamics, DynamicsSummary, MassProperties, masses_for_design,
                           solve_dynamics, summarize)
from core.errors import DesignError
from core.geometry import Design
from core.kinematics import Motion, check_rpms, crank_angles, solve
from core.metrics import CycleMetrics, analyze
from core.spec import Spec

DEFAULT_RPMS = (40.0, 60.0)
DEFAULT_STEP = 1.0
# The classic course-design loads of a shaper (lever 200 N, J = 1.1 kg·m², ram 700 N,
# cutting force 7000 N at 80 mm below the guide), so the Forces view shows a case at once.
DEFAULT_MASSES = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                                cut_force_N=7000.0, cut_height_mm=80.0, delta=1.0 / 30.0)


class DesignModel(QObject):
    """Holds the spec the user typed, the last valid design and its results.

    Signals:
      ``resultsChanged`` — design, motion or metrics were recomputed;
      ``specChanged`` — the edited inputs changed (valid or not);
      ``errorChanged`` — the validation error appeared, changed or cleared;
      ``angleChanged(int)`` — the animation index moved;
      ``forcesChanged`` — dynamics were recomputed (after any design or load change);
      ``forcesErrorChanged`` — a load input became invalid or valid again;
      ``dirtyChanged(bool)``, ``pathChanged(str)`` — file state.
    """

    resultsChanged = Signal()
    specChanged = Signal()
    errorChanged = Signal()
    forcesChanged = Signal()
    forcesErrorChanged = Signal()
    angleChanged = Signal(int)
    dirtyChanged = Signal(bool)
    pathChanged = Signal(str)

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._spec = Spec()
        self._valid_spec = self._spec
        self._rpms: tuple[float, ...] = DEFAULT_RPMS
        self._step = DEFAULT_STEP
        self._error: DesignError | None = None
        self._index = 0
        self._dirty = False
        self._path = ""
        self._design: Design = self._spec.design()
        self._motion: Motion = solve(self._design, crank_angles(self._step), self._rpms)
        self._metrics: CycleMetrics = analyze(self._design, self._rpms)
        self._masses = DEFAULT_MASSES
        self._mass_inputs: dict[str, Any] = {}
        self._forces_error: DesignError | None = None
        self._dynamics, self._dynamics_summary = self._solve_forces(self._design, self._motion, self._masses)

    # ---- read access -------------------------------------------------
    @property
    def spec(self) -> Spec:
        """The inputs as the user last typed them (may be invalid)."""
        return self._spec

    @property
    def valid_spec(self) -> Spec:
        """The inputs of the design on screen (what Save writes)."""
        return self._valid_spec

    @property
    def design(self) -> Design:
        """The last valid design."""
        return self._design

    @property
    def motion(self) -> Motion:
        return self._motion

    @property
    def metrics(self) -> CycleMetrics:
        return self._metrics

    @property
    def masses(self) -> MassProperties:
        """The last valid loads (as entered; see ``core.dynamics.masses_for_design`` for what is solved)."""
        return self._masses

    @property
    def mass_inputs(self) -> dict[str, Any]:
        """Load fields as last typed, including invalid ones not yet applied."""
        return {**self._masses.__dict__, **self._mass_inputs}

    @property
    def dynamics(self) -> Dynamics:
        return self._dynamics

    @property
    def dynamics_summary(self) -> DynamicsSummary:
        return self._dynamics_summary

    @property
    def forces_error(self) -> DesignError | None:
        return self._forces_error

    @property
    def rpms(self) -> tuple[float, ...]:
        return self._rpms

    @property
    def step_deg(self) -> float:
        return self._step

    @property
    def error(self) -> DesignError | None:
        return self._error

    @property
    def angle_index(self) -> int:
        return self._index

    @property
    def crank_deg(self) -> float:
        return math.degrees(float(self._motion.crank_angle[self._index]))

    @property
    def angle_count(self) -> int:
        return int(self._motion.crank_angle.size)

    @property
    def dirty(self) -> bool:
        return self._dirty

    @property
    def path(self) -> str:
        return self._path

    # ---- edits -------------------------------------------------------
    def set_spec(self, **changes: Any) -> None:
        """Change some inputs at once; recompute if they form a valid design."""
        spec = replace(self._spec, **changes)
        if spec == self._spec:
            return
        self._spec = spec
        self.specChanged.emit()
        self._mark_dirty()
        self._recompute()

    def set_rpms(self, rpms) -> None:
        """Set the crank speeds (r/min); an invalid list is reported, not applied."""
        try:
            values = tuple(float(v) for v in check_rpms(list(rpms)))
        except DesignError as exc:
            self._set_error(exc)
            return
        if values == self._rpms:
            if self._error is not None and self._error.parameter == "rpm":
                self._set_error(None)
            return
        self._rpms = values
        self._mark_dirty()
        self._recompute()

    def set_step(self, step_deg: float) -> None:
        if step_deg == self._step:
            return
        try:
            crank_angles(step_deg)
        except DesignError as exc:
            self._set_error(exc)
            return
        fraction = self._index / max(self.angle_count - 1, 1)
        self._step = float(step_deg)
        self._mark_dirty()
        self._recompute(keep_fraction=fraction)

    def set_angle_index(self, index: int) -> None:
        index = int(index) % self.angle_count
        if index != self._index:
            self._index = index
            self.angleChanged.emit(index)

    def set_angle_deg(self, degrees: float) -> None:
        """Move the animation to the grid angle nearest ``degrees`` (wrapped to one cycle)."""
        deg = float(degrees) % 360.0
        grid = np.degrees(self._motion.crank_angle)
        self.set_angle_index(int(np.argmin(np.abs(grid - deg))))

    def set_masses(self, **changes: Any) -> None:
        """Change some load inputs; apply them if they are all valid."""
        inputs = {**self._mass_inputs, **changes}
        if inputs == self._mass_inputs:
            return
        self._mass_inputs = inputs
        try:
            masses = replace(self._masses, **inputs)
            dynamics, summary = self._solve_forces(self._design, self._motion, masses)
        except DesignError as exc:
            self._set_forces_error(exc)
            return
        self._mark_dirty()
        self._masses, self._mass_inputs = masses, {}
        self._dynamics, self._dynamics_summary = dynamics, summary
        self._set_forces_error(None)
        self.forcesChanged.emit()

    def load_state(self, spec: Spec, rpms, step_deg: float, path: str = "",
                   masses: MassProperties | None = None) -> None:
        """Replace everything at once (after a file was read and validated)."""
        self._masses = DEFAULT_MASSES if masses is None else masses
        self._mass_inputs = {}
        self._set_forces_error(None)
        self._spec = spec
        self._rpms = tuple(float(v) for v in rpms)
        self._step = float(step_deg)
        self._index = 0
        self.specChanged.emit()
        self._recompute()
        self.set_clean(path)

    def set_clean(self, path: str) -> None:
        if path != self._path:
            self._path = path
            self.pathChanged.emit(path)
        if self._dirty:
            self._dirty = False
            self.dirtyChanged.emit(False)

    # ---- internals ---------------------------------------------------
    def _mark_dirty(self) -> None:
        if not self._dirty:
            self._dirty = True
            self.dirtyChanged.emit(True)

    def _set_error(self, error: DesignError | None) -> None:
        same = (error is None and self._error is None) or (
            error is not None and self._error is not None and str(error) == str(self._error))
        self._error = error
        if not same:
            self.errorChanged.emit()

    def _set_forces_error(self, error: DesignError | None) -> None:
        changed = (error is None) != (self._forces_error is None) or (
            error is not None and str(error) != str(self._forces_error))
        self._forces_error = error
        if changed:
            self.forcesErrorChanged.emit()

    @staticmethod
    def _solve_forces(design: Design, motion: Motion,
                      masses: MassProperties) -> tuple[Dynamics, DynamicsSummary]:
        used = masses_for_design(design, masses)
        return (solve_dynamics(design, motion.crank_angle, motion.rpm, used),
                summarize(design, motion.rpm, used))

    def _recompute(self, keep_fraction: float | None = None) -> None:
        try:
            design = self._spec.design()
            motion = solve(design, crank_angles(self._step), self._rpms)
            metrics = analyze(design, self._rpms)
            dynamics, summary = self._solve_forces(design, motion, self._masses)
        except DesignError as exc:
            self._set_error(exc)
            return
        self._design, self._motion, self._metrics = design, motion, metrics
        self._dynamics, self._dynamics_summary = dynamics, summary
        self._valid_spec = self._spec
        if keep_fraction is not None:
            self._index = int(round(keep_fraction * (motion.crank_angle.size - 1)))
        self._index = min(self._index, motion.crank_angle.size - 1)
        self._set_error(None)
        self.resultsChanged.emit()
        self.forcesChanged.emit()
        self.angleChanged.emit(self._index)
