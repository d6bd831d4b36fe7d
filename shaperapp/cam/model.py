"""The cam's inputs and the last valid cam, beside the design model.

The cam is computed from what the user typed in the Cam tab and from the design on
screen (its cut window times the feed; its speeds give the follower's ω and α). A typed
value that cannot make a cam names its field (``error``) and the last valid cam stays;
a change of the linkage recomputes the cam. Every edit is an undoable step on the design
model's undo stack, so Ctrl+Z undoes cam and design edits in the order they were made.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from PySide6.QtCore import QCoreApplication, QObject, Signal

# The cam's code (its solver, synthesis and timing) is imported where a cam is first made
# or read: the model exists from start-up, the cam is computed on the tab's first visit.
from core.cam.defaults import BOSS_MM, CLEARANCE_MM, HUB_MM, RETURN_PRESSURE_DEG
from core.errors import DesignError
from shaperapp.design.model import DesignModel
from shaperapp.design.results import COMPUTE_ERRORS, compute_error
from shaperapp.design.undo import InputEdit, push_edit

if TYPE_CHECKING:
    from core.cam import Cam, CamInputs

NUMBERS = ("arm", "swing", "pressure", "return_pressure", "rise", "dwell", "return", "hub", "boss",
           "clearance")
OPTIONAL = ("roller", "base", "distance", "phase")      # blank: chosen by the tool
CHOICES = ("rise_law", "return_law")
DEFAULTS: dict[str, Any] = {"arm": 120.0, "swing": 15.0, "pressure": 40.0, "return_pressure": RETURN_PRESSURE_DEG,
                            "rise": 60.0, "dwell": 10.0, "return": 60.0, "rise_law": "sine",
                            "return_law": "sine", "roller": "", "base": "", "distance": "", "phase": "",
                            "hub": HUB_MM, "boss": BOSS_MM, "clearance": CLEARANCE_MM}
PHASES = ("rise", "dwell", "return")
"""The fields whose sum must fit in a turn: the one typed last is the one marked."""
SUM_TEXT = "must fit in 360°"


@dataclass(frozen=True)
class CamTyped:
    """The cam's fields as typed: floats, text that is not a number, '' for a blank
    optional field; one state of the undo history."""

    values: tuple[tuple[str, Any], ...] = tuple(sorted(DEFAULTS.items()))

    @property
    def dict(self) -> dict[str, Any]:
        return dict(self.values)

    def with_(self, **changes: Any) -> "CamTyped":
        return CamTyped(tuple(sorted({**self.dict, **changes}.items())))


def _number(name: str, value: Any) -> float:
    if isinstance(value, str):
        raise DesignError(name, value, "must be a number")
    if not math.isfinite(value):
        raise DesignError(name, value, "must be a finite number")
    return float(value)


def _optional(name: str, value: Any) -> float | None:
    return None if value == "" else _number(name, value)


def cam_inputs(typed: CamTyped) -> tuple[CamInputs, float | None]:
    """The core inputs and the phase (or None) of the typed fields; DesignError names one."""
    from core.cam import CamInputs, Program
    v = typed.dict
    program = Program(swing_deg=_number("swing", v["swing"]), rise_deg=_number("rise", v["rise"]),
                      dwell_deg=_number("dwell", v["dwell"]), return_deg=_number("return", v["return"]),
                      rise_law=v["rise_law"], return_law=v["return_law"])
    inputs = CamInputs(arm_mm=_number("arm", v["arm"]), program=program,
                       pressure_deg=_number("pressure", v["pressure"]),
                       return_pressure_deg=_number("return_pressure", v["return_pressure"]),
                       roller_mm=_optional("roller", v["roller"]), base_mm=_optional("base", v["base"]),
                       distance_mm=_optional("distance", v["distance"]), hub_mm=_number("hub", v["hub"]),
                       boss_mm=_number("boss", v["boss"]), clearance_mm=_number("clearance", v["clearance"]))
    return inputs, _optional("phase", v["phase"])


def blamed(error: DesignError, typed: CamTyped, edited: list[str]) -> DesignError:
    """The error as the form shows it: a condition on several fields (the phases' sum, a cam
    that does not clear its hub or the pivot boss) keeps core's field if it was typed since the last
    valid cam, else names the one of them typed last (issue 34: typing rise = 300 marked
    the outer dwell)."""
    from core.cam.build import FitError
    if isinstance(error, FitError):
        group = tuple(n for n in DEFAULTS if n != "phase")
    elif SUM_TEXT in error.allowed:
        group = PHASES
    else:
        return error
    recent = [n for n in edited if n in group]
    if not recent or error.parameter in recent:
        return error
    return DesignError(recent[-1], typed.dict[recent[-1]], error.allowed)


class CamModel(QObject):
    """Signals: ``camChanged`` (a new valid cam), ``errorChanged``, ``typedChanged``."""

    camChanged = Signal()
    errorChanged = Signal()
    typedChanged = Signal()

    def __init__(self, model: DesignModel, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.design_model = model
        self._typed = CamTyped()
        self._error: DesignError | None = None
        self._active = False        # the Cam tab is on screen: a linkage edit recomputes at once
        self._stale = True          # else it only marks the cam stale (an edit stays ~30 ms cheaper,
        self._cam: Cam | None = None    # and start-up computes no cam)
        self._valid_typed = self._typed
        self._edited: list[str] = []    # fields changed since the last valid cam, the latest last
        model.parts.register("cam", self.document)
        model.loaded.connect(self._load)
        model.resultsChanged.connect(self._linkage_changed)
        model.forcesChanged.connect(self._linkage_changed)     # the idle margin is a load

    @property
    def cam(self) -> Cam:
        """The last valid cam (recomputed first if the linkage changed while hidden)."""
        if self._stale:
            self._recompute()
        return self._cam

    def set_active(self, on: bool) -> None:
        """The Cam tab is shown (recompute now if stale) or hidden."""
        self._active = on
        if on and self._stale:
            self._recompute()

    def _linkage_changed(self) -> None:
        if self._active:
            self._recompute()
        else:
            self._stale = True

    @property
    def typed(self) -> CamTyped:
        return self._typed

    @property
    def error(self) -> DesignError | None:
        """Why the typed cam is refused, as of the last computation (on screen: current)."""
        return self._error

    def set_fields(self, **changes: Any) -> None:
        """Change some typed fields (one undoable step)."""
        after = self._typed.with_(**changes)
        if after == self._typed:
            return
        names = sorted(changes)
        push_edit(self.design_model.undo_stack,
                  InputEdit(self._apply, self._typed, after, ("cam", tuple(names)),
                            lambda: QCoreApplication.translate("CamModel", "edit cam")))

    def cam_angle(self, crank_angle: np.ndarray | float) -> np.ndarray:
        """Cam angle (rad) at crank angles (rad): the crank angle less the phase."""
        t = self._cam.timing
        return np.asarray(crank_angle, dtype=float) - (0.0 if t is None else math.radians(t.phase_deg))

    def current_cam_angle(self) -> float:
        m = self.design_model
        return float(self.cam_angle(m.motion.crank_angle[m.angle_index]))

    def document(self) -> dict[str, Any]:
        """The inputs of the cam on screen, as the design file keeps them."""
        from core.cam.file import cam_to_dict
        return cam_to_dict(*cam_inputs(self._valid_typed))

    def _load(self) -> None:
        """A file was opened (or New): its cam, or the default one."""
        from core.cam.file import cam_from_dict
        data = self.design_model.parts.loaded("cam")
        self._edited = []
        self._apply(CamTyped() if data is None else typed_from(*cam_from_dict(data)), edited=False)

    def _compute(self, typed: CamTyped) -> Cam:
        from core.cam import design_cam
        inputs, phase = cam_inputs(typed)
        m = self.design_model
        return design_cam(inputs, m.design, m.masses.idle_fraction, phase)

    def _apply(self, typed: CamTyped, edited: bool = True) -> None:
        if edited:          # an edit, an undo or a redo: what changed is what was typed
            changed = sorted(k for k, v in typed.dict.items() if self._typed.dict.get(k) != v)
            self._edited = [n for n in self._edited if n not in changed] + changed
        self._typed = typed
        self.typedChanged.emit()
        self._recompute()

    def _recompute(self) -> None:
        self._stale = False
        try:
            cam = self._compute(self._typed)
        except DesignError as exc:
            self._set_error(blamed(exc, self._typed, self._edited))
            self._keep_some_cam()
            return
        except COMPUTE_ERRORS as exc:
            self._set_error(compute_error(exc))
            self._keep_some_cam()
            return
        self._set_error(None)
        self._edited = []
        self._valid_typed = self._typed
        if cam != self._cam:
            self._cam = cam
            self.camChanged.emit()

    def _keep_some_cam(self) -> None:
        """The first computation failed (a design whose cut leaves no room for the default
        feed): show the default cam, untimed, as the last valid one."""
        if self._cam is None:
            from core.cam import design_cam
            inputs, _ = cam_inputs(CamTyped())
            self._cam = design_cam(inputs)

    def _set_error(self, error: DesignError | None) -> None:
        if str(error) != str(self._error):
            self._error = error
            self.errorChanged.emit()
        self._error = error



def typed_from(inputs: CamInputs, phase_deg: float | None) -> CamTyped:
    """The typed fields that give ``inputs`` and ``phase_deg`` (blank for None)."""
    p = inputs.program
    blank = lambda v: "" if v is None else float(v)  # noqa: E731
    return CamTyped().with_(arm=inputs.arm_mm, swing=p.swing_deg, rise=p.rise_deg, dwell=p.dwell_deg,
                            **{"return": p.return_deg}, rise_law=p.rise_law, return_law=p.return_law,
                            pressure=inputs.pressure_deg, return_pressure=inputs.return_pressure_deg,
                            roller=blank(inputs.roller_mm), base=blank(inputs.base_mm),
                            distance=blank(inputs.distance_mm), phase=blank(phase_deg),
                            hub=inputs.hub_mm, boss=inputs.boss_mm, clearance=inputs.clearance_mm)
