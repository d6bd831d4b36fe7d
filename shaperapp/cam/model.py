"""The cam's inputs and the last valid cam, beside the design model.

The cam is computed from what the user typed in the Cam tab and from the design on
screen (its cut window times the feed; its speeds give the follower's ω and α). A typed
value that cannot make a cam names its field (``error``) and the last valid cam stays;
a change of the linkage recomputes the cam. Every edit is an undoable step on the design
model's undo stack, so Ctrl+Z undoes cam and design edits in the order they were made.

A refusal whose advice is a search of many designs (0.1–0.4 s) is shown at once with its
statement and what is looked for (``core.cam.pending``); the search runs on a worker
thread (``widgets.worker``, :class:`AdviceJob`) and its advice replaces the text if the
fields are still the ones refused: any later computation (an edit, an undo, a linkage
change) stops it and drops what it finds.
"""
from __future__ import annotations

import math
import threading
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from PySide6.QtCore import QCoreApplication, QObject

# The cam's code (its solver, synthesis and timing) is imported where a cam is first made
# or read: the model exists from start-up, the cam is computed on the tab's first visit.
from core.base.errors import DesignError
from core.base.progress import Cancelled
from core.cam.defaults import BOSS_MM, CLEARANCE_MM, HUB_MM, RETURN_PRESSURE_DEG
from shaperapp.design.model import DesignModel
from shaperapp.design.results import COMPUTE_ERRORS, compute_error
from shaperapp.parts.model import PartModel, Typed, number
from shaperapp.widgets.worker import JobRunner, Report

if TYPE_CHECKING:
    from core.cam import Cam, CamInputs
    from core.cam.pending import PendingAdvice

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
class CamTyped(Typed):
    """The cam's fields as typed: floats, text that is not a number, '' for a blank
    optional field; one state of the undo history."""

    values: tuple[tuple[str, Any], ...] = tuple(sorted(DEFAULTS.items()))


def _optional(name: str, value: Any) -> float | None:
    return None if value == "" else number(name, value)


def cam_inputs(typed: CamTyped) -> tuple[CamInputs, float | None]:
    """The core inputs and the phase (or None) of the typed fields; DesignError names one."""
    from core.cam import CamInputs, Program
    v = typed.dict
    program = Program(swing_deg=number("swing", v["swing"]), rise_deg=number("rise", v["rise"]),
                      dwell_deg=number("dwell", v["dwell"]), return_deg=number("return", v["return"]),
                      rise_law=v["rise_law"], return_law=v["return_law"])
    inputs = CamInputs(arm_mm=number("arm", v["arm"]), program=program,
                       pressure_deg=number("pressure", v["pressure"]),
                       return_pressure_deg=number("return_pressure", v["return_pressure"]),
                       roller_mm=_optional("roller", v["roller"]), base_mm=_optional("base", v["base"]),
                       distance_mm=_optional("distance", v["distance"]), hub_mm=number("hub", v["hub"]),
                       boss_mm=number("boss", v["boss"]), clearance_mm=number("clearance", v["clearance"]))
    return inputs, _optional("phase", v["phase"])


def blamed(error: DesignError, typed: CamTyped, edited: list[str]) -> DesignError:
    """The error as the form shows it: a condition on several fields (the phases' sum, a cam
    that does not clear its hub or the pivot boss) keeps core's field if it was typed since the last
    valid cam, else names the one of them typed last (issue 34: typing rise = 300 marked
    the outer dwell)."""
    from core.cam.build import FitError
    from core.cam.pending import PendingAdvice
    said = error.refusal if isinstance(error, PendingAdvice) else error    # blamed as its advice will be
    if isinstance(said, FitError):
        group = tuple(n for n in DEFAULTS if n != "phase")
    elif SUM_TEXT in error.allowed:
        group = PHASES
    else:
        return error
    recent = [n for n in edited if n in group]
    if not recent or error.parameter in recent:
        return error
    return DesignError(recent[-1], typed.dict[recent[-1]], error.allowed)


class AdviceJob:
    """A pending refusal's search (``worker.Job``): plain core on the worker thread, asked
    before each design it tries whether to stop. Reports the refusal with its advice, as
    the model's computation would have had it (a corner of the closed forms as
    ``compute_error`` says it)."""

    def __init__(self, pending: PendingAdvice) -> None:
        self.pending = pending
        self.stop = threading.Event()

    def run(self, report: Report) -> None:
        try:
            error = self.pending.seek(self.stop.is_set)
        except Cancelled:
            report("cancelled")
            return
        except COMPUTE_ERRORS as exc:
            error = compute_error(exc)
        report("finished", error)


class CamModel(PartModel):
    """Signals: ``camChanged`` (a new valid cam), ``errorChanged``, ``typedChanged``.

    Computed lazily: while the Cam tab is hidden a linkage edit only marks the cam stale
    (an edit stays ~30 ms cheaper, and start-up computes no cam)."""

    camChanged = PartModel.valueChanged     # one signal, the name the part's readers use
    PART = "cam"

    def __init__(self, model: DesignModel, parent: QObject | None = None) -> None:
        super().__init__(model, CamTyped(), None, parent=parent)
        self._active = False        # the Cam tab is on screen: a linkage edit recomputes at once
        self._stale = True
        self._pending: PendingAdvice | None = None      # the last computation's, if its advice is searched
        self.search = JobRunner(self)
        self.search.finished.connect(self._advised)
        model.resultsChanged.connect(self._linkage_changed)
        model.forcesChanged.connect(self._linkage_changed)     # the idle margin is a load
        if model.parts.loaded(self.PART) is not None:     # made after a file with a cam was opened
            self._load()

    @property
    def cam(self) -> Cam:
        """The last valid cam (recomputed first if the linkage changed while hidden)."""
        if self._stale:
            self._recompute()
        return self._value

    def set_active(self, on: bool) -> None:
        """The Cam tab is shown (recompute now if stale) or hidden."""
        self._active = on
        if on and self._stale:
            self._recompute()

    def searching(self) -> bool:
        """Whether a search for a refusal's advice still runs (the current one, or one
        stopped that has not yet returned)."""
        return self.search.running

    def shutdown(self) -> None:
        """Stop the search and wait for it (the window is closing)."""
        self.search.cancel()
        self.search.wait()

    def _linkage_changed(self) -> None:
        if self._active:
            self._recompute()
        else:
            self._stale = True
            self.search.cancel()        # its refusal is of the linkage before: recomputed when shown

    def edit_text(self) -> str:
        return QCoreApplication.translate("CamModel", "edit cam")

    def unmade_text(self) -> str:
        return QCoreApplication.translate("CamModel", "This design's cam cannot be made: no cam is shown.")

    def cam_angle(self, crank_angle: np.ndarray | float) -> np.ndarray:
        """Cam angle (rad) at crank angles (rad): the crank angle less the phase."""
        t = self._value.timing
        return np.asarray(crank_angle, dtype=float) - (0.0 if t is None else math.radians(t.phase_deg))

    def current_cam_angle(self) -> float:
        m = self.design_model
        return float(self.cam_angle(m.motion.crank_angle[m.angle_index]))

    def document(self) -> dict[str, Any]:
        """The inputs of the cam on screen, as the design file keeps them."""
        from core.cam.file import cam_to_dict
        return cam_to_dict(*cam_inputs(self._valid_typed))

    def typed_of(self, data: Any) -> CamTyped:
        from core.cam.file import cam_from_dict
        return CamTyped() if data is None else typed_from(*cam_from_dict(data))

    def compute(self, typed: CamTyped) -> Cam:
        from core.cam import design_cam
        from core.cam.pending import PendingAdvice
        inputs, phase = cam_inputs(typed)
        m = self.design_model
        try:
            return design_cam(inputs, m.design, m.masses.idle_fraction, phase, advice_later=True)
        except PendingAdvice as pending:
            self._pending = pending
            raise

    def blame(self, error: DesignError) -> DesignError:
        return blamed(error, self._typed, self._edited)

    def _recompute(self) -> None:
        self._stale = False
        self.search.cancel()                # what it would find is for fields no longer computed
        self._pending = None
        super()._recompute()
        if self._pending is not None:
            self.search.start(AdviceJob(self._pending))

    def _advised(self, job: AdviceJob, error: DesignError) -> None:
        """The advice of the refusal on screen, found (a job replaced or stopped meanwhile is
        no longer ``search.job``: what it found is dropped)."""
        if job is self.search.job and job.pending is self._pending and not self._stale:
            self._set_error(self.blame(error))

    def refused(self) -> None:
        """The first computation failed (a design whose cut leaves no room for the default
        feed): show the default cam, untimed, as the last valid one."""
        if self._value is None:
            from core.cam import design_cam
            inputs, _ = cam_inputs(CamTyped())
            self._value = design_cam(inputs)


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
