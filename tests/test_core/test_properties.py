"""Invariants over random valid designs: what a designer asked for is what the motion does."""
import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from core.base.errors import DesignError
from core.linkage.geometry import synthesize
from core.linkage.kinematics import crank_angles, solve
from core.linkage.metrics import analyze

finite = dict(allow_nan=False, allow_infinity=False)


@st.composite
def designs(draw):
    crank = draw(st.floats(20, 400, **finite))
    k = draw(st.floats(1.05, 3.0, **finite))
    theta = math.pi * (k - 1) / (k + 1)
    least = 2 * crank * (1 + math.sin(theta / 2))
    stroke = draw(st.floats(1.02, 4.0, **finite)) * least
    variant = draw(st.sampled_from(["block", "rod"]))
    guide = draw(st.sampled_from(["chord", "sagitta"]))
    kwargs = {}
    if variant == "rod":
        kwargs["rod_ratio"] = draw(st.floats(0.3, 1.2, **finite))
        kwargs["rod_side"] = draw(st.sampled_from(["trailing", "leading"]))
    try:
        design = synthesize(crank, k, stroke, guide=guide, **kwargs)
    except DesignError:
        assume(False)  # e.g. guide below the crank circle for a very short lever
    return design, k, stroke


@settings(max_examples=150, deadline=None)
@given(designs())
def test_measured_stroke_and_time_ratio(case):
    design, k, stroke = case
    metrics = analyze(design, [60])
    assert metrics.stroke_mm == pytest.approx(stroke, rel=1e-9)
    assert metrics.time_ratio == pytest.approx(k, rel=1e-9)
    assert metrics.work_start_deg == pytest.approx(0.0, abs=1e-7)
    assert metrics.ram_min_mm == pytest.approx(0.0, abs=1e-9 * stroke)


@settings(max_examples=150, deadline=None)
@given(designs(), st.floats(1, 500, **finite))
def test_velocity_zero_at_limits_and_cycle_closes(case, rpm):
    design, k, stroke = case
    theta = math.pi * (k - 1) / (k + 1)
    m = solve(design, np.array([0.0, math.pi + theta, 2 * math.pi]), [rpm])
    v_scale = np.abs(solve(design, crank_angles(5), [rpm]).ram_v).max()
    assert abs(m.ram_v[0, 0]) < 1e-9 * v_scale
    assert abs(m.ram_v[0, 1]) < 1e-9 * v_scale
    assert m.ram_x[1] == pytest.approx(stroke, rel=1e-9)
    for field in ("ram_x", "ram_v", "ram_a", "lever_angle", "lever_omega", "lever_alpha"):
        values = getattr(m, field)
        assert np.allclose(values[..., 0], values[..., 2], atol=1e-9 * max(1.0, np.abs(values).max()))


@settings(max_examples=150, deadline=None)
@given(designs())
def test_working_stroke_moves_forward(case):
    design, k, _ = case
    theta = math.pi * (k - 1) / (k + 1)
    phi = crank_angles(1)
    m = solve(design, phi, [60])
    inner_work = (phi > 1e-3) & (phi < math.pi + theta - 1e-3)
    inner_back = (phi > math.pi + theta + 1e-3) & (phi < 2 * math.pi - 1e-3)
    assert np.all(m.ram_v[0, inner_work] > 0)
    assert np.all(m.ram_v[0, inner_back] < 0)


bad_number = st.one_of(st.floats(max_value=0.0, **finite), st.just(float("nan")),
                       st.just(float("inf")), st.just(-float("inf")))


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(["crank", "time_ratio", "stroke"]), bad_number)
def test_invalid_inputs_raise_domain_error_only(name, value):
    args = dict(crank=100.0, time_ratio=1.4, stroke=300.0)
    args[name] = value if name != "time_ratio" else min(value, 1.0) if math.isfinite(value) else value
    with pytest.raises(DesignError) as info:
        synthesize(**args)
    assert info.value.parameter == name


@settings(max_examples=200, deadline=None)
@given(st.floats(0.05, 300, **finite), st.floats(1.01, 4.9, **finite), st.floats(1, 5000, **finite),
       st.one_of(st.none(), st.floats(-10, 3, **finite)))
def test_any_input_gives_design_or_domain_error(crank, k, stroke, ratio):
    try:
        design = synthesize(crank, k, stroke, rod_ratio=ratio)
    except DesignError:
        return
    metrics = analyze(design, [40])
    assert metrics.stroke_mm == pytest.approx(stroke, rel=1e-8)
