"""Switching input mode carries the design over both ways (core, no screen)."""
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from core.base.errors import DesignError
from core.linkage.geometry import MAX_TIME_RATIO
from core.linkage.spec import NUMBER_FIELDS, Spec


def same_design(a, b, rel=1e-9):
    for name in ("crank", "frame", "lever", "guide"):
        assert getattr(a, name) == pytest.approx(getattr(b, name), rel=rel), name
    assert (a.rod is None) == (b.rod is None)
    if a.rod is not None:
        assert a.rod == pytest.approx(b.rod, rel=rel)


def test_worked_example_both_ways():
    spec = Spec(time_ratio=1.6, stroke=450.0)
    design = spec.design()
    dims = spec.switch_mode("dimensions", design)
    assert dims.mode == "dimensions"
    # L2 = L1/sin(θ/2), L3 = H/(2 sin(θ/2)) with θ = 180°·0.6/2.6 (hand formulas)
    half = math.sin(math.radians(180 * 0.6 / 2.6) / 2)
    assert dims.frame == pytest.approx(100 / half, rel=1e-9) and dims.lever == pytest.approx(225 / half, rel=1e-9)
    same_design(dims.design(), design)
    back = dims.switch_mode("synthesis", dims.design())
    assert back.time_ratio == 1.6 and back.stroke == 450.0      # rounded to 10 digits: as typed again


k_values = st.one_of(st.floats(1.01, MAX_TIME_RATIO), st.just(MAX_TIME_RATIO), st.just(1.01))


@settings(max_examples=300, deadline=None)
@given(crank=st.floats(1.0, 2000.0), k=k_values, stroke_factor=st.floats(1.0, 3.0),
       variant=st.sampled_from(("block", "rod")), rule=st.sampled_from(("chord", "sagitta")),
       on_bound=st.booleans())
def test_switching_keeps_a_valid_design_the_same(crank, k, stroke_factor, variant, rule, on_bound):
    """Any valid synthesis, including K = 5 and a lever exactly L2 + L1 long (corners where
    sin/asin round trips fall just outside a bound), switches to dimensions and back
    with the same mechanism, still valid."""
    half = math.sin(math.pi * (k - 1) / (k + 1) / 2)
    frame = crank / half
    shortest_stroke = 2 * (crank + frame) * half
    stroke = shortest_stroke * (1.0 if on_bound else stroke_factor)
    spec = Spec(crank=crank, time_ratio=k, stroke=stroke, variant=variant, guide_rule=rule, rod_ratio=1.5)
    try:
        design = spec.design()
    except DesignError:
        return                         # outside the domain (e.g. frame over 100 000 mm)
    dims = spec.switch_mode("dimensions", design)
    same_design(dims.design(), design)
    back = dims.switch_mode("synthesis", dims.design())
    same_design(back.design(), design)
    assert back.time_ratio == pytest.approx(k, rel=1e-9) and back.stroke == pytest.approx(stroke, rel=1e-9)
    back.check_fields()


def test_switching_an_invalid_spec_still_switches():
    spec = Spec(crank="x")
    design = Spec().design()
    dims = spec.switch_mode("dimensions", design)
    assert dims.mode == "dimensions" and dims.frame == pytest.approx(design.frame)


def test_active_fields():
    assert Spec().active_fields() == {"crank", "time_ratio", "stroke"}
    assert Spec(mode="dimensions", variant="rod", rod_input="length",
                guide_rule="height").active_fields() == {"crank", "frame", "lever", "rod_length", "guide_height"}
    assert set(NUMBER_FIELDS) >= Spec(variant="rod").active_fields()
