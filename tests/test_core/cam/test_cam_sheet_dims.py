"""The cam sheet's sizes and sector angles, readable (issue 40, item 2): the four phase arcs
were one unlabelled circle (no arrowheads, R ≈ 70 mm) and the cam had no dimension of its
base radius r0, its centre distance a or its arm l. Now each arc ends in an arrowhead on
each edge ray, and a, l and r0 are dimensions whose values are the cam's (core.cam), on the
paper as the sheet's placement maps them."""
from __future__ import annotations

import math

import numpy as np
import pytest

from core.cam import CamInputs, Program, design_cam
from core.drawing.cam_sheet import cam_sheet
from core.drawing.sheet import Polyline, paper
from core.linkage.geometry import from_dimensions, synthesize

SCHEME_I = from_dimensions(110.0, 380.0, 540.0, rod=135.0)
DATA_SHEET = CamInputs(120.0, Program(15.0, 60.0, 10.0, 60.0, "sine", "sine"))


@pytest.mark.parametrize("linkage", [SCHEME_I, synthesize(100.0, 1.4, 300.0)], ids=["scheme I", "default"])
@pytest.mark.parametrize("size", ["A1", "A3"])
def test_a_l_and_r0_are_dimensioned_with_the_cams_values(linkage, size):
    cam = design_cam(DATA_SHEET, linkage)
    drawn = cam_sheet(cam, 60.0, paper(size))
    dims = {d.name: d for d in drawn.sheet.dimensions}
    assert dims["a"].value == pytest.approx(cam.follower.distance_mm, rel=1e-9)
    assert dims["l"].value == pytest.approx(DATA_SHEET.arm_mm, rel=1e-9)
    assert dims["r0"].value == pytest.approx(cam.base_radius_mm, rel=1e-9)
    o, a = np.asarray(drawn.centre), np.asarray(drawn.pivot)
    assert {tuple(np.round(p, 6)) for p in dims["a"].points} == {tuple(np.round(o, 6)), tuple(np.round(a, 6))}
    assert any(np.allclose(p, o) for p in dims["r0"].points)
    texts = {d.name: d.text.text for d in dims.values()}
    assert texts["a"].startswith("a = ") and texts["r0"].startswith("r0 = ") and texts["l"].startswith("l = ")


def test_each_phase_arc_ends_in_an_arrowhead_on_its_edge_rays():
    """The four edges (0, rise, rise + dwell, rise + dwell + return, measured counter-clockwise
    from the line of centres) each carry two arrowhead tips, one for each arc that ends
    there, at one radius about O."""
    cam = design_cam(DATA_SHEET, SCHEME_I)
    drawn = cam_sheet(cam, 60.0, paper("A1"))
    o = np.asarray(drawn.centre)
    p = cam.program
    edges = [0.0, p.rise_deg, p.rise_deg + p.dwell_deg, p.rise_deg + p.dwell_deg + p.return_deg]
    heads = [np.asarray(it.points, float) for it in drawn.areas["profile"][1]
             if isinstance(it, Polyline) and it.filled]
    tips = []
    for h in heads:         # a head's tip: its vertex farthest from the base's middle
        base_mid = (h[1] + h[2]) / 2.0
        tips.append(h[np.argmax(np.hypot(*(h - base_mid).T))])
    found = []              # (edge, radius) of each tip on an edge ray
    for t in tips:
        angle = math.degrees(math.atan2(t[1] - o[1], t[0] - o[0])) % 360.0
        found += [(e, round(math.hypot(*(t - o)), 6)) for e in edges
                  if abs((angle - e + 180.0) % 360.0 - 180.0) < 0.05]
    # the arcs' radius: where tips sit on every edge (the turning sense's head may sit on one)
    radius = max({r for _, r in found}, key=lambda r: len({e for e, q in found if q == r}))
    on_ray = {e: sum(1 for f, r in found if f == e and r == radius) for e in edges}
    assert on_ray == {e: 2 for e in edges}
