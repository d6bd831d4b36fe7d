"""Every reported peak is the true extremum of the closed-form curves (issue 7, item 1).

The reference here is written independently of core.linkage.extrema and core.linkage.metrics:
the curves are sampled on a very fine uniform grid of the crank angle, the
largest sample is refined with scipy's bounded scalar minimizer inside its two
neighbouring cells, and the better of both is the reference. Designs are drawn
over the whole accepted domain, with weight on its corners: K near 1 and near
5, a rod barely long enough to reach the guide or to clear its dead centre,
both variants and both rod sides, synthesis and direct dimensions.
"""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st
from scipy.optimize import minimize_scalar

from core.linkage.designs import ROD_MARGIN
from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties
from core.forces.flywheel import summarize
from core.base.errors import DesignError
from core.linkage.geometry import Design, from_dimensions, rod_drive_margin, synthesize
from core.linkage.kinematics import pressure_angle, shape
from core.linkage.extrema import grid_argmax
from core.linkage.polish import polish_minimum
from core.linkage.metrics import analyze, lever_peaks
from sweeps import examples

DENSE = 100_001
finite = dict(allow_nan=False, allow_infinity=False)


def dense_max(curve, n=DENSE, values=None):
    """max over φ ∈ [0, 2π] of curve(φ-array), by samples then a bounded refinement."""
    phi = np.linspace(0.0, 2.0 * math.pi, n)
    values = curve(phi) if values is None else values
    best = float(values.max())
    for i in np.argsort(values)[-3:]:          # the three best samples, each refined
        lo, hi = phi[max(i - 1, 0)], phi[min(i + 1, n - 1)]
        res = minimize_scalar(lambda p: -float(curve(np.array([p]))[0]), bounds=(lo, hi),
                              method="bounded", options={"xatol": 1e-13})
        best = max(best, -res.fun)
    return best


@st.composite
def corner_designs(draw):
    """A valid design, often at a corner of the accepted domain."""
    corner = draw(st.sampled_from(["k_low", "k_high", "any"]))
    k = {"k_low": draw(st.floats(1.0005, 1.02, **finite)),
         "k_high": draw(st.floats(4.9, 5.0, **finite)),
         "any": draw(st.floats(1.02, 4.9, **finite))}[corner]
    crank = draw(st.floats(5.0, 400.0, **finite))
    theta = math.pi * (k - 1) / (k + 1)
    least = 2 * crank * (1 + math.sin(theta / 2))
    stroke = draw(st.floats(1.0, 3.0, **finite)) * least
    variant = draw(st.sampled_from(["block", "rod", "rod", "rod"]))
    try:
        base = synthesize(crank, k, stroke)
    except DesignError:
        assume(False)
    kwargs = {}
    if variant == "block":
        kwargs["guide"] = draw(st.sampled_from(["chord", "sagitta", "between"]))
        if kwargs["guide"] == "between":
            low = max(base.frame + base.crank, base.lever * math.cos(theta / 2) * 0.9)
            kwargs["guide"] = draw(st.floats(0.0, 1.0, **finite)) * (base.lever - low) * 0.999 + low * 1.0001
    else:
        guide = draw(st.floats(0.0, 1.0, **finite)) * 0.3 * base.lever + (base.frame + base.crank) * 1.001
        rise = max(guide - base.lever * math.cos(theta / 2), base.lever - guide)
        # A rod just long enough (a margin of 1e-6 … 1 over the reach limit) or a long one.
        margin = 10 ** draw(st.floats(-6.0, 0.5, **finite))
        kwargs.update(guide=guide, rod=rise / math.sqrt(1 - ROD_MARGIN ** 2) * (1 + margin),
                      rod_side=draw(st.sampled_from(["trailing", "leading"])))
    try:
        if draw(st.booleans()):
            return synthesize(crank, k, stroke, **kwargs)
        return from_dimensions(base.crank, base.frame, base.lever, **kwargs)
    except DesignError:
        assume(False)


def reference_peaks(design):
    dense = shape(design, np.linspace(0.0, 2.0 * math.pi, DENSE))
    curves = {"v_work": lambda s: s.ram1, "v_return": lambda s: -s.ram1,
              "a": lambda s: np.abs(s.ram2), "lever1": lambda s: np.abs(s.lever1),
              "lever2": lambda s: np.abs(s.lever2)}
    if design.rod is not None:
        curves["pressure"] = lambda s: pressure_angle(s.rod)
    return {name: dense_max(lambda phi, f=f: f(shape(design, phi)), values=f(dense))
            for name, f in curves.items()}


# The two true-extremum sweeps are slow sweeps (tests/sweeps.py): each example refines every
# curve's three best of 100 001 samples; CI draws a share of the examples, the profile
# thorough all of them; the explicit examples, the failures they once found, always run.
@pytest.mark.slow
@settings(max_examples=examples(60), deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(corner_designs())
# Found by this test: |a| peaks 0.055° beside a grid sample that lies on the sharp angle; the
# peak's cell ranked below a lower one and its tangent bound (invalid on a convex curve) did
# not vouch for it, so the sample (0.27 % low) was reported.
@example(Design(crank=5.0, frame=5.773502691896258, lever=26.933756729740644,
                guide=16.844371458779797, rod=10.408444851656489, rod_side="leading"))
def test_every_peak_is_the_true_extremum(design):
    metrics = analyze(design, [60.0])
    s = metrics.speeds[0]
    w = 2 * math.pi
    got = {"v_work": s.v_work_max_m_s * 1000 / w, "v_return": s.v_return_max_m_s * 1000 / w,
           "a": s.a_max_m_s2 * 1000 / w ** 2, "lever1": s.lever_omega_max_rad_s / w,
           "lever2": s.lever_alpha_max_rad_s2 / w ** 2}
    if design.rod is not None:
        got["pressure"] = math.radians(metrics.pressure_angle_max_deg)
    for name, ref in reference_peaks(design).items():
        # Within 1e-6 of the reference, and never below it by more than rounding: a rod at
        # its reach limit divides by a reach of 1e-3·L4, which costs a few digits.
        assert got[name] == pytest.approx(ref, rel=1e-6), name
        assert got[name] >= ref * (1 - 1e-7), name


def test_lever_peaks_closed_form_against_samples():
    for ratio in (1e-6, 0.1, 0.5, 0.8, 0.866):
        design = from_dimensions(ratio * 1000.0, 1000.0, 3000.0, guide=2500.0)
        omega, alpha = lever_peaks(np.array(ratio))
        assert omega == pytest.approx(ratio / (1 - ratio), rel=1e-12)   # crank pin between O2 and O4
        ref = dense_max(lambda phi: np.abs(shape(design, phi).lever2))
        assert alpha == pytest.approx(ref, rel=1e-9)


def test_sharp_peak_of_a_rod_at_its_reach_limit_is_found():
    """A rod that barely reaches the guide gives a narrow acceleration spike that a
    7200-point grid undersamples; the reported peak is still the spike's top."""
    base = synthesize(100.0, 1.6, 400.0)
    guide = base.lever * 0.95
    rise = max(guide - base.lever * math.cos(base.theta / 2), base.lever - guide)
    design = synthesize(100.0, 1.6, 400.0, guide=guide, rod=rise / math.sqrt(1 - ROD_MARGIN ** 2) * (1 + 1e-6))
    a_max = analyze(design, [60.0]).speeds[0].a_max_m_s2 * 1000 / (2 * math.pi) ** 2
    coarse = np.abs(shape(design, np.linspace(0, 2 * math.pi, 7200, endpoint=False)).ram2).max()
    ref = dense_max(lambda phi: np.abs(shape(design, phi).ram2), n=400_001)
    assert a_max == pytest.approx(ref, rel=1e-6)
    assert coarse < 0.99 * ref      # what the old fixed grid reported


def test_drive_margin_is_the_true_minimum():
    rng = np.random.default_rng(7)
    checked = 0
    while checked < 40:
        k = rng.uniform(1.01, 5.0)
        try:
            base = synthesize(rng.uniform(20, 200), k, rng.uniform(400, 2000))
            guide = base.lever * rng.uniform(0.9, 1.1)
            design = synthesize(base.crank, k, base.stroke, guide=guide,
                                rod=abs(base.lever - guide) + rng.uniform(0.01, 0.5) * base.lever,
                                rod_side=rng.choice(["leading", "trailing"]))
        except DesignError:
            continue
        checked += 1
        half = design.theta / 2
        psi = np.linspace(-half, half, 400_001)
        d = design.guide - design.lever * np.cos(psi)
        r = np.sqrt(design.rod ** 2 - d ** 2)
        ref = (r * np.cos(psi) - design.rod_sign * d * np.sin(psi)).min()
        got = rod_drive_margin(design)
        assert got <= ref + 1e-12 * design.rod
        assert got == pytest.approx(ref, rel=1e-7, abs=1e-9 * design.rod)


LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0, ram_cg_mm=(15.0, -30.0))


def torque_reference(design, rpm, masses, sign):
    """Largest sign·torque, each smooth piece refined separately (the cut switches it)."""
    phi = np.linspace(0.0, 2.0 * math.pi, 100_001)
    dyn = solve_dynamics(design, phi, [rpm], masses)
    values = sign * dyn.crank_torque[0]
    cutting = dyn.cut_force[0] > 0
    best = float(values.max())
    def at(p):
        dyn = solve_dynamics(design, np.array([p]), [rpm], masses)
        return sign * float(dyn.crank_torque[0, 0]), bool(dyn.cut_force[0, 0] > 0)

    for i in np.argsort(values)[-3:]:
        j, k = max(i - 1, 0), min(i + 1, phi.size - 1)
        if cutting[j] == cutting[i] == cutting[k]:
            res = minimize_scalar(lambda p: -at(p)[0], bounds=(phi[j], phi[k]), method="bounded",
                                  options={"xatol": 1e-12})
            best = max(best, -res.fun)
            continue
        # Next to a switch of the cut: find it by bisection on the solver's own cut force,
        # then take the torque just on either side of it (the one-sided values).
        a, b = (j, i) if cutting[j] != cutting[i] else (i, k)
        a, b = phi[a], phi[b]
        side = at(a)[1]
        for _ in range(60):
            mid = (a + b) / 2.0
            a, b = (mid, b) if at(mid)[1] == side else (a, mid)
        best = max(best, at(a)[0], at(b)[0])
    return best


@pytest.mark.slow
@settings(max_examples=examples(15), deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(corner_designs(), st.sampled_from([20.0, 60.0, 150.0]))
# A rod 0.002·L4 short of upright: the torque spikes to −2.8e7 N·m and both searches lose
# digits there (they differed by 2.5e-9 of the peak, beyond the 1e-9 this test once allowed).
@example(Design(crank=122.64474107129799, frame=141.7258956076097, lever=772.2971844546279,
                guide=264.63500731558656, rod=507.6631079490523, rod_side="leading"), 20.0)
def test_peak_torque_is_the_true_extremum(design, rpm):
    summary = summarize(design, [rpm], LOADS).speeds[0]
    top = torque_reference(design, rpm, LOADS, 1.0)
    bottom = -torque_reference(design, rpm, LOADS, -1.0)
    scale = max(abs(top), abs(bottom))
    # The dense reference can only fall short of the true peak (a switch between samples).
    assert top - 1e-8 * scale <= summary.max_torque_N_m <= top + 1e-6 * scale
    assert bottom - 1e-6 * scale <= summary.min_torque_N_m <= bottom + 1e-8 * scale


def test_grid_argmax_says_where_the_maximum_lies():
    """sin(x − c) on a coarse periodic grid peaks at c + π/2 (mod 2π); a rising line on a
    non-wrapping segment peaks at its last sample."""
    shift = np.array([0.0, 0.3, 2.0, 5.9])[:, None]
    x = np.arange(16) * (2 * math.pi / 16)
    fun = lambda t, c: (np.sin(t - c), np.cos(t - c))  # noqa: E731
    best, where = grid_argmax(fun, x, np.sin(x - shift), np.cos(x - shift), args=(shift,),
                              segments=[(0, 16, 2 * math.pi)])
    np.testing.assert_allclose(best, 1.0, rtol=0, atol=1e-15)
    np.testing.assert_allclose(np.mod(where - shift[:, 0] - math.pi / 2 + math.pi, 2 * math.pi),
                               math.pi, rtol=0, atol=1e-9)
    line = lambda t: (2.0 * t, np.full_like(t, 2.0))  # noqa: E731
    best, where = grid_argmax(line, x, 2.0 * x[None], np.full((1, 16), 2.0))
    assert (best.tolist(), where.tolist()) == ([2.0 * x[-1]], [x[-1]])


def _counting(fun):
    calls = []

    def counted(t, *args):
        calls.append(t.size)
        return fun(t, *args)
    return counted, calls


def test_polish_minimum_closes_a_bracket_once_its_minimum_is_found():
    """A parabola's vertex is found by the first interpolation; the bracket then closes
    with a probe at the tolerance on each side instead of golden sections on the wide one
    (the peak torque's polish took 17 calls of the closed form for this, now 8)."""
    centre = np.array([3e-5, -2e-4, 4e-4, 1.7])
    fun, calls = _counting(lambda t, c: 1e3 * (t - c) ** 2 + 5.0)
    xl, xr = centre - 9.3e-4, centre + 8.1e-4
    at, value = polish_minimum(fun, xl, centre + 1e-4, xr, [centre])
    used = len(calls)                           # the rule before this fix took 6
    np.testing.assert_allclose(at, centre, rtol=0, atol=1e-8)
    np.testing.assert_array_equal(value, fun(at, centre))
    assert used <= 4                            # one call for the three starting points


def test_polish_minimum_finds_smooth_minima_with_known_values():
    """cos has its minima at π + c; the bracket's values passed in are used as they are."""
    shift = np.linspace(-1.0, 1.0, 9)
    fun, calls = _counting(lambda t, c: np.cos(t - c))
    xl, xm, xr = math.pi + shift - 0.004, math.pi + shift + 0.001, math.pi + shift + 0.003
    at, value = polish_minimum(fun, xl, xm, xr, [shift],
                               values=tuple(np.cos(v - shift) for v in (xl, xm, xr)))
    np.testing.assert_allclose(at, math.pi + shift, rtol=0, atol=1e-8)
    np.testing.assert_allclose(value, -1.0, rtol=0, atol=1e-15)
    assert len(calls) <= 5                      # the rule before this fix took 17


def test_piece_maximum_finds_a_peak_just_inside_its_interval_whose_sample_lies_outside():
    """Issue 42, item 12: a sweep missed the peak torque of a design with K = 1.01 by 6e-5
    (−44.19116 N·m for −44.19401): the peak lay 0.006 rad inside the piece after the cut,
    its nearest sample just before the switch, outside the piece, so no sample inside
    was a local maximum and only the piece's end counted. Here f = −(x − 0.505)² sampled
    every 0.1 on [0, 1], the interval [0.503, 1]: the maximum, 0 at 0.505, is by hand."""
    from core.linkage.extrema import piece_maximum

    def f(x):
        return -(x - 0.505) ** 2

    x = np.linspace(0.0, 1.0, 11)
    best = piece_maximum(f, x, f(x)[None, :], np.array([0.503]), np.array([1.0]))
    assert best[0] == pytest.approx(0.0, abs=1e-15)
    # The same interval reached across a wrapping segment's end: [−0.497, 0.2] mod 1.
    g = lambda t: -(np.mod(t + 0.5, 1.0) - 0.5 - 0.005) ** 2    # noqa: E731 peak at 0.005
    best = piece_maximum(g, x[:-1], g(x[:-1])[None, :], np.array([0.003]), np.array([0.2]),
                         segments=[(0, 10, 1.0)], period=1.0)
    assert best[0] == pytest.approx(0.0, abs=1e-15)
