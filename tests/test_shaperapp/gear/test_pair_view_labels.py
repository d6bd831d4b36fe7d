"""The names of the centres O1, O2 clear of the teeth (issue 40, item 2): a small pinion's
"O1" was drawn at −22, +16 px from its centre, on its teeth. Each name's box now lies inside
the root circle or outside the tip circle, never on the ring of the teeth."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, strategies as st
from PySide6.QtCore import QPointF, QRectF
from PySide6.QtGui import QColor, QImage, QPainter

from core.gear import GearPairInputs, design_pair
from core.gear.mesh import gear_outline, mesh_angles, placed
from shaperapp.gear.pair_view import centre_label_box, pair_span, paint_pair, MARGIN


def distances(box: QRectF, c: QPointF) -> tuple[float, float]:
    """The least and the greatest distance from ``c`` to a point of ``box``."""
    dx = max(box.left() - c.x(), 0.0, c.x() - box.right())
    dy = max(box.top() - c.y(), 0.0, c.y() - box.bottom())
    far = max(math.hypot(x - c.x(), y - c.y()) for x in (box.left(), box.right())
              for y in (box.top(), box.bottom()))
    return math.hypot(dx, dy), far


@given(root=st.floats(0.0, 400.0), ring=st.floats(1.0, 60.0), width=st.floats(8.0, 30.0),
       height=st.floats(8.0, 20.0))
def test_a_centres_name_is_never_on_the_teeth(root, ring, width, height):
    c = QPointF(300.0, 200.0)
    near, far = distances(centre_label_box(c, root, root + ring, width, height), c)
    assert far <= root or near >= root + ring


def test_the_small_pinions_name_is_off_its_teeth(qapp):
    """z 10/40, m 6 in a 230 × 200 px view, as at 1280 × 720: the pinion's root circle is
    ~17 px, too small for the name, which goes under the tip circle; the old place was on
    the teeth. The drawing's scale is the view's: the span fitted with its margins."""
    pair = design_pair(GearPairInputs(10, 40, 6.0, centre_mm=162.0))
    rect = QRectF(0, 0, 230, 200)
    lo, hi = pair_span(pair)
    span = hi - lo
    scale = min(rect.width() / (span[0] * (1 + 2 * MARGIN)), rect.height() / (span[1] * (1 + 2 * MARGIN)))
    image = QImage(230, 200, QImage.Format.Format_ARGB32)
    image.fill(QColor("white"))
    painter = QPainter(image)
    metrics = painter.fontMetrics()
    turns = mesh_angles(pair, 0.0)
    paint_pair(painter, rect, pair, (placed(gear_outline(pair, 1), float(turns[0])),
                                     placed(gear_outline(pair, 2), float(turns[1]), (pair.centre_mm, 0.0))))
    painter.end()
    w, h = metrics.horizontalAdvance("O1"), metrics.height()
    root, tip = pair.gear1.rf * scale, pair.gear1.ra * scale
    old = QRectF(0, 0, w, h).translated(-22.0, 16.0 - metrics.ascent())
    near_old, far_old = distances(old, QPointF(0, 0))
    assert root < far_old and near_old < tip                # on the ring of the teeth
    c = QPointF(rect.center().x() - (lo[0] + hi[0]) / 2.0 * scale, rect.center().y())
    box = centre_label_box(c, root, tip, w, h)
    near, far = distances(box, c)
    assert near >= tip and rect.contains(box)
    ink = [image.pixelColor(int(x), int(y)).lightness() < 128
           for x in range(int(box.left()), int(box.right())) for y in range(int(box.top()), int(box.bottom()))]
    assert any(ink)                                       # the name is drawn there
