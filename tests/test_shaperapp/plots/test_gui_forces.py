"""The forces view shows what core computes, edits the loads, and marks bad input.

Expected values come from core directly (solve_dynamics / summarize on the
model's design, angles and speeds, with masses built in the test), never from
``model.dynamics`` or the widget's own output.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from PySide6.QtCore import QEvent, QPointF, Qt
from PySide6.QtGui import QImage
from PySide6.QtSvg import QSvgRenderer
from PySide6.QtWidgets import QApplication

from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties

from core.forces.flywheel import summarize
from shaperapp.design.errors import as_typed
from shaperapp.design.model import DesignModel
from shaperapp.plots.forces_panel import ForcesPanel
from shaperapp.widgets.messages import describe

from gui_helpers import curve_items, shown

SPEED_CURVES = ("torque", "power", "energy")
JOINT_ARRAYS = {"O2": ("o2_x", "o2_y"), "A": ("a_x", "a_y"), "O4": ("o4_x", "o4_y"),
                "B": ("b_x", "b_y"), "C": ("c_x", "c_y")}


@pytest.fixture
def panel(qtbot, model) -> ForcesPanel:
    return shown(qtbot, ForcesPanel(model), 1000, 800)


def core_results(model: DesignModel, masses: MassProperties):
    """Dynamics and summary straight from core for the model's design, angles and speeds."""
    dyn = solve_dynamics(model.design, model.motion.crank_angle, model.rpms, masses)
    return dyn, summarize(model.design, model.rpms, masses)


def assert_matches_core(panel: ForcesPanel, model: DesignModel, masses: MassProperties) -> None:
    dyn, summary = core_results(model, masses)
    degrees = np.degrees(model.motion.crank_angle)
    expected = {"torque": (degrees, dyn.crank_torque),
                "power": (degrees, dyn.power / 1000.0),                 # drawn in kW
                "energy": (np.degrees(summary.crank_angle), summary.energy)}
    for name, (x_expected, rows) in expected.items():
        shown = panel.plots.curve_data(name)
        assert len(shown) == len(model.rpms), name
        for (x, y), row in zip(shown, rows):
            np.testing.assert_allclose(x, x_expected, rtol=0, atol=1e-9, err_msg=name)
            np.testing.assert_allclose(y, row, rtol=1e-12, atol=1e-9, err_msg=name)
    assert panel.plots.mean_torque_lines() == pytest.approx(
        [s.mean_torque_N_m for s in summary.speeds], rel=1e-12, abs=1e-9)
    speed = panel.plots.selected_speed()
    for joint, (fx, fy) in JOINT_ARRAYS.items():
        shown = panel.plots.curve_data(f"force:{joint}")
        if getattr(dyn, fx) is None:
            assert shown == [], joint
            continue
        (x, y), = shown
        magnitude_kN = np.hypot(getattr(dyn, fx)[speed], getattr(dyn, fy)[speed]) / 1000.0
        np.testing.assert_allclose(x, degrees, rtol=0, atol=1e-9)
        np.testing.assert_allclose(y, magnitude_kN, rtol=1e-12, atol=1e-12, err_msg=joint)
    (x, y), = panel.plots.curve_data("force:guide")
    np.testing.assert_allclose(y, np.abs(dyn.guide_normal[speed]) / 1000.0, rtol=1e-12, atol=1e-12)


def type_into(qtbot, edit, text: str) -> None:
    edit.selectAll()
    qtbot.keyClicks(edit, text)


def click_plot(qtbot, panel: ForcesPanel, name: str, x: float) -> None:
    """Left-click plot ``name`` at data x, halfway up its current y range."""
    plot = panel.plots.plot_item(name)
    (_, _), (y0, y1) = plot.vb.viewRange()
    view = plot.scene().views()[0]
    pos = view.mapFromScene(plot.vb.mapViewToScene(QPointF(x, (y0 + y1) / 2)))
    qtbot.mouseClick(view.viewport(), Qt.MouseButton.LeftButton, pos=pos)


def test_curves_equal_core(panel, model):
    masses = model.masses
    assert model.design.rod is None and masses.rod_mass_kg == 0.0
    assert_matches_core(panel, model, masses)
    assert panel.plots.legend_names()[:2] == [f"{r:g} r/min" for r in model.rpms]
    assert panel.plots.speed_names() == [f"{r:g} r/min" for r in model.rpms]
    assert "C" not in panel.plots.legend_names("joints")
    # the second speed's joint forces
    panel.plots.set_selected_speed(1)
    assert panel.plots.selected_speed() == 1
    assert_matches_core(panel, model, masses)


def test_typing_ram_mass_redraws_from_core(panel, model, qtbot):
    masses = model.masses
    before = panel.plots.curve_data("torque")
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, panel.loads.field("ram_mass_kg"), "120")
    assert model.masses.ram_mass_kg == 120.0
    after = panel.plots.curve_data("torque")
    assert not np.allclose(before[1][1], after[1][1])
    assert_matches_core(panel, model, replace(masses, ram_mass_kg=120.0))
    assert panel.loads.marked_fields() == [] and panel.loads.error_text() == ""


@pytest.mark.parametrize("name, text, parameter, good", [
    ("ram_mass_kg", "-3", "ram_mass_kg", "3"),
    ("delta", "abc", "delta", "0.05"),
    ("delta", "0", "delta", "0.05"),
    ("ram_cg_dy", "up", "ram_cg_mm", "3"),
    ("idle_percent", "60", "idle_fraction", "3"),
])
def test_invalid_value_marks_field_and_keeps_curves(panel, model, qtbot, name, text, parameter,
                                                   good):
    before = {n: panel.plots.curve_data(n) for n in SPEED_CURVES + ("force:A",)}
    masses = model.masses
    with qtbot.waitSignal(model.forcesErrorChanged, timeout=10_000):
        type_into(qtbot, panel.loads.field(name), text)
    assert model.forces_error is not None and model.forces_error.parameter == parameter
    assert panel.loads.marked_fields() == [name]
    # in the field's unit: the idle margin in % (test_gui_loads_advice.py)
    assert describe(as_typed(model.forces_error)) in panel.loads.error_text()
    assert model.masses == masses
    for n, curves in before.items():
        for (x0, y0), (x1, y1) in zip(curves, panel.plots.curve_data(n)):
            np.testing.assert_array_equal(x0, x1)
            np.testing.assert_array_equal(y0, y1)
    assert panel.loads.field(name).text() == text          # what was typed stays for correction
    # a valid value clears the mark and the message
    with qtbot.waitSignal(model.forcesErrorChanged, timeout=10_000):
        type_into(qtbot, panel.loads.field(name), good)
    assert model.forces_error is None
    assert panel.loads.marked_fields() == [] and panel.loads.error_text() == ""


def test_delta_accepts_a_fraction(panel, model, qtbot):
    assert panel.loads.field("delta").text() == "0.03333"          # the default 1/30
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, panel.loads.field("delta"), "1/20")
    assert model.masses.delta == 1.0 / 20.0
    assert panel.loads.field("delta").text() == "1/20"
    with qtbot.waitSignal(model.forcesErrorChanged, timeout=10_000):
        type_into(qtbot, panel.loads.field("delta"), "1/0")
    assert panel.loads.marked_fields() == ["delta"]


def test_idle_is_typed_in_percent_and_moves_the_cutting_zone(panel, model, qtbot):
    assert float(panel.loads.field("idle_percent").text()) == pytest.approx(
        100.0 * model.masses.idle_fraction)
    masses = model.masses
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, panel.loads.field("idle_percent"), "15")
    assert model.masses.idle_fraction == pytest.approx(0.15, rel=1e-15)
    assert_shading_matches_core(panel, model, replace(masses, idle_fraction=0.15))


def test_lever_cg_empty_means_half_the_lever(panel, model, qtbot):
    edit = panel.loads.field("lever_cg_mm")
    assert edit.text() == "" and model.masses.lever_cg_mm is None
    assert "L3/2" in edit.placeholderText()
    masses = model.masses
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, edit, "200")
    assert model.masses.lever_cg_mm == 200.0
    assert_matches_core(panel, model, replace(masses, lever_cg_mm=200.0))
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        edit.selectAll()
        qtbot.keyClick(edit, Qt.Key.Key_Delete)
    assert model.masses.lever_cg_mm is None


def test_ram_offsets_and_gravity(panel, model, qtbot):
    masses = model.masses
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, panel.loads.field("ram_cg_dx"), "40")
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, panel.loads.field("ram_cg_dy"), "-25")
    assert model.masses.ram_cg_mm == (40.0, -25.0)
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        panel.loads.gravity_box().setChecked(False)
    assert model.masses.gravity is False
    assert_matches_core(panel, model, replace(masses, ram_cg_mm=(40.0, -25.0), gravity=False))


def test_model_change_shows_in_fields(panel, model):
    model.set_masses(ram_mass_kg=55.5, cut_force_N=1234.0)
    assert panel.loads.field("ram_mass_kg").text() == "55.5"
    assert panel.loads.field("cut_force_N").text() == "1234"
    model.set_masses(block_mass_kg="heavy")                    # invalid, from elsewhere
    assert panel.loads.field("block_mass_kg").text() == "heavy"
    assert panel.loads.marked_fields() == ["block_mass_kg"]


def test_three_speeds_give_three_curves(panel, model):
    model.set_rpms([40, 60, 80])
    for name in SPEED_CURVES:
        assert len(panel.plots.curve_data(name)) == 3
    assert panel.plots.speed_names() == ["40 r/min", "60 r/min", "80 r/min"]
    assert panel.plots.legend_names()[:3] == ["40 r/min", "60 r/min", "80 r/min"]
    assert len(panel.plots.mean_torque_lines()) == 3
    assert_matches_core(panel, model, model.masses)
    model.set_rpms([50])
    assert [len(panel.plots.curve_data(n)) for n in SPEED_CURVES] == [1, 1, 1]
    # removed, not just emptied: the speed's torque curve and its mean-torque line, each
    # a solid and a dashed item
    assert len(curve_items(panel.plots.plot_item("torque"))) == 2 * 2
    assert_matches_core(panel, model, model.masses)


def test_rod_variant_enables_rod_mass_and_adds_c(panel, model, qtbot):
    assert not panel.loads.field("rod_mass_kg").isEnabled()
    assert panel.plots.curve_data("force:C") == []
    model.set_spec(variant="rod")
    assert model.error is None and model.design.rod is not None
    assert panel.loads.field("rod_mass_kg").isEnabled()
    assert "C" in panel.plots.legend_names("joints")
    masses = model.masses
    assert_matches_core(panel, model, masses)
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, panel.loads.field("rod_mass_kg"), "6")
    assert_matches_core(panel, model, replace(masses, rod_mass_kg=6.0))
    model.set_spec(variant="block")
    assert not panel.loads.field("rod_mass_kg").isEnabled()
    assert panel.plots.curve_data("force:C") == []
    assert "C" not in panel.plots.legend_names("joints")


def assert_shading_matches_core(panel: ForcesPanel, model: DesignModel,
                                masses: MassProperties) -> None:
    """Every grid angle with a cutting force lies in a shaded span, every other outside."""
    dyn, _ = core_results(model, masses)
    degrees = np.degrees(model.motion.crank_angle)
    cutting = dyn.cut_force[0] != 0.0
    spans = panel.plots.cut_spans()
    assert spans
    inside = np.zeros_like(cutting)
    for start, end in spans:
        inside |= (degrees >= start) & (degrees <= end)
    np.testing.assert_array_equal(inside, cutting)


def test_cutting_zone_is_where_core_cuts(panel, model):
    assert_shading_matches_core(panel, model, model.masses)
    model.set_spec(time_ratio=1.7)
    assert_shading_matches_core(panel, model, model.masses)
    model.set_masses(cut_force_N=0.0)
    assert panel.plots.cut_spans() == []


def test_cursor_follows_angle_and_click_sets_it(panel, model, qtbot):
    model.set_angle_index(90)
    assert panel.plots.cursor_value() == pytest.approx(math.degrees(model.motion.crank_angle[90]))
    model.set_angle_index(250)
    assert panel.plots.cursor_value() == pytest.approx(math.degrees(model.motion.crank_angle[250]))
    click_plot(qtbot, panel, "power", 123.4)
    assert model.crank_deg == pytest.approx(123.4, abs=1.0)
    click_plot(qtbot, panel, "force", 301.0)
    assert model.crank_deg == pytest.approx(301.0, abs=1.0)
    assert panel.plots.cursor_value() == pytest.approx(model.crank_deg)


def test_mouse_readout(qtbot, panel, model):
    plot = panel.plots.plot_item("torque")
    view = plot.scene().views()[0]
    pos = view.mapFromScene(plot.vb.mapViewToScene(QPointF(100.2, 0.0)))
    qtbot.mouseMove(view.viewport(), pos)
    qtbot.waitUntil(lambda: "r/min" in panel.plots.readout_text() and "100." in panel.plots.readout_text(),
                    timeout=10_000)
    dyn, _ = core_results(model, model.masses)
    index = int(np.argmin(np.abs(np.degrees(model.motion.crank_angle) - 100.2)))
    for row in dyn.crank_torque:
        assert f"{row[index]:.4g} N·m" in panel.plots.readout_text()


def test_language_change_keeps_texts(panel, model):
    QApplication.sendEvent(panel, QEvent(QEvent.Type.LanguageChange))
    assert panel.plots.legend_names()[:2] == [f"{r:g} r/min" for r in model.rpms]
    assert panel.plots.plot_item("torque").getAxis("left").labelText


def test_export_png_and_svg(panel, tmp_path):
    png = tmp_path / "forces.png"
    panel.export_image(str(png))
    image = QImage(str(png))
    assert not image.isNull() and image.width() >= 1600
    colours = {image.pixel(x, y) for x in range(0, image.width(), 37)
               for y in range(0, image.height(), 37)}
    assert len(colours) > 5
    svg = tmp_path / "forces.svg"
    panel.export_image(str(svg))
    assert QSvgRenderer(str(svg)).isValid()
    assert "r/min" in svg.read_text(encoding="utf-8")
    with pytest.raises(ValueError):
        panel.export_image(str(tmp_path / "forces.xyz"))
