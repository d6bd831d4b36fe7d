"""The Gear tab strokes each gear's outline through the points the screen needs (issue 40
item 5: stroking a 40-tooth gear's 11 160 points, a tenth of a pixel apart, was most of a
Gear edit): every dropped point lies within the tolerance of the line drawn, and the
drawing differs from the full outline's by no more than a few levels of antialiasing."""
from __future__ import annotations

import math

import numpy as np
import pytest
from PySide6.QtCore import QRectF
from PySide6.QtGui import QColor, QImage, QPainter

import shaperapp.gear.pair_view as pair_view
from core.gear import GearPairInputs, design_pair
from core.gear.mesh import gear_outline, placed
from shaperapp.gear.pair_view import DRAWN_TOLERANCE_PX, paint_pair, thinned

PAIRS = [GearPairInputs(13, 40, 6.0, centre_mm=162.0), GearPairInputs(10, 40, 6.0, centre_mm=162.0),
         GearPairInputs(17, 61, 2.5), GearPairInputs(25, 26, 4.0, x1=0.3, x2=-0.1)]


def segment_distance(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    """The distance from ``p`` to the segment ``a``–``b``, worked out from scratch."""
    d = b - a
    t = 0.0 if not d.any() else min(max(float(np.dot(p - a, d) / np.dot(d, d)), 0.0), 1.0)
    return float(np.linalg.norm(p - (a + t * d)))


@pytest.mark.parametrize("inputs", PAIRS)
@pytest.mark.parametrize("k", [1, 2])
def test_every_dropped_point_lies_within_the_tolerance(inputs, k):
    pair = design_pair(inputs)
    outline = placed(gear_outline(pair, k), 0.37, (5.0, -2.0))      # turned and moved, as painted
    tolerance = 0.004                                              # mm: 0.01 px at 2.5 px a mm
    drawn = thinned(outline, (pair.gear1, pair.gear2)[k - 1].teeth, tolerance)
    assert len(drawn) < len(outline) / 3
    # the kept points are points of the outline, in its order, the first of them kept
    first = {}                      # each point of the outline → where it first comes
    for i, point in enumerate(map(tuple, outline.tolist())):
        first.setdefault(point, i)
    index = [first[point] for point in map(tuple, drawn.tolist())]
    assert index[0] == 0 and index == sorted(index)
    ring = index + [len(outline)]
    closed = np.vstack([outline, outline[:1]])
    worst = max(segment_distance(closed[j], closed[a], closed[b])
                for a, b in zip(ring, ring[1:]) for j in range(a + 1, b))
    assert worst <= tolerance * (1 + 1e-9)


def image_of(pair, tolerance_px: float, size=(335, 328)) -> np.ndarray:
    image = QImage(*size, QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    painter = QPainter(image)
    outlines = (placed(gear_outline(pair, 1), 0.2), placed(gear_outline(pair, 2), 1.1, (pair.centre_mm, 0.0)))
    paint_pair(painter, QRectF(0, 0, *size), pair, outlines, "φ", tolerance_px=tolerance_px)
    painter.end()
    return np.frombuffer(image.constBits(), np.uint8).reshape(size[1], size[0], 4).astype(int)


def test_the_drawing_looks_as_the_full_outlines(qapp):
    """The tab's size at 1366 × 768: no pixel moves by more than 16 levels of 255 (the
    differences are the stroke's antialiased edge, where the joins moved)."""
    pair = design_pair(PAIRS[0])
    full, thin = image_of(pair, 0.0), image_of(pair, DRAWN_TOLERANCE_PX)
    assert np.abs(full - thin).max() <= 16


def test_the_view_strokes_fewer_points_than_the_outline(qapp, monkeypatch):
    """What the tab paints: each gear's polygon a third of its outline's points or fewer."""
    from shaperapp.design.model import DesignModel
    from shaperapp.gear.model import GearModel
    sizes = []
    original = pair_view.screen_polygon
    monkeypatch.setattr(pair_view, "screen_polygon", lambda points, *a: sizes.append(len(points))
                        or original(points, *a))
    model = GearModel(DesignModel())
    view = pair_view.GearPairView(model)
    view.resize(335, 328)
    view.grab()
    whole = [len(o) for o in view.outlines()]
    assert len(sizes) == 2 and all(n <= math.ceil(w / 3) for n, w in zip(sizes, whole))
