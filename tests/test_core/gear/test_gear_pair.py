"""Issue 35, item 1: the gear pair against independent involute geometry.

References here share nothing with core.gear's formulas: α′ by brentq on tan α − α, tip
thickness measured on involute points built from the parametric equations, tip radii from
the standard clearance at a′, ε from the angle each gear turns while in contact.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from core.base.errors import DesignError
from core.gear import GearPairInputs, design_pair, pair_checks
from core.gear.involute import inv_inverse

REL = 1e-9


def _alpha_w(total: float, z: int, alpha: float) -> float:
    target = 2 * math.tan(alpha) * total / z + (math.tan(alpha) - alpha)
    return brentq(lambda a: math.tan(a) - a - target, 1e-6, math.pi / 2 - 1e-9, xtol=1e-16,
                  rtol=1e-15)


def _flank_half_angle(rb: float, r: float, s: float, radius: float) -> float:
    """Half the angle a tooth subtends at ``radius``, measured on involute points: the
    involute (rb(cos t + t sin t), rb(sin t − t cos t)) is placed so that at the reference
    radius its half-angle is s / (2 r)."""
    def polar(radius_k):
        t = math.sqrt((radius_k / rb) ** 2 - 1.0)
        x, y = rb * (math.cos(t) + t * math.sin(t)), rb * (math.sin(t) - t * math.cos(t))
        return math.atan2(y, x)
    return s / (2 * r) + polar(r) - polar(radius)


def _close(a: float, b: float, rel: float = REL) -> None:
    assert a == pytest.approx(b, rel=rel, abs=1e-12)


def test_inv_inverse_to_1e_14():
    """inv α′ of the solved α′ agrees to 1e-14 (relative), inv evaluated as
    (sin α − α cos α) / cos α in extended precision, from α′ = 1° to 89.5°."""
    low, high = math.tan(math.radians(1)) - math.radians(1), 50.0
    for value in np.geomspace(low, high, 400):
        alpha = np.longdouble(inv_inverse(float(value)))
        found = (np.sin(alpha) - alpha * np.cos(alpha)) / np.cos(alpha)
        assert abs(found - np.longdouble(value)) <= 1e-14 * value


def test_worked_example_centre_given():
    """z1 = z2 = 12, m = 10 mm, α = 20°, a′ = 130 mm (the classic exercise of the shifted pair
    whose standard centre, 120 mm, is too small for the housing): α′ = 29.84° and x1 + x2 =
    1.2505 by the tables; here to 1e-9 by brentq."""
    pair = design_pair(GearPairInputs(z1=12, z2=12, module_mm=10.0, centre_mm=130.0))
    alpha = math.radians(20)
    alpha_w = math.acos(120 * math.cos(alpha) / 130)
    _close(pair.alpha_w, alpha_w)
    assert math.degrees(alpha_w) == pytest.approx(29.84, abs=0.005)
    total = (math.tan(alpha_w) - alpha_w - math.tan(alpha) + alpha) * 24 / (2 * math.tan(alpha))
    _close(pair.gear1.shift + pair.gear2.shift, total)
    _close(_alpha_w(total, 24, alpha), alpha_w)
    # the split: the pinion's least uncut shift (h*a − z sin²α / 2), the rest to the gear
    _close(pair.gear1.shift, 1 - 12 * math.sin(alpha) ** 2 / 2)
    _close(pair.y, 1.0)
    _close(pair.dy, total - 1.0)


def test_standard_pair_textbook_values():
    """z1 = 20, z2 = 40, m = 4: a = 120, da1 = 88, df1 = 70, db1 = 80 cos 20°, s = 2π."""
    pair = design_pair(GearPairInputs(z1=20, z2=40, module_mm=4.0, x1=0.0, x2=0.0))
    _close(pair.centre_mm, 120.0)
    _close(pair.alpha_w, math.radians(20))
    _close(2 * pair.gear1.ra, 88.0)
    _close(2 * pair.gear1.rf, 70.0)
    _close(2 * pair.gear2.ra, 168.0)
    _close(2 * pair.gear1.rb, 80 * math.cos(math.radians(20)))
    _close(pair.gear1.s, 2 * math.pi)
    assert all(c.ok for c in pair_checks(pair))


def _identities(pair) -> None:
    p = pair.inputs
    m, alpha = p.module_mm, p.alpha
    a = m * (p.z1 + p.z2) / 2
    _close(pair.centre_mm * math.cos(pair.alpha_w), a * math.cos(alpha))
    _close(pair.alpha_w, _alpha_w(pair.gear1.shift + pair.gear2.shift, p.z1 + p.z2, alpha))
    for gear, other in ((pair.gear1, pair.gear2), (pair.gear2, pair.gear1)):
        _close(gear.s + gear.e, math.pi * m)
        # the tip clears the other's root by c* m at a′ (what Δy is for)
        _close(gear.ra, pair.centre_mm - other.rf - p.clearance * m)
        _close(gear.rw, pair.centre_mm * gear.teeth / (p.z1 + p.z2))
        _close(gear.sa, 2 * gear.ra * _flank_half_angle(gear.rb, gear.r, gear.s, gear.ra))
    # ε: the angle gear 1 turns while one pair is in contact, over its angular pitch
    g1, g2 = pair.gear1, pair.gear2
    start = pair.n1n2 - math.sqrt(g2.ra ** 2 - g2.rb ** 2)
    end = math.sqrt(g1.ra ** 2 - g1.rb ** 2)
    _close(pair.contact_ratio, (end - start) / g1.rb / (2 * math.pi / p.z1))
    _close(pair.contact_ratio, pair.b1b2 / (math.pi * m * math.cos(alpha)))
    _close(pair.n1n2, (g1.rb + g2.rb) * math.tan(pair.alpha_w))      # the common tangent


@given(st.integers(5, 150), st.integers(5, 150), st.sampled_from([1.0, 2.5, 4.0, 6.0, 10.0]),
       st.floats(-0.5, 1.0), st.floats(-0.5, 1.0), st.floats(15.0, 25.0))
@settings(max_examples=150, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
def test_identities_hold(z1, z2, m, x1, x2, alpha_deg):
    try:
        pair = design_pair(GearPairInputs(z1=z1, z2=z2, module_mm=m, x1=x1, x2=x2,
                                          pressure_angle_deg=alpha_deg))
    except DesignError:
        assume(False)
    _identities(pair)


@given(st.integers(5, 80), st.integers(5, 150), st.floats(0.0, 1.5))
@settings(max_examples=100, deadline=None)
def test_centre_mode_meshes_at_the_centre_it_was_given(z1, z2, extra):
    """a′ given: the shifts found mesh without backlash at exactly that a′, and both uncut."""
    a = 5.0 * (z1 + z2) / 2
    try:
        pair = design_pair(GearPairInputs(z1=z1, z2=z2, module_mm=5.0, centre_mm=a + extra * 5))
    except DesignError as exc:
        assert exc.parameter == "centre"
        return
    _identities(pair)
    _close(pair.centre_mm, a + extra * 5)
    assert not pair.gear1.undercut and not pair.gear2.undercut


@pytest.mark.parametrize("z1, z2, mode", [(13, 40, "balanced"), (10, 12, "positive"),
                                          (20, 40, "balanced")])
def test_rule_without_shifts(z1, z2, mode):
    alpha = math.radians(20)
    pair = design_pair(GearPairInputs(z1=z1, z2=z2, module_mm=4.0))
    assert pair.mode == mode
    z_min = 2 / math.sin(alpha) ** 2
    x_min1, x_min2 = (z_min - z1) / z_min, (z_min - z2) / z_min
    assert pair.gear1.shift >= x_min1 - 1e-12 and pair.gear2.shift >= x_min2 - 1e-12
    if mode == "balanced":
        _close(pair.gear1.shift, max(x_min1, 0.0))
        assert pair.gear2.shift == -pair.gear1.shift
        _close(pair.centre_mm, 2.0 * (z1 + z2))
    else:                 # the least positive pair's a′, rounded up to m/10 = 0.2 mm
        assert round(pair.centre_mm / 0.2, 9) % 1 == 0 and pair.centre_mm > 2.0 * (z1 + z2)
        assert pair.gear1.shift >= 0 and pair.gear2.shift >= 0
    _identities(pair)


def test_checks_say_what_to_change():
    pair = design_pair(GearPairInputs(z1=8, z2=30, module_mm=2.0, x1=0.0, x2=0.0))
    failed = {c.name: c for c in pair_checks(pair) if not c.ok}
    assert "undercut1" in failed and "x1" in failed["undercut1"].advice
    assert "interference1" in failed        # gear 2's tip reaches below the undercut pinion's N1
    thin = design_pair(GearPairInputs(z1=12, z2=40, module_mm=2.0, x1=0.75, x2=0.0))
    assert [c.name for c in pair_checks(thin) if not c.ok] == ["tip1"]


@pytest.mark.parametrize("kwargs, parameter", [
    (dict(z1=4, z2=30, module_mm=2), "z1"), (dict(z1=12.5, z2=30, module_mm=2), "z1"),
    (dict(z1=12, z2=30, module_mm=0), "module"), (dict(z1=12, z2=30, module_mm=2, x1=0.5), "x2"),
    (dict(z1=12, z2=30, module_mm=2, centre_mm=38), "centre"),
    (dict(z1=12, z2=30, module_mm=2, centre_mm=40.0), "centre"),
    (dict(z1=12, z2=30, module_mm=2, centre_mm=50), "centre"),
    (dict(z1=12, z2=30, module_mm=2, x1=1.5, x2=0), "x1"),
    (dict(z1=30, z2=12, module_mm=2, x1=0, x2=1.5), "x2"),
    (dict(z1=12, z2=30, module_mm=2, x1=0, x2=5), "x2"),
    (dict(z1=5, z2=60, module_mm=2), "z1")])
def test_bad_inputs_name_the_field(kwargs, parameter):
    with pytest.raises(DesignError) as info:
        design_pair(GearPairInputs(**kwargs))
    assert info.value.parameter == parameter


def test_module_outside_the_first_series_is_noted():
    assert GearPairInputs(z1=12, z2=30, module_mm=2.5).module_note is None
    assert "GB/T 1357" in GearPairInputs(z1=12, z2=30, module_mm=2.2).module_note
