"""A drawn item's outline as segments in its own frame: the lines the labels keep off.

Split from mechanism.py because it reads any item (the mechanism's bodies and pins, the
dimensions' lines), not only the mechanism's, and reading Qt's polygons safely is a
concern of its own (issue 40).
"""
from __future__ import annotations

import numpy as np
from pyqtgraph.functions import ndarray_from_qpolygonf
from PySide6.QtGui import QPainterPath
from PySide6.QtWidgets import QGraphicsEllipseItem

from shaperapp.plots.items import CurveItem

from .place import local_segments


def outline(item) -> np.ndarray:
    """An item's painter path (an ellipse's circle, a curve's data) as segments in its
    own frame. Each subpath's points are copied while Qt's polygon still holds them:
    pyqtgraph's ``ndarray_from_qpolygonf`` only views the polygon's memory, and read
    after the list of polygons was freed it gave whatever the allocator had written
    there since, so the labels' raster changed from run to run (issue 40)."""
    if isinstance(item, CurveItem):
        pts = np.column_stack([item.x, item.y])
        if item.connect == "pairs":
            return pts.reshape(-1, 2, 2)
        ends = np.stack([pts[:-1], pts[1:]], axis=1)
        return ends[np.isfinite(ends).all(axis=(1, 2))]
    if isinstance(item, QGraphicsEllipseItem):
        path = QPainterPath()
        path.addEllipse(item.rect())
    else:
        path = item.path()
    polygons = path.toSubpathPolygons()      # alive until every point is copied
    return local_segments([ndarray_from_qpolygonf(p).copy() for p in polygons])
