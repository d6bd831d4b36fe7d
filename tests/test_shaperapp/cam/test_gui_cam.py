"""The Cam tab (issue 23, items 3 and 5): figures and drawing equal core's cam, a bad value
marks its field and keeps the last valid cam, the drawing and the plots follow the
animation's crank angle, the exports write core's numbers, and cam edits undo."""
from __future__ import annotations

import csv
import math

import ezdxf
import numpy as np
import pytest

from core.cam import CamInputs, Program, design_cam
from core.cam.follower import pitch, profile
from core.cam.table import cam_table
from core.linkage.kinematics import crank_angles
from core.linkage.spec import Spec
from shaperapp.cam.tab import CamTab

from gui_helpers import shown


@pytest.fixture
def tab(qtbot, model):
    return shown(qtbot, CamTab(model), 1000, 650)


def core_cam(model, **program):
    prog = Program(**{**dict(swing_deg=15.0, rise_deg=60.0, dwell_deg=10.0, return_deg=60.0), **program})
    return design_cam(CamInputs(arm_mm=120.0, program=prog, pressure_deg=40.0, return_pressure_deg=70.0),
                      model.design, model.masses.idle_fraction)


def type_into(qtbot, tab, name, text):
    edit = tab.form.fields[name].edit
    edit.selectAll()
    qtbot.keyClicks(edit, text)
    tab.form.commit()


def test_figures_and_drawing_are_cores(tab, model):
    want = core_cam(model)
    cam = tab.cam_model.cam
    assert cam.base_radius_mm == pytest.approx(want.base_radius_mm, rel=1e-12)
    assert cam.timing.phase_deg == pytest.approx(want.timing.phase_deg, rel=1e-12)
    rows = dict(tab.figure_rows())
    assert rows["Base radius r0"] == f"{want.base_radius_mm:.3f} mm"
    assert rows["Centre distance a"] == f"{want.follower.distance_mm:.3f} mm"
    assert f"{want.base_radius_mm:.3f} mm" in tab.figures.text()
    pitch_pts, profile_pts = tab.profile.curves()
    delta = np.linspace(0.0, 2 * math.pi, pitch_pts.shape[1], endpoint=False)
    p = pitch(want.follower, want.program, delta)
    assert np.abs(profile_pts - profile(p, want.roller_mm)).max() < 1e-9


def test_bad_value_marks_its_field_and_keeps_the_cam(qtbot, tab, model):
    before = tab.cam_model.cam
    type_into(qtbot, tab, "swing", "120")
    assert tab.form.marked_fields() == ["swing"]
    assert tab.form.error_label.isVisible()
    assert tab.form.error_label.text().startswith("⚠ Follower swing ψmax: must be at least 1 and at most 60")
    assert tab.cam_model.cam is before
    type_into(qtbot, tab, "swing", "20")
    assert tab.form.marked_fields() == [] and not tab.form.error_label.isVisible()
    assert tab.cam_model.cam.program.swing_deg == 20.0
    assert tab.cam_model.cam.base_radius_mm == pytest.approx(core_cam(model, swing_deg=20.0).base_radius_mm)


@pytest.mark.parametrize("name, text", [("roller", "50"), ("arm", "abc"), ("rise", "200"),
                                        ("phase", "90")])
def test_each_bad_input_names_its_field(qtbot, tab, name, text):
    before = tab.cam_model.cam
    type_into(qtbot, tab, name, text)
    assert tab.form.marked_fields() == [name]
    assert tab.cam_model.cam is before


def test_feed_during_the_cut_is_refused_after_a_linkage_change(qtbot, tab, model):
    type_into(qtbot, tab, "rise", "95")
    type_into(qtbot, tab, "return", "95")
    assert tab.form.marked_fields() == []      # 200° of feed in the 204.7° outside the cut
    kept = tab.cam_model.cam
    model.set_spec(time_ratio=1.6)      # a quicker return: 194.5° outside the cut
    assert tab.form.marked_fields() == ["rise"]
    assert tab.cam_model.cam is kept
    model.set_spec(time_ratio=1.4)
    assert tab.form.marked_fields() == []


def test_drawing_and_cursor_follow_the_animation(tab, model):
    phase = tab.cam_model.cam.timing.phase_deg
    for crank in (0.0, 231.0, 250.0):
        model.set_angle_deg(crank)
        delta = math.degrees(tab.cam_model.current_cam_angle())
        grid = math.degrees(float(model.motion.crank_angle[model.angle_index]))
        assert delta == pytest.approx(grid - phase, abs=1e-9)
        for cursor in tab.plots.cursors:
            assert cursor.value() == pytest.approx(delta % 360.0, abs=1e-9)


def test_plots_are_cores_series(tab, model):
    d = tab.plots.data()
    cam = tab.cam_model.cam
    m = cam.program.motion(np.radians(d["cam_deg"]))
    omega = model.rpms[1] * 2 * math.pi / 60
    assert np.allclose(d["omega"][1], m.psi1 * omega)
    x, y = tab.plots.curves["pressure"].getData()
    assert np.max(y) == pytest.approx(max(cam.max_pressure_rise_deg, cam.max_pressure_return_deg), abs=0.05)



def test_an_edit_fits_the_plots_axes_once(tab, model):
    """The redraw fits the left axes to the new ranges itself; the fit the ranges' signals
    queued would only do it again in the edit's paint (issue 40 item 5)."""
    tab.cam_model.set_fields(rise=65.0)
    plots = tab.plots
    assert not plots._fit_timer.isActive()
    width = max(math.ceil(plot.getAxis("left").needed_width()) for plot in plots.plots)
    assert all(plot.getAxis("left").fixedWidth == width for plot in plots.plots)

def test_exports_write_cores_numbers(tab, model, tmp_path):
    tab.export_csv(str(tmp_path / "cam.csv"))
    rows = list(csv.reader(open(tmp_path / "cam.csv")))
    names, data = cam_table(tab.cam_model.cam, crank_angles(1.0), model.rpms[0])
    assert tuple(rows[0]) == names
    assert np.allclose(np.array(rows[1:], dtype=float), data, rtol=1e-9, atol=1e-9)
    tab.export_dxf(str(tmp_path / "cam.dxf"))
    doc = ezdxf.readfile(tmp_path / "cam.dxf")
    assert doc.header["$INSUNITS"] == 4 and not doc.audit().has_errors
    tab.export_image(str(tmp_path / "cam.png"))
    tab.export_image(str(tmp_path / "cam.svg"))
    assert (tmp_path / "cam.png").stat().st_size > 1000
    assert "<svg" in (tmp_path / "cam.svg").read_text()


def test_the_dxf_notes_are_in_the_apps_language(tab, tmp_path):
    """The Cam tab's DXF wrote its notes in English in the Chinese app too: they are the
    Chinese cam sheet's words now, with the cam's figures."""
    from dxf_checks import notes_of
    from shaperapp.widgets.i18n import set_language
    cam = tab.cam_model.cam
    set_language("zh_CN")
    try:
        tab.export_dxf(str(tmp_path / "zh.dxf"))
    finally:
        set_language("en")
    tab.export_dxf(str(tmp_path / "en.dxf"))
    zh, en = notes_of(tmp_path / "zh.dxf").splitlines(), notes_of(tmp_path / "en.dxf").splitlines()
    assert zh[0] == f"理论廓线基圆半径 r0 = {cam.base_radius_mm:.3f} mm" and zh[-1].endswith("凸轮顺时针转动")
    assert en[0] == f"Base radius r0 (pitch curve) = {cam.base_radius_mm:.3f} mm"
    assert en[-1].endswith("the cam turns clockwise") and len(zh) == len(en) == 7


def test_cam_edits_undo_with_the_design(qtbot, tab, model):
    type_into(qtbot, tab, "arm", "150")
    assert tab.cam_model.cam.follower.arm_mm == 150.0
    model.undo_stack.undo()
    assert tab.cam_model.cam.follower.arm_mm == 120.0
    assert tab.form.fields["arm"].edit.text() == "120"
    model.undo_stack.redo()
    assert tab.cam_model.cam.follower.arm_mm == 150.0


def test_every_cam_message_has_a_translatable_template(model):
    """Each refusal core makes for a cam matches the messages' templates (whole, or a
    statement and its advice clause by clause), so the Chinese UI never shows core's English
    sentence."""
    import re

    from core.cam.timing import timing
    from core.base.errors import DesignError
    from shaperapp.widgets import i18n
    from shaperapp.widgets.messages import allowed_text
    design = model.design
    attempts = [
        lambda: Program(rise_deg=200.0, dwell_deg=100.0, return_deg=100.0),
        lambda: timing(Program(rise_deg=120.0, dwell_deg=20.0, return_deg=120.0), design, 0.05),
        lambda: timing(Program(), design, 0.05, phase_deg=90.0),
        lambda: design_cam(CamInputs(roller_mm=100.0)),
        lambda: design_cam(CamInputs(pressure_deg=5.0)),
        lambda: design_cam(CamInputs(base_mm=5.0, distance_mm=300.0)),
        lambda: CamInputs(base_mm=30.0),
    ]
    for attempt in attempts:
        with pytest.raises(DesignError) as info:
            attempt()
        i18n.set_language("zh_CN")
        try:
            shown = allowed_text(info.value.allowed)
        finally:
            i18n.set_language("en")
        assert not re.search(r"[A-Za-z]{4,}", shown), (info.value.allowed, shown)


def test_cam_inputs_save_and_reopen(qtbot, tab, model, tmp_path):
    """Save writes the cam's inputs beside the design; opening the file brings them back;
    a file without a cam (every older one) opens with the default cam."""
    import json

    from PySide6.QtCore import QSettings

    from shaperapp.design.document import Document
    document = Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    type_into(qtbot, tab, "arm", "150")
    tab.form.laws["rise_law"].setCurrentIndex(tab.form.laws["rise_law"].findData("poly345"))
    tab.form._choose("rise_law")
    type_into(qtbot, tab, "roller", "5")
    assert document.save_to(str(tmp_path / "d.json"))
    saved = json.loads((tmp_path / "d.json").read_text())["cam"]
    assert saved["arm_mm"] == 150.0 and saved["rise_law"] == "poly345" and saved["roller_mm"] == 5.0
    assert saved["base_mm"] is None
    cam = tab.cam_model.cam
    document.new()
    assert tab.cam_model.cam.follower.arm_mm == 120.0 and tab.form.fields["roller"].edit.text() == ""
    assert document.open_path(str(tmp_path / "d.json"))
    assert tab.cam_model.cam == cam and tab.form.fields["arm"].edit.text() == "150"
    assert not model.dirty
    old = json.loads((tmp_path / "d.json").read_text())
    del old["cam"]
    (tmp_path / "old.json").write_text(json.dumps(old))
    assert document.open_path(str(tmp_path / "old.json"))
    assert tab.cam_model.cam.follower.arm_mm == 120.0


def test_a_damaged_cam_in_a_file_is_refused_and_changes_nothing(qtbot, tab, model, tmp_path):
    import json

    from PySide6.QtCore import QSettings

    from core.files.io import save_design
    from shaperapp.design.document import Document
    document = Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    messages = []
    document.failed.connect(messages.append)
    for bad in ({"arm_mm": "long"}, {"swing_deg": 500}, {"rise_law": "linear"}, [1, 2], {"bogus": 1}):
        save_design(tmp_path / "bad.json", Spec(time_ratio=1.5), [40.0], 1.0, extra={"cam": bad})
        before = (model.valid_spec, tab.cam_model.cam)
        assert not document.open_path(str(tmp_path / "bad.json"))
        assert (model.valid_spec, tab.cam_model.cam) == before and messages


def test_a_hidden_cam_tab_costs_a_design_edit_nothing(qtbot, model, monkeypatch):
    """While the Cam tab is hidden a linkage edit computes no cam (the edit budget of
    docs/performance.md); showing the tab brings the cam up to date."""
    import core.cam     # the cam model imports design_cam from it when it first computes a cam
    calls = []
    real = core.cam.design_cam
    monkeypatch.setattr(core.cam, "design_cam", lambda *a, **k: calls.append(1) or real(*a, **k))
    tab = CamTab(model)
    qtbot.addWidget(tab)
    model.set_spec(time_ratio=1.6)
    model.set_spec(stroke=320.0)
    assert calls == []
    shown(qtbot, tab, 900, 600)
    assert len(calls) == 1
    assert tab.cam_model.cam.timing.phase_deg == pytest.approx(core_cam(model).timing.phase_deg)


def test_the_library_keeps_the_cam(qtbot, tab, model, tmp_path, monkeypatch):
    """A design saved to the library and opened again brings its cam back."""
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QMessageBox

    from shaperapp.library.pane import LibraryPane
    monkeypatch.setenv("SHAPER_LIBRARY", str(tmp_path / "default.sqlite"))
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: None)
    pane = LibraryPane(model, settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    qtbot.addWidget(pane)
    assert pane.open_library(str(tmp_path / "lib.sqlite"))
    type_into(qtbot, tab, "swing", "22")
    type_into(qtbot, tab, "dwell", "0")
    cam = tab.cam_model.cam
    assert pane.actions.save_current("with cam")
    type_into(qtbot, tab, "swing", "12")
    assert tab.cam_model.cam.program.swing_deg == 12.0
    assert pane.actions.open_in_model("with cam")
    assert tab.cam_model.cam == cam and tab.form.fields["swing"].edit.text() == "22"
