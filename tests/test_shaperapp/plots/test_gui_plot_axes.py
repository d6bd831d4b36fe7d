"""The plots' lean axis drawing (plot_axes.TickAxis) against pyqtgraph's general one.

TickAxis replaces pyqtgraph's ``tickValues`` and ``generateDrawSpecs`` with versions
that serve only the app's options, for speed. pyqtgraph's own methods, called on the
same axis, are the independent reference: ticks, grid lines, label texts and boxes
must agree for any range, in both the plain and the degree step sets.
"""
from __future__ import annotations

import numpy as np
import pyqtgraph as pg
import pytest
from PySide6.QtGui import QPainter, QPicture
from PySide6.QtWidgets import QApplication

from shaperapp.plots.axes import styled_plot_item

from gui_helpers import shown
from layout_probe import drawn_ticks


def specs(axis, method):
    picture = QPicture()
    painter = QPainter(picture)
    try:
        axis_spec, ticks, texts = method(axis, painter)
    finally:
        painter.end()
    lines = [(pen.color().name(pen.color().NameFormat.HexArgb), (a.x(), a.y()), (b.x(), b.y()))
             for pen, a, b in [axis_spec] + list(ticks)]
    labels = [(r.getRect(), int(flags), text) for r, flags, text in texts]
    return lines, labels


@pytest.mark.parametrize("degrees", [False, True])
def test_lean_axis_draws_what_pyqtgraph_draws(qtbot, degrees):
    view = pg.GraphicsLayoutWidget()
    item = styled_plot_item(0.0)
    view.addItem(item)
    item.getAxis("bottom").set_degree_steps(degrees)
    shown(qtbot, view, 640, 260)
    rng = np.random.default_rng(7)
    checked = 0
    for _ in range(40):
        low = rng.uniform(-1e4, 1e4) * 10.0 ** rng.integers(-6, 3)
        high = low + abs(rng.normal()) * 10.0 ** rng.integers(-5, 4)
        item.setYRange(low, high, padding=0.0)
        item.setXRange(-rng.uniform(0, 90), rng.uniform(90, 720), padding=0.0)
        QApplication.processEvents()
        for side in ("left", "bottom"):
            axis = item.getAxis(side)
            ours, theirs = specs(axis, type(axis).generateDrawSpecs), specs(axis, pg.AxisItem.generateDrawSpecs)
            assert ours == theirs, (side, low, high)
            assert axis.tickValues(*axis.range, 300.0) == pg.AxisItem.tickValues(axis, *axis.range, 300.0)
            checked += len(theirs[1])
    assert checked > 100            # labels were compared, not just empty lists


def drawn_labels(axis) -> list[tuple[float, str]]:
    """(tick value, text) of every label the axis draws now."""
    lo, hi = sorted(axis.range)
    levels = axis.tickValues(lo, hi, axis.size().height())
    if not levels:
        return []
    spacing, values = levels[0]                      # only the major ticks carry text
    shown_texts = [text for _, text in drawn_ticks(axis)]
    return [(v, t) for v, t in zip(values, axis.tickStrings(values, axis.scale, spacing)) if t in shown_texts]


def test_a_short_plot_keeps_more_than_one_label(qtbot):
    """Compare's acceleration at 1280 × 720 with 16 speeds: ±5.62 m/s² over 69 px showed "0"
    alone (1, 2, 5 steps: 2 too close for the labels, 5 leaves only 0 inside the ends)."""
    view = pg.GraphicsLayoutWidget()
    item = styled_plot_item(0.0)
    view.addItem(item)
    shown(qtbot, view, 300, 110)
    item.setYRange(-5.619216716610326, 5.619025393229169, padding=0.0)
    QApplication.processEvents()
    axis = item.getAxis("left")
    assert 60 <= axis.size().height() <= 80, axis.size().height()       # the case's height
    labels = drawn_labels(axis)
    assert len(labels) >= 2, labels


def test_every_label_reads_its_tick_value(qtbot):
    """A label is its tick's value exactly, whatever the step (the half step 2.5 printed
    as "2" with pyqtgraph's decimals)."""
    view = pg.GraphicsLayoutWidget()
    item = styled_plot_item(0.0)
    view.addItem(item)
    rng = np.random.default_rng(11)
    checked = 0
    for height in (60, 75, 90, 140, 260):
        shown(qtbot, view, 300, height)
        for _ in range(25):
            span = 10.0 ** rng.uniform(-2, 4)
            low = rng.uniform(-1.0, 0.5) * span
            item.setYRange(low, low + span, padding=0.0)
            QApplication.processEvents()
            for value, text in drawn_labels(item.getAxis("left")):
                # a tick is a multiple of its step, so its label is exact (pyqtgraph's %g
                # above 10000 keeps six digits)
                assert abs(float(text.replace("−", "-")) - value) <= 1e-9 * span + 1e-6 * abs(value), \
                    (height, low, span, value, text)
                checked += 1
    assert checked > 200


def test_the_sides_no_plot_shows_never_lay_out_their_labels(qtbot, monkeypatch):
    """Issue 43 item 5: pyqtgraph makes an axis for every side of a plot, and each laid out
    its label as HTML five or six times while made and styled; the app shows only the
    plots' left and bottom axes and none of the scheme's, so the others lay out nothing.
    The axes shown keep pyqtgraph's label."""
    from shaperapp.scheme.draw import canvas
    laid_out = []
    real = pg.AxisItem._updateLabel
    monkeypatch.setattr(pg.AxisItem, "_updateLabel", lambda axis: (laid_out.append(axis), real(axis)))
    item = styled_plot_item(0.0)
    scheme = canvas()
    qtbot.addWidget(scheme)
    sides = {side: item.getAxis(side) for side in ("left", "bottom", "top", "right")}
    assert {side for side, axis in sides.items() if axis.isVisible()} == {"left", "bottom"}
    assert not any(scheme.getPlotItem().getAxis(side).isVisible() for side in sides)
    hidden = [sides["top"], sides["right"], *(scheme.getPlotItem().getAxis(side) for side in sides)]
    assert not [axis for axis in laid_out if any(axis is h for h in hidden)]
    item.setLabel("left", "Ram velocity", units="m/s")
    assert "Ram velocity" in sides["left"].label.toHtml()
