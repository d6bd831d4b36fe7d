"""Many designs at once: the same verdicts, messages and figures as one design at a time."""
import math
from dataclasses import replace

import numpy as np
import pytest

from core.forces.masses import MassProperties

from core.forces.flywheel import summarize
from core.base.errors import DesignError
from core.linkage.metrics import analyze
from core.space.optimize import objective_of, optimize
from core.linkage.spec import Spec
from core.space.sweep import evaluate, grid, spec_changes, spec_designs

RNG_SEED = 11
LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)


def random_inputs(rng, count, mode, variant, rod_input):
    """Inputs spread wide enough that every rule refuses some of them."""
    values = {"crank": rng.uniform(-20, 400, count),
              "guide": rng.uniform(100, 1500, count)}
    if mode == "synthesis":
        values["time_ratio"] = rng.uniform(0.9, 5.3, count)
        values["stroke"] = rng.uniform(-50, 1500, count)
        values["crank"][::17] = 1e-4                         # below the length floor
        values["time_ratio"][::23] = 1 + 1e-12               # K too close to 1
    else:
        values["frame"] = rng.uniform(50, 600, count)
        values["lever"] = rng.uniform(100, 1500, count)
    if variant == "rod":
        if rod_input == "ratio":
            values["rod_ratio"] = rng.uniform(-0.1, 1.5, count)
        else:
            values["rod"] = rng.uniform(-10, 900, count)
    for v in values.values():
        v[::29] = np.nan
    return values


def one_spec(spec, values, i):
    """The Spec of design ``i`` alone, as the form would hold it."""
    changes = {"crank": values["crank"][i], "guide_rule": "height",
               "guide_height": values["guide"][i]}
    for key in ("time_ratio", "stroke", "frame", "lever"):
        if key in values:
            changes[key] = values[key][i]
    if "rod_ratio" in values:
        changes.update(variant="rod", rod_input="ratio", rod_ratio=values["rod_ratio"][i])
    if "rod" in values:
        changes.update(variant="rod", rod_input="length", rod_length=values["rod"][i])
    return replace(spec, **changes)


@pytest.mark.parametrize("mode, variant, rod_input, side", [
    ("synthesis", "block", "ratio", "trailing"), ("synthesis", "rod", "ratio", "leading"),
    ("synthesis", "rod", "length", "trailing"), ("dimensions", "block", "ratio", "trailing"),
    ("dimensions", "rod", "length", "leading"), ("dimensions", "rod", "ratio", "trailing")])
def test_verdicts_equal_single_design_validation(mode, variant, rod_input, side):
    rng = np.random.default_rng(RNG_SEED)
    spec = Spec(mode=mode, variant=variant, rod_input=rod_input, rod_side=side)
    values = random_inputs(rng, 600, mode, variant, rod_input)
    designs, verdict = spec_designs(spec, values)
    parameters = set()
    for i in range(600):
        try:
            single = one_spec(spec, values, i).design()
            expected = None
        except DesignError as exc:
            expected = exc
        got = verdict.error(i)
        if expected is None:
            assert got is None, (i, got)
            assert designs.lever[i] == pytest.approx(single.lever, rel=1e-12)
            assert designs.guide[i] == pytest.approx(single.guide, rel=1e-12)
        else:
            assert got is not None, (i, expected)
            assert (got.parameter, got.allowed) == (expected.parameter, expected.allowed), i
            assert str(got) == str(expected)
            parameters.add((got.parameter, got.allowed.split(' ')[:3] == ['must', 'be', '≥'],
                            got.allowed[:12]))
    assert verdict.ok.sum() > 20                      # a fair share of valid designs
    assert len(parameters) >= 5                       # and of different rules


@pytest.mark.parametrize("variant", ["block", "rod"])
def test_sweep_figures_equal_analyze_and_summarize(variant):
    rng = np.random.default_rng(3)
    spec = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant=variant, rod_ratio=0.4)
    values = {"crank": rng.uniform(60, 140, 400), "time_ratio": rng.uniform(1.05, 4.5, 400),
              "stroke": rng.uniform(250, 700, 400)}
    if variant == "rod":
        values["rod_ratio"] = rng.uniform(0.2, 1.2, 400)
    rpms = [25.0, 60.0]
    ev = evaluate(spec, values, rpms, LOADS)
    valid = np.flatnonzero(ev.valid)
    assert valid.size > 50
    for i in valid[:: max(1, valid.size // 25)]:
        changes = {k: float(v[i]) for k, v in values.items()}
        design = replace(spec, **changes).design()
        metrics = analyze(design, rpms)
        summary = summarize(design, rpms, LOADS)
        assert ev.peaks.time_ratio[i] == pytest.approx(metrics.time_ratio, rel=1e-6)
        assert ev.peaks.stroke_mm[i] == pytest.approx(metrics.stroke_mm, rel=1e-6)
        if variant == "rod":
            assert math.degrees(ev.peaks.pressure_max[i]) == pytest.approx(
                metrics.pressure_angle_max_deg, rel=1e-6)
        for j, s in enumerate(metrics.speeds):
            for key in ("v_work_max_m_s", "v_return_max_m_s", "a_max_m_s2"):
                assert ev.figures[key][i, j] == pytest.approx(getattr(s, key), rel=1e-6)
            for key in ("mean_torque_N_m", "max_torque_N_m", "flywheel_inertia_kg_m2"):
                assert ev.dynamics[key][i, j] == pytest.approx(getattr(summary.speeds[j], key), rel=1e-6)
    invalid = np.flatnonzero(~ev.valid)
    assert np.all(np.isnan(ev.figures["a_max_m_s2"][invalid]))


def test_grid_varies_the_first_name_slowest():
    values = grid({"crank": (80.0, 120.0, 3), "guide": (500.0, 600.0, 2)})
    assert values["crank"].tolist() == [80, 80, 100, 100, 120, 120]
    assert values["guide"].tolist() == [500, 600, 500, 600, 500, 600]


def test_too_many_designs_are_refused():
    with pytest.raises(DesignError) as info:
        grid({"crank": (1, 2, 2000), "guide": (1, 2, 2000)})
    assert info.value.parameter == "vary"


def brute(spec, names, bounds, objective, rpms, count, masses=None):
    axes = [np.linspace(lo, hi, count) for lo, hi in bounds]
    mesh = [m.reshape(-1) for m in np.meshgrid(*axes, indexing="ij")]
    ev = evaluate(spec, dict(zip(names, mesh)), rpms, masses)
    return objective_of(ev, objective).min()


@pytest.mark.parametrize("objective, names, bounds", [
    ("pressure-angle", ("rod_ratio", "guide"), ((0.2, 1.0), (450.0, 700.0))),
    ("accel", ("rod_ratio", "guide"), ((0.2, 1.0), (450.0, 700.0))),
    ("accel", ("crank",), ((60.0, 140.0),)),
])
def test_optimum_is_at_least_as_good_as_a_dense_grid(objective, names, bounds):
    spec = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant="rod", rod_ratio=0.3)
    best = optimize(spec, dict(zip(names, bounds)), objective, [40.0, 60.0])
    reference = brute(spec, names, bounds, objective, [40.0, 60.0], 201 if len(names) == 2 else 4001)
    assert best.value <= reference * (1 + 1e-12)
    assert best.value < best.start_value
    for x, (lo, hi) in zip(best.x, bounds):
        assert lo <= x <= hi
    # The reported figures are the optimal design's own.
    design = replace(spec, guide_rule="height" if "guide" in names else spec.guide_rule,
                     **{("guide_height" if n == "guide" else n): float(v)
                        for n, v in zip(names, best.x)}).design()
    value = (analyze(design, [40.0, 60.0]).pressure_angle_max_deg if objective == "pressure-angle"
             else analyze(design, [40.0, 60.0]).speeds[-1].a_max_m_s2)
    assert best.value == pytest.approx(value, rel=1e-9)


def test_optimum_with_loads_beats_a_grid():
    spec = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant="rod", rod_ratio=0.3)
    bounds = {"rod_ratio": (0.25, 1.0)}
    best = optimize(spec, bounds, "peak-torque", [40.0], LOADS)
    reference = brute(spec, ("rod_ratio",), ((0.25, 1.0),), "peak-torque", [40.0], 121, LOADS)
    assert best.value <= reference * (1 + 1e-12)


def test_objective_needs_rod_or_loads():
    block = Spec(crank=100.0, time_ratio=1.46, stroke=312.0)
    with pytest.raises(DesignError) as info:
        optimize(block, {"crank": (80.0, 120.0)}, "pressure-angle", [40.0])
    assert info.value.parameter == "objective"
    with pytest.raises(DesignError):
        optimize(block, {"crank": (80.0, 120.0)}, "flywheel", [40.0])


def test_a_start_one_rounding_step_past_the_box_is_clipped(monkeypatch):
    """Differential evolution can return a point one rounding step past an end of the box;
    the Nelder–Mead polish then started outside its bounds with an OptimizeWarning
    (printed to the console of the GUI). The polish now starts inside."""
    import warnings

    import scipy.optimize

    real = scipy.optimize.differential_evolution

    def one_step_past(func, bounds, **kwargs):
        result = real(func, bounds, **kwargs)
        result.x = np.array([np.nextafter(hi, np.inf) for _, hi in bounds])
        result.fun = -1.0                  # better than anything, so the polish starts there
        return result

    monkeypatch.setattr(scipy.optimize, "differential_evolution", one_step_past)
    spec = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant="rod", rod_ratio=0.3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        best = optimize(spec, {"crank": (60.0, 140.0)}, "accel", [40.0])
    assert 60.0 <= best.x[0] <= 140.0


def test_a_sweep_best_on_the_end_of_the_box_starts_the_search():
    """The sweep's best lay on an end of the box; SciPy's scaling put it one rounding
    step outside and differential evolution raised ValueError ("Some entries in x0 lay
    outside the specified bounds"): found by the GUI fuzz test's Optimize, bounds found
    by a search for ends that scale past 1."""
    low, high = 114.57213655596335, 144.69066664934076
    middle = 0.5 * (low + high)
    assert (low - middle) * (1.0 / (high - low)) + 0.5 < 0.0   # SciPy's scaling of the low end
    best = optimize(Spec(), {"crank": (low, high)}, "accel", [40.0])
    assert low <= best.x[0] <= high
    reference = brute(Spec(), ("crank",), ((low, high),), "accel", [40.0], 4001)
    assert best.value <= reference * (1 + 1e-12)


def test_tidy_values_round_to_the_resolution_inside_bounds_and_stay_valid():
    from core.space.sweep import tidy_values

    spec = Spec()
    assert tidy_values(spec, {"crank": 52.564102564102564, "time_ratio": 1.2999999999},
                       {"crank": 0.0256, "time_ratio": 0.0005}) == {"crank": 52.56, "time_ratio": 1.3}
    # rounded inward at a bound (94.6907 would lie past 94.690666…)
    high = 94.69066664934076
    assert tidy_values(spec, {"crank": high}, {"crank": 1e-4}, {"crank": (80.0, high)}) == {"crank": 94.6906}
    # a rounding that would make the design invalid takes the multiple on the valid side: the
    # guide must lie above L2 + L1 (445.398… mm here), and 445.45 to the nearest millimetre is
    # 445 (it kept all the exact digits, which the optimizer's table then cut to 6 and so
    # printed a K that shaper analyze refused); exact where neither multiple is valid
    rod = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant="rod", rod_ratio=0.3)
    limit = rod.design().frame + rod.design().crank
    assert 445.0 < limit < 445.45
    assert tidy_values(rod, {"guide": 445.45}, {"guide": 1.0}) == {"guide": 446.0}
    assert tidy_values(rod, {"guide": 445.45}, {"guide": 1.0}, {"guide": (445.4, 445.9)}) == {"guide": 445.45}
    assert tidy_values(rod, {"guide": 445.7}, {"guide": 1.0}) == {"guide": 446.0}
    # a design invalid either way (an invalid cell clicked) still gets short values
    assert tidy_values(rod, {"guide": 300.123456}, {"guide": 0.01}) == {"guide": 300.12}


@pytest.mark.parametrize("objective, bounds", [
    ("accel", {"crank": (50.0, 150.0), "time_ratio": (1.05, 3.0)}),
    ("pressure-angle", {"rod_ratio": (0.3, 1.0), "guide": (480.0, 620.0)}),
])
def test_tidy_optimum_is_short_close_and_no_worse_than_a_millionth(objective, bounds):
    from core.space.optimize import tidy_optimum

    spec = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant="rod", rod_ratio=0.3)
    best = optimize(spec, bounds, objective, [40.0, 60.0])
    values, value = tidy_optimum(spec, best, bounds, [40.0, 60.0])
    for name, x in zip(best.names, best.x):
        lo, hi = bounds[name]
        assert lo <= values[name] <= hi and abs(values[name] - x) <= 1e-6 * (hi - lo)
        assert len(repr(values[name])) <= 10, values
    assert best.value <= value <= best.value * (1 + 1e-6)
    # the value returned is the rounded design's own, by analyze
    design = replace(spec, **spec_changes(values)).design()
    metrics = analyze(design, [40.0, 60.0])
    own = metrics.pressure_angle_max_deg if objective == "pressure-angle" else metrics.speeds[-1].a_max_m_s2
    assert value == pytest.approx(own, rel=1e-9)
