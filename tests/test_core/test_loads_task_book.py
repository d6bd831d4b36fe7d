"""Loads as the task book states them (issue 41 item 2) and the ram on its guide's ends
(issue 40 item 3), checked against laws the solver does not use.

* A weight G typed in N is the mass G/g with the one g of core, and prints back as typed.
* The rotating parts reduced to the crank are Σ J·(ω/ω2)² (kinetic energy), and the
  flywheel the task book asks for, J_F − J_c, is rebuilt here from the torque curve
  integrated by the trapezoid rule (an energy balance the solver does not do).
* Where the guide's resultant falls outside the guide, the two end forces hold the ram in
  equilibrium (forces and moments about C rebuilt from the bodies' kinematics, 1e-9).
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from core.files.design_file import masses_from_dict, masses_to_dict
from core.forces.dynamics import solve_dynamics
from core.forces.masses import GRAVITY, MassProperties
from core.base.errors import DesignError
from core.forces.flywheel import summarize
from core.linkage.geometry import synthesize
from core.linkage.kinematics import shape, ram_origin

MM = 1e-3


def block_design():
    return synthesize(100.0, 1.4, 300.0)


def rod_design():
    return synthesize(100.0, 1.4, 300.0, guide="sagitta", rod_ratio=0.45)


def task_book(**extra) -> MassProperties:
    values = dict(lever_weight_N=200.0, lever_inertia_kg_m2=1.1, ram_weight_N=700.0,
                  cut_force_N=7000.0, cut_height_mm=80.0)
    values.update(extra)
    return MassProperties(**values)


# ---- weights ------------------------------------------------------------------------------

def test_a_weight_is_its_mass_under_cores_one_g_and_prints_as_typed():
    m = task_book()
    assert GRAVITY == 9.81
    assert m.lever_mass_kg == 200.0 / 9.81 and m.ram_mass_kg == 700.0 / 9.81
    assert m.weight("lever_mass_kg") == 200.0 and m.weight("ram_mass_kg") == 700.0
    # a mass given as a mass weighs m·g
    assert MassProperties(lever_mass_kg=20.0).weight("lever_mass_kg") == 20.0 * 9.81
    # the ram's weight alone on the block variant's guide: N = G6 (700 N, not 686.7 N)
    dyn = solve_dynamics(block_design(), np.radians([200.0, 300.0]), [60.0], task_book(cut_force_N=0.0))
    np.testing.assert_allclose(dyn.guide_normal, 700.0, rtol=1e-14)


def test_a_weight_and_a_mass_of_one_link_are_refused_naming_both():
    with pytest.raises(DesignError) as info:
        MassProperties(lever_mass_kg=20.0, lever_weight_N=200.0)
    assert "lever_mass_kg" in str(info.value) and "lever_weight_N" in str(info.value)
    with pytest.raises(DesignError) as info:
        MassProperties(ram_mass_kg=70.0, ram_weight_N=700.0)
    assert "ram_weight_N" in str(info.value)
    m = task_book()
    assert replace(m, cut_force_N=1.0).lever_mass_kg == m.lever_mass_kg   # replace keeps working
    with pytest.raises(DesignError):
        MassProperties(ram_weight_N=-1.0)


def test_the_design_file_keeps_a_weight_as_a_weight_and_old_files_read():
    m = task_book(rotors=((0.5, 1.0), (0.02, 15.0)), guide_length_mm=450.0)
    data = masses_to_dict(m)
    assert data["lever_weight_N"] == 200.0 and "lever_mass_kg" not in data
    assert data["ram_weight_N"] == 700.0 and "ram_mass_kg" not in data
    assert data["rotors"] == [{"J_kg_m2": 0.5, "speed_ratio": 1.0}, {"J_kg_m2": 0.02, "speed_ratio": 15.0}]
    assert masses_from_dict(data) == m
    old = {"lever_mass_kg": 20.0, "lever_inertia_kg_m2": 1.1, "ram_mass_kg": 70.0, "cut_force_N": 7000.0}
    read = masses_from_dict(old)
    assert read.lever_mass_kg == 20.0 and read.lever_weight_N is None and read.rotors == ()
    assert "lever_mass_kg" in masses_to_dict(read) and "lever_weight_N" not in masses_to_dict(read)
    with pytest.raises(DesignError):
        masses_from_dict({"lever_mass_kg": 20.0, "lever_weight_N": 200.0})
    with pytest.raises(DesignError):
        masses_from_dict({"rotors": [[0.5, 1.0]]})


# ---- the rotating parts and the flywheel ----------------------------------------------------

def test_rotating_parts_reduce_to_the_crank_by_their_kinetic_energy():
    rotors = ((0.5, 1.0), (0.02, 15.0), (0.003, 62.5))
    m = task_book(rotors=rotors)
    # ½ Σ J_i ω_i² = ½ J_c ω2²: at ω2 = 1 rad/s, ω_i = ratio
    kinetic = sum(0.5 * j * r ** 2 for j, r in rotors)
    assert m.rotor_inertia_kg_m2 == pytest.approx(2 * kinetic, rel=1e-15)
    assert m.rotor_inertia_kg_m2 == pytest.approx(0.5 + 0.02 * 225 + 0.003 * 3906.25, rel=1e-15)


def test_flywheel_needed_is_the_energy_balance_less_the_rotating_parts():
    design = block_design()
    rpm = 60.0
    rotors = ((0.5, 1.0), (0.02, 15.0))
    m = task_book(rotors=rotors)
    s = summarize(design, [rpm], m).speeds[0]
    # Energy balance by hand: the torque over a fine grid, less its mean, integrated.
    phi = np.linspace(0.0, 2 * math.pi, 72001)
    torque = solve_dynamics(design, phi, [rpm], m).crank_torque[0]
    mean = np.trapezoid(torque, phi) / (2 * math.pi)
    energy = np.concatenate([[0.0], np.cumsum((torque[1:] + torque[:-1] - 2 * mean) / 2 * np.diff(phi))])
    swing = energy.max() - energy.min()
    omega = rpm * math.pi / 30.0
    jf = swing / (omega ** 2 * m.delta)
    assert s.flywheel_inertia_kg_m2 == pytest.approx(jf, rel=2e-3)
    jc = 0.5 + 0.02 * 15.0 ** 2
    assert s.flywheel_needed
    assert s.flywheel_inertia_needed_kg_m2 == pytest.approx(jf - jc, rel=2e-3)
    assert s.flywheel_inertia_needed_kg_m2 == pytest.approx(s.flywheel_inertia_kg_m2 - jc, rel=1e-12)


def test_no_flywheel_is_needed_when_the_rotating_parts_hold_delta():
    design = block_design()
    plain = summarize(design, [60.0], task_book()).speeds[0]
    big = summarize(design, [60.0], task_book(rotors=((plain.flywheel_inertia_kg_m2 * 1.01, 1.0),)))
    s = big.speeds[0]
    assert not s.flywheel_needed
    assert s.flywheel_inertia_needed_kg_m2 == 0.0 and s.flywheel_inertia_net_kg_m2 == 0.0
    assert big.rotor_inertia_kg_m2 == pytest.approx(plain.flywheel_inertia_kg_m2 * 1.01)
    # without rotating parts nothing changes: J_F needed = J_F
    assert plain.flywheel_inertia_needed_kg_m2 == plain.flywheel_inertia_kg_m2


# ---- the ram on the guide's ends ------------------------------------------------------------

def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


@pytest.mark.parametrize("make", [block_design, rod_design], ids=["block", "rod"])
@pytest.mark.parametrize("length", [None, 120.0, 900.0])
def test_the_guide_ends_hold_the_ram_in_equilibrium(make, length):
    design = make()
    phi = np.radians(np.arange(0.0, 360.0, 2.0)) + 0.003
    masses = task_book(ram_cg_mm=(37.0, -24.0), guide_length_mm=length, idle_fraction=0.07)
    dyn = solve_dynamics(design, phi, [25.0, 63.0], masses)
    sh = shape(design, phi)
    w2 = (dyn.omega ** 2)[:, None]
    c = sh.ram_joint * MM
    # The guide, fixed in the frame: length (default H) centred on C's mid-travel.
    span = design.stroke if length is None else length
    centre = (ram_origin(design) + design.stroke / 2.0) * MM
    rear_x, front_x = centre - span * MM / 2.0, centre + span * MM / 2.0
    np.testing.assert_allclose(dyn.guide_rear_mm * MM, rear_x - c[0], atol=1e-12)
    np.testing.assert_allclose(dyn.guide_front_mm * MM, front_x - c[0], atol=1e-12)
    g = GRAVITY
    m6 = masses.ram_mass_kg
    dx, dy = (v * MM for v in masses.ram_cg_mm)
    a_c = w2 * sh.ram2 * MM                                       # the ram translates in x
    if design.rod is None:
        drive_x, drive_y, arm_y = dyn.b_x, dyn.b_y, sh.lever_tip[1] * MM - c[1]
    else:
        drive_x, drive_y, arm_y = dyn.c_x, dyn.c_y, 0.0
    tool_y = -masses.cut_height_mm * MM
    # Sum of the forces on the ram (y) and of their moments about C, the guide as its
    # two end forces at the ends' positions.
    fy = drive_y - m6 * g + dyn.guide_rear_N + dyn.guide_front_N
    fx = drive_x - dyn.cut_force - m6 * a_c
    moment = (cross((0.0, arm_y), (drive_x, drive_y))
              + cross((0.0, tool_y), (-dyn.cut_force, 0.0))
              + cross((dx, dy), (-m6 * a_c, -m6 * g))
              + (rear_x - c[0]) * dyn.guide_rear_N + (front_x - c[0]) * dyn.guide_front_N)
    scale = np.abs(np.stack([dyn.guide_rear_N, dyn.guide_front_N, drive_x])).max()
    assert np.abs(fy).max() <= 1e-9 * scale
    assert np.abs(fx).max() <= 1e-9 * scale
    assert np.abs(moment).max() <= 1e-9 * scale * design.lever * MM
    # Tilted exactly where the resultant's line leaves the guide; there the ends push
    # opposite ways (one on the upper way, one on the lower), elsewhere the same way.
    off = dyn.guide_offset_mm
    outside = ~(np.isfinite(off) & (off >= dyn.guide_rear_mm - 1e-6) & (off <= dyn.guide_front_mm + 1e-6))
    np.testing.assert_array_equal(dyn.guide_tilted, outside)
    assert np.all(dyn.guide_rear_N[outside] * dyn.guide_front_N[outside] <= 1e-9 * scale ** 2)
    assert np.all(dyn.guide_rear_N[~outside] * dyn.guide_front_N[~outside] >= -1e-9 * scale ** 2)


def test_the_seed_design_tilts_its_ram_while_cutting():
    # Issue 40 item 3: the resultant of the seed loads falls about a metre from C, far
    # outside a guide as long as the stroke; the ends carry it instead.
    design = block_design()
    dyn = solve_dynamics(design, np.radians([90.0, 300.0]), [60.0], task_book())
    assert abs(dyn.guide_offset_mm[0, 0]) > 3 * design.stroke
    assert dyn.guide_tilted[0, 0] and not dyn.guide_tilted[0, 1]
    assert dyn.guide_rear_N[0, 0] + dyn.guide_front_N[0, 0] == pytest.approx(700.0, rel=1e-12)
    with pytest.raises(DesignError):
        task_book(guide_length_mm=0.0)


def test_the_kinetostatic_sheet_prints_the_end_forces_and_the_flywheel_needed():
    from core.drawing.forces import ENGLISH, flywheel_rows, guide_rows
    design = block_design()
    m = task_book(rotors=((0.5, 1.0), (0.02, 15.0)))
    rows = dict(guide_rows(design, 60.0, m, (90.0, 270.0), ENGLISH))
    d = solve_dynamics(design, np.radians([90.0, 270.0]), [60.0], m)
    assert rows["Guide ends rear / front, φ = 90°"] == \
        f"{d.guide_rear_N[0, 0]:.4g} N / {d.guide_front_N[0, 0]:.4g} N"
    assert rows["Guide reaction N, φ = 270°"] == f"700 N, {d.guide_offset_mm[0, 1]:.4g} mm from C"
    s = summarize(design, [60.0], m)
    table = dict(flywheel_rows(s, m, ENGLISH))
    assert table[ENGLISH["J_c"]] == "5.000 kg·m²"     # 4 significant digits, core/base/figure_text.py
    assert table[ENGLISH["J_needed"]] == f"{s.speeds[0].flywheel_inertia_kg_m2 - 5.0:.4g} kg·m²"
    none = task_book(rotors=((1e5, 1.0),))
    assert dict(flywheel_rows(summarize(design, [60.0], none), none, ENGLISH))[ENGLISH["J_needed"]] \
        == ENGLISH["none_needed"]
