"""A refusal whose advice is a search, said at once and advised later (``advice_later``, the
Cam tab's way): the refusal raised at once names no value and says what is looked for;
``seek()`` gives exactly the refusal ``design_cam`` raises without it (type, field, value,
text); a refusal whose advice is no search, and every cam that designs, are the same
either way; a search asked to stop stops before its next design.

On 9b888d9 design_cam has no ``advice_later``: every test here fails there."""
from __future__ import annotations

import threading
import time

import pytest

from core.base.errors import DesignError
from core.base.progress import Cancelled
from core.cam import CamInputs, Program, design_cam
from core.cam.pending import SEEKING, PendingAdvice
from core.linkage.spec import Spec

SHEET = Program(15.0, 60.0, 10.0, 60.0)             # the form's default cam
EXAMPLE = Program(8.375, 44.0, 0.0, 40.0, "sine", "parabolic")
SEARCHED = {     # refusals whose advice designs many cams: each kind of search
    "typed-roller-boss": CamInputs(arm_mm=120.0, program=SHEET, roller_mm=5.0, boss_mm=90.0),
    "typed-roller-curvature": CamInputs(arm_mm=120.0, program=SHEET, roller_mm=30.0),
    "typed-roller-blank": CamInputs(arm_mm=52.5, program=EXAMPLE, pressure_deg=36.0, roller_mm=3.0),
    "allowance": CamInputs(arm_mm=120.0, program=SHEET, pressure_deg=5.0),
    "both-allowances": CamInputs(arm_mm=120.0, program=Program(30.0, 40.0, 10.0, 40.0), pressure_deg=10.0,
                                 return_pressure_deg=5.0),
    "boss-swing": CamInputs(arm_mm=120.0, program=SHEET, boss_mm=90.0),
    "boss-arm": CamInputs(arm_mm=120.0, program=SHEET, boss_mm=500.0),
    "hub-swing": CamInputs(arm_mm=65.0, program=Program(13.0, 130.0, 8.0, 60.0, "sine", "cosine"),
                           pressure_deg=27.5, hub_mm=100.0, boss_mm=35.0, clearance_mm=5.0),
    "automatic-roller-arm": CamInputs(arm_mm=15.0, program=Program(26.94, 97.56, 36.63, 45.13, "parabolic",
                                                                   "parabolic"), pressure_deg=35.06),
    "checked-no-roller": CamInputs(arm_mm=120.0, base_mm=15.0, distance_mm=110.0, roller_mm=5.0),
    "checked-sharp": CamInputs(arm_mm=52.5, program=EXAMPLE, pressure_deg=36.0, base_mm=15.523,
                               distance_mm=45.183),
}
AT_ONCE = {      # refusals said in full at once, and cams
    "checked-hub": CamInputs(arm_mm=120.0, base_mm=15.0, distance_mm=110.0),     # a few tens of ms
    "checked-roller-range": CamInputs(arm_mm=120.0, base_mm=20.0, distance_mm=110.0, roller_mm=6.0),
    "timing": CamInputs(arm_mm=120.0, program=Program(15.0, 200.0, 10.0, 60.0)),   # no room outside the cut
    "designed": CamInputs(arm_mm=120.0, program=SHEET),
    "designed-raised": CamInputs(arm_mm=120.0, program=Program(45.0, 100.0, 10.0, 60.0)),
}


def said(exc: DesignError) -> tuple:
    return type(exc), exc.parameter, exc.value, exc.allowed


def outcome(call):
    """What a call gives: the cam, or the refusal as (type, field, value, text)."""
    try:
        return call()
    except DesignError as exc:
        return said(exc)


@pytest.mark.parametrize("inputs", SEARCHED.values(), ids=SEARCHED.keys())
def test_a_searched_refusal_is_said_at_once_and_advised_as_design_cam_advises(inputs):
    now = outcome(lambda: design_cam(inputs))
    with pytest.raises(PendingAdvice) as pending:
        design_cam(inputs, advice_later=True)
    statement, sep, seeking = pending.value.allowed.rpartition("; ")
    assert sep and seeking in SEEKING.values() and statement
    assert pending.value.refusal.parameter == pending.value.parameter
    assert said(pending.value.seek()) == now
    assert now[3].rpartition("; ")[2] not in pending.value.allowed      # the advice was not known yet


@pytest.mark.parametrize("inputs", AT_ONCE.values(), ids=AT_ONCE.keys())
def test_what_needs_no_search_is_the_same_either_way(inputs):
    design = Spec().design()
    now = outcome(lambda: design_cam(inputs, design))
    later = outcome(lambda: design_cam(inputs, design, advice_later=True))
    assert not isinstance(later, tuple) or later[0] is not PendingAdvice
    assert later == now


def test_a_search_asked_to_stop_stops_before_its_next_design():
    with pytest.raises(PendingAdvice) as pending:
        design_cam(SEARCHED["boss-arm"], advice_later=True)
    asked = []

    def should_stop() -> bool:
        asked.append(time.perf_counter())
        return len(asked) > 3
    with pytest.raises(Cancelled):
        pending.value.seek(should_stop)
    assert len(asked) == 4                  # asked before each design, stopped at once


def test_a_search_stopped_on_one_thread_stops_no_design_on_another():
    with pytest.raises(PendingAdvice) as pending:
        design_cam(SEARCHED["boss-swing"], advice_later=True)
    inside, release = threading.Event(), threading.Event()

    def should_stop() -> bool:
        inside.set()
        release.wait(10.0)
        return True
    stopped = []
    def search() -> None:
        try:
            stopped.append(pending.value.seek(should_stop))
        except Cancelled:
            pass
    worker = threading.Thread(target=search)
    try:
        worker.start()
        assert inside.wait(10.0)                  # the worker's search is asking to stop
        # meanwhile this thread designs a refusal with a search of its own, in full
        assert outcome(lambda: design_cam(SEARCHED["allowance"]))[3].endswith("an allowance of 7.6° gives one")
    finally:
        release.set()
        worker.join(10.0)
    assert not stopped and not worker.is_alive()
