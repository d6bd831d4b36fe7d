"""A sheet's polyline as the painter gets it: filled through numpy, the same points a
QPointF per point gives (the sheet's y up turned to the painter's y down)."""
import numpy as np
from PySide6.QtCore import QPointF
from PySide6.QtGui import QPolygonF

from shaperapp.widgets.sheet_paint import _polygon


def test_the_polygon_holds_the_points_a_qpointf_each_would(qapp):
    rng = np.random.default_rng(3)
    for n in (0, 1, 2, 361):
        points = rng.uniform(-10.0, 900.0, (n, 2))
        height = 594.0
        want = QPolygonF([QPointF(float(x), height - float(y)) for x, y in points])
        got = _polygon(points, height)
        assert [(p.x(), p.y()) for p in got] == [(p.x(), p.y()) for p in want]
    assert [(p.x(), p.y()) for p in _polygon(((1, 2), (3, 4.5)), 10.0)] == [(1.0, 8.0), (3.0, 5.5)]
