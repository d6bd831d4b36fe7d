"""The lever's force polygon: its inertia force from the kinematics and the joint forces
from core.forces.dynamics close, which checks the lever's equilibrium in core.forces.dynamics."""
import numpy as np
import pytest

from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties, masses_for_design
from core.linkage.geometry import synthesize
from core.forces.polygons import lever_force_polygon

LOADS = dict(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
             cut_height_mm=80, block_mass_kg=3, lever_cg_mm=250)
DESIGNS = {"block": synthesize(100, 1.4, 300),
           "rod": synthesize(100, 1.46, 312, rod_ratio=0.3),
           "leading": synthesize(150, 1.2, 600, rod_ratio=0.8, rod_side="leading")}


def masses(design, **extra):
    rod = {"rod_mass_kg": 8.0} if design.rod is not None else {}
    return masses_for_design(design, MassProperties(**{**LOADS, **extra}, **rod))


@pytest.mark.parametrize("name", sorted(DESIGNS))
@pytest.mark.parametrize("angle", [0.0, 17.0, 90.0, 181.5, 250.0, 333.0])
def test_closes_and_holds_the_joint_forces(name, angle):
    design = DESIGNS[name]
    m = masses(design)
    poly = lever_force_polygon(design, angle, 60.0, m)
    assert poly.closure_error() < 1e-9 * poly.largest()
    d = solve_dynamics(design, np.radians([angle]), [60.0], m)
    by_key = {v.key: v.value for v in poly.vectors}
    assert by_key["R_O4"] == pytest.approx((d.o4_x[0, 0], d.o4_y[0, 0]))
    assert by_key["R_4B"] == pytest.approx((-d.b_x[0, 0], -d.b_y[0, 0]))
    assert by_key["G_4"] == pytest.approx((0.0, -20 * m.g))


def test_inertia_force_against_finite_differences():
    """F_I4 = −m4·a_S4 with a_S4 the second time derivative of the centre of mass's
    position, here by central differences of the positions (step 1e-4 rad)."""
    design, m = DESIGNS["rod"], masses(DESIGNS["rod"])
    angle, rpm, h = 123.0, 60.0, 1e-4
    from core.linkage.kinematics import rpm_to_omega, shape
    phi = np.radians(angle) + np.array([-h, 0.0, h])
    tip = shape(design, phi).lever_tip                          # (2, 3) mm, along the lever
    cg = tip * (m.lever_cg(design) / design.lever) * 1e-3        # m
    a = (cg[:, 2] - 2 * cg[:, 1] + cg[:, 0]) / h ** 2 * rpm_to_omega(rpm) ** 2
    poly = lever_force_polygon(design, angle, rpm, m)
    f_i4 = dict((v.key, v.value) for v in poly.vectors)["F_I4"]
    assert f_i4 == pytest.approx(tuple(-20.0 * a), rel=1e-5)


def test_without_gravity_and_lever_mass_only_the_joint_forces_remain():
    design = DESIGNS["block"]
    m = masses(design, lever_mass_kg=0.0, lever_inertia_kg_m2=0.0)
    keys = [v.key for v in lever_force_polygon(design, 45.0, 40.0, m).vectors]
    assert keys == ["R_A", "R_O4", "R_4B"]
