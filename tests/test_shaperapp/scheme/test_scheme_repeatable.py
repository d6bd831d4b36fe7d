"""The scheme's labels are a function of the design and the view only (issue 40): under
load two runs of `shaper report` on one design placed §3's H and L3 differently. The label
search reads the lines drawn from Qt's painter paths (``outlines.outline``), and it read
each subpath's points through a view of a polygon already freed: whatever the allocator had
written there since. Here freed memory is written over on purpose (``freed_memory``) after
the paths are read and before their points are used."""
from __future__ import annotations

import numpy as np
from PySide6.QtCore import QRectF
from PySide6.QtGui import QColor, QImage, QPainter, QPainterPath
from PySide6.QtWidgets import QGraphicsPathItem

import shaperapp.scheme.outlines as outlines
from core.linkage.metrics import analyze
from core.linkage.spec import Spec
from freed_memory import scribbled
from shaperapp.report.figures import ReportViews


def test_outline_is_the_paths_points_whatever_freed_memory_holds(qapp, monkeypatch):
    path = QPainterPath()
    path.addEllipse(QRectF(0.0, 0.0, 10.0, 6.0))
    path.addRect(QRectF(20.0, 0.0, 5.0, 5.0))
    path.moveTo(30.0, 0.0)
    path.lineTo(40.0, 3.0)
    path.lineTo(35.0, 8.0)
    # each point read on its own from Qt: a copy, whatever happens to the polygon later
    polylines = [np.array([(p.x(), p.y()) for p in polygon]) for polygon in path.toSubpathPolygons()]
    expected = np.concatenate([np.stack([p[:-1], p[1:]], axis=1) for p in polylines])
    monkeypatch.setattr(outlines, "local_segments", scribbled(outlines.local_segments))
    got = outlines.outline(QGraphicsPathItem(path))
    assert got.shape == expected.shape == (16 + 4 + 2, 2, 2)
    assert np.array_equal(got, expected), np.abs(got - expected).max()


def limit_schemes_image(spec: Spec) -> np.ndarray:
    """The report's §3 figure (both limit positions, as ``ReportViews.limit_schemes`` draws
    it) painted at 1 px per mm on a 170 × 85 mm page figure, 8× finer: its pixels."""
    rpms = [40.0, 60.0]
    views = ReportViews(spec, rpms, None, analyze(spec.design(), rpms))
    try:
        paint = views.limit_schemes()
        image = QImage(8 * 170, 8 * 85, QImage.Format.Format_RGB32)
        image.fill(QColor("white"))
        painter = QPainter(image)
        paint(painter, QRectF(0.0, 0.0, image.width(), image.height()), 8.0)
        painter.end()
        return np.frombuffer(image.constBits(), dtype=np.uint8).copy()
    finally:
        views.close()


def test_the_reports_limit_schemes_are_alike_whatever_freed_memory_holds(qapp, monkeypatch):
    """The figure drawn twice, the second time with freed memory written over whenever the
    scheme reads a body's outline: the same pixels (the labels in the same places)."""
    spec = Spec(crank=100.0, time_ratio=1.4, stroke=300.0)
    plain = limit_schemes_image(spec)
    monkeypatch.setattr(outlines, "local_segments", scribbled(outlines.local_segments))
    forced = limit_schemes_image(spec)
    assert plain.shape == forced.shape
    assert np.array_equal(plain, forced), f"{np.count_nonzero(plain != forced)} bytes differ"
