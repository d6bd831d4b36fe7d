"""Regression tests for the plot defects of issue 8 (item 5), on both views that use the
shared plot stack: 16 speeds, refit, navigation, our own menu, ticks, cursor values,
read-out after a design change, a cursor per speed in time mode.

Expected numbers come from core (solve / solve_dynamics on the model's design), the
colour check from an independent CIELAB conversion, never from the widgets' output.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from PySide6.QtGui import QImage, QPainter
from PySide6.QtWidgets import QApplication

from core.linkage.kinematics import solve
from shaperapp.plots.forces import ForcePlots
from shaperapp.plots.kinematics import PlotsWidget
from shaperapp.widgets.style import SPEED_COLOURS, fmt

from colour_checks import ciede2000, closest_pair, lab
from gui_helpers import shown

SIXTEEN = [20.0 + 5.0 * i for i in range(16)]


@pytest.fixture
def plots(qtbot, model) -> PlotsWidget:
    return shown(qtbot, PlotsWidget(model), 560, 640)    # the kinematics pane at 1366 px


@pytest.fixture
def forces(qtbot, model) -> ForcePlots:
    return shown(qtbot, ForcePlots(model), 520, 640)


def test_sixteen_distinct_speed_colours():
    assert len(SPEED_COLOURS) == 16
    colours = [lab(c) for c in SPEED_COLOURS]
    closest = min(np.linalg.norm(a - b) for i, a in enumerate(colours) for b in colours[i + 1:])
    assert closest > 20.0                # clearly different to the eye (ΔE*ab)
    for reserved in ("#37474f", "#444444", "#c2185b", "#ffffff"):   # shared, cursor, force, page
        assert min(np.linalg.norm(lab(reserved) - c) for c in colours) > 10.0


def test_sixteen_speed_colours_a_reader_tells_apart():
    """Issue 40: CIEDE2000, the difference as the eye weighs it, over every pair of the 16 is
    above 20 (the pair readers confused, 85 and 95 r/min of 30…105, was 10.6; the best 16 the
    palette's bounds allow reach 21), and each colour stands out on the white page."""
    closest, first, second = closest_pair(list(SPEED_COLOURS))
    assert closest > 20.0, (closest, first, second)
    white = lab("#ffffff")
    for colour in SPEED_COLOURS:
        assert ciede2000(lab(colour), white) >= 30.0, colour
        assert 30.0 <= lab(colour)[0] <= 72.0, colour          # neither near-black nor pale


def scene_bottom(item) -> float:
    return item.sceneBoundingRect().bottom()


@pytest.mark.parametrize("view", ["plots", "forces"])
def test_sixteen_speeds_legend_wraps_and_plots_stay_in_the_pane(request, model, view):
    widget = request.getfixturevalue(view)
    model.set_rpms(SIXTEEN)
    QApplication.processEvents()
    stack = widget.stack()
    group = "main" if view == "plots" else "speeds"
    legend = stack.legend(group)
    names = legend.names()
    assert names[:16] == [f"{r:g} r/min" for r in SIXTEEN]
    assert 1 < legend.columns() < 16                      # wrapped into rows
    graphics = stack.findChild(type(stack._view))
    width, height = graphics.width(), graphics.height()
    assert legend.head.sceneBoundingRect().right() <= width + 1
    last = "ram_a" if view == "plots" else "force"
    assert scene_bottom(widget.plot_item(last)) <= height + 1   # nothing pushed out
    colours = {c.colour.name() for c in stack.plot("ram_v" if view == "plots" else "torque").curves
               if c.role == "" and c.legend}
    assert len(colours) == 16


def fits(widget, name: str, values: np.ndarray) -> bool:
    (_, _), (y0, y1) = widget.plot_item(name).vb.viewRange()
    span = values.max() - values.min()
    return y0 <= values.min() and y1 >= values.max() and y1 - y0 < 1.5 * span


def test_views_refit_after_removing_speeds_and_the_legend_stays(plots, model):
    model.set_rpms(SIXTEEN)
    QApplication.processEvents()
    view = plots.plot_item("ram_v").vb
    view.scaleBy((0.3, 0.3))                              # the user zoomed in
    model.set_rpms([40, 60])
    QApplication.processEvents()
    motion = solve(model.design, model.motion.crank_angle, [40, 60])
    assert fits(plots, "ram_v", motion.ram_v) and fits(plots, "ram_a", motion.ram_a)
    assert view.viewRange()[0] == pytest.approx([0.0, 360.0])
    legend = plots.stack().legend("main")
    assert legend.names() == ["40 r/min", "60 r/min"]
    assert legend.head.isVisible() and legend.head.sceneBoundingRect().height() > 10
    assert legend.head.scene() is plots.plot_item("ram_v").scene()
    # the plots fill the pane again, no blank band where the long legend was
    graphics = plots.stack()._view
    assert scene_bottom(plots.plot_item("ram_a")) > 0.8 * graphics.height()


def test_a_design_change_refits_a_zoomed_view(plots, model):
    plots.plot_item("ram_v").vb.setXRange(100.0, 120.0, padding=0.0)
    model.set_spec(time_ratio=1.6)
    assert model.error is None
    motion = solve(model.design, model.motion.crank_angle, model.rpms)
    assert plots.plot_item("ram_v").vb.viewRange()[0] == pytest.approx([0.0, 360.0])
    assert fits(plots, "ram_v", motion.ram_v)


def wheel(qtbot, widget, name: str, where: str, steps: int) -> None:
    """Turn the mouse wheel over plot ``name``: in the plot or over its left axis."""
    from PySide6.QtGui import QWheelEvent
    plot = widget.plot_item(name)
    view = plot.scene().views()[0]
    rect = plot.vb.sceneBoundingRect()
    point = rect.center()
    if where == "axis":          # over the tick labels, left of the plot area
        point.setX(rect.left() - 20)
    pos = view.mapFromScene(point)
    event = QWheelEvent(QPointF(pos), QPointF(view.viewport().mapToGlobal(pos)), QPoint(0, 0),
                        QPoint(0, 120 * steps), Qt.MouseButton.NoButton,
                        Qt.KeyboardModifier.NoModifier, Qt.ScrollPhase.NoScrollPhase, False)
    QApplication.sendEvent(view.viewport(), event)


def test_wheel_zooms_x_over_the_plot_and_y_over_its_axis_then_double_click_fits(qtbot, plots, model):
    vb_v, vb_a = plots.plot_item("ram_v").vb, plots.plot_item("ram_a").vb
    x0, y0 = vb_v.viewRange()
    wheel(qtbot, plots, "ram_v", "plot", 3)
    x1, _ = vb_v.viewRange()
    assert x1[1] - x1[0] < 0.9 * (x0[1] - x0[0])          # x zoomed in …
    assert vb_a.viewRange()[0] == pytest.approx(x1)        # … in every plot (linked)
    # y follows the visible part of the curves: within the x window, with a margin
    inside = (np.degrees(model.motion.crank_angle) >= x1[0]) & (np.degrees(model.motion.crank_angle) <= x1[1])
    ram_v = model.motion.ram_v[:, inside]
    (_, _), (lo, hi) = vb_v.viewRange()
    assert lo <= ram_v.min() and hi >= ram_v.max() and hi - lo < 1.5 * np.ptp(ram_v)
    before_y_a = vb_a.viewRange()[1]
    wheel(qtbot, plots, "ram_v", "axis", 3)               # over the y axis: y only
    assert np.ptp(vb_v.viewRange()[1]) < 0.9 * (hi - lo)
    assert vb_v.viewRange()[0] == pytest.approx(x1)
    assert vb_a.viewRange()[1] == pytest.approx(before_y_a)
    # double-click: everything back
    view = plots.plot_item("ram_v").scene().views()[0]
    pos = view.mapFromScene(vb_v.sceneBoundingRect().center())
    # a real double click: press, release, double-click, release
    qtbot.mouseClick(view.viewport(), Qt.MouseButton.LeftButton, pos=pos)
    qtbot.mouseDClick(view.viewport(), Qt.MouseButton.LeftButton, pos=pos)
    qtbot.mouseRelease(view.viewport(), Qt.MouseButton.LeftButton, pos=pos)
    assert vb_v.viewRange()[0] == pytest.approx([0.0, 360.0])
    assert fits(plots, "ram_v", model.motion.ram_v)


def test_box_zoom_by_dragging_and_fit_button(qtbot, plots, model):
    vb = plots.plot_item("ram_a").vb
    view = vb.scene().views()[0]
    start = view.mapFromScene(vb.mapViewToScene(QPointF(90.0, 0.0)))
    end = view.mapFromScene(vb.mapViewToScene(QPointF(180.0, 2.0)))
    qtbot.mousePress(view.viewport(), Qt.MouseButton.LeftButton, pos=start)
    for k in range(1, 6):
        qtbot.mouseMove(view.viewport(), start + (end - start) * k / 5)
    qtbot.mouseRelease(view.viewport(), Qt.MouseButton.LeftButton, pos=end)
    (x0, x1), (y0, y1) = vb.viewRange()
    assert x0 == pytest.approx(90.0, abs=3.0) and x1 == pytest.approx(180.0, abs=3.0)
    assert y0 == pytest.approx(0.0, abs=0.3) and y1 == pytest.approx(2.0, abs=0.3)
    plots.stack().fit_action.trigger()
    assert vb.viewRange()[0] == pytest.approx([0.0, 360.0])
    assert fits(plots, "ram_a", model.motion.ram_a)


@pytest.mark.parametrize("view", ["plots", "forces"])
def test_right_click_opens_our_menu_never_pyqtgraphs(qtbot, request, view):
    widget = request.getfixturevalue(view)
    name = "ram_v" if view == "plots" else "torque"
    vb = widget.plot_item(name).vb
    assert vb.menu is None                                   # pyqtgraph's ViewBoxMenu never built
    assert vb.scene().contextMenu == []                      # no "Export..." entry
    menu = widget.stack()._menu
    view_widget = vb.scene().views()[0]
    pos = view_widget.mapFromScene(vb.sceneBoundingRect().center())
    qtbot.mouseClick(view_widget.viewport(), Qt.MouseButton.RightButton, pos=pos)
    qtbot.waitUntil(menu.isVisible, timeout=10_000)
    texts = [a.text() for a in menu.actions()]
    assert widget.stack().fit_action.text() in texts
    assert not any("Export" in t or "View All" in t for t in texts)
    menu.close()


def test_menu_is_translated(plots):
    from shaperapp.widgets import i18n
    try:
        assert i18n.set_language("zh_CN")
        QApplication.processEvents()
        texts = [a.text() for a in plots.stack()._menu.actions()]
        assert all(t and not t.isascii() for t in texts), texts
    finally:
        i18n.set_language("en")
        QApplication.processEvents()
    assert plots.stack().fit_action.text() == "Fit all"


def text_rects(axis) -> list:
    image = QImage(10, 10, QImage.Format.Format_ARGB32)
    painter = QPainter(image)
    try:
        painter.setFont(axis.style["tickFont"] or painter.font())
        _, _, texts = axis.generateDrawSpecs(painter)
    finally:
        painter.end()
    return [rect for rect, _, _ in texts]


def assert_no_overlap(rects) -> None:
    for i, a in enumerate(rects):
        for b in rects[i + 1:]:
            assert not a.intersects(b), (a, b)


@pytest.mark.parametrize("width", [260, 330, 420, 520, 700, 1000, 1500])
def test_tick_labels_never_overlap(qtbot, model, width):
    plots, forces = PlotsWidget(model), ForcePlots(model)
    for widget, bottom in ((plots, "ram_a"), (forces, "force")):
        shown(qtbot, widget, width, 520)
        for mode in (("angle", "time") if widget is plots else ("angle",)):
            if widget is plots:
                widget.set_x_mode(mode)
            QApplication.processEvents()
            axis = widget.plot_item(bottom).getAxis("bottom")
            rects = text_rects(axis)
            assert len(rects) >= 2, (width, mode)
            assert_no_overlap(rects)
            for name in ("ram_v",) if widget is plots else ("torque", "power"):
                assert_no_overlap(text_rects(widget.plot_item(name).getAxis("left")))


def test_cursor_marks_each_speeds_value(plots, model):
    model.set_rpms([30, 45, 90])
    model.set_angle_index(123)
    motion = solve(model.design, model.motion.crank_angle, model.rpms)
    phi = math.degrees(model.motion.crank_angle[123])
    dots = plots.cursor_dots("ram_v")
    assert [label for label, _, _ in dots] == ["30 r/min", "45 r/min", "90 r/min"]
    for (_, x, y), expected in zip(dots, motion.ram_v[:, 123]):
        assert x == pytest.approx(phi) and y == pytest.approx(expected, rel=1e-9, abs=1e-12)
    assert plots.cursor_values("ram_v") == [pytest.approx(phi)]


def test_time_mode_has_a_cursor_per_speed(plots, model):
    model.set_rpms([30, 45, 90])
    plots.set_x_mode("time")
    model.set_angle_index(200)
    omega = np.array([30, 45, 90]) * 2.0 * math.pi / 60.0
    times = math.radians(200.0) / omega                    # 1° grid: index 200 is 200°
    for name in ("ram_x", "ram_v", "ram_a"):
        assert plots.cursor_values(name) == pytest.approx(list(times))
    motion = solve(model.design, model.motion.crank_angle, model.rpms)
    for (_, x, y), t, v in zip(plots.cursor_dots("ram_v"), times, motion.ram_v[:, 200]):
        assert x == pytest.approx(t) and y == pytest.approx(v, rel=1e-9, abs=1e-12)


def hover(qtbot, widget, name: str, x: float) -> None:
    plot = widget.plot_item(name)
    view = plot.scene().views()[0]
    (_, _), (y0, y1) = plot.vb.viewRange()
    pos = view.mapFromScene(plot.vb.mapViewToScene(QPointF(x, (y0 + y1) / 2)))
    qtbot.mouseMove(view.viewport(), pos)


def test_readout_refreshes_after_a_design_change(qtbot, plots, model):
    hover(qtbot, plots, "ram_v", 100.2)
    qtbot.waitUntil(lambda: "100." in plots.readout_text(), timeout=10_000)
    model.set_spec(time_ratio=1.6)                      # the mouse has not moved
    assert model.error is None
    motion = solve(model.design, model.motion.crank_angle, model.rpms)
    text = plots.readout_text()
    for row in motion.ram_v:
        assert f"{fmt(row[100], '.4g')} m/s" in text


def test_readout_follows_the_cursor_when_the_mouse_is_away(qtbot, forces, model):
    model.set_angle_index(0)
    qtbot.wait(150)
    model.set_angle_index(75)
    qtbot.waitUntil(lambda: "75.0" in forces.readout_text(), timeout=10_000)
    from core.forces.dynamics import solve_dynamics
    dyn = solve_dynamics(model.design, model.motion.crank_angle, model.rpms, model.masses)
    for row in dyn.crank_torque:
        assert f"{fmt(row[75], '.4g')} N·m" in forces.readout_text()



def test_an_edit_reads_out_at_the_cursor_once(qtbot, forces, model):
    """The edit's refresh reads at the cursor at once; the throttle's refresh it had also
    started would only write the same text again 100 ms later, inside the next keystroke's
    edit (issue 40 item 5: a third more read-outs than edits)."""
    from core.forces.dynamics import solve_dynamics
    from shaperapp.plots.readout import Readout
    model.set_angle_index(40)
    qtbot.waitUntil(lambda: "40.0" in forces.readout_text(), timeout=10_000)
    model.set_masses(cut_force_N=7100.0)
    assert not forces.findChild(Readout)._timer.isActive()
    dyn = solve_dynamics(model.design, model.motion.crank_angle, model.rpms, model.masses)
    for row in dyn.crank_torque:
        assert f"{fmt(row[40], '.4g')} N·m" in forces.readout_text()


def test_a_read_out_of_as_many_entries_as_before_lays_out_less(qtbot, forces, model, monkeypatch):
    """16 speeds need the compact read-out; the next read-out (an edit, the cursor moving)
    tries the number that fitted last and one more, not a whole bisection again (issue 40
    item 5), and says what the bisection said."""
    from shaperapp.plots.readout import Readout
    model.set_rpms(SIXTEEN)
    readout = forces.findChild(Readout)
    qtbot.waitUntil(lambda: "N·m" in readout.toolTip(), timeout=10_000)     # compact: all in the tip
    text, laid_out = readout.text(), []
    original = readout._text_height
    monkeypatch.setattr(readout, "_text_height", lambda html: laid_out.append(html) or original(html))
    readout.update_text()
    assert readout.text() == text
    assert len(laid_out) <= 4, len(laid_out)

def test_readout_never_shows_negative_zero(qtbot, plots, model):
    model.set_angle_index(5)
    qtbot.wait(150)
    model.set_angle_index(0)               # a limit position: v is ±1e-17 in core
    qtbot.waitUntil(lambda: "0.0°" in plots.readout_text(), timeout=10_000)
    assert "-0 " not in plots.readout_text() and "-0." not in plots.readout_text()


def test_legend_click_hides_a_speed_everywhere(qtbot, plots, model):
    model.set_rpms([30, 45, 90])
    legend = plots.stack().legend("main")
    sample = legend._legend.items[1][0]
    view = plots.plot_item("ram_v").scene().views()[0]
    qtbot.mouseClick(view.viewport(), Qt.MouseButton.LeftButton,
                     pos=view.mapFromScene(sample.sceneBoundingRect().center()))
    for name in ("ram_v", "ram_a"):
        shown = [c.label for c in plots.stack().plot(name).shown_curves()]
        assert shown == ["30 r/min", "90 r/min"]
        assert [label for label, _, _ in plots.cursor_dots(name)] == ["30 r/min", "90 r/min"]
    # the displacement is the same at every speed: one curve, not hidden with a speed
    assert [c.label for c in plots.stack().plot("ram_x").shown_curves()] == ["every speed"]
    model.set_spec(time_ratio=1.5)                       # stays hidden after a redraw
    assert [c.label for c in plots.stack().plot("ram_v").shown_curves()] == ["30 r/min", "90 r/min"]


def test_displacement_against_the_angle_is_one_curve_with_one_readout_value(qtbot, plots, model):
    """16 speeds give 16 velocity curves but one displacement curve (the same at every
    speed against the crank angle), and the read-out lists that value once."""
    model.set_rpms([20 + 5 * i for i in range(16)])
    assert len(plots.stack().plot("ram_v").shown_curves()) == 16
    assert len(plots.stack().plot("ram_x").shown_curves()) == 1
    hover(qtbot, plots, "ram_x", 100.2)
    qtbot.waitUntil(lambda: "100." in plots.readout_text(), timeout=10_000)
    text = plots.readout_text()
    assert "r/min:" not in text and text.count("every speed") == 1
    x = model.motion.ram_x[100]                         # nearest grid angle: 100°
    assert f"{fmt(x, '.4g')} mm" in text


def test_a_small_edit_keeps_a_y_range_that_still_fits_and_a_large_one_refits(plots, model):
    """Nudging K keeps each axis (no jump, no tick redraw) while its range holds the curves
    with half the padding and is at most 1.25× a fresh fit; a large change, and Fit, fit
    afresh. Either way every curve is inside."""
    vb = plots.plot_item("ram_v").vb
    before = vb.viewRange()[1]
    model.set_spec(time_ratio=1.41)
    QApplication.processEvents()
    values = model.motion.ram_v
    span = np.ptp(values)
    y0, y1 = vb.viewRange()[1]
    assert [y0, y1] == pytest.approx(before)
    assert y0 < values.min() - 0.03 * span and y1 > values.max() + 0.03 * span
    model.set_spec(stroke=500.0)                      # much faster: refitted
    QApplication.processEvents()
    values = model.motion.ram_v
    y0, y1 = vb.viewRange()[1]
    assert y0 <= values.min() and y1 >= values.max() and y1 - y0 < 1.3 * np.ptp(values)
    model.set_spec(stroke=480.0)                      # a bit slower: kept …
    QApplication.processEvents()
    kept = vb.viewRange()[1]
    assert kept == pytest.approx([y0, y1])
    plots.stack().fit()                               # … until Fit, which fits exactly
    values = model.motion.ram_v
    pad = 0.08 * np.ptp(values)
    assert vb.viewRange()[1] == pytest.approx([values.min() - pad, values.max() + pad])


def test_readout_follows_the_crank_moved_under_a_still_mouse(qtbot, plots, model):
    """Issue 34 item 8: the mouse left over a plot at 216.4°, the crank stepped on with the
    keys to 217°: the read-out kept "φ = 216.4°" beside the animation bar's 217.0."""
    hover(qtbot, plots, "ram_v", 216.4)
    qtbot.waitUntil(lambda: "r/min" in plots.readout_text() and "cursor" not in plots.readout_text(),
                    timeout=10_000)
    assert "217.0" not in plots.readout_text()
    model.set_angle_index(217)                     # 1° grid: 217°, as the step key does
    qtbot.waitUntil(lambda: "217.0°" in plots.readout_text(), timeout=10_000)
    motion = solve(model.design, model.motion.crank_angle, model.rpms)
    for row in motion.ram_v:
        assert f"{fmt(row[217], '.4g')} m/s" in plots.readout_text()


@pytest.mark.parametrize("view", ["plots", "forces"])
def test_sixteen_speeds_keep_the_readout_to_two_lines(qtbot, request, model, view):
    """With 16 speeds the read-out took 5 lines (kinematics in time mode, forces) and pushed
    the lowest plot below the window; now it keeps two, shows the speeds it has room for
    and lists every value in its tooltip."""
    from core.forces.dynamics import solve_dynamics
    from shaperapp.plots.readout import Readout
    widget = request.getfixturevalue(view)
    model.set_rpms(SIXTEEN)
    if view == "plots":
        widget.set_x_mode("time")
    model.set_angle_index(0)
    qtbot.wait(150)
    model.set_angle_index(100)
    readout = widget.findChild(Readout)
    if view == "plots":
        x = solve(model.design, model.motion.crank_angle, model.rpms).ram_x[100]   # every speed's
        values, unit = [x] * len(SIXTEEN), "mm"
    else:
        dyn = solve_dynamics(model.design, model.motion.crank_angle, model.rpms, model.masses)
        values, unit = dyn.crank_torque[:, 100], "N·m"
    first = f"{SIXTEEN[0]:g}: {fmt(values[0], '.4g')}"                  # the first speed, compact
    # The text at 100 itself: "cursor" was already in the text at 0 when the machine took
    # longer than 150 ms to show it, and the text at 100 had not come yet.
    qtbot.waitUntil(lambda: "cursor" in widget.readout_text() and first in widget.readout_text(),
                    timeout=10_000)
    qtbot.wait(150)                                                     # laid out
    lines = readout.fontMetrics().lineSpacing()
    assert readout.height() <= 2 * lines + 8, (readout.height(), lines)      # 5 lines before
    text, tip = widget.readout_text(), readout.toolTip()
    assert first in text
    for rpm, value in zip(SIXTEEN, values):
        assert f"{rpm:g} r/min: {fmt(value, '.4g')} {unit}" in tip, rpm   # every speed's value


def test_sixteen_speeds_legend_keeps_its_keys_on_a_row_of_their_own(qtbot, plots, model):
    """The keys' long names ("working stroke") widened every column of one grid: 16 speeds
    took 6 legend rows in the 560 px pane, and the acceleration plot fell below the window.
    Now the speeds wrap by their own widths (3 rows) and the keys take one row."""
    from shaperapp.plots.legend import ROW_HEIGHT
    model.set_rpms(SIXTEEN)
    plots.set_x_mode("time")                     # its keys: working stroke, return stroke
    QApplication.processEvents()
    legend = plots.stack().legend("main")
    assert legend.columns() >= 6                                   # 4 before
    row = max(ROW_HEIGHT, legend._legend.items[0][1].minimumHeight())      # one line of entries
    assert legend.head.sceneBoundingRect().height() <= 4 * row + 1, (legend.head.sceneBoundingRect(), row)
    assert len(legend.names()) == 18 and legend.names()[:16] == [f"{r:g} r/min" for r in SIXTEEN]
