"""The feed cam's drawing sheet as data: laid out like every sheet, and every drawing on it
measured back against core and against the independent restatement of the cam."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

from core.cam import CamInputs, Program, design_cam
from core.cam.laws import LAWS
from core.cam.table import cam_summary
from core.cli.cmd_cam import summary_rows
from core.drawing.cam_sheet import ENGLISH, cam_sheet, ratio_text
from core.drawing.checks import outside_border, overlapping_texts
from core.drawing.sheet import Circle, Polyline, Text, marked, paper
from core.base.errors import DesignError
from core.linkage.geometry import synthesize
from sheet_checks import assert_laid_out
from sweeps import examples

import cam_reference as ref

LINKAGE = synthesize(100.0, 1.4, 300.0)
DATA_SHEET = CamInputs(120.0, Program(15.0, 60.0, 10.0, 60.0, "sine", "sine"))
LARGE = CamInputs(400.0, Program(25.0, 50.0, 20.0, 50.0, "parabolic", "cosine"), 35.0, 60.0)
SERIES = {m * 10.0 ** k for m in (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0) for k in range(0, 4)}
ENLARGED = {1 / 2.0, 1 / 2.5, 1 / 4.0, 1 / 5.0}


@pytest.fixture(scope="module")
def cam():
    return design_cam(DATA_SHEET, LINKAGE)


@pytest.mark.parametrize("inputs", [DATA_SHEET, LARGE], ids=["data sheet", "large"])
@pytest.mark.parametrize("size", ["A1", "A2", "A3"])
def test_inside_the_border_in_own_areas_without_overlap(inputs, size):
    drawn = cam_sheet(design_cam(inputs, LINKAGE), 40.0, paper(size))
    assert_laid_out(drawn.sheet, drawn.areas)
    assert drawn.scale in SERIES | ENLARGED


@pytest.mark.parametrize("inputs, size", [(DATA_SHEET, "A1"), (DATA_SHEET, "A3"), (LARGE, "A2")])
def test_lengths_on_the_paper_over_the_scale_are_cores(inputs, size):
    """The base circle's radius and the distance O–A on the paper, times the stated scale,
    are core's base radius and centre distance; the roller touches the base circle's
    point at the arm's length from the pivot; the caption and the title block state the
    scale the drawing is drawn at."""
    c = design_cam(inputs, LINKAGE)
    drawn = cam_sheet(c, 40.0, paper(size))
    mu = drawn.scale
    assert drawn.base_circle.radius * mu == pytest.approx(c.base_radius_mm, rel=1e-12)
    assert math.dist(drawn.pivot, drawn.centre) * mu == pytest.approx(c.follower.distance_mm, rel=1e-12)
    assert drawn.base_circle.center == pytest.approx(drawn.centre)
    rollers = [it for it in drawn.areas["profile"][1] if isinstance(it, Circle)
               and it.radius * mu == pytest.approx(c.roller_mm, rel=1e-9)]
    assert len(rollers) == 1
    b0 = rollers[0].center
    assert math.dist(b0, drawn.centre) * mu == pytest.approx(c.base_radius_mm, rel=1e-9)
    assert math.dist(b0, drawn.pivot) * mu == pytest.approx(c.follower.arm_mm, rel=1e-9)
    texts = [it.text for it in drawn.sheet.items if isinstance(it, Text)]
    stated = ratio_text(mu)
    assert any(f"μl = {mu / 1000:g} m/mm ({stated})" in t for t in texts)
    assert stated in texts                                   # the title block's scale cell


def test_ratio_text_writes_enlargements_the_gb_way():
    assert (ratio_text(2.5), ratio_text(1.0), ratio_text(0.5), ratio_text(0.4)) == \
        ("1:2.5", "1:1", "2:1", "2.5:1")


CHARTS = ("psi", "omega", "alpha", "angle")


def _curve(items, origin, key, n_min=100):
    """The chart's curve: the charts are drawn in CHARTS' order, each one long polyline
    starting at the charts' common δ = 0."""
    lines = [it for it in items if isinstance(it, Polyline) and len(it.points) >= n_min
             and abs(it.points[0, 0] - origin[0]) < 1e-9]
    assert len(lines) == len(CHARTS)
    return lines[CHARTS.index(key)]


def test_follower_curves_read_back_are_the_sine_law(cam):
    """ψ, ω and α read off the paper with their μ are the cycloidal law's closed forms,
    written here from the textbook (ψ = ψmax(u − sin 2πu/2π) on the rise, mirrored on the
    return), at n = 40 r/min."""
    drawn = cam_sheet(cam, 40.0, paper("A1"))
    items = drawn.areas["curves"][1]
    w = 40.0 * 2 * math.pi / 60.0
    swing, rise, dwell, back = math.radians(15.0), math.radians(60.0), math.radians(10.0), math.radians(60.0)
    read = {}
    for key in ("psi", "omega", "alpha"):
        mu_y, mu_x, origin = drawn.charts[key]
        pts = _curve(items, origin, key).points
        read[key] = (np.radians((pts[:, 0] - origin[0]) * mu_x), (pts[:, 1] - origin[1]) * mu_y)
    d, psi_deg = read["psi"]
    u_up, u_back = d / rise, (d - rise - dwell) / back
    up, ret = u_up <= 1, (u_back >= 0) & (u_back <= 1)
    expect = np.where(up, u_up - np.sin(2 * math.pi * u_up) / (2 * math.pi),
                      np.where(ret, 1 - (u_back - np.sin(2 * math.pi * u_back) / (2 * math.pi)),
                               np.where(d < rise + dwell, 1.0, 0.0)))
    assert psi_deg == pytest.approx(np.degrees(swing * expect), abs=1e-9)
    d, omega = read["omega"]
    u_up, u_back = d / rise, (d - rise - dwell) / back
    expect = np.where(d < rise, swing / rise * (1 - np.cos(2 * math.pi * u_up)),
                      np.where((u_back >= 0) & (u_back < 1), -swing / back * (1 - np.cos(2 * math.pi * u_back)), 0))
    assert omega == pytest.approx(expect * w, abs=1e-9)
    d, alpha = read["alpha"]
    u_up, u_back = d / rise, (d - rise - dwell) / back
    expect = np.where(d < rise, 2 * math.pi * swing / rise ** 2 * np.sin(2 * math.pi * u_up),
                      np.where((u_back >= 0) & (u_back < 1),
                               -2 * math.pi * swing / back ** 2 * np.sin(2 * math.pi * u_back), 0))
    assert alpha == pytest.approx(expect * w * w, abs=1e-9)


def test_pressure_angle_read_back_is_the_numerical_normals_and_the_allowances_are_drawn(cam):
    """The pressure-angle curve read off the paper equals the angle between the pitch
    curve's numerical normal and the roller's motion (cam_reference, central differences);
    the dashed allowances lie at [α] over the rise and at the return's over the return."""
    drawn = cam_sheet(cam, 40.0, paper("A1"))
    mu_y, mu_x, origin = drawn.charts["angle"]
    items = drawn.areas["curves"][1]
    pts = _curve(items, origin, "angle").points
    deg = (pts[:, 0] - origin[0]) * mu_x
    on_phase = (deg < 59.9) | ((deg > 70.1) & (deg < 129.9))       # away from the law's joins
    f = cam.follower
    numeric = ref.numeric_pressure(f.distance_mm, f.arm_mm, math.radians(f.initial_deg), f.side,
                                   lambda dl: cam.program.motion(dl).psi, np.radians(deg[on_phase]))
    assert (pts[on_phase, 1] - origin[1]) * mu_y == pytest.approx(np.degrees(numeric), abs=1e-5)
    dashed = [it.points for it in items if isinstance(it, Polyline) and it.layer == "DASHED"]
    levels = sorted(((p[0, 0] - origin[0]) * mu_x, (p[1, 0] - origin[0]) * mu_x,
                     (p[0, 1] - origin[1]) * mu_y) for p in dashed)
    assert np.array(levels) == pytest.approx(np.array([(0.0, 60.0, 40.0), (70.0, 130.0, 70.0)]))


def test_table_gives_shaper_cams_figures_and_the_sectors_their_angles(cam):
    drawn = cam_sheet(cam, 40.0, paper("A1"))
    rows = dict(drawn.rows)
    printed = dict(summary_rows({**cam_summary(cam), "rpm": 40.0, "follower_omega_max_rad_s": 0.0,
                                 "follower_alpha_max_rad_s2": 0.0}))
    assert rows[ENGLISH["base"]] == printed["base radius r0 (pitch curve)"]
    assert rows[ENGLISH["distance"]] == printed["centre distance a"]
    assert rows[ENGLISH["roller"]] == printed["roller r"].split(" (")[0]
    assert rows[ENGLISH["rho"]] == printed["min convex radius ρmin (pitch curve)"]
    assert float(rows[ENGLISH["initial"]].rstrip("°")) == pytest.approx(cam.follower.initial_deg, abs=5e-4)
    assert rows[ENGLISH["phase"]] == f"{cam.timing.phase_deg:.3f}°"
    texts = {it.text for it in drawn.areas["profile"][1] if isinstance(it, Text)}
    assert {"δ0 = 60°", "δs = 10°", "δ0′ = 60°", "δs′ = 230°"} <= texts


def test_sector_rays_are_at_the_phase_edges_against_the_turning(cam):
    """The rays from O mark 0, δ0, δ0 + δs and δ0 + δs + δ0′ counter-clockwise from the
    line of centres (the inverted pivot's direction, the cam turning clockwise)."""
    drawn = cam_sheet(cam, 40.0, paper("A1"))
    o = np.asarray(drawn.centre)
    rays = [it.points for it in drawn.areas["profile"][1] if isinstance(it, Polyline)
            and len(it.points) == 2 and it.layer == "THIN" and np.allclose(it.points[0], o)]
    angles = sorted(round(math.degrees(math.atan2(*(p[1] - o)[::-1])) % 360.0, 9) for p in rays)
    assert angles == pytest.approx([0.0, 60.0, 70.0, 130.0])


def test_chinese_labels_change_the_texts_only(cam):
    labels = {k: "中文" + v for k, v in ENGLISH.items()}
    en = cam_sheet(cam, 40.0, paper("A2"))
    zh = cam_sheet(cam, 40.0, paper("A2"), labels=labels)
    assert en.scale == zh.scale and en.charts == zh.charts
    assert any(getattr(it, "text", "").startswith("中文") for it in zh.sheet.items)
    assert overlapping_texts(zh.sheet) == [] and outside_border(zh.sheet) == []


@pytest.mark.slow     # a random sweep of sheets (19 s of the suite): CI draws a share (tests/sweeps.py)
@settings(max_examples=examples(40), deadline=None, suppress_health_check=[HealthCheck.too_slow])
# the arm's text, set at its font's widths (narrower), sat on the rise sector's arc and left
# "δ0 = 64.5°" no spot: the sector went unnamed (a thorough run, seed 31337)
@example(rise_law="cosine", return_law="parabolic", swing=12.0, rise=64.5, dwell=0.0, back=40.0,
         arm=129.5, allowed=40.0, size="A3", rpm=10.0)
# the return sector's angle had no free spot round its arc, left of a cam near the area's edge
@example(rise_law="parabolic", return_law="parabolic", swing=18.0, rise=73.0, dwell=24.0, back=120.75,
         arm=55.0, allowed=31.0, size="A2", rpm=10.0)
# a batch of leader lines tested against the taken boxes, each marked by the wrong index
# (δs's leader chosen through a line; the batched label search's first version)
@example(rise_law="parabolic", return_law="parabolic", swing=5.0, rise=75.0, dwell=40.0, back=54.25,
         arm=153.0, allowed=30.0, size="A3", rpm=10.0)
# the arm's dimension text led out across its own dimension line (its own lines unchecked)
@example(rise_law="parabolic", return_law="parabolic", swing=17.0, rise=40.0, dwell=0.0, back=40.0,
         arm=50.0, allowed=34.0, size="A2", rpm=10.0)
# the base radius's text under the turning-sense arrow, which was drawn after the dimensions
@example(rise_law="parabolic", return_law="parabolic", swing=18.0, rise=44.0, dwell=0.0, back=40.0,
         arm=64.0, allowed=30.0, size="A3", rpm=10.0)
# found by a whole-suite run of 29 November that took the dimensions' fix above in mid-run
# (which code it ran is not known): "r0 = 32.8" crossed by a thin line on A1; clear now
@example(rise_law="parabolic", return_law="parabolic", swing=5.0, rise=40.0, dwell=0.0, back=40.0,
         arm=155.0, allowed=31.0, size="A1", rpm=10.0)
@given(rise_law=st.sampled_from(LAWS), return_law=st.sampled_from(LAWS),
       swing=st.floats(5.0, 30.0), rise=st.floats(40.0, 150.0),
       dwell=st.one_of(st.just(0.0), st.floats(1.0, 40.0)), back=st.floats(40.0, 150.0),
       arm=st.floats(50.0, 400.0), allowed=st.floats(30.0, 50.0), size=st.sampled_from(["A1", "A2", "A3"]), rpm=st.floats(10.0, 120.0))
def test_any_cam_and_paper_are_laid_out(rise_law, return_law, swing, rise, dwell, back, arm, allowed,
                                        size, rpm):
    try:
        c = design_cam(CamInputs(arm, Program(swing, rise, dwell, back, rise_law, return_law), allowed))
    except DesignError:            # no roller fits (a small sharp cam): nothing to draw
        assume(False)
    drawn = cam_sheet(c, rpm, paper(size))
    assert_laid_out(drawn.sheet, drawn.areas)
    assert drawn.base_circle.radius * drawn.scale == pytest.approx(c.base_radius_mm, rel=1e-12)
    assert re.fullmatch(r"[\d.]+:[\d.]+", ratio_text(drawn.scale))
    texts = [it.text for it in drawn.areas["profile"][1] if isinstance(it, Text)]
    inner = 360.0 - rise - dwell - back
    for key, span in (("rise_sector", rise), ("dwell_sector", dwell), ("return_sector", back),
                      ("inner_sector", inner)):          # every sector with its angle, none left out
        prefix = marked(ENGLISH[key])[0].split("{")[0]
        assert sum(t.startswith(prefix) for t in texts) == (1 if span > 0 else 0), (key, texts)


def test_a_checked_cam_beyond_the_allowance_says_so():
    """A cam checked with a base radius below the synthesized one exceeds [α]: the table
    says so, as shaper cam does; the synthesized cam's table does not."""
    synthesized = design_cam(DATA_SHEET)
    assert ENGLISH["allowance"] not in dict(cam_sheet(synthesized, 40.0, paper("A2")).rows)
    small = design_cam(CamInputs(120.0, DATA_SHEET.program, base_mm=0.9 * synthesized.base_radius_mm,
                                 distance_mm=synthesized.follower.distance_mm))
    assert not small.within_allowance
    drawn = cam_sheet(small, 40.0, paper("A2"))
    assert dict(drawn.rows)[ENGLISH["allowance"]] == ENGLISH["exceeded"]
    assert_laid_out(drawn.sheet, drawn.areas)
