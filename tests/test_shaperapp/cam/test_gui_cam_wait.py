"""The Cam tab never waits for a refusal's advice: an edit whose refusal names a value only
after designing many cams shows its statement and what is looked for at once, the search
runs on the worker thread (no whole cam of it is designed on the GUI thread), and its
advice then reads exactly as core's synchronous refusal does, in English and in Chinese.
An edit, an undo or another refusal meanwhile drops what the search finds; closing the
window or the tab while it runs neither crashes nor hangs.

On 9b888d9 the search ran inside the edit on the GUI thread (0.1–0.4 s): every test here
fails there (the model has no ``searching``; the probes ran on the main thread)."""
from __future__ import annotations

import gc
import threading

import pytest
from PySide6.QtWidgets import QApplication

import core.cam.cam as cam_module
from core.base.errors import DesignError
from core.cam import CamInputs, Program, design_cam
from core.cam.pending import SEEKING, PendingAdvice
from shaperapp.cam.model import cam_inputs
from shaperapp.cam.tab import CamTab
from shaperapp.widgets import i18n
from shaperapp.widgets.messages import describe
from shaperapp.widgets.worker import COLLECTOR

from gui_helpers import main_window, shown
from test_gui_cam_advice import assert_reads_in_chinese
from test_gui_cam_build import type_into

# (fields typed first, the field typed last and its text): each refused after a search
SEARCHED = {
    "boss-arm": ({}, ("boss", "500")),                      # an arm of 687.0 mm (no swing …)
    "boss-swing": ({}, ("boss", "90")),                     # a swing of 12.0°
    "typed-roller": ({"roller": "5"}, ("boss", "90")),      # an arm of 133.1 mm
    "allowance": ({}, ("pressure", "5")),                   # an allowance of 7.6°
    "automatic-roller": ({"swing": "26.94", "rise": "97.56", "dwell": "36.63", "return": "45.13",
                          "pressure": "35.06"}, ("arm", "15")),      # an arm of 32.3 mm
}


SHEET = Program(15.0, 60.0, 10.0, 60.0)
EXAMPLE = Program(8.375, 44.0, 0.0, 40.0, "sine", "parabolic")
PENDING = {     # each statement said while its advice is looked for, and each SEEKING
    "typed-roller": CamInputs(arm_mm=120.0, program=SHEET, roller_mm=5.0, boss_mm=90.0),
    "allowance": CamInputs(arm_mm=120.0, program=SHEET, pressure_deg=5.0),
    "boss": CamInputs(arm_mm=120.0, program=SHEET, boss_mm=500.0),
    "hub": CamInputs(arm_mm=65.0, program=Program(13.0, 130.0, 8.0, 60.0, "sine", "cosine"), pressure_deg=27.5,
                     hub_mm=100.0, boss_mm=35.0, clearance_mm=5.0),
    "automatic-roller": CamInputs(arm_mm=15.0, program=Program(26.94, 97.56, 36.63, 45.13, "parabolic",
                                                               "parabolic"), pressure_deg=35.06),
    "checked-no-roller": CamInputs(arm_mm=120.0, base_mm=15.0, distance_mm=110.0, roller_mm=5.0),
    "checked-sharp": CamInputs(arm_mm=52.5, program=EXAMPLE, pressure_deg=36.0, base_mm=15.523, distance_mm=45.183),
}


@pytest.fixture
def tab(qtbot, model):
    widget = shown(qtbot, CamTab(model), 1000, 650)
    yield widget
    widget.cam_model.shutdown()


@pytest.fixture
def probes(monkeypatch):
    """Whether each whole cam a search designs (``cam._probe``) ran on the GUI thread."""
    on_gui_thread: list[bool] = []
    probe = cam_module._probe

    def counted(inputs):
        on_gui_thread.append(threading.current_thread() is threading.main_thread())
        return probe(inputs)
    monkeypatch.setattr(cam_module, "_probe", counted)
    return on_gui_thread


def synchronous(tab) -> DesignError:
    """Core's refusal of the fields on screen, advice and all (as the CLI has it), blamed on
    the field as the form blames it."""
    inputs, phase = cam_inputs(tab.cam_model.typed)
    m = tab.cam_model.design_model
    with pytest.raises(DesignError) as refused:
        design_cam(inputs, m.design, m.masses.idle_fraction, phase)
    return tab.cam_model.blame(refused.value)


def searched(qtbot, tab) -> None:
    qtbot.waitUntil(lambda: not tab.cam_model.searching(), timeout=30_000)


@pytest.mark.parametrize("language", ["en", "zh_CN"])
@pytest.mark.parametrize("case", SEARCHED)
def test_the_search_runs_off_the_gui_thread_and_its_advice_is_cores(qtbot, tab, probes, case, language):
    first, (name, text) = SEARCHED[case]
    for field, value in first.items():
        type_into(qtbot, tab, field, value)
    assert tab.form.marked_fields() == []
    before = tab.cam_model.cam
    i18n.set_language(language)
    try:
        probes.clear()
        type_into(qtbot, tab, name, text, advised=False)
        # back in the event loop with the statement on screen and the search on the worker
        assert tab.cam_model.searching() and True not in probes
        interim = tab.cam_model.error
        assert interim.allowed.rpartition("; ")[2] in SEEKING.values()
        assert tab.form.error_label.text().startswith("⚠ " + describe(interim))
        assert tab.cam_model.cam is before and tab.form.marked_fields() == [interim.parameter]
        searched(qtbot, tab)
        assert len(probes) > 3 and True not in probes          # a search of designs, all on the worker
        final, expected = tab.cam_model.error, synchronous(tab)
        assert (final.parameter, final.value, final.allowed) == (expected.parameter, expected.value,
                                                                 expected.allowed)
        assert final.allowed != interim.allowed and "looking for" not in final.allowed
        assert tab.form.error_label.text().startswith("⚠ " + describe(expected))
        assert tab.form.marked_fields() == [expected.parameter]
        assert tab.cam_model.cam is before
        if language == "zh_CN":     # neither text left in English
            for error in (interim, expected):
                assert describe(error) != f"{error.parameter}: {error.allowed}"
                assert "looking" not in describe(error) and "gives one" not in describe(error)
    finally:
        i18n.set_language("en")


def test_a_valid_edit_meanwhile_drops_the_searchs_advice(qtbot, tab):
    stopped = []
    tab.cam_model.search.cancelled.connect(stopped.append)
    type_into(qtbot, tab, "boss", "500", advised=False)
    assert tab.cam_model.searching()
    type_into(qtbot, tab, "boss", "12.5", advised=False)       # at once, before the search ends
    searched(qtbot, tab)
    QApplication.processEvents()
    assert tab.cam_model.error is None and tab.form.marked_fields() == []
    assert tab.form.error_label.text() == "" and not tab.form.error_label.isVisible()
    assert tab.cam_model.cam.inputs.boss_mm == 12.5
    assert len(stopped) == 1            # the search stopped at its next design, not run out


def test_another_refusal_meanwhile_shows_its_own_advice(qtbot, tab):
    type_into(qtbot, tab, "boss", "500", advised=False)
    first = tab.cam_model.search.job
    type_into(qtbot, tab, "boss", "90", advised=False)
    assert tab.cam_model.search.job is not first
    searched(qtbot, tab)
    assert tab.cam_model.error.allowed.endswith("; a swing of 12.0° gives one")
    assert tab.cam_model.error.allowed == synchronous(tab).allowed
    assert tab.cam_model.typed.dict["boss"] == 90.0


def test_an_undo_meanwhile_drops_the_searchs_advice(qtbot, tab):
    cam = tab.cam_model.cam
    type_into(qtbot, tab, "boss", "500", advised=False)
    tab.cam_model.design_model.undo_stack.undo()
    searched(qtbot, tab)
    assert tab.cam_model.error is None and tab.cam_model.typed.dict["boss"] == 12.5
    assert tab.cam_model.cam == cam
    tab.cam_model.design_model.undo_stack.redo()               # the refusal again, advised again
    assert "looking for" in tab.cam_model.error.allowed
    searched(qtbot, tab)
    assert tab.cam_model.error.allowed == synchronous(tab).allowed


def test_a_linkage_edit_while_hidden_drops_the_searchs_advice(qtbot, tab):
    type_into(qtbot, tab, "boss", "500", advised=False)
    tab.hide()
    tab.cam_model.design_model.set_spec(stroke=310.0)
    searched(qtbot, tab)
    assert "looking for" in tab.cam_model.error.allowed         # not advised for the linkage before
    tab.show()                                                  # shown: computed for this linkage
    searched(qtbot, tab)
    assert tab.cam_model.error.allowed == synchronous(tab).allowed


def test_closing_the_window_while_a_search_runs(qtbot, tmp_path):
    with main_window(tmp_path) as window:
        window.tabs.setCurrentWidget(window.cam)
        QApplication.processEvents()
        window.cam_model.set_fields(boss=500.0)
        assert window.cam_model.searching()
        window.model.set_clean("")
        assert window.close()
        assert not window.cam_model.searching()                # stopped and waited for
    assert COLLECTOR.join(10.0)


def test_closing_the_tab_while_a_search_runs(qtbot, model):
    was_enabled = gc.isenabled()
    widget = CamTab(model)
    widget.show()
    qtbot.waitExposed(widget)
    widget.cam_model.set_fields(boss=500.0)
    assert widget.cam_model.searching() and COLLECTOR.holding and not gc.isenabled()
    widget.close()
    widget.deleteLater()                # the runner goes with it; its thread ends by itself
    QApplication.processEvents()
    assert COLLECTOR.join(10.0)         # what the suite's fixture waits for after every Qt test
    assert gc.isenabled() == was_enabled and not COLLECTOR.holding      # given back as found
    QApplication.processEvents()


@pytest.mark.parametrize("inputs", PENDING.values(), ids=PENDING.keys())
def test_every_refusal_said_while_its_advice_is_looked_for_reads_in_chinese(qapp, inputs):
    with pytest.raises(PendingAdvice) as pending:
        design_cam(inputs, advice_later=True)
    assert_reads_in_chinese(pending.value)


def test_the_cases_above_say_every_search():
    said = set()
    for inputs in PENDING.values():
        with pytest.raises(PendingAdvice) as pending:
            design_cam(inputs, advice_later=True)
        said.add(pending.value.allowed.rpartition("; ")[2])
    assert said == set(SEEKING.values())
