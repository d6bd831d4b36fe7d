"""The kinetostatic sheet as data: inside the border, nothing overlapping, and every
force, torque, energy and flywheel figure on it measured back against core."""
import math

import numpy as np
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from core.cli.cmd_dynamics import speed_rows
from core.drawing.forces import ENGLISH, forces_sheet, joint_forces
from core.drawing.motion import motion_sheet
from core.drawing.checks import outside_border, overlapping_texts
from core.drawing.sheet import Polyline, Text, paper
from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties, masses_for_design
from core.base.errors import DesignError
from core.forces.flywheel import summarize
from core.linkage.geometry import synthesize
from core.linkage.spec import Spec
from core.linkage.kinematics import rpm_to_omega
from sheet_checks import assert_laid_out
from sweeps import examples

BLOCK = synthesize(100.0, 1.4, 300.0)
ROD = synthesize(100.0, 1.46, 312.0, rod_ratio=0.3)
LEADING = synthesize(150.0, 1.2, 600.0, rod_ratio=0.8, rod_side="leading")
LOADS = dict(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000, cut_height_mm=80)


def masses(design):
    extra = {"rod_mass_kg": 8.0} if design.rod is not None else {}
    return masses_for_design(design, MassProperties(**LOADS, **extra))


@pytest.mark.parametrize("design", [BLOCK, ROD, LEADING], ids=["block", "rod", "leading"])
@pytest.mark.parametrize("size", ["A1", "A3"])
def test_inside_the_border_in_own_areas_without_overlap(design, size):
    drawn = forces_sheet(design, 60.0, masses(design), paper(size))
    assert_laid_out(drawn.sheet, drawn.areas)


@pytest.mark.parametrize("design", [BLOCK, ROD], ids=["block", "rod"])
def test_force_names_carry_their_index_as_a_subscript(design):
    """R_O2, F_I6 … were written with the underscore on the sheet: now the letter and its
    index one standard size smaller and lowered, as two plain texts in every renderer."""
    from core.drawing.sheet import TEXT_HEIGHTS, Text
    sheet = forces_sheet(design, 60.0, masses(design), paper("A1")).sheet
    texts = [t for t in sheet.items if isinstance(t, Text)]
    named = {(t.text[:s], t.text[s:e]) for t in texts for s, e in t.subscripts}
    assert {("R", "O2"), ("R", "A"), ("R", "O4"), ("F", "I6"), ("G", "6")} <= named
    assert ("R", "C" if design.rod is not None else "B") in named
    assert not [t.text for t in texts if "_" in t.text and t.text.split("_")[0] in ("R", "F", "G")]
    # the force names (the captions' and tables' indices are subscripts too, see test_sheet)
    for label in (t for t in texts if t.subscripts and t.text[:t.subscripts[0][0]] in ("R", "F", "G")):
        base, index = label.runs()
        assert (base.height, index.height) == (3.5, 2.5) and index.height in TEXT_HEIGHTS
        assert index.position[1] < base.position[1]                     # lowered
        assert index.position[0] == pytest.approx(base.position[0] + base.width)


def test_default_positions_are_the_motion_sheets():
    """The same two positions as the report's and the motion sheet's polygons."""
    m = masses(BLOCK)
    assert forces_sheet(BLOCK, 40.0, m, paper("A1")).diagram_deg == \
        motion_sheet(BLOCK, 40.0, paper("A1")).diagram_deg
    assert forces_sheet(BLOCK, 40.0, m, paper("A1"), diagram_deg=(30.0, 300.0)).diagram_deg == (30.0, 300.0)


@pytest.mark.parametrize("design", [BLOCK, ROD], ids=["block", "rod"])
def test_arrows_times_their_scale_are_the_forces_and_the_ram_is_in_equilibrium(design):
    """Each arrow's length × μF and direction is core's force; the arrows on the ram
    (block: P, G6, F_I6, N, R_B; rod: P, G6, F_I6, N, R_C) add up to zero on the paper:
    d'Alembert's equilibrium of the ram, which the drawing does not impose."""
    m = masses(design)
    drawn = forces_sheet(design, 40.0, m, paper("A1"), diagram_deg=(80.0, 250.0))
    for k, angle in enumerate((80.0, 250.0)):
        d = solve_dynamics(design, np.radians([angle]), [40.0], m)
        expected = {"R_O4": (d.o4_x, d.o4_y), "R_O2": (d.o2_x, d.o2_y), "R_A": (d.a_x, d.a_y),
                    "R_B": (d.b_x, d.b_y), "N": (0.0 * d.guide_normal, d.guide_normal)}
        mu = drawn.force_scales[k]
        for name, (fx, fy) in expected.items():
            tail, head = drawn.arrows[(k, name)]
            assert (head - tail) * mu == pytest.approx([float(np.ravel(fx)[0]), float(np.ravel(fy)[0])],
                                                       rel=1e-9, abs=1e-6), name
        on_ram = ["P", "G_6", "F_I6", "N", "R_B" if design.rod is None else "R_C"]
        total = sum(((drawn.arrows[(k, n)][1] - drawn.arrows[(k, n)][0]) * mu
                     for n in on_ram if (k, n) in drawn.arrows), np.zeros(2))
        if design.rod is not None:     # R_C is the rod on the ram; R_B (on the rod) is not on it
            assert (k, "R_C") in drawn.arrows
        assert np.hypot(*total) < 1e-6 * m.cut_force_N


def test_the_cutting_force_is_drawn_only_while_cutting():
    m = masses(BLOCK)
    names = {n for n, _, _ in joint_forces(BLOCK, 40.0, m, 90.0)}
    assert "P" in names
    assert "P" not in {n for n, _, _ in joint_forces(BLOCK, 40.0, m, 270.0)}


def _curve(items, n_min=100):
    return next(it for it in items if isinstance(it, Polyline) and len(it.points) >= n_min)


def test_torque_curve_and_mean_measure_true():
    """The torque curve read off the paper with the stated μM and μφ is core's torque, and
    its dashed mean line is the cycle mean (trapezoid rule over 0.1°, independent of
    core.forces.flywheel's exact integration)."""
    m = masses(BLOCK)
    drawn = forces_sheet(BLOCK, 40.0, m, paper("A1"))
    mu_m, mu_phi, (ox, oy) = drawn.torque_chart
    items = drawn.areas["torque"][1]
    curve = _curve(items)
    phi = (curve.points[:, 0] - ox) * mu_phi
    torque = (curve.points[:, 1] - oy) * mu_m
    core_torque = solve_dynamics(BLOCK, np.radians(phi), [40.0], m).crank_torque[0]
    assert torque == pytest.approx(core_torque, rel=1e-9, abs=1e-6)
    fine = np.radians(np.linspace(0.0, 360.0, 3601))
    t = solve_dynamics(BLOCK, fine, [40.0], m).crank_torque[0]
    mean = np.trapezoid(t, fine) / (2 * math.pi)
    dashed = [it for it in items if isinstance(it, Polyline) and it.layer == "DASHED"]
    assert len(dashed) == 1
    assert (dashed[0].points[0, 1] - oy) * mu_m == pytest.approx(mean, rel=5e-3)


def test_energy_curve_spans_delta_w_and_the_table_gives_the_flywheel():
    """max − min of the energy curve on the paper × μE is ΔW_max, and an independent
    cumulative trapezoid of (M − M_m) gives it within 0.5 %; the table's J_F is
    ΔW_max/(ω²δ) and its texts are those ``shaper dynamics`` prints."""
    m = masses(BLOCK)
    drawn = forces_sheet(BLOCK, 40.0, m, paper("A1"))
    mu_e, _, (_, oy) = drawn.energy_chart
    energy = (_curve(drawn.areas["energy"][1]).points[:, 1] - oy) * mu_e
    fine = np.radians(np.linspace(0.0, 360.0, 36001))
    t = solve_dynamics(BLOCK, fine, [40.0], m).crank_torque[0]
    cumulative = np.concatenate([[0.0], np.cumsum((t[1:] + t[:-1]) / 2 * np.diff(fine))])
    cumulative -= cumulative[-1] * fine / (2 * math.pi)          # subtract the mean's work
    independent = cumulative.max() - cumulative.min()
    assert energy.max() - energy.min() == pytest.approx(independent, rel=5e-3)
    rows = dict(drawn.rows)
    summary = summarize(BLOCK, [40.0], m)
    cli = dict(speed_rows(summary.speeds[0]))
    dw = float(rows[ENGLISH["dW"]].split()[0])
    assert rows[ENGLISH["dW"]] == cli["energy fluctuation ΔW_max"]
    assert rows[ENGLISH["J_F"]] == cli["flywheel J_F"]
    w = float(rpm_to_omega(40.0))
    assert float(rows[ENGLISH["J_F"]].split()[0]) == pytest.approx(dw / (w * w * m.delta), rel=1e-3)
    assert energy.max() - energy.min() == pytest.approx(dw, rel=1e-3)


def test_chinese_labels_change_the_texts_only():
    m = masses(ROD)
    labels = {k: "中文" + v for k, v in ENGLISH.items()}
    en = forces_sheet(ROD, 40.0, m, paper("A1"))
    zh = forces_sheet(ROD, 40.0, m, paper("A1"), labels=labels)
    assert en.force_scales == zh.force_scales and en.scale == zh.scale
    assert any(getattr(it, "text", "").startswith("中文") for it in zh.sheet.items)
    assert overlapping_texts(zh.sheet) == [] and outside_border(zh.sheet) == []


finite = dict(allow_nan=False, allow_infinity=False)


@pytest.mark.slow       # a random sweep: each example lays out a whole kinetostatic sheet
@settings(max_examples=examples(25), deadline=None)
# A torque of 10^5 N·m: its tick label "-1.000e+05" stood outside the torque's area
# (a chart's y labels had a fixed 21 mm; found by this test in a CI run).
@example(crank=182.0, k=2.5, stretch=3.0, rod=0.5, work=0.0, back=0.0, size="A1", rpm=110.0)
@given(crank=st.floats(30, 300, **finite), k=st.floats(1.1, 2.5, **finite),
       stretch=st.floats(1.1, 3.0, **finite), rod=st.one_of(st.none(), st.floats(0.3, 1.0, **finite)),
       work=st.floats(0, 360, **finite), back=st.floats(0, 360, **finite),
       size=st.sampled_from(["A1", "A2", "A3"]), rpm=st.floats(10, 120, **finite))
def test_any_design_positions_and_paper_are_laid_out(crank, k, stretch, rod, work, back, size, rpm):
    theta = math.pi * (k - 1) / (k + 1)
    try:
        design = synthesize(crank, k, stretch * 2 * crank * (1 + math.sin(theta / 2)), rod_ratio=rod)
    except DesignError:
        assume(False)
    drawn = forces_sheet(design, rpm, masses(design), paper(size), diagram_deg=(work, back))
    assert_laid_out(drawn.sheet, drawn.areas)


def y_numbers(items):
    """The chart's y tick numbers: plain numbers set right of a point ("rm", left of the axis)."""
    out = []
    for t in items:
        if isinstance(t, Text) and t.align == "rm":
            try:
                out.append((float(t.text), t))
            except ValueError:
                pass
    return out


SCHEME_I = Spec(mode="dimensions", crank=110.0, frame=380.0, lever=540.0, variant="rod", rod_ratio=0.25).design()


@pytest.mark.parametrize("size", ["A3", "A1"])
@pytest.mark.parametrize("design", [SCHEME_I, BLOCK, ROD], ids=["scheme-I", "block", "rod"])
def test_the_torque_and_energy_charts_number_their_y_axes(design, size):
    """A reader reads a torque or an energy off the chart by its numbered y ticks: at least
    one beside the axis, each number the value at its height. The scale is first measured
    on the curve (its highest point on the paper times μ is core's largest value); A3's
    torque chart, 21 mm high at μM = 40 (N·m)/mm, was ticked every 1000 N·m and had no
    number but the note μM (the task book's 方案 I with shaper drawing's loads)."""
    m = masses_for_design(design, MassProperties(**LOADS))
    drawn = forces_sheet(design, 60.0, m, paper(size))
    summary = summarize(design, [60.0], m)
    peaks = {"torque": summary.speeds[0].max_torque_N_m, "energy": float(np.max(summary.energy[0]))}
    for name, (mu, _, origin) in (("torque", drawn.torque_chart), ("energy", drawn.energy_chart)):
        _, items = drawn.areas[name]
        curve = max((it for it in items if isinstance(it, Polyline)), key=lambda p: len(p.points))
        assert (curve.points[:, 1].max() - origin[1]) * mu == pytest.approx(peaks[name], rel=2e-3), name
        numbers = y_numbers(items)
        assert numbers, (name, size)
        ticks = [it.points for it in items if isinstance(it, Polyline) and len(it.points) == 2
                 and it.points[1, 0] == pytest.approx(origin[0]) and it.points[0, 1] == it.points[1, 1]
                 and it.points[0, 0] < origin[0]]
        for value, text in numbers:
            assert value != 0.0
            assert (text.position[1] - origin[1]) * mu == pytest.approx(value, rel=1e-9), (name, text.text)
            assert text.box()[2] < origin[0]                                  # left of the axis
            assert any(abs(t[0, 1] - text.position[1]) < 1e-9 for t in ticks), (name, text.text)


# 方案 I–III of the task book (L1, L2, L3, L4/L3, n r/min, G4 N, J_S4 kg·m², G6 N, P N, y_P mm)
TASK_BOOK = {"I": (110, 380, 540, 0.25, 60, 200, 1.1, 700, 7000, 80),
             "II": (90, 350, 580, 0.3, 64, 220, 1.2, 800, 9000, 80),
             "III": (110, 430, 810, 0.36, 72, 220, 1.2, 620, 8000, 100)}


def _head_labels(drawn, k: int):
    """(force, its arrow's head, its label, whether a leader ties them) on mechanism ``k``
    (1, 2) of a kinetostatic sheet: the label is the text of the force's name, its leader
    a two-point thin line from 0.5 mm off the head to the label's box."""
    from core.drawing.forces import FORCE_NAMES
    from core.drawing.labels import box_distance
    from core.drawing.sheet import symbol
    _, items = drawn.areas[f"mechanism {k}"]
    texts = {t.text: t for t in items if isinstance(t, Text)}
    lines = [np.asarray(it.points, float) for it in items
             if isinstance(it, Polyline) and len(it.points) == 2 and not it.filled]
    out = []
    for (kk, name), (_, head) in drawn.shown.items():
        label = texts.get(symbol(FORCE_NAMES[name])[0]) if kk == k - 1 else None
        if label is None:
            continue
        box = np.array(label.box())
        led = any(np.hypot(*(a - head)) < 0.6 and box_distance(box, c[None])[0] < 0.5
                  for p in lines for a, c in ((p[0], p[1]), (p[1], p[0])))
        out.append((name, np.asarray(head, float), label, led))
    return out


@pytest.mark.parametrize("name, size", [("I", "A3"), ("II", "A3"), ("III", "A3"), ("II", "A2")])
def test_a_force_led_out_stands_off_the_other_arrowheads(name, size):
    """方案 III on A3 at φ = 270°: R_O2 went out on a leader to a spot 3.2 mm beside R_C's
    arrowhead, whose own name stood farther off, so the pair read the wrong way round; on
    A2 方案 II's G6 stood 0.6 mm from R_A's head. A force's name on a leader keeps at least
    its own height from every other force's arrowhead (the labels' search, leader spots
    first kept off every named point), at both positions the sheet draws; and every name
    is on the sheet, clear of every line and text (assert_laid_out)."""
    from core.drawing.labels import box_distance
    from core.linkage.geometry import from_dimensions
    l1, l2, l3, rod, n, g4, j4, g6, p, yp = TASK_BOOK[name]
    design = from_dimensions(l1, l2, l3, rod_ratio=rod)
    loads = MassProperties(lever_mass_kg=g4 / 9.81, lever_inertia_kg_m2=j4, ram_mass_kg=g6 / 9.81,
                           cut_force_N=p, cut_height_mm=yp, rod_mass_kg=8.0)
    drawn = forces_sheet(design, float(n), masses_for_design(design, loads), paper(size))
    assert_laid_out(drawn.sheet, drawn.areas)
    for k in (1, 2):
        found = _head_labels(drawn, k)
        assert len(found) == sum(1 for kk, _ in drawn.shown if kk == k - 1)      # every force named
        for force, head, label, led in found:
            if led:
                others = np.array([h for f, h, _, _ in found if f != force and not np.allclose(h, head)])
                clear = box_distance(np.array(label.box()), others).min()
                assert clear >= label.height - 1e-9, (k, force, round(float(clear), 2))
