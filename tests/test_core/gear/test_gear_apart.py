"""Shifts so large that the teeth never touch are refused, naming what to type (hunt of
1 December). On 756ad63, x1 = x2 = 5 of a 13/40 pair at m = 6 (each shift within its range
of ±5) was accepted: its addendum reduction Δy = 3.56 cut the tips below the roots (da1 =
107.28 mm, df1 = 123 mm), `shaper gear` printed ε = −0.94 and B1B2 = −16.6 mm as results,
and its meshing sheet (`--dxf`, the course's 04-gear) stopped with "internal error
(IndexError …)", exit 1. A pair now meshes only when the actual line of action has a length
and each tip circle lies outside its root circle (``core.gear.pair.meshes``)."""
from __future__ import annotations

import re
from dataclasses import replace

import pytest
from hypothesis import given, settings, strategies as st

from core.base.errors import DesignError
from core.gear import GearPairInputs, design_pair
from core.gear.pair import meshes

from cli_runner import shaper_in_process

APART = "cuts both tips so far that the teeth never touch"


def refusal(p: GearPairInputs) -> DesignError:
    with pytest.raises(DesignError) as info:
        design_pair(p)
    return info.value


@pytest.mark.parametrize("p, name, field", [
    (GearPairInputs(z1=13, z2=40, module_mm=6.0, x1=5.0, x2=5.0), "x1", "x1"),
    (GearPairInputs(z1=13, z2=40, module_mm=6.0, x1=3.5, x2=3.5), "x1", "x1"),
    (GearPairInputs(z1=5, z2=40, module_mm=1.0, centre_mm=26.5), "centre", "centre_mm"),
])
def test_teeth_that_never_touch_are_refused_with_the_value_that_makes_them_touch(p, name, field):
    """Refused naming the larger shift (or a′); its printed value typed, the pair is designed
    and meshes; one step of the last decimal above it, it is refused again."""
    error = refusal(p)
    assert error.parameter == name and APART in error.allowed, str(error)
    value = float(re.search(r"give (?:x\d|a′) ≤ (\S+?)(?: mm)?$", error.allowed).group(1))
    pair = design_pair(replace(p, **{field: value}))
    assert meshes(pair) and pair.contact_ratio > 0.0 and pair.b1b2 > 0.0
    assert pair.gear1.ra > pair.gear1.rf and pair.gear2.ra > pair.gear2.rf
    assert APART in refusal(replace(p, **{field: value + 1e-4})).allowed


@settings(max_examples=60, deadline=None)
@given(z1=st.integers(5, 60), z2=st.integers(5, 200), x1=st.floats(-1.0, 5.0), x2=st.floats(-1.0, 5.0),
       module=st.sampled_from([1.0, 6.0]))
def test_every_pair_designed_meshes(z1, z2, x1, x2, module):
    """Whatever shifts within range are typed, a pair that is designed has a positive
    contact ratio and teeth with a height: no negative ε or B1B2 is printed as a result."""
    try:
        pair = design_pair(GearPairInputs(z1=z1, z2=z2, module_mm=module, x1=x1, x2=x2))
    except DesignError:
        return
    assert pair.b1b2 > 0.0 and pair.contact_ratio > 0.0
    assert pair.gear1.ra > pair.gear1.rf and pair.gear2.ra > pair.gear2.rf


def test_the_meshing_sheet_of_such_shifts_is_a_refusal_not_an_internal_error(tmp_path):
    """`shaper gear --dxf` of x1 = x2 = 4: one line naming --x1, exit 2, no file (it was
    'internal error (IndexError …)', exit 1)."""
    out = tmp_path / "g.dxf"
    status, _, err = shaper_in_process("gear", "--z1", 13, "--z2", 40, "--module", 6, "--x1", 4, "--x2", 4,
                                       "--dxf", out)
    assert status == 2 and err.startswith("shaper: error: --x1: ") and APART in err, err
    assert err.count("\n") == 1 and not out.exists()
