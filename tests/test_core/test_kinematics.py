"""Closed-form rates against high-order finite differences of our own positions.

Finite differences are used here only, as a check; core never differences.
"""
import math

import numpy as np
import pytest

from core.linkage.geometry import synthesize
from core.linkage.kinematics import crank_angles, rpm_to_omega, shape, solve

DESIGNS = {
    "block": synthesize(100, 1.4, 300),
    "rod-trailing": synthesize(100, 1.4, 300, rod_ratio=0.3, guide="sagitta"),
    "rod-leading": synthesize(80, 1.8, 380, rod=160, rod_side="leading"),
    "rod-high-guide": synthesize(120, 1.6, 450, rod_ratio=0.5, guide=640.0),
}
H = 1e-3  # rad


def fd1(f, phi):
    """Sixth-order central difference of f at phi (vectorized)."""
    c = [(3, 1 / 60), (2, -3 / 20), (1, 3 / 4)]
    return sum(w * (f(phi + k * H) - f(phi - k * H)) for k, w in c) / H


def fd2(f, phi):
    c = [(3, 1 / 90), (2, -3 / 20), (1, 3 / 2)]
    return (sum(w * (f(phi + k * H) + f(phi - k * H)) for k, w in c) - 49 / 18 * f(phi)) / H ** 2


@pytest.mark.parametrize("name", DESIGNS)
def test_rates_match_finite_differences(name):
    design = DESIGNS[name]
    phi = np.linspace(0, 2 * math.pi, 97)
    rpm = np.array([40.0, 73.0])
    motion = solve(design, phi, rpm)
    w = rpm_to_omega(rpm)[:, None]
    x = lambda p: solve(design, p, [1]).ram_x  # noqa: E731
    psi = lambda p: shape(design, p).lever  # noqa: E731
    scale = np.abs(fd1(x, phi)).max()
    assert np.allclose(motion.ram_v, w * fd1(x, phi) / 1000, atol=1e-7 * scale * w.max() / 1000)
    assert np.allclose(motion.ram_a, w ** 2 * fd2(x, phi) / 1000, rtol=0, atol=2e-5 * w.max() ** 2)
    assert np.allclose(motion.lever_omega, w * fd1(psi, phi), atol=1e-9)
    assert np.allclose(motion.lever_alpha, w ** 2 * fd2(psi, phi), atol=1e-6)
    s = lambda p: shape(design, p).slide  # noqa: E731
    assert np.allclose(motion.slide_v, w * fd1(s, phi) / 1000, atol=1e-9)
    if design.rod is not None:
        lam = lambda p: shape(design, p).rod  # noqa: E731
        assert np.allclose(motion.rod_omega, w * fd1(lam, phi), atol=1e-8)
        assert np.allclose(motion.rod_alpha, w ** 2 * fd2(lam, phi), atol=1e-5)


@pytest.mark.parametrize("name", DESIGNS)
def test_joints_keep_link_lengths(name):
    design = DESIGNS[name]
    sh = shape(design, crank_angles(0.5))
    a, b, c = sh.crank_pin, sh.lever_tip, sh.ram_joint
    assert np.allclose(np.hypot(a[0], a[1] - design.frame), design.crank)
    assert np.allclose(np.hypot(*b), design.lever)
    # A lies on the lever line O4B.
    assert np.allclose(a[0] * b[1] - a[1] * b[0], 0, atol=1e-9 * design.lever ** 2)
    assert np.allclose(c[1], design.guide)
    if design.rod is not None:
        assert np.allclose(np.hypot(*(c - b)), design.rod)
    else:
        assert np.allclose(c[0], b[0])


@pytest.mark.parametrize("name", DESIGNS)
def test_coriolis_is_twice_lever_rate_times_sliding_speed(name):
    motion = solve(DESIGNS[name], crank_angles(5), [50])
    assert np.allclose(motion.coriolis, 2 * motion.lever_omega * motion.slide_v)


def test_rates_scale_with_speed():
    design = DESIGNS["rod-trailing"]
    m = solve(design, crank_angles(1), [30, 60])
    assert np.allclose(m.ram_v[1], 2 * m.ram_v[0])
    assert np.allclose(m.ram_a[1], 4 * m.ram_a[0])
    assert np.allclose(m.time[0], 2 * m.time[1])
    assert m.time[0, -1] == pytest.approx(2.0)  # one revolution at 30 r/min


def test_angle_grid():
    grid = np.degrees(crank_angles(1))
    assert grid.size == 361 and grid[0] == 0 and grid[-1] == 360
    grid = np.degrees(crank_angles(7))
    assert grid[-1] == 360 and np.all(np.diff(grid) > 0)
    assert crank_angles(0.01).size == 36001


def test_block_peak_speeds_match_hand_calculation():
    # With the crank pin on the line O2O4 the lever turns at ω·L1/(L2 ± L1); the ram
    # (block variant) then moves at L3 times that: the textbook quick-return check.
    from core.linkage.metrics import analyze
    d = synthesize(100, 1.4, 300)
    w = 40 * 2 * math.pi / 60
    s = analyze(d, [40]).speeds[0]
    assert s.v_work_max_m_s == pytest.approx(w * d.lever * d.crank / (d.frame + d.crank) / 1000, rel=1e-9)
    assert s.v_return_max_m_s == pytest.approx(w * d.lever * d.crank / (d.frame - d.crank) / 1000, rel=1e-9)
    assert s.v_work_mean_m_s == pytest.approx(0.300 / 0.875, rel=1e-12)


@pytest.mark.parametrize("name", DESIGNS)
def test_one_angle_as_a_scalar_gives_the_same_shape(name):
    """shape() writes its pairs and the rod's terms in place; one angle given as a
    number (no angle axis) must still work and agree with the same angle in an array."""
    import dataclasses
    design = DESIGNS[name]
    for phi in (0.5, 4.0):
        one, row = shape(design, phi), shape(design, np.array([phi]))
        for field in dataclasses.fields(one):
            a, b = getattr(one, field.name), getattr(row, field.name)
            if a is None:
                assert b is None
            else:
                assert np.array_equal(np.asarray(a), np.asarray(b)[..., 0]), field.name


@pytest.mark.parametrize("name", DESIGNS)
def test_ram_zero_is_the_same_whether_or_not_the_angles_start_at_zero(name):
    """solve takes the ram's zero from its first sample when the angles start at φ = 0
    and from ram_origin otherwise: both must give the same displacement, to the bit."""
    design = DESIGNS[name]
    phi = crank_angles(1)
    assert phi[0] == 0.0
    from_first = solve(design, phi, [40]).ram_x
    apart = solve(design, phi[1:], [40]).ram_x
    assert from_first[0] == 0.0
    assert np.array_equal(from_first[1:], apart)
