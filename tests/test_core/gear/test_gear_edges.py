"""The gear's edges (issue 42, item 11): a refusal's hinted centre distance is itself
accepted; a rack whose tip rounding does not fit its tooth is refused by name, and every
rack accepted cuts a tooth space that is not folded on itself; the rule's rounding of a′
scales with the module, so its pairs are the same at m = 0.1, 1 and 10."""
from __future__ import annotations

import math
import re
from dataclasses import replace

import pytest
from hypothesis import assume, given, settings, strategies as st

from core.base.errors import DesignError
from core.gear import GearPairInputs, design_pair, pair_checks
from core.gear.involute import least_shift
from core.gear.profile import flank
from core.gear.shift import mesh_of_sum


def refusal(**kwargs) -> str | None:
    try:
        design_pair(GearPairInputs(**kwargs))
    except DesignError as exc:
        return str(exc)
    return None


def test_the_issues_hint_is_accepted():
    text = refusal(z1=12, z2=40, module_mm=2.0, centre_mm=49.1049)
    hint = float(re.search(r"give ≥ (\S+) mm", text).group(1))
    assert hint >= 49.104929944 and refusal(z1=12, z2=40, module_mm=2.0, centre_mm=hint) is None


@settings(max_examples=150, deadline=None)
@given(z1=st.integers(5, 40), z2=st.integers(5, 120), module=st.sampled_from([0.3, 1.0, 2.0, 2.5, 6.0]),
       below=st.floats(1e-7, 0.02))
def test_a_hinted_least_centre_is_accepted(z1, z2, module, below):
    """Just under the least a′ that keeps both gears uncut: the hint names a′ that is."""
    p = GearPairInputs(z1, z2, module)
    need = sum(least_shift(z, p.alpha, p.addendum) for z in (z1, z2))
    try:
        least = mesh_of_sum(p, need)[1]
    except DesignError:                 # no a′ below which the gears undercut: α′ ≤ 0 first
        assume(False)
        return
    text = refusal(z1=z1, z2=z2, module_mm=module, centre_mm=least * (1 - below))
    assume(text is not None and "give ≥" in text)
    hint = float(re.search(r"give ≥ (\S+) mm", text).group(1))
    again = refusal(z1=z1, z2=z2, module_mm=module, centre_mm=hint)
    assert again is None or "uncut" not in again, (hint, least, again)


@settings(max_examples=100, deadline=None)
@given(z1=st.integers(5, 40), z2=st.integers(5, 120), module=st.sampled_from([0.3, 1.0, 2.0, 6.0]),
       below=st.floats(1e-9, 0.3))
def test_a_hinted_least_working_angle_is_accepted(z1, z2, module, below):
    p = GearPairInputs(z1, z2, module)
    bound = module * (z1 + z2) / 2 * math.cos(p.alpha)
    text = refusal(z1=z1, z2=z2, module_mm=module, centre_mm=bound * (1 - below))
    hint = float(re.search(r"a cos α = (\S+) mm", text).group(1))
    assert hint > bound
    again = refusal(z1=z1, z2=z2, module_mm=module, centre_mm=hint)
    assert again is None or "a cos α" not in again


@pytest.mark.parametrize("alpha, most", [(20.0, 0.295), (25.0, 0.203)])
def test_a_rack_whose_tip_rounding_does_not_fit_is_refused_by_name(alpha, most):
    """The issue's bounds: c* ≤ (π/4 − h*a tan α)/(tan α + sec α), 0.295 at 20°, 0.203 at 25°;
    the hinted bound is itself accepted."""
    a = math.radians(alpha)
    assert (math.pi / 4 - math.tan(a)) / (math.tan(a) + 1 / math.cos(a)) == pytest.approx(most, abs=5e-4)
    with pytest.raises(DesignError) as refused:
        design_pair(GearPairInputs(13, 40, 6.0, pressure_angle_deg=alpha, clearance=most + 0.002))
    assert refused.value.parameter == "clearance"
    hint = float(re.search(r"must be ≤ (\S+)", str(refused.value)).group(1))
    design_pair(GearPairInputs(13, 40, 6.0, pressure_angle_deg=alpha, clearance=hint))


@settings(max_examples=200, deadline=None)
@given(z=st.integers(8, 120), alpha=st.floats(14.0, 32.0), addendum=st.floats(0.6, 1.3),
       share=st.floats(0.05, 1.0), x=st.floats(-0.3, 0.8))
def test_an_accepted_rack_cuts_a_tooth_space_not_folded(z, alpha, addendum, share, x):
    """Every rack accepted: the fillet reaches the root circle inside the half pitch, so the
    root arc from the space's middle to the flank runs forwards (it ran back up to 0.9°)."""
    a = math.radians(alpha)
    most = (math.pi / 4 - addendum * math.tan(a)) / (math.tan(a) + 1 / math.cos(a))
    assume(most > 0.0)
    try:
        pair = design_pair(GearPairInputs(z, 60, 2.0, x1=x, x2=0.0, pressure_angle_deg=alpha,
                                          addendum=addendum, clearance=share * min(most, 1.0)))
    except DesignError:
        assume(False)
        return
    f = flank(pair.inputs, pair.gear1)
    assert f.radius[0] == pytest.approx(pair.gear1.rf, rel=1e-9)
    assert f.angle[0] <= math.pi / z + 1e-12


@pytest.mark.parametrize("z1, z2", [(10, 22), (12, 20), (8, 12), (14, 19)])
def test_the_rules_pair_scales_with_the_module(z1, z2):
    """At m = 0.1 a 1.70 mm pair was rounded to 2.0 mm (x2 = 4.27, refused as pointed).
    The step is m/10 for these modules, so the rule's shifts are the same at m = 0.1, 1, 10
    and a′ is within one step of the least positive pair's."""
    pairs = [design_pair(GearPairInputs(z1, z2, m)) for m in (0.1, 1.0, 10.0)]
    for pair, m in zip(pairs, (0.1, 1.0, 10.0)):
        assert pair.mode == "positive"
        assert pair.gear1.shift == pytest.approx(pairs[1].gear1.shift, abs=1e-9)
        assert pair.gear2.shift == pytest.approx(pairs[1].gear2.shift, abs=1e-9)
        p = pair.inputs
        least = mesh_of_sum(p, sum(max(least_shift(z, p.alpha, p.addendum), 0.0) for z in (z1, z2)))[1]
        assert least <= pair.centre_mm < least + m / 10 + 1e-12


@settings(max_examples=100, deadline=None)
@given(z1=st.integers(9, 16), x1=st.floats(-0.5, 0.2))
def test_the_undercut_advice_names_a_shift_that_is_uncut(z1, x1):
    """'raise x1 to ≥ X': X rounded up, so x1 = X is uncut (X = 0.5321 for 0.53214… was not)."""
    from core.gear import pair_checks
    try:
        pair = design_pair(GearPairInputs(z1, 40, 2.0, x1=x1, x2=0.5))
    except DesignError:
        assume(False)
        return
    check = pair_checks(pair)[0]
    assume(not check.ok)
    x = float(re.search(r"raise x1 to ≥ (\S+)", check.advice).group(1))
    assert not design_pair(GearPairInputs(z1, 40, 2.0, x1=x, x2=0.5)).gear1.undercut


def test_the_refusal_tells_the_two_sums_apart():
    """'needs x1 + x2 = -1.0414, below the -1.0414': the sums get the digits that differ."""
    text = refusal(z1=12, z2=40, module_mm=2.0, centre_mm=49.1049)
    given, least = re.search(r"x1 \+ x2 = (\S+), below the (\S+) ", text).groups()
    assert float(given) < float(least) and given != least


@settings(max_examples=40, deadline=None)
@given(z1=st.integers(5, 150), z2=st.integers(5, 150), alpha=st.floats(15.0, 30.0),
       x2=st.floats(-5.0, 0.0), x1=st.floats(-5.0, 0.0))
def test_a_shift_sum_too_negative_to_mesh_is_told_the_sum_that_meshes(z1, z2, alpha, x1, x2):
    """'raise x1 + x2 above X' (409f94c: 'raise the shifts', by no amount): x1 raised so that
    the sum is X as printed, the pair meshes (α′ > 0); another refusal may follow, with its
    own advice."""
    p = GearPairInputs(z1=z1, z2=z2, module_mm=4.0, pressure_angle_deg=alpha, x1=x1, x2=x2)
    try:
        design_pair(p)
        return
    except DesignError as exc:
        m = re.search(r"the gears would not mesh \(α′ ≤ 0\); raise x1 \+ x2 above (\S+)$", exc.allowed)
        if "would not mesh" not in exc.allowed:
            return
        assert m, exc.allowed
    try:
        design_pair(replace(p, x1=float(m.group(1)) - x2))
    except DesignError as exc:
        assert "would not mesh" not in exc.allowed, exc.allowed


def _refused(p: GearPairInputs) -> DesignError | None:
    try:
        design_pair(p)
    except DesignError as exc:
        return exc
    return None


@settings(max_examples=40, deadline=None)
@given(z1=st.integers(5, 60), z2=st.integers(5, 120), x1=st.floats(0.0, 5.0), x2=st.floats(0.0, 5.0),
       stretch=st.floats(1.0, 1.3), rule=st.booleans())
def test_a_pointed_tip_is_mended_by_following_its_advice(z1, z2, x1, x2, stretch, rule):
    """A pointed tip's refusal names the value that mends it ('give x1 ≤ V', 'give a′ ≤ V mm',
    'give z1 ≥ N'): typed, the tip is no longer pointed. Where it says no smaller shift or
    centre distance helps, stepping that value down (0.01 of x, m/100 of a′) to the end of
    its range finds the tip pointed all the way ('give gear k more teeth'); the rule's
    'give more teeth' walks z_k up one at a time. (test_gear_amounts: each value passes the
    tip check and is the least.)"""
    base = GearPairInputs(z1=z1, z2=z2, module_mm=4.0)
    given_shifts = GearPairInputs(z1=z1, z2=z2, module_mm=4.0, x1=x1, x2=x2)
    centre = GearPairInputs(z1=z1, z2=z2, module_mm=4.0,
                            centre_mm=2.0 * (z1 + z2) * stretch)      # m (z1 + z2)/2 · stretch
    for p in (base if rule else given_shifts, centre):
        error = _refused(p)
        if error is None or "pointed" not in error.allowed:
            continue
        k = int(re.search(r"the tip of gear (\d) pointed", error.allowed).group(1))
        pointed = f"the tip of gear {k} pointed"
        if m := re.search(r"give (x\d|a′|z\d) [≤≥] ([^,\s]+)", error.allowed):
            field = {"a′": "centre_mm"}.get(m.group(1), m.group(1))
            value = int(m.group(2)) if field.startswith("z") else float(m.group(2))
            again = _refused(replace(p, **{field: value}))
            assert again is None or pointed not in again.allowed, (error.allowed, again.allowed)
            continue
        if "no smaller x" in error.allowed:
            field, step, stop, mended = f"x{k}", -0.01, -5.0, False
        elif "no smaller centre distance" in error.allowed:
            field, step, stop, mended = "centre_mm", -0.04, 2.0 * (z1 + z2) * math.cos(math.radians(20.0)), False
        else:
            assert error.allowed.endswith("give more teeth, or the shifts or the centre distance"), error.allowed
            field, step, stop, mended = f"z{k}", 1, 1000, True
        q = p
        while True:
            value = getattr(q, field) + step
            if not mended and (value - stop) * (1 if step < 0 else -1) <= 0:
                break                                   # to the end of the range: none was thick enough
            assert (value - stop) * (1 if step < 0 else -1) > 0, f"{field} left its range still pointed"
            q = replace(q, **{field: value})
            again = _refused(q)
            if mended and (again is None or pointed not in again.allowed):
                break
            if not mended and again is None:
                assert not {c.name: c for c in pair_checks(design_pair(q))}[f"tip{k}"].ok, (error.allowed, value)
