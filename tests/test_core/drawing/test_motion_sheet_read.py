"""The motion sheet read as a teacher reads it (issue 40, item 2), 方案 I of the task book:
the crank's numbers 1 … 12 and the tool path's 1 … 12 interleaved near the crank circle
("4 6 5 7 9"); the working stroke's end 8′ was not on the curves; the polygons had no
vector equation and no magnitudes beside them. Measured on the sheet's items against core."""
import math

import numpy as np
import pytest

from core.drawing.motion import motion_sheet
from core.drawing.sheet import Circle, Text, paper
from core.linkage.geometry import from_dimensions
from core.linkage.kinematics import solve
from core.forces.polygons import acceleration_polygon, velocity_polygon
from core.course_design.positions import special_angles

SCHEME_I = from_dimensions(110.0, 380.0, 540.0, rod=135.0)


@pytest.fixture(scope="module", params=["A1", "A3"])
def drawn(request):
    return motion_sheet(SCHEME_I, 60.0, paper(request.param))


def gap(a, b) -> float:
    """Between two boxes, mm (0 when they meet)."""
    return math.hypot(max(a[0] - b[2], b[0] - a[2], 0.0), max(a[1] - b[3], b[1] - a[3], 0.0))


def test_crank_numbers_keep_apart_from_the_tool_paths(drawn):
    """The crank's numbers are 3.5 mm high, the tool path's 2.5 mm; no crank number stands
    within a text height (3.5 mm) of a tool path number, where the two rows read as one."""
    texts = [t for t in drawn.areas["mechanism"][1] if isinstance(t, Text) and t.text.isdigit()]
    crank = [t for t in texts if t.height == 3.5]
    path = [t for t in texts if t.height < 3.5]
    assert len(path) >= 10 and len(crank) == 12, (len(path), sorted(t.text for t in crank))
    close = [(c.text, p.text) for c in crank for p in path if gap(c.box(), p.box()) < 3.5 - 1e-6]
    assert close == []


def test_the_working_strokes_end_8_prime_is_marked_on_each_curve(drawn):
    """A point on each of the s, v and a curves at the limit position φ = 213.65° (8′: after
    position 8 at 210°), where s is the stroke and v is zero, named 8′ beside it."""
    limit = special_angles(SCHEME_I, 0.05)["limit_work_end"]
    items = drawn.areas["curves"][1]
    dots = [c for c in items if isinstance(c, Circle)]
    names = [t for t in items if isinstance(t, Text) and t.text == "8′"]
    assert len(dots) == 3 and len(names) == 3
    for dot in dots:
        assert min(math.dist(dot.center, n.position) for n in names) < 12.0
    xs = {round(d.center[0], 6) for d in dots}
    assert len(xs) == 1                           # one crank angle on the one φ scale
    at = solve(SCHEME_I, np.radians([limit]), [60.0])
    assert abs(float(at.ram_v[0, 0])) < 1e-9 and float(at.ram_x[0]) == pytest.approx(SCHEME_I.stroke, rel=1e-9)


def test_each_polygon_has_its_equations_and_magnitudes_beside_it():
    """A1: v_A4 = v_A3 + v_A4A3 and v_C = v_B + v_CB (the rod's); a^n_A4 + a^t_A4 = a_A3 +
    a^k_A4A3 + a^r_A4A3 and a_C = a_B + a^n_CB + a^t_CB; and every vector's magnitude as
    core's polygon has it, to 4 digits; v_C and a_C are the ram's v and a (core.linkage.kinematics).
    (On A3 the acceleration polygon's eleven rows do not fit beside it and are left out.)"""
    drawn = motion_sheet(SCHEME_I, 60.0, paper("A1"))
    texts = [t.text for t in drawn.areas["polygons"][1] if isinstance(t, Text)]
    for angle in drawn.diagram_deg:
        v, a = velocity_polygon(SCHEME_I, angle, 60.0), acceleration_polygon(SCHEME_I, angle, 60.0)
        for poly in (v, a):
            for vec in poly.vectors:
                base, _, index = vec.key.partition("_")
                base, _, sup = base.partition("^")
                assert f"{base}{index}{sup} = {vec.magnitude:.4g} {poly.unit}" in texts, vec.key
        ram = solve(SCHEME_I, np.radians([angle]), [60.0])
        assert f"vC = {abs(float(ram.ram_v[0, 0])):.4g} m/s" in texts
        assert f"aC = {abs(float(ram.ram_a[0, 0])):.4g} m/s²" in texts
    assert texts.count("vA4 = vA3 + vA4A3") == 2 and texts.count("vC = vB + vCB") == 2
    assert texts.count("aA4n + aA4t = aA3 + aA4A3k + aA4A3r") == 2
    assert texts.count("aC = aB + aCBn + aCBt") == 2
