"""The meshing sheet (issue 35, item 3) as data and as the DXF of ``shaper gear --dxf``:
laid out like every sheet, the teeth in mesh without overlap, and in the DXF's model
coordinates the pinion's circles about (0, 0), the gear's about (a′, 0), every flank vertex on
an involute of its base circle (checked from the vertices alone), the texts on their layer."""
from __future__ import annotations

import math

import ezdxf
import numpy as np
import pytest

from core.drawing.gear_sheet import ENGLISH, gear_sheet, teeth_outline
from core.drawing.sheet import paper
from core.gear import GearPairInputs, design_pair
from core.gear.profile import flank
from sheet_checks import assert_laid_out

from cli_runner import shaper_in_process

PAIRS = {"shaper": dict(z1=13, z2=40, module_mm=6.0, centre_mm=162.0),
         "rule": dict(z1=13, z2=40, module_mm=6.0),
         "small": dict(z1=10, z2=12, module_mm=5.0),
         "large": dict(z1=17, z2=120, module_mm=4.0, x1=0.1, x2=0.0),
         "textbook": dict(z1=12, z2=12, module_mm=10.0, centre_mm=130.0)}


@pytest.mark.parametrize("name", sorted(PAIRS))
@pytest.mark.parametrize("size", ["A0", "A1", "A2", "A3"])
def test_laid_out_inside_the_border_without_overlap(name, size):
    drawn = gear_sheet(design_pair(GearPairInputs(**PAIRS[name])), paper(size))
    assert_laid_out(drawn.sheet, drawn.areas)
    texts = [t.text for t in drawn.sheet.items if hasattr(t, "text")]
    # the sheet's name in the title block, on one line or (its 48.1 mm at 5 mm over the
    # cell's 48) broken at its space, at 5 mm rather than one line at 3.5 mm
    assert ("Gear meshing" in texts or {"Gear", "meshing"} <= set(texts)) and any("α′ = " in t for t in texts)


def test_interference_shows_b2_before_n1():
    """An undercut pinion whose mate's tip reaches below N1 (B2 before N1): the straightened
    line of action still names B2, at its place before N1."""
    pair = design_pair(GearPairInputs(z1=8, z2=30, module_mm=2.0, x1=0.0, x2=0.0))
    assert pair.n1b2 < 0.0
    drawn = gear_sheet(pair, paper("A2"))
    assert_laid_out(drawn.sheet, drawn.areas)
    names = {t.text: t.position[0] for t in drawn.areas["line"][1] if hasattr(t, "text")}
    assert names["B2"] < names["N1"] < names["P"] < names["B1"] < names.get("N2", math.inf)


@pytest.mark.parametrize("name", sorted(PAIRS))
def test_teeth_touch_in_mesh_and_never_overlap(name):
    """No point of the pinion's drawn teeth lies inside the gear's material (its tooth at
    that radius, from the flank), and some touch it (the pair is in contact, no backlash)."""
    pair = design_pair(GearPairInputs(**PAIRS[name]))
    g2 = pair.gear2
    f = flank(pair.inputs, g2)
    alpha, alpha_w = pair.inputs.alpha, pair.alpha_w
    psi_w = g2.s / (2 * g2.r) + math.tan(alpha) - alpha - (math.tan(alpha_w) - alpha_w)
    d = teeth_outline(pair, 1) - (pair.centre_mm, 0.0)
    radius, theta = np.hypot(d[:, 0], d[:, 1]), np.arctan2(d[:, 1], d[:, 0])
    pitch = 2 * math.pi / g2.teeth
    off_axis = np.abs((theta - (math.pi - psi_w) + pitch / 2) % pitch - pitch / 2)
    inside = (radius > g2.rf) & (radius < g2.ra)
    depth = ((np.interp(radius, f.radius, f.angle) - off_axis) * radius)[inside]
    m = pair.inputs.module_mm
    assert depth.max() < 1e-5 * m          # the polylines' chords: none cuts in
    assert depth.max() > -1e-3 * m         # and they touch


def _dxf(tmp_path, kwargs) -> tuple[object, object]:
    pair = design_pair(GearPairInputs(**kwargs))
    words = ["--z1", str(kwargs["z1"]), "--z2", str(kwargs["z2"]), "--module", str(kwargs["module_mm"])]
    for key, option in (("centre_mm", "--centre"), ("x1", "--x1"), ("x2", "--x2")):
        if key in kwargs:
            words += [option, str(kwargs[key])]
    out = tmp_path / "gear.dxf"
    status, _, err = shaper_in_process("gear", *words, "--dxf", str(out))
    assert status == 0, err
    doc = ezdxf.readfile(out)
    assert doc.header["$INSUNITS"] == 4 and not doc.audit().has_errors
    return pair, doc


def _involute_spread(points: np.ndarray, rb: float, pitch: float) -> float:
    """Every point of an involute flank of the base circle rb has the same
    θ ± (tan β − β) (cos β = rb/ρ; + on one side of the teeth, − on the other) modulo the
    pitch: the largest distance, mm at the point, from the nearest of the two values."""
    rho = np.hypot(points[:, 0], points[:, 1])
    beta = np.arccos(rb / rho)
    theta = np.arctan2(points[:, 1], points[:, 0])
    candidates = [(theta + s * (np.tan(beta) - beta)) % pitch for s in (1.0, -1.0)]
    misses = []
    for c in candidates:                     # each side's value: the most common one
        hist, edges = np.histogram(c, bins=2000, range=(0.0, pitch))
        near = c[np.abs(c - edges[hist.argmax()]) < 3 * (edges[1] - edges[0])]
        misses.append(np.abs((c - float(np.median(near)) + pitch / 2) % pitch - pitch / 2))
    return float((np.minimum(*misses) * rho).max())


@pytest.mark.parametrize("name", ["shaper", "textbook", "rule"])
def test_dxf_model_coordinates_and_involute_flanks(name, tmp_path):
    pair, doc = _dxf(tmp_path, PAIRS[name])
    msp = doc.modelspace()
    m, alpha = pair.inputs.module_mm, math.radians(20)
    a = pair.centre_mm
    circles = [(c.dxf.center.x, c.dxf.center.y, c.dxf.radius) for c in msp.query("CIRCLE")]
    z1, z2 = pair.inputs.z1, pair.inputs.z2
    rb1, rb2 = m * z1 * math.cos(alpha) / 2, m * z2 * math.cos(alpha) / 2
    at_o1 = sorted(r for x, y, r in circles if abs(x) < 1e-9 and abs(y) < 1e-9)
    expected1 = sorted([m * z1 / 2, rb1, pair.gear1.ra, pair.gear1.rf, rb1 / math.cos(pair.alpha_w)])
    assert at_o1 == pytest.approx(expected1, rel=1e-9)
    # the gear's circles (whole, or arcs cut at the window): every point at its radius from (a′, 0)
    ring = {round(v, 6) for v in (m * z2 / 2, rb2, pair.gear2.ra, pair.gear2.rf, rb2 / math.cos(pair.alpha_w))}
    found = {round(r, 6) for x, y, r in circles if abs(x - a) < 1e-9 and abs(y) < 1e-9}
    for poly in msp.query("LWPOLYLINE"):
        pts = np.array([(p[0], p[1]) for p in poly.get_points()])
        if poly.dxf.layer != "OUTLINE" and len(pts) > 20:
            d = np.hypot(pts[:, 0] - a, pts[:, 1])
            if np.ptp(d) < 1e-9 * a:
                found.add(round(float(d[0]), 6))
    assert ring <= found
    # the teeth: the two long OUTLINE polylines, the pinion's about O1, the gear's about O2
    teeth = sorted((p for p in msp.query('LWPOLYLINE[layer=="OUTLINE"]') if len(p) > 200),
                   key=lambda p: min(q[0] for q in p.get_points()))
    assert len(teeth) == 2
    for poly, centre, z, rb, gear in ((teeth[0], 0.0, z1, rb1, pair.gear1), (teeth[1], a, z2, rb2, pair.gear2)):
        pts = np.array([(p[0], p[1]) for p in poly.get_points()]) - (centre, 0.0)
        rho = np.hypot(pts[:, 0], pts[:, 1])
        form = math.hypot(rb, max(gear.form_length, 0.0))
        flank_pts = pts[(rho > form + 1e-6 * m) & (rho < gear.ra - 1e-6 * m)]
        assert len(flank_pts) >= 5 * 2 * 40               # five teeth, two flanks, densely
        assert _involute_spread(flank_pts, rb, 2 * math.pi / z) < 1e-9 * gear.ra
        assert rho.max() == pytest.approx(gear.ra, rel=1e-9) and rho.min() == pytest.approx(gear.rf, rel=1e-9)
    texts = [t.dxf.text for t in msp.query("TEXT")]
    # the sheet's name, on one line or broken at its space (as in the PDF); shaper gear's sheet
    # is the pair alone, a set of one ("4/4" is the course design's, shaper drawing --content gear)
    assert (ENGLISH["title"] in texts or set(ENGLISH["title"].split()) <= set(texts))
    assert "1/1" in texts and "4/4" not in texts
    assert {t.dxf.layer for t in msp.query("TEXT")} <= {"TEXT", "TITLE"}


@pytest.mark.parametrize("name", sorted(PAIRS))
@pytest.mark.parametrize("size", ["A1", "A3"])
def test_the_strip_names_both_limit_points(name, size):
    """Issue 42: the strip was scaled to B2B1 alone and N2 fell off its end. Now N1, B2, P,
    B1, N2 are all named, N1 left of P and N2 right of it (names close together are moved
    apart by the label search, so only the far ones' order is fixed)."""
    pair = design_pair(GearPairInputs(**PAIRS[name]))
    drawn = gear_sheet(pair, paper(size))
    names = {t.text: t.position[0] for t in drawn.areas["line"][1] if hasattr(t, "text")}
    along = {"N1": 0.0, "B2": pair.n1b2, "P": pair.n1p, "B1": pair.n1b1, "N2": pair.n1n2}
    assert set(along) <= set(names)
    assert names["N1"] < names["P"] < names["N2"]


def test_the_least_tip_thickness_reads_as_a_multiple_of_the_module():
    """Issue 40: "Tip s_a ≥ 0.25 m" read as metres; now 0.25·m (= 1.5 mm) at m = 6."""
    drawn = gear_sheet(design_pair(GearPairInputs(**PAIRS["shaper"])), paper("A2"))
    texts = " ".join(t.text for t in drawn.sheet.items if hasattr(t, "text"))
    assert "0.25·m (= 1.5 mm)" in texts and "0.25 m" not in texts


def test_the_base_pitch_is_marked_as_the_other_dimensions():
    """The strip's base pitch is a dimension on a drawing, so it has the drawings' 2 places
    (docs/methods.md), as α′ = 22.74° beside it: it read p_b = 17.713. p_b = π·m·cos α =
    π·6·cos 20° = 17.7128 mm."""
    drawn = gear_sheet(design_pair(GearPairInputs(**PAIRS["shaper"])), paper("A3"))
    marks = [t.text for t in drawn.areas["line"][1] if hasattr(t, "text") and t.text.startswith("pb =")]
    assert marks and set(marks) == {f"pb = {math.pi * 6 * math.cos(math.radians(20)):.2f}"}
