"""Rod variant (rod leading the tip) against seed 000's Example 1-4.

Conversion to our conventions: mirror x (seed cuts toward −x), so the seed's
counter-clockwise θ1 is our clockwise rotation and φ = θ1 + θ/2; ram
displacement = −(sE − sE(φ=0)), v = −vE, a = −aE; lever ψ = θ3 − 90°,
ψ̇ = ω3, ψ̈ = α3; rod angle λ = 180° − θ4, λ̇ = −ω4.
"""
import math
from pathlib import Path

import numpy as np
import pytest

from core.linkage.geometry import from_dimensions
from core.linkage.kinematics import solve

from seed000 import L1, L3, L4, L6, L61, six_bar
from locations import DATA

RPM_ONE_RAD_S = 60.0 / (2.0 * math.pi)  # ω1 = 1 rad/s as in the seed
REFERENCE = DATA / "seed000_six_bar_octave.txt"


@pytest.fixture(scope="module")
def design():
    return from_dimensions(L1 * 1000, L6 * 1000, L3 * 1000, guide=L61 * 1000,
                           rod=L4 * 1000, rod_side="leading")


def seed_theta1(design, phi):
    return phi - design.theta / 2.0


def test_design_implies_seed_geometry(design):
    # θ from the seed's data: sin(θ/2) = l1/l6.
    assert math.degrees(design.theta) == pytest.approx(2 * math.degrees(math.asin(125 / 275)))
    # The seed starts its loop at θ1 = 5.8119 − 2π, its rounded value of the limit
    # that begins cutting (−θ/2 in its frame).
    assert seed_theta1(design, 0.0) == pytest.approx(5.8119 - 2 * math.pi, abs=1e-3)


@pytest.mark.parametrize("phi_deg", [0.0, 17.0, 45.0, 90.0, 133.0, 180.0, 207.0, 240.0, 270.0, 300.0, 333.0, 359.0])
def test_matches_seed_formulas(design, phi_deg):
    phi = math.radians(phi_deg)
    ours = solve(design, np.array([0.0, phi]), [RPM_ONE_RAD_S])
    ref0 = six_bar(seed_theta1(design, 0.0))
    ref = six_bar(seed_theta1(design, phi))
    assert ours.ram_x[1] == pytest.approx(-(ref["sE"] - ref0["sE"]) * 1000, abs=1e-9)
    assert ours.ram_v[0, 1] == pytest.approx(-ref["vE"], abs=1e-12)
    assert ours.ram_a[0, 1] == pytest.approx(-ref["aE"], abs=1e-12)
    assert math.degrees(ours.lever_angle[1]) == pytest.approx(math.degrees(ref["theta3"]) - 90.0, abs=1e-9)
    assert ours.lever_omega[0, 1] == pytest.approx(ref["omega3"], abs=1e-12)
    assert ours.lever_alpha[0, 1] == pytest.approx(ref["alpha3"], abs=1e-12)
    assert ours.rod_angle[1] == pytest.approx(math.pi - ref["theta4"], abs=1e-12)
    assert ours.rod_omega[0, 1] == pytest.approx(-ref["omega4"], abs=1e-12)
    assert ours.rod_alpha[0, 1] == pytest.approx(-ref["alpha4"], abs=1e-12)
    # The block slides along the lever at the seed's v2 (same direction, away from O4).
    assert ours.slide_v[0, 1] == pytest.approx(ref["v2"], abs=1e-12)


def test_matches_octave_output(design):
    rows = np.loadtxt(REFERENCE, comments="#")
    theta1, sE, vE, aE, theta3, omega3, alpha3 = rows[:, 1:].T
    phi = theta1 + design.theta / 2.0
    ours = solve(design, phi, [RPM_ONE_RAD_S])
    # The Octave run starts at θ1 = 5.8119 − 2π, 4e-6 rad off our exact limit: compare x to row 0.
    assert ours.ram_x - ours.ram_x[0] == pytest.approx(-(sE - sE[0]) * 1000, abs=1e-6)
    assert ours.ram_v[0] == pytest.approx(-vE, abs=1e-9)
    assert ours.ram_a[0] == pytest.approx(-aE, abs=1e-9)
    assert ours.lever_angle == pytest.approx(theta3 - math.pi / 2, abs=1e-9)
    assert ours.lever_omega[0] == pytest.approx(omega3, abs=1e-9)
    assert ours.lever_alpha[0] == pytest.approx(alpha3, abs=1e-9)
