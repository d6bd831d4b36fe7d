"""The motion plots show what core computes, follow the model, and export.

Expected values come from core directly (solve on the model's design) or from
the definitions (ω = 2π n / 60, K = working / return angle), never from the
widget's own output.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from PySide6.QtCore import QEvent, QPointF, Qt
from PySide6.QtGui import QImage
from PySide6.QtSvg import QSvgRenderer
from PySide6.QtWidgets import QApplication

from core.linkage.kinematics import crank_angles, solve
from shaperapp.design.model import DesignModel
from shaperapp.plots.kinematics import LEVER_PLOTS, PLOT_NAMES, SHARED_PLOTS, PlotsWidget

from gui_helpers import curve_items, shown


@pytest.fixture
def widget(qtbot, model) -> PlotsWidget:
    return shown(qtbot, PlotsWidget(model), 900, 700)


def core_curves(model: DesignModel, name: str) -> tuple[np.ndarray, np.ndarray]:
    """(crank angle in °, values (speeds, angles)) straight from core for ``name``."""
    phi = crank_angles(model.step_deg)
    motion = solve(model.design, phi, model.rpms)
    values = {
        "ram_x": motion.ram_x[None, :],                     # the same at every speed: one curve
        "ram_v": motion.ram_v,
        "ram_a": motion.ram_a,
        "lever_angle": np.degrees(motion.lever_angle)[None, :],
        "lever_omega": motion.lever_omega,
        "lever_alpha": motion.lever_alpha,
    }[name]
    return np.degrees(phi), values


def assert_matches_core(widget: PlotsWidget, model: DesignModel) -> None:
    for name in PLOT_NAMES:
        x_deg, values = core_curves(model, name)
        shown = widget.curve_data(name)
        assert len(shown) == (1 if name in SHARED_PLOTS else len(model.rpms)), name
        for (x, y), expected in zip(shown, values):
            np.testing.assert_allclose(x, x_deg, rtol=0, atol=1e-9, err_msg=name)
            np.testing.assert_allclose(y, expected, rtol=1e-12, atol=1e-12, err_msg=name)


def click_plot(qtbot, widget: PlotsWidget, name: str, x: float) -> None:
    """Left-click plot ``name`` at data x, halfway up its current y range."""
    plot = widget.plot_item(name)
    (_, _), (y0, y1) = plot.vb.viewRange()
    view = plot.scene().views()[0]
    pos = view.mapFromScene(plot.vb.mapViewToScene(QPointF(x, (y0 + y1) / 2)))
    qtbot.mouseClick(view.viewport(), Qt.MouseButton.LeftButton, pos=pos)


def test_curves_equal_core(widget, model):
    assert_matches_core(widget, model)
    assert widget.legend_names() == [f"{r:g} r/min" for r in model.rpms]


def test_spec_change_redraws_from_core(widget, model):
    before = widget.curve_data("ram_v")
    model.set_spec(time_ratio=1.6)
    assert model.error is None
    after = widget.curve_data("ram_v")
    assert not np.allclose(before[0][1], after[0][1])
    assert_matches_core(widget, model)
    # The shaded working stroke spans K/(1+K) of the turn.
    start, end = widget.work_span()
    assert end - start == pytest.approx(360.0 * 1.6 / 2.6, abs=1e-6)


def test_rod_variant_equals_core(widget, model):
    model.set_spec(variant="rod")
    assert model.error is None and model.design.rod is not None
    assert_matches_core(widget, model)


def test_speeds_add_and_remove_curves(widget, model):
    model.set_rpms([40, 60, 80])
    for name in PLOT_NAMES:
        assert len(widget.curve_data(name)) == (1 if name in SHARED_PLOTS else 3)
    assert widget.legend_names() == ["40 r/min", "60 r/min", "80 r/min"]
    assert_matches_core(widget, model)

    model.set_rpms([40, 80])
    assert widget.legend_names() == ["40 r/min", "80 r/min"]
    assert_matches_core(widget, model)
    # removed curves are gone from the plot, not merely emptied
    assert len(curve_items(widget.plot_item("ram_v"))) == 2 * 2


def test_invalid_spec_keeps_curves(widget, model):
    before = {name: widget.curve_data(name) for name in PLOT_NAMES}
    model.set_spec(time_ratio=0.5)
    assert model.error is not None
    for name in PLOT_NAMES:
        for (x0, y0), (x1, y1) in zip(before[name], widget.curve_data(name)):
            np.testing.assert_array_equal(x0, x1)
            np.testing.assert_array_equal(y0, y1)


def test_cursor_follows_angle(widget, model):
    model.set_angle_index(90)
    assert widget.cursor_value() == pytest.approx(90.0)   # 1° step
    model.set_angle_index(200)
    assert widget.cursor_value() == pytest.approx(200.0)
    widget.set_x_mode("time")
    # at 200° the first speed has turned for φ / ω seconds
    omega = model.rpms[0] * 2 * math.pi / 60
    assert widget.cursor_value() == pytest.approx(math.radians(200.0) / omega)


def test_click_moves_animation(qtbot, widget, model):
    click_plot(qtbot, widget, "ram_v", 123.4)
    assert model.crank_deg == pytest.approx(123.4, abs=1.0)
    click_plot(qtbot, widget, "ram_a", 300.2)
    assert model.crank_deg == pytest.approx(300.2, abs=1.0)


def test_click_in_time_mode_uses_first_speed(qtbot, widget, model):
    widget.set_x_mode("time")
    t = 0.5
    click_plot(qtbot, widget, "ram_v", t)
    expected = math.degrees(t * model.rpms[0] * 2 * math.pi / 60)
    assert model.crank_deg == pytest.approx(expected, abs=1.0)


def test_time_mode_uses_each_speeds_time(widget, model):
    model.set_rpms([30, 45, 90])
    widget.set_x_mode("time")
    phi = crank_angles(model.step_deg)
    _, ram_v = core_curves(model, "ram_v")
    for (x, y), rpm, expected in zip(widget.curve_data("ram_v"), model.rpms, ram_v):
        np.testing.assert_allclose(x, phi / (rpm * 2 * math.pi / 60), rtol=1e-12)
        np.testing.assert_allclose(y, expected, rtol=1e-12, atol=1e-12)
    assert widget.work_span() is None
    assert widget.legend_names()[:3] == ["30 r/min", "45 r/min", "90 r/min"]
    assert len(widget.legend_names()) == 5          # plus the solid/dashed stroke key
    # the x range covers the slowest speed's whole cycle: 60/30 s
    (x0, x1), _ = widget.plot_item("ram_v").vb.viewRange()
    assert (x0, x1) == pytest.approx((0.0, 2.0), abs=1e-6)

    widget.set_x_mode("angle")
    assert_matches_core(widget, model)
    assert len(widget.legend_names()) == 3


def test_y_range_fits_new_results(widget, model):
    def fits(name: str) -> bool:
        _, values = core_curves(model, name)
        (_, _), (y0, y1) = widget.plot_item(name).vb.viewRange()
        span = values.max() - values.min()
        return y0 <= values.min() and y1 >= values.max() and y1 - y0 < 1.5 * span

    model.set_rpms([40, 120])
    assert fits("ram_v") and fits("ram_a")
    # a plot shown after the change fits its curves too
    widget.set_plot_visible("lever_alpha", True)
    assert fits("lever_alpha")


def test_lever_plots_show_and_hide(widget):
    for name in LEVER_PLOTS:
        assert not widget.plot_visible(name)
        assert widget.plot_item(name).scene() is None
    widget.set_plot_visible("lever_omega", True)
    assert widget.plot_item("lever_omega").scene() is widget.plot_item("ram_v").scene()
    widget.set_plot_visible("lever_omega", False)
    assert widget.plot_item("lever_omega").scene() is None
    with pytest.raises(ValueError):
        widget.set_plot_visible("ram_v", False)


def test_mouse_readout(qtbot, widget, model):
    plot = widget.plot_item("ram_v")
    view = plot.scene().views()[0]
    pos = view.mapFromScene(plot.vb.mapViewToScene(QPointF(100.2, 0.0)))
    qtbot.mouseMove(view.viewport(), pos)
    qtbot.waitUntil(lambda: "r/min" in widget.readout_text() and "100." in widget.readout_text(),
                    timeout=10_000)
    _, ram_v = core_curves(model, "ram_v")
    text = widget.readout_text()
    for row in ram_v:
        assert f"{row[100]:.4g} m/s" in text     # nearest grid angle: 100°


def test_language_change_keeps_texts(widget, model):
    QApplication.sendEvent(widget, QEvent(QEvent.Type.LanguageChange))
    assert widget.legend_names() == [f"{r:g} r/min" for r in model.rpms]
    assert widget.plot_item("ram_v").getAxis("left").labelText


def test_export_png_and_svg(widget, tmp_path):
    widget.set_plot_visible("lever_angle", True)
    png = tmp_path / "plots.png"
    widget.export_image(str(png))
    image = QImage(str(png))
    assert not image.isNull() and image.width() >= 1600
    # something besides the background was drawn
    colours = {image.pixel(x, y) for x in range(0, image.width(), 37)
               for y in range(0, image.height(), 37)}
    assert len(colours) > 5

    svg = tmp_path / "plots.svg"
    widget.export_image(str(svg))
    assert svg.stat().st_size > 0
    assert QSvgRenderer(str(svg)).isValid()
    assert "r/min" in svg.read_text(encoding="utf-8")

    with pytest.raises(ValueError):
        widget.export_image(str(tmp_path / "plots.xyz"))
