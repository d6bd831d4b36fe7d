"""The positions table: numbered rows equal the curves, special rows are what their names say."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from core.linkage.cut import cutting_force
from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties
from core.base.errors import DesignError
from core.linkage.geometry import Design, synthesize
from core.files.io import curve_table
from core.linkage.kinematics import shape, solve
from core.linkage.metrics import analyze
from core.course_design.positions import (SPECIAL_NAMES, column_texts, display_values, position_table,
                            positions, positions_csv, special_angles, table_records)
from test_properties import designs

LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70,
                       cut_force_N=7000, cut_height_mm=80, idle_fraction=0.05)


def classic(**kw):
    return synthesize(100, 1.4, 300, **kw)


def test_numbered_positions_start_at_the_working_limit_and_are_equally_spaced():
    where = positions(classic(), 12, [45, 100])
    assert where.crank_deg[:12].tolist() == [30.0 * i for i in range(12)]
    assert where.number.tolist() == list(range(1, 13)) + [0] * 8
    assert where.name == ("",) * 12 + SPECIAL_NAMES + ("", "")
    assert where.crank_deg[-2:].tolist() == [45.0, 100.0]


@pytest.mark.parametrize("kw", [{}, {"rod_ratio": 0.3}, {"rod_ratio": 0.5, "rod_side": "leading"}])
def test_rows_equal_the_curves_and_dynamics_at_the_same_angles(kw):
    design = classic(**kw)
    where = positions(design, 12, [45])
    table = position_table(design, where, [40, 60], LOADS)
    phi = np.radians(where.crank_deg)
    names, curves = curve_table(solve(design, phi, [40, 60]))
    dyn = solve_dynamics(design, phi, [40, 60], LOADS)
    for i, name in enumerate(names):
        np.testing.assert_allclose(table.data[:, table.columns.index(name)], curves[:, i],
                                   rtol=1e-12, atol=1e-12)
    torque = table.data[:, table.columns.index("crank_torque_N_m")]
    np.testing.assert_array_equal(torque, dyn.crank_torque.reshape(-1))
    assert table.data.shape[0] == 2 * where.crank_deg.size


def test_kinematics_only_without_loads():
    table = position_table(classic(), positions(classic()), [40])
    assert "crank_torque_N_m" not in table.columns
    assert table.columns[:2] == ("rpm", "crank_deg")


def test_classic_special_positions_by_hand():
    """Block variant, K = 1.4: θ = 30°, limits at 0 and 210°; the lever (and the ram)
    turns fastest when the crank pin crosses the line O2O4, at 90° + θ/2 and 270° + θ/2."""
    special = special_angles(classic(), 0.05)
    assert special["limit_work_start"] == pytest.approx(0.0, abs=1e-9)
    assert special["limit_work_end"] == pytest.approx(210.0, abs=1e-9)
    assert special["v_work_max"] == pytest.approx(105.0, abs=1e-9)
    assert special["v_return_max"] == pytest.approx(285.0, abs=1e-9)
    # Block variant, by hand: x = L3·sin ψ + H/2, and the crank pin A = (L1 cos β, L2 + L1 sin β),
    # β = 180° + θ/2 − φ, lies on the lever line: L1·cos(β + ψ) = L2·sin ψ.
    design = classic()
    h = design.stroke
    psi = math.asin((0.05 * h - h / 2) / design.lever)
    betas = [-psi + s * math.acos(design.frame * math.sin(psi) / design.crank) for s in (1, -1)]
    phis = [math.degrees(math.pi + design.theta / 2 - b) % 360 for b in betas]
    phi = [p for p in phis if p < 210][0]                          # the one on the working stroke
    assert special["cut_start"] == pytest.approx(phi % 360, abs=1e-9)


def test_special_positions_against_cycle_metrics():
    for design in (classic(), classic(rod_ratio=0.3), classic(rod_ratio=0.4, rod_side="leading")):
        metrics = analyze(design, [40])
        where = positions(design, 12, (), LOADS.idle_fraction)
        row = {name: position_table(design, where, [40]).row(0, 12 + i)
               for i, name in enumerate(SPECIAL_NAMES)}
        assert row["limit_work_start"]["crank_deg"] == metrics.work_start_deg
        assert row["limit_work_end"]["crank_deg"] == pytest.approx(metrics.work_end_deg, abs=1e-12)
        assert row["limit_work_end"]["ram_x_mm"] == pytest.approx(metrics.stroke_mm, rel=1e-12)
        for name in ("limit_work_start", "limit_work_end"):
            assert abs(row[name]["ram_v_m_s"]) < 1e-12
        v = metrics.speeds[0]
        for name in ("v_work_max", "v_return_max"):
            assert abs(row[name]["ram_a_m_s2"]) < 1e-9 * v.a_max_m_s2
        assert row["cut_start"]["ram_x_mm"] == pytest.approx(0.05 * design.stroke, rel=1e-12)
        assert row["cut_end"]["ram_x_mm"] == pytest.approx(0.95 * design.stroke, rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(designs(), st.floats(0.0, 0.45))
def test_special_positions_are_exact_for_random_designs(case, idle):
    design, _, stroke = case
    special = special_angles(design, idle)
    phi = np.radians([special[n] for n in SPECIAL_NAMES])
    sh = shape(design, phi)
    x = sh.ram_joint[0] - shape(design, np.zeros(1)).ram_joint[0, 0]
    scale = np.abs(shape(design, np.linspace(0, 2 * np.pi, 721)).ram1).max()
    assert np.abs(sh.ram1[:2]).max() < 1e-9 * scale                # dead points
    assert x[2] == pytest.approx(idle * stroke, abs=1e-9 * stroke)
    assert x[3] == pytest.approx((1 - idle) * stroke, abs=1e-9 * stroke)
    # speed peaks: local extrema of the velocity, checked by finite steps on both sides
    h = 1e-4
    near = shape(design, np.concatenate([phi[4:] - h, phi[4:] + h])).ram1
    assert near[0] <= sh.ram1[4] and near[2] <= sh.ram1[4]
    assert near[1] >= sh.ram1[5] and near[3] >= sh.ram1[5]
    assert sh.ram1[4] > 0 > sh.ram1[5]
    # the cut (dynamics) switches on and off at cut_start / cut_end
    if idle > 0:
        loads = MassProperties(cut_force_N=1.0, idle_fraction=idle)
        around = np.concatenate([phi[2:4] - 1e-7, phi[2:4] + 1e-7])
        cut = cutting_force(design, shape(design, around), loads)
        assert cut.tolist() == [0.0, 1.0, 1.0, 0.0]


@settings(max_examples=60, deadline=None)
@given(designs(), st.floats(1.0, 500.0))
def test_speed_rows_are_analyzes_peaks(case, rpm):
    """The table's speed at the v_work_max / v_return_max rows is the peak ``analyze``
    reports (one code path finds both), evaluated here by ``solve`` at the row's angle."""
    design = case[0]
    where = positions(design, 12)
    table = position_table(design, where, [rpm])
    v = analyze(design, [rpm]).speeds[0]
    rows = {name: table.row(0, 12 + i) for i, name in enumerate(SPECIAL_NAMES)}
    assert rows["v_work_max"]["ram_v_m_s"] == pytest.approx(v.v_work_max_m_s, rel=1e-9)
    assert -rows["v_return_max"]["ram_v_m_s"] == pytest.approx(v.v_return_max_m_s, rel=1e-9)


def test_bad_counts_and_angles_name_the_option():
    with pytest.raises(DesignError) as err:
        positions(classic(), 0)
    assert err.value.parameter == "positions"
    with pytest.raises(DesignError) as err:
        positions(classic(), 12.5)
    assert err.value.parameter == "positions"
    with pytest.raises(DesignError) as err:
        positions(classic(), 12, [float("nan")])
    assert err.value.parameter == "at"
    with pytest.raises(DesignError) as err:
        positions(classic(), 12, [], 0.5)
    assert err.value.parameter == "idle_fraction"


def test_records_and_csv_carry_position_and_name():
    design = classic()
    table = position_table(design, positions(design, 4, [45]), [40, 60], LOADS)
    records = table_records(table)
    assert len(records) == 2 * (4 + 6 + 1)
    assert [r["position"] for r in records[:5]] == [1, 2, 3, 4, None]
    assert records[4]["name"] == "limit_work_start" and records[10]["name"] == ""
    assert records[11]["rpm"] == 60.0 and records[11]["crank_deg"] == 0.0
    lines = positions_csv(table).splitlines()
    assert lines[0].startswith("position,name,rpm,crank_deg,")
    assert lines[5].startswith(",limit_work_start,40,")
    assert len(lines) == 1 + len(records)


def test_display_cleans_round_off_only():
    data = np.array([[1e-17, 5.0, np.nan], [2.0, -3e-8, 1.0]])
    shown = display_values(data)
    assert shown[0, 0] == 0.0 and shown[1, 1] == -3e-8 and np.isnan(shown[0, 2])
    # one number of decimals per column: 5 significant digits of its largest value
    assert column_texts(np.array([0.49913332, 834.29, -0.0000031, float("nan")])) == \
        ["0.50", "834.29", "0.00", ""]
    assert column_texts(np.array([0.49913332, -0.84773, 0.0])) == ["0.49913", "-0.84773", "0.00000"]
    assert column_texts(np.array([12345.6, 1.0])) == ["12346", "1"]


@settings(max_examples=60, deadline=None)
@given(designs())
def test_margins_are_positive_and_vanish_at_the_rule(case):
    """Every accepted design clears every rule; moving a length by its margin reaches the rule."""
    from core.linkage.geometry import Design
    from core.linkage.margins import margins
    design = case[0]
    found = {m.rule: m for m in margins(design)}
    assert all(m.margin >= 0 for m in found.values())
    lever = found["lever_reach"]
    with pytest.raises(DesignError):
        Design(design.crank, design.frame, design.lever - lever.margin * 1.0001 - 1e-9,
               design.guide, design.rod, design.rod_side)
    if design.rod is not None:
        reach = found["rod_reach"]
        with pytest.raises(DesignError):
            Design(design.crank, design.frame, design.lever, design.guide,
                   design.rod - reach.margin * 1.0001 - 1e-9, design.rod_side)


def test_vanishing_idle_margin_gives_the_limits():
    """An idle margin below round-off (found by hypothesis) must not bisect a bracket without
    a sign change: the cut then starts and ends at the limit positions."""
    design = synthesize(20.0, 1.05, 200.0)
    special = special_angles(design, 2.6e-295)
    # x is flat (quadratic) at a dead point, so round-off of 1e-14 mm in x is ~1e-6° in φ
    assert special["cut_start"] == pytest.approx(special["limit_work_start"] % 360, abs=1e-4)
    assert special["cut_end"] == pytest.approx(special["limit_work_end"], abs=1e-4)


def test_cut_end_found_when_the_grid_sample_on_the_dead_point_rounds_past_it():
    """Found by hypothesis: with K = 2 the energy grid's sample at 240° lies one ulp past
    π + θ, so the end of a cut that ends 2e-6 rad before the dead point was put on the dead
    point itself. The ram just before cut_end must still be cutting."""
    design = Design(crank=20.0, frame=40.00000000000001, lever=120.00000000000001,
                    guide=103.92304845413265, rod=None, rod_side="trailing")
    idle = 1e-12
    end = math.radians(special_angles(design, idle)["cut_end"])
    assert end < math.pi + design.theta - 1e-6
    loads = MassProperties(cut_force_N=1.0, idle_fraction=idle)
    cut = cutting_force(design, shape(design, np.array([end - 1e-7, end + 1e-7])), loads)
    assert cut.tolist() == [1.0, 0.0]
