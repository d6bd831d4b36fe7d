"""The Gear tab fills a gear's outline polygon from the array at once (``screen_polygon``):
each vertex must be exactly the point-by-point mapping, middle at the centre, y up."""
from __future__ import annotations

import numpy as np

from core.gear import GearPairInputs, design_pair
from core.gear.mesh import gear_outline

from shaperapp.widgets.screen_polygon import screen_polygon


def test_the_polygon_is_the_outline_mapped_point_by_point(qapp):
    outline = gear_outline(design_pair(GearPairInputs(13, 40, 6.0, centre_mm=162.0)), 2)
    middle, scale, centre = np.array([81.0, -3.5]), 1.7, (450.0, 300.0)
    poly = screen_polygon(outline, centre, middle, scale)
    assert poly.size() == len(outline) > 1000
    for k in (0, 1, len(outline) // 3, len(outline) - 1):
        x, y = outline[k]
        assert poly.at(k).x() == centre[0] + (x - middle[0]) * scale
        assert poly.at(k).y() == centre[1] - (y - middle[1]) * scale
    got = np.array([[poly.at(k).x(), poly.at(k).y()] for k in range(poly.size())])
    want = np.column_stack([centre[0] + (outline[:, 0] - middle[0]) * scale,
                            centre[1] - (outline[:, 1] - middle[1]) * scale])
    assert np.array_equal(got, want)
    top = int(np.argmax(outline[:, 1]))          # y up: the highest point is the least screen y
    assert poly.at(top).y() == min(p[1] for p in got)


def test_an_empty_outline_is_an_empty_polygon(qapp):
    assert screen_polygon(np.empty((0, 2)), (0.0, 0.0), np.zeros(2), 1.0).size() == 0
