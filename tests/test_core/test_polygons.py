"""Vector polygons: each closes, and each vector equals the kinematics and finite differences."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties
from core.linkage.geometry import synthesize
from core.linkage.kinematics import rpm_to_omega, shape, solve
from core.forces.polygons import (acceleration_polygon, force_polygon, nice_scale, paper, polygons,
                           velocity_polygon)
from test_properties import designs

LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70,
                       cut_force_N=7000, cut_height_mm=80, rod_mass_kg=4.0, ram_cg_mm=(30, -20))
DESIGNS = [synthesize(100, 1.4, 300), synthesize(100, 1.4, 300, rod_ratio=0.3),
           synthesize(100, 1.6, 320, rod_ratio=0.4, rod_side="leading", guide="sagitta")]


def vec(polygon, key):
    return np.array(next(v.value for v in polygon.vectors if v.key == key))


@settings(max_examples=80, deadline=None)
@given(designs(), st.floats(0, 360), st.floats(1, 300))
def test_velocity_and_acceleration_polygons_close(case, phi, rpm):
    design = case[0]
    for polygon in (velocity_polygon(design, phi, rpm), acceleration_polygon(design, phi, rpm)):
        assert polygon.closure_error() <= 1e-12 * max(polygon.largest(), 1e-300)


@pytest.mark.parametrize("design", DESIGNS)
@pytest.mark.parametrize("phi", [0.0, 37.0, 105.0, 200.0, 290.0])
def test_force_polygon_closes(design, phi):
    loads = LOADS if design.rod is not None else MassProperties(**{**LOADS.__dict__, "rod_mass_kg": 0})
    polygon = force_polygon(design, phi, 45, loads)
    assert polygon.closure_error() <= 1e-9 * polygon.largest()
    assert vec(polygon, "R_B").tolist() == pytest.approx(
        [float(getattr(solve_dynamics(design, np.radians([phi]), [45], loads), f)[0, 0])
         for f in ("b_x", "b_y")])


@pytest.mark.parametrize("design", DESIGNS)
@pytest.mark.parametrize("phi", [20.0, 100.0, 250.0, 333.0])
def test_vectors_equal_the_kinematics(design, phi):
    m = solve(design, np.radians([phi]), [60])
    v, a = velocity_polygon(design, phi, 60), acceleration_polygon(design, phi, 60)
    w = float(rpm_to_omega(60))
    s = float(m.shape.slide[0]) / 1000
    assert np.linalg.norm(vec(v, "v_A3")) == pytest.approx(w * design.crank / 1000)
    assert vec(v, "v_C").tolist() == pytest.approx([m.ram_v[0, 0], 0.0])
    assert np.linalg.norm(vec(v, "v_A4A3")) == pytest.approx(abs(m.slide_v[0, 0]))
    assert np.linalg.norm(vec(v, "v_A4")) == pytest.approx(abs(m.lever_omega[0, 0]) * s)
    assert np.linalg.norm(vec(a, "a^k_A4A3")) == pytest.approx(abs(m.coriolis[0, 0]))
    assert np.linalg.norm(vec(a, "a^n_A4")) == pytest.approx(m.lever_omega[0, 0] ** 2 * s)
    assert np.linalg.norm(vec(a, "a^t_A4")) == pytest.approx(abs(m.lever_alpha[0, 0]) * s)
    assert np.linalg.norm(vec(a, "a_A3")) == pytest.approx(w * w * design.crank / 1000)
    assert vec(a, "a_C").tolist() == pytest.approx([m.ram_a[0, 0], 0.0])
    # b lies on the line p–a4 at O4B/O4A of its length (both polygons)
    np.testing.assert_allclose(vec(v, "v_B"), vec(v, "v_A4") * design.lever / 1000 / s, atol=1e-14)
    np.testing.assert_allclose(np.array(a.points["b'"]), np.array(a.points["a4'"]) * design.lever / 1000 / s,
                               atol=1e-12)
    if design.rod is not None:
        assert np.linalg.norm(vec(v, "v_CB")) == pytest.approx(abs(m.rod_omega[0, 0]) * design.rod / 1000)
        assert np.linalg.norm(vec(a, "a^n_CB")) == pytest.approx(m.rod_omega[0, 0] ** 2 * design.rod / 1000)
        assert np.linalg.norm(vec(a, "a^t_CB")) == pytest.approx(abs(m.rod_alpha[0, 0]) * design.rod / 1000)


@pytest.mark.parametrize("design", DESIGNS)
@pytest.mark.parametrize("phi", [20.0, 140.0, 260.0])
def test_vectors_equal_finite_differences_of_positions(design, phi):
    """Positions at φ ± k·h (time steps h/ω), differenced: absolute and relative motions."""
    rpm = 50.0
    w = float(rpm_to_omega(rpm))
    h = 1e-3
    offsets = np.array([-2, -1, 0, 1, 2]) * h
    sh = shape(design, np.radians(phi) + offsets)
    d1 = np.array([1, -8, 0, 8, -1]) / (12 * h) * w / 1000        # d/dt, mm → m
    d2 = np.array([-1, 16, -30, 16, -1]) / (12 * h * h) * w * w / 1000
    v, a = velocity_polygon(design, phi, rpm), acceleration_polygon(design, phi, rpm)
    for point, v_key, a_key in ((sh.crank_pin, "v_A3", "a_A3"), (sh.lever_tip, "v_B", "a_B"),
                                (sh.ram_joint, "v_C", "a_C")):
        np.testing.assert_allclose(point @ d1, vec(v, v_key), atol=1e-8)
        np.testing.assert_allclose(point @ d2, vec(a, a_key), atol=1e-6)
    # the lever point at the block's current distance (A3), and the slide of A3 relative to A2
    s0 = sh.slide[2]
    u = sh.crank_pin / sh.slide
    np.testing.assert_allclose((s0 * u) @ d1, vec(v, "v_A4"), atol=1e-8)
    rel = (s0 - sh.slide) * u                                      # A3 − A2 seen along the lever
    np.testing.assert_allclose(rel @ d1, vec(v, "v_A4A3"), atol=1e-8)


def test_block_variant_relative_motion_is_vertical():
    design = DESIGNS[0]
    v, a = velocity_polygon(design, 70, 40), acceleration_polygon(design, 70, 40)
    assert vec(v, "v_CB")[0] == 0.0 and vec(a, "a^r_CB")[0] == 0.0
    assert v.closure_error() < 1e-15 and a.closure_error() < 1e-14


def test_force_polygon_by_hand_on_the_return_stroke():
    """Block variant, no cut and no gravity on the return: R_B is the ram's inertia force
    reversed, N = 0 (and zero forces are left out)."""
    design = DESIGNS[0]
    loads = MassProperties(ram_mass_kg=70, gravity=False)
    polygon = force_polygon(design, 250, 40, loads)
    m = solve(design, np.radians([250]), [40])
    assert [v.key for v in polygon.vectors] == ["F_I6", "R_B"]
    assert vec(polygon, "R_B").tolist() == pytest.approx([70 * m.ram_a[0, 0], 0.0])


def test_polygons_without_loads_skip_the_force_polygon():
    assert set(polygons(DESIGNS[1], 30, 40)) == {"velocity", "acceleration"}
    assert set(polygons(DESIGNS[1], 30, 40, LOADS)) == {"velocity", "acceleration", "force"}


@settings(max_examples=200, deadline=None)
@given(st.floats(1e-6, 1e7), st.floats(20, 200))
def test_nice_scale_is_round_and_fits(largest, target):
    mu = nice_scale(largest, target)
    mantissa = mu / 10 ** math.floor(math.log10(mu) + 1e-12)
    assert any(abs(mantissa - m) < 1e-9 for m in (1, 2, 2.5, 5))
    assert largest / mu <= target * (1 + 1e-9)
    assert largest / mu > target / 2.5 * (1 - 1e-9)      # the next nice scale down would not fit


def test_paper_is_value_over_scale():
    v = velocity_polygon(DESIGNS[0], 100, 40)
    pts = paper(v, 0.01)
    assert pts["c"][0] == pytest.approx(v.points["c"][0] / 0.01)
