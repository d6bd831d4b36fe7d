"""The one model object: what the user typed, the design it gives, its results.

Widgets read from it and call its setters; it emits a signal only when a
value really changes. A parameter change recomputes the whole cycle once;
the animation only moves an index into the precomputed arrays.

Two states live here. The *inputs* are what the user typed, valid or not
(``spec``, ``rpm_inputs``, ``step_input``, ``mass_inputs``); every edit of them is
an undoable step on ``undo_stack``. The *design on screen* (``valid_spec``,
``rpms``, ``step_deg``, ``masses`` and everything computed from them) changes only
when the inputs are valid, so Save always writes a design that reopens.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING, Any, Callable, Hashable

import numpy as np
from PySide6.QtCore import QCoreApplication, QObject, Signal

from core.forces.dynamics import Dynamics, DynamicsSummary
from core.forces.masses import MassProperties
from core.base.errors import DesignError
from core.linkage.geometry import Design
from core.linkage.kinematics import Motion
from core.linkage.metrics import CycleMetrics
from core.linkage.spec import Spec

from .inputs import DEFAULT_MASSES, DEFAULT_RPMS, DEFAULT_STEP, Inputs, same_typed, spec_edit_key, typed_spec
from .errors import ShownError
from .results import (COMPUTE_ERRORS, as_design_error, compute, compute_error, compute_motion, compute_whole,
                      solve_forces)
from .parts import FileParts
from .undo import InputEdit, edit_text, owned_undo_stack, push_edit

if TYPE_CHECKING:       # a type only: core.space.compare is imported when a comparison is made
    from core.space.compare import Candidate

class DesignModel(QObject):
    """Holds the inputs the user typed, the last valid design and its results.

    Signals:
      ``resultsChanged`` — design, motion or metrics were recomputed;
      ``specChanged`` — the typed inputs (spec, speeds or step) changed, valid or not;
      ``errorChanged`` — the validation error appeared, changed or cleared;
      ``angleChanged(int)`` — the animation index moved;
      ``forcesChanged`` — dynamics were recomputed (after any design or load change);
      ``forcesErrorChanged`` — a load input became invalid or valid again, or was reset;
      ``dirtyChanged(bool)``, ``pathChanged(str)`` — file state;
      ``loaded`` — a whole state was put in (opened, new); parts read ``parts.loaded``.
    """

    resultsChanged = Signal()
    specChanged = Signal()
    errorChanged = Signal()
    forcesChanged = Signal()
    forcesErrorChanged = Signal()
    angleChanged = Signal(int)
    dirtyChanged = Signal(bool)
    pathChanged = Signal(str)
    loaded = Signal()

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._path = ""
        self._library_name = ""
        self._index = 0
        self._error = ShownError(self.errorChanged)
        self._forces_error = ShownError(self.forcesErrorChanged)
        self._session = 0
        self._valid_spec = Spec()
        self._rpms: tuple[float, ...] = DEFAULT_RPMS
        self._step = DEFAULT_STEP
        self._masses = DEFAULT_MASSES
        self._inputs = Inputs.of(self._valid_spec, self._rpms, self._step, self._masses)
        (self._design, self._motion, self._metrics,
         self._dynamics, self._dynamics_summary) = compute(self._inputs, self._masses)
        self.undo_stack = owned_undo_stack(self)
        self.undo_stack.cleanChanged.connect(self._on_clean_changed)
        self._comparison: tuple[Candidate, ...] = ()
        self.parts = FileParts()        # the file's parts other models keep (cam, gear)

    def saved_parts(self) -> dict[str, Any]:
        """The parts other models keep, as Save writes them (``parts.py``)."""
        return self.parts.saved()

    # ---- read access -------------------------------------------------
    @property
    def comparison_candidates(self) -> tuple[Candidate, ...]:
        """The designs on the Compare tab, as the report's "include the comparison" finds
        them. Session state beside the design: not saved, not undone."""
        return self._comparison

    def set_comparison_candidates(self, candidates) -> None:
        """Set by the Compare tab whenever its list changes."""
        self._comparison = tuple(candidates)

    @property
    def spec(self) -> Spec:
        """The inputs as the user last typed them (may be invalid)."""
        return self._inputs.spec

    @property
    def valid_spec(self) -> Spec:
        """The inputs of the design on screen (what Save writes); every field valid."""
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
        """The last valid loads (as entered; see ``core.forces.masses.masses_for_design`` for what is solved)."""
        return self._masses

    @property
    def mass_inputs(self) -> dict[str, Any]:
        """Load fields as last typed, including invalid ones not yet applied."""
        return self._inputs.load_dict

    @property
    def dynamics(self) -> Dynamics:
        return self._dynamics

    @property
    def dynamics_summary(self) -> DynamicsSummary:
        """Solved on first use after each change (see ``SummaryOnDemand``); one that cannot
        be computed is shown as undefined values with the forces error."""
        return self.cycle_summary(peaks=True)

    def cycle_summary(self, peaks: bool = True) -> DynamicsSummary:
        """:attr:`dynamics_summary`; ``peaks=False`` may leave out the exact torque peaks
        (NaN), for views that show only the energy, the means and the flywheel."""
        try:
            return self._dynamics_summary.get(peaks)
        except (DesignError, *COMPUTE_ERRORS) as exc:
            self._forces_error.set(as_design_error(exc), force=True)
            return self._dynamics_summary.undefined()

    @property
    def forces_error(self) -> DesignError | None:
        return self._forces_error.value

    @property
    def rpms(self) -> tuple[float, ...]:
        """Crank speeds of the design on screen, r/min."""
        return self._rpms

    @property
    def rpm_inputs(self) -> tuple[Any, ...]:
        """Speeds as typed: floats, or the text of an entry that is not a number."""
        return self._inputs.rpms

    @property
    def step_deg(self) -> float:
        return self._step

    @property
    def step_input(self) -> Any:
        """The angle step as typed (a float, or text that is not a number)."""
        return self._inputs.step

    @property
    def error(self) -> DesignError | None:
        return self._error.value

    @property
    def inputs_valid(self) -> bool:
        """True when what the user typed is the design on screen (nothing pending or invalid)."""
        return self._error.value is None and self._forces_error.value is None

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
        return not self.undo_stack.isClean()

    @property
    def path(self) -> str:
        return self._path

    # ---- edits (each one undoable) -----------------------------------
    def set_spec(self, **changes: Any) -> None:
        """Change some inputs at once; recompute if they form a valid design.

        A change of mode carries the design on screen over (``Spec.switch_mode``).
        A field that the new mode, variant or rule leaves unused keeps its last
        valid value instead of invalid text, so Save never writes one."""
        old = self._inputs.spec
        mode = changes.pop("mode", old.mode)
        requested, spec = typed_spec(old, mode, changes, self._design, self._valid_spec)
        if spec == old:
            if requested != old:
                self.specChanged.emit()       # the form shows the value kept instead
            return
        key, names = spec_edit_key(old, mode, changes)
        self._push(replace(self._inputs, spec=spec), key, lambda: edit_text(names))

    def set_rpms(self, rpms) -> None:
        """Set the crank speeds (r/min, or text as typed); an invalid list is reported, not applied."""
        values = tuple(rpms)
        if values == self._inputs.rpms:
            return
        self._push(replace(self._inputs, rpms=values), None, lambda: edit_text(["rpm"]))

    def set_step(self, step_deg: Any) -> None:
        """Set the angle step (degrees, or text as typed)."""
        if same_typed(step_deg, self._inputs.step):
            return
        self._push(replace(self._inputs, step=step_deg), ("step",), lambda: edit_text(["step"]))

    def set_masses(self, **changes: Any) -> None:
        """Change some load inputs; apply them if they are all valid."""
        loads = {**self._inputs.load_dict, **changes}
        if loads == self._inputs.load_dict:
            return
        names = sorted(changes)
        self._push(replace(self._inputs, loads=tuple(sorted(loads.items()))),
                   ("loads", tuple(names)), lambda: edit_text(names))

    def revert_invalid(self) -> None:
        """Put the design on screen back into every input (one undoable step)."""
        inputs = Inputs.of(self._valid_spec, self._rpms, self._step, self._masses)
        if inputs != self._inputs:
            self._push(inputs, None, lambda: QCoreApplication.translate("model", "revert invalid inputs"))

    def end_typing(self) -> None:
        """The user left a field: the next keystrokes start a new undo step."""
        self._session += 1

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

    # ---- files ---------------------------------------------------------
    def load_state(self, spec: Spec, rpms, step_deg: float, path: str = "",
                   masses: MassProperties | None = None, parts: dict[str, Any] | None = None,
                   library_name: str = "") -> None:
        """Replace everything at once, or nothing: the whole design is computed first.

        Raises DesignError (and changes nothing) when the state cannot be computed;
        otherwise clears the undo history and marks the state saved as ``path``.
        ``library_name``: the library entry it came from (see :attr:`source_name`)."""
        masses = DEFAULT_MASSES if masses is None else masses
        inputs = Inputs.of(spec, tuple(float(v) for v in rpms), float(step_deg), masses)

        def check() -> None:
            spec.check_fields()
            self.parts.check(parts or {})       # a part its model cannot show: refused too
        results = compute_whole(inputs, masses, check)
        self._inputs, self._library_name = inputs, library_name
        self._valid_spec, self._rpms, self._step, self._masses = spec, inputs.rpms, inputs.step, masses
        self._design, self._motion, self._metrics, self._dynamics, self._dynamics_summary = results
        self._index = 0
        self.parts.set_loaded(parts or {})
        self.undo_stack.clear()
        self._error.set(None)
        self._forces_error.set(None, force=True)
        self.specChanged.emit()
        self.resultsChanged.emit()
        self.forcesChanged.emit()
        self.angleChanged.emit(0)
        self.loaded.emit()
        self.set_clean(path)

    def set_clean(self, path: str) -> None:
        """The inputs now match the file at ``path`` (saved or opened)."""
        self.set_path(path)
        self.undo_stack.setClean()

    @property
    def source_name(self) -> str:
        """The design's file name without the suffix, else the library entry it was opened
        from, else "". Kept through edits: :attr:`dirty` says if the screen still shows it."""
        from core.library.names import file_stem   # here: the first screen never imports the library
        return file_stem(self._path) if self._path else self._library_name

    def set_path(self, path: str) -> None:
        """The file the design belongs to, without marking anything saved."""
        if path != self._path:
            self._path = path
            self.pathChanged.emit(path)

    # ---- internals ---------------------------------------------------
    def _on_clean_changed(self, clean: bool) -> None:
        self.dirtyChanged.emit(not clean)

    def _push(self, inputs: Inputs, key: Hashable | None, describe: Callable[[], str]) -> None:
        if key is not None:
            key = (key, self._session)
        push_edit(self.undo_stack, InputEdit(self._apply, self._inputs, inputs, key, describe))

    def _apply(self, inputs: Inputs) -> None:
        """Make ``inputs`` the typed state and recompute what they change (undo/redo too).

        Everything is computed before any view hears of it, so that a view reading the
        forces on resultsChanged never sees the previous design's."""
        old = self._inputs
        self._inputs = inputs
        design_inputs = (inputs.spec, inputs.rpms, inputs.step)
        design_changed = design_inputs != (old.spec, old.rpms, old.step)
        loads_changed = inputs.loads != old.loads
        if design_changed:
            self.specChanged.emit()
            design_changed = self._recompute()
        forces = (loads_changed or design_changed) and self._recompute_forces(design_changed,
                                                                              announce=loads_changed)
        if design_changed:
            self.resultsChanged.emit()
        if forces:
            self.forcesChanged.emit()
        if design_changed:
            self.angleChanged.emit(self._index)

    def _recompute(self) -> bool:
        """The typed design's motion and metrics; False (and the error shown) if it fails."""
        inputs = self._inputs
        try:
            design, motion, metrics = compute_motion(inputs)
        except DesignError as exc:
            self._error.set(exc)
            return False
        except COMPUTE_ERRORS as exc:
            self._error.set(compute_error(exc))
            return False
        fraction = self._index / max(self.angle_count - 1, 1)
        self._design, self._motion, self._metrics = design, motion, metrics
        self._valid_spec = inputs.spec
        self._rpms = tuple(float(v) for v in inputs.rpms)
        self._step = float(inputs.step)
        self._index = min(int(round(fraction * (motion.crank_angle.size - 1))), motion.crank_angle.size - 1)
        self._error.set(None)
        return True

    def _recompute_forces(self, design_changed: bool, announce: bool) -> bool:
        """Solve the loads typed (if valid) on the design on screen; invalid loads keep
        the last valid ones, which are solved again only when the design changed. True
        when the forces changed."""
        try:
            masses = replace(DEFAULT_MASSES, **self._inputs.load_dict)
            dynamics, summary = solve_forces(self._design, self._motion, masses)
        except (DesignError, *COMPUTE_ERRORS) as exc:
            self._forces_error.set(as_design_error(exc), force=announce)
            if not design_changed:
                return False
            masses = self._masses
            dynamics, summary = solve_forces(self._design, self._motion, masses)
        else:
            self._forces_error.set(None, force=announce)
        self._masses, self._dynamics, self._dynamics_summary = masses, dynamics, summary
        return True
