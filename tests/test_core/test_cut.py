"""One rule for the cutting force at a switch angle: the cut includes its ends, so every
row, position and ``--at`` angle at one crank angle shows the same loads."""
import json
import math
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

# What `shaper table` writes, in this process; test_cli_table.py runs the real command.
from cli_runner import shaper_run_in_process as shaper
from core.linkage.cut import SWITCH_TOLERANCE, cut_window, cutting
from core.linkage.designs import Designs
from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties
from core.base.errors import DesignError
from core.forces.flywheel import summarize
from core.linkage.geometry import from_dimensions, synthesize
from core.linkage.kinematics import solve
from core.space.optimize import optimize
from core.course_design.positions import position_table, positions
from core.linkage.spec import Spec

LOADS = ["--lever-mass", "30", "--lever-inertia", "2", "--ram-mass", "200",
         "--cut-force", "9000"]


def test_issue_table_rows_at_240_degrees_agree():
    """Position 9 (240°) and the row 'limit position, end of working stroke'
    (240.00000000000003°) had P = 9000 and 0 N, O2_x = 10 814 and −3 800 N."""
    run = shaper("table", "--dims", "120,240,450", "--guide", "420", "--rpm", "64", *LOADS,
                 "--idle", "0", "--json")
    assert run.returncode == 0, run.stderr
    rows = json.loads(run.stdout)
    ninth = next(r for r in rows if r["position"] == 9)
    end = next(r for r in rows if r["name"] == "limit_work_end")
    assert ninth["crank_deg"] == pytest.approx(end["crank_deg"], abs=1e-9)
    for key, value in ninth.items():
        if key not in ("position", "name", "crank_deg"):
            assert end[key] == pytest.approx(value, rel=1e-9, abs=1e-9), key
    assert end["cut_force_N"] == 9000.0      # the cut includes its end


def test_issue_at_0_360_720_agree_on_a_rod_design():
    run = shaper("table", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod-ratio", "0.4",
                 "--rpm", "40", *LOADS, "--idle", "0", "--positions", "1", "--at", "0,360,720",
                 "--json")
    assert run.returncode == 0, run.stderr
    rows = [r for r in json.loads(run.stdout) if r["name"] == "" and r["position"] is None]
    assert [r["cut_force_N"] for r in rows] == [9000.0] * 3
    for key in ("crank_torque_N_m", "O2_x_N", "B_x_N"):
        assert rows[1][key] == pytest.approx(rows[0][key], rel=1e-9, abs=1e-6)
        assert rows[2][key] == pytest.approx(rows[0][key], rel=1e-9, abs=1e-6)


def test_text_table_says_which_side_a_switch_row_shows():
    run = shaper("table", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40",
                 "--cut-force", "7000")
    assert run.returncode == 0, run.stderr
    assert "cut_start and cut_end rows show the cutting side" in run.stdout


@st.composite
def designs(draw):
    crank = draw(st.floats(40.0, 200.0))
    k = draw(st.floats(1.1, 2.5))
    theta = math.pi * (k - 1) / (k + 1)
    stroke = draw(st.floats(1.3, 3.5)) * 2 * crank * (1 + math.sin(theta / 2))
    rod = {}
    if draw(st.booleans()):
        rod = dict(rod_ratio=draw(st.floats(0.25, 1.5)),
                   rod_side=draw(st.sampled_from(["trailing", "leading"])))
    try:
        return synthesize(crank, k, stroke, **rod)
    except DesignError:
        assume(False)


@settings(max_examples=60, deadline=None)
@given(designs(), st.one_of(st.just(0.0), st.floats(0.0, 0.45)), st.integers(-2, 2))
def test_rows_at_one_angle_never_disagree(design, idle, turns):
    """Every special row equals an ``--at`` row at the same angle a whole number of turns
    away, in every column, cut force included."""
    special = positions(design, 4, idle_fraction=idle)
    angles = special.crank_deg[4:]
    where = positions(design, 4, extra_deg=list(angles + 360.0 * turns), idle_fraction=idle)
    masses = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70,
                            cut_force_N=7000, idle_fraction=idle)
    table = position_table(design, where, [40.0], masses)
    data = table.data
    k = where.crank_deg.size
    rows, twins = data[4:4 + angles.size], data[k - angles.size:k]
    keep = [i for i, c in enumerate(table.columns) if c not in ("crank_deg", "time_s")]
    scale = np.nanmax(np.abs(data[:, keep]), axis=0)
    np.testing.assert_allclose(twins[:, keep], rows[:, keep], rtol=0, atol=1e-7 * scale.max())
    p = table.columns.index("cut_force_N")
    names = where.name[4:4 + angles.size]
    for name in ("cut_start", "cut_end"):
        assert rows[names.index(name), p] == 7000.0          # the cut includes its ends


def test_cutting_is_a_closed_window_modulo_a_turn():
    design = synthesize(100.0, 1.4, 300.0)
    on, off = (float(v[0]) for v in cut_window(Designs.of(design), 0.05))
    tol = SWITCH_TOLERANCE
    phi = np.array([on - 10 * tol, on, on + tol / 2, off, off + tol / 2, off + 10 * tol,
                    on + 2 * math.pi, off - 4 * math.pi])
    assert cutting(design, phi, 0.05).tolist() == [False, True, True, True, True, False,
                                                   True, True]
    # idle 0: both dead points cut, whichever turn the angle is given in
    end = math.pi + design.theta
    assert cutting(design, np.array([0.0, 2 * math.pi, -2 * math.pi, end, end - 2 * math.pi,
                                     end + 1e-6]), 0.0).tolist() == [True] * 5 + [False]


def test_solve_dynamics_uses_the_rule_at_the_dead_points():
    """With idle 0 the cut state followed the round-off sign of the ram velocity."""
    design = from_dimensions(120.0, 240.0, 450.0, guide=420.0)
    masses = MassProperties(cut_force_N=9000.0, idle_fraction=0.0)
    end = math.pi + design.theta
    phi = np.array([0.0, 2 * math.pi, 4 * math.pi, end, math.radians(240.0)])
    dyn = solve_dynamics(design, phi, [64.0], masses)
    assert dyn.cut_force[0].tolist() == [9000.0] * 5


def test_flywheel_optimum_against_a_fine_grid_of_exact_evaluations():
    """The optimizer chased the grid's noise (it reported 898.064 where the design's
    J_F was 898.454). Now the reported value is the design's own, at any sampling step,
    and no point of a fine grid of exact evaluations is better."""
    loads = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                           rod_mass_kg=6.0, cut_force_N=7000.0, cut_height_mm=80.0)
    spec = Spec(crank=100.0, time_ratio=1.4, stroke=300.0, variant="rod", rod_ratio=0.3,
                guide_rule="height", guide_height=550.0)
    bounds = (495.0, 600.0)
    best = optimize(spec, {"guide": bounds}, "flywheel", [40.0], loads)
    design = replace(spec, guide_height=float(best.x[0])).design()
    fine = summarize(design, [40.0], loads, intervals=36_000).speeds[0].flywheel_inertia_kg_m2
    assert best.value == pytest.approx(fine, rel=1e-11)
    grid = np.linspace(*bounds, 1001)
    values = [summarize(replace(spec, guide_height=float(g)).design(), [40.0], loads,
                        peaks=False).speeds[0].flywheel_inertia_kg_m2 for g in grid]
    assert best.value <= min(values) * (1 + 1e-12)
    # Exact values are smooth in the guide height: the grid's best neighbours the optimum.
    assert abs(best.x[0] - grid[int(np.argmin(values))]) <= 2 * (grid[1] - grid[0])


def test_json_rows_print_round_off_zeros_as_zero():
    """As the CSV does: the limit positions' velocity was −2.1e-16 m/s, torques 1e-13 N·m."""
    run = shaper("table", "--dims", "120,240,450", "--guide", "420", "--rpm", "64", *LOADS,
                 "--idle", "0", "--json")
    rows = json.loads(run.stdout)
    first = next(r for r in rows if r["position"] == 1)
    assert first["ram_v_m_s"] == 0.0 and first["lever_omega_rad_s"] == 0.0
    assert first["crank_torque_N_m"] == 0.0 and first["power_W"] == 0.0
    tiny = [(r["position"], k, v) for r in rows for k, v in r.items()
            if isinstance(v, float) and 0.0 < abs(v) < 1e-9]
    assert tiny == []
