"""The teeth as drawn (issue 35, item 3): the flank points the rack generates lie on the
involute of the base circle, the fillet reaches the root circle, and nothing is cut from the
tooth that the rack does not cut."""
from __future__ import annotations

import math

import numpy as np
import pytest

from core.gear import GearPairInputs, design_pair
from core.gear.profile import flank, rack_tip_radius, tooth_outline

PAIRS = [dict(z1=13, z2=40, module_mm=6.0), dict(z1=12, z2=12, module_mm=10.0, centre_mm=130.0),
         dict(z1=20, z2=40, module_mm=4.0, x1=0.0, x2=0.0), dict(z1=10, z2=36, module_mm=5.0,
                                                                 x1=0.45, x2=0.2)]


def _on_involute(points: np.ndarray, rb: float) -> np.ndarray:
    """How far each point is from the involute of the circle rb that passes through the
    first of them, by the polar equation θ = θ0 + tan β − β, cos β = rb / ρ (independent
    of core.gear: θ0 from the first point)."""
    rho = np.hypot(points[:, 0], points[:, 1])
    beta = np.arccos(np.minimum(rb / rho, 1.0))            # N itself: ρ = rb to the last bit
    theta = np.arctan2(points[:, 1], points[:, 0])
    theta0 = theta[0] + (np.tan(beta[0]) - beta[0])        # the upper flank unwinds clockwise
    return rho * np.abs(theta - (theta0 - (np.tan(beta) - beta)))


@pytest.mark.parametrize("kwargs", PAIRS)
def test_flank_vertices_lie_on_the_involute(kwargs):
    pair = design_pair(GearPairInputs(**kwargs))
    for gear in (pair.gear1, pair.gear2):
        f = flank(pair.inputs, gear)
        pts = f.points()[f.involute]
        assert len(pts) >= 40
        assert _on_involute(pts, gear.rb).max() < 1e-9 * gear.ra
        # the tooth's thickness on the reference circle is s: the involute's angle there
        rho = np.hypot(pts[:, 0], pts[:, 1])
        theta = np.arctan2(pts[:, 1], pts[:, 0])
        beta = np.arccos(gear.rb / rho)
        base_angle = theta + np.tan(beta) - beta          # where the involute leaves the base circle
        alpha = pair.inputs.alpha
        at_r = base_angle[0] - (math.tan(alpha) - alpha)
        assert 2 * gear.r * at_r == pytest.approx(gear.s, rel=1e-9)
        assert f.radius[-1] == pytest.approx(gear.ra, rel=1e-12)
        assert f.radius[0] == pytest.approx(gear.rf, rel=1e-12)


def test_fillet_points_are_a_tip_radius_from_the_trochoid():
    """Each fillet point lies ρ from the trochoid of the rack tip circle's centre (sampled
    finely here, by its own definition: the centre carried by the rolling rack)."""
    pair = design_pair(GearPairInputs(z1=13, z2=40, module_mm=6.0))
    p, gear = pair.inputs, pair.gear1
    f = flank(p, gear)
    fillet = f.points()[~f.involute]
    rho = rack_tip_radius(p)
    m, a, r = p.module_mm, p.alpha, gear.r
    h_c = (1.25 - gear.shift) * m - rho
    u_c = math.pi * m / 4 - gear.shift * m * math.tan(a) - h_c * math.tan(a) - rho / math.cos(a)
    turn = math.pi / 2 - math.pi / gear.teeth                # the tooth's axis to +x

    def centre(phi):
        """The tip circle's centre carried by the rack rolling through φ, in the tooth's frame."""
        x, y = u_c - r * phi, r - h_c
        t = -phi - turn
        return np.cos(t) * x - np.sin(t) * y, np.sin(t) * x + np.cos(t) * y
    from scipy.optimize import minimize_scalar
    grid = np.linspace(-1.0, 1.0, 20001)
    cx, cy = centre(grid)
    for point in fillet:
        k = int(np.argmin(np.hypot(cx - point[0], cy - point[1])))
        best = minimize_scalar(lambda f: math.hypot(*(np.array(centre(f)) - point)),
                               bounds=(grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]),
                               method="bounded", options={"xatol": 1e-12})
        assert best.fun == pytest.approx(rho, abs=1e-6 * m)


def test_undercut_tooth_is_waisted_and_outline_closes_a_pitch():
    pair = design_pair(GearPairInputs(z1=8, z2=30, module_mm=2.0, x1=0.0, x2=0.0))
    f = flank(pair.inputs, pair.gear1)
    below_base = f.angle[f.radius < pair.gear1.rb]
    above = f.angle[(f.radius > pair.gear1.rb) & (f.radius < pair.gear1.r)]
    assert below_base.min() < above.min()                    # thinner below the base circle
    outline = tooth_outline(pair.inputs, pair.gear1)
    ends = np.arctan2(outline[[0, -1], 1], outline[[0, -1], 0])
    assert ends[1] - ends[0] == pytest.approx(2 * math.pi / 8, rel=1e-12)


from hypothesis import HealthCheck, assume, example, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from core.base.errors import DesignError  # noqa: E402


@given(st.integers(5, 150), st.integers(5, 150), st.floats(-0.5, 1.0), st.floats(-0.5, 1.0),
       st.floats(0.0, 0.4))
@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@example(13, 5, 0.21875, 0.0, 0.0)         # undercut by a hair: the flank reaches N, ρ = rb
@example(11, 5, 0.3, -0.5, 0.16)           # deep undercut: its branch ran on above the tip
def test_any_pair_flanks_run_root_to_tip_on_the_involute(z1, z2, x1, x2, clearance):
    try:
        pair = design_pair(GearPairInputs(z1=z1, z2=z2, module_mm=2.0, x1=x1, x2=x2,
                                          clearance=clearance))
    except DesignError:
        assume(False)
    for gear in (pair.gear1, pair.gear2):
        f = flank(pair.inputs, gear)
        assert f.radius[0] == pytest.approx(gear.rf, rel=1e-9)
        assert f.radius[-1] == pytest.approx(gear.ra, rel=1e-9)
        assert np.all(np.diff(f.radius) >= -1e-12)
        pts = f.points()[f.involute]
        if len(pts) > 1:
            assert _on_involute(pts, gear.rb).max() < 1e-9 * gear.ra
