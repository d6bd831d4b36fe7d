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
