"""The sweep's faster paths give the figures of the slower ones (issue 24).

The grid shares the lever tip's terms between designs with the same L1, L2, L3
(core.linkage.metrics.shared_rates): the rates are rates_at's, bit for bit. The peaks are
polished by Newton's method on the slope: the fourth derivative it needs
(core.linkage.rates.rates4_at) is checked against finite differences of the third, the
polisher (polish.newton_maximum) against maxima known in closed form, and the peaks
against those of the bracketed search it replaces.
"""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from core.linkage import metrics
from core.linkage.designs import Designs
from core.linkage.extrema import grid_argmax
from core.linkage.polish import newton_maximum
from core.linkage.rates import rates4_at, rates_at
from core.linkage.metrics import _BETA, _BETA_FINE, cycle_peaks, shared_rates
from core.linkage.spec import Spec
from core.space.sweep import grid, spec_designs

finite = dict(allow_nan=False, allow_infinity=False)


def rod_family(count: int) -> Designs:
    """The valid designs of a rod-ratio × guide sweep (the benchmark's family), count²."""
    spec = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant="rod", rod_ratio=0.3)
    designs, verdict = spec_designs(spec, grid({"rod_ratio": (0.25, 1.15, count),
                                                "guide": (480.0, 680.0, count)}))
    return designs.flat().take(np.flatnonzero(verdict.ok.reshape(-1)))


def _levers(levers: int, count: int, rod: bool, side: str = "trailing", seed: int = 0):
    """``count`` designs drawn from ``levers`` distinct (L1, L2, L3), shuffled, each with its
    own guide and rod (some too short to reach: NaN rates)."""
    rng = np.random.default_rng(seed)
    crank = rng.uniform(60.0, 140.0, levers)
    frame = crank / rng.uniform(0.2, 0.8, levers)
    lever = (frame + crank) * rng.uniform(1.05, 1.6, levers)
    pick = rng.integers(0, levers, count)
    guide = (frame + crank)[pick] * rng.uniform(1.01, 1.3, count)
    rodlen = lever[pick] * rng.uniform(0.05, 1.2, count) if rod else None
    return Designs(crank[pick], frame[pick], lever[pick], guide, rodlen, side).column()


def _same(col: Designs, beta: np.ndarray) -> None:
    cos, sin = np.cos(beta), np.sin(beta)
    want, got = rates_at(col, cos, sin), shared_rates(col, cos, sin)
    for a, b in zip(want, got):
        assert a.shape == b.shape
        np.testing.assert_array_equal(a, b)           # NaN where the rod cannot reach, alike


@pytest.mark.parametrize("levers", [1, 3, 40, 1000])
@pytest.mark.parametrize("rod,side", [(False, "trailing"), (True, "trailing"), (True, "leading")])
def test_shared_rates_are_rates_at_bit_for_bit(levers, rod, side):
    """One lever (broadcast views), a few (gathered rows), all distinct (rates_at itself)."""
    col = _levers(levers, 1000, rod, side)
    _same(col, _BETA)
    _same(col, _BETA_FINE)
    assert np.isnan(rates_at(col, np.cos(_BETA), np.sin(_BETA)).ram1).any() == rod


@settings(max_examples=30, deadline=None)
@given(levers=st.integers(1, 12), count=st.integers(1, 300), seed=st.integers(0, 2 ** 32 - 1),
       rod=st.booleans())
def test_shared_rates_hypothesis(levers, count, seed, rod):
    _same(_levers(levers, count, rod, seed=seed), _BETA)


def test_the_sweep_of_rod_and_guide_shares_one_lever(monkeypatch):
    """The rod-ratio × guide family (the sweep benchmark's) computes the tip's terms for one
    design per chunk, and its peaks are those computed without sharing."""
    good = rod_family(40)
    sizes = []
    tip_rates = metrics.tip_rates
    monkeypatch.setattr(metrics, "tip_rates",
                        lambda d, c, s: sizes.append(d.crank.size) or tip_rates(d, c, s))
    shared = cycle_peaks(good)
    assert sizes == [1]
    monkeypatch.setattr(metrics, "SHARE_BELOW", -1.0)          # never share
    alone = cycle_peaks(good)
    for name in shared.__dataclass_fields__:
        np.testing.assert_array_equal(getattr(shared, name), getattr(alone, name))


def _designs(count, rod, side="trailing", seed=3):
    rng = np.random.default_rng(seed)
    crank = rng.uniform(20.0, 200.0, count)
    frame = crank / rng.uniform(0.05, 0.86, count)
    lever = (frame + crank) * rng.uniform(1.02, 2.0, count)
    guide = (frame + crank) * rng.uniform(1.01, 1.4, count)
    # A rod whose reach stays above ~0.3·L4 (its largest rise is at ψ = 0 or a dead point):
    # closer to its limit, the fifth and higher derivatives outgrow a difference quotient.
    rise = np.maximum(np.abs(guide - lever), guide - lever * np.sqrt(1.0 - (crank / frame) ** 2))
    rodlen = rise * rng.uniform(1.05, 3.0, count) if rod else None
    return Designs(crank, frame, lever, guide, rodlen, side).column()


@pytest.mark.parametrize("rod,side", [(False, "trailing"), (True, "trailing"), (True, "leading")])
def test_fourth_derivative_is_the_slope_of_the_third(rod, side):
    """d⁴Cx/dφ⁴ against the five-point difference of d³Cx/dφ³ (its error ~h⁴·f⁽⁸⁾ falls 16×
    as h halves: at h = 1e-3 it reached 2e-6 of the scale for a crank of 0.83·L2), and the
    first three are rates_at's, bit for bit."""
    col = _designs(300, rod, side)
    beta = np.linspace(0.0, 2.0 * math.pi, 97)
    got = rates4_at(col, np.cos(beta), np.sin(beta))
    for a, b in zip(rates_at(col, np.cos(beta), np.sin(beta)), got[:3]):
        np.testing.assert_array_equal(a, b)
    h = 2.5e-4

    def third(shift):       # d/dφ = −d/dβ: φ + shift is β − shift
        return rates_at(col, np.cos(beta - shift), np.sin(beta - shift)).ram3
    diff = (-third(2 * h) + 8 * third(h) - 8 * third(-h) + third(-2 * h)) / (12 * h)
    ok = np.isfinite(diff) & np.isfinite(got[3])
    assert ok.mean() > 0.5
    scale = np.nanmax(np.abs(got[3]), axis=-1, keepdims=True)
    np.testing.assert_array_less(np.abs(diff - got[3])[ok], (1e-7 * np.broadcast_to(scale, ok.shape))[ok])


def _cell(fun, centre, width, offset):
    """The cell [lo, hi] ∋ centre of a grid of step ``width`` shifted by ``offset``, with the
    curve's values and slopes at its ends."""
    lo = centre - offset * width
    hi = lo + width
    (v_lo, s_lo, _), (v_hi, s_hi, _) = fun(lo), fun(hi)
    return lo, hi, v_lo, v_hi, s_lo, s_hi


def skewed_peak(centre: float, size: float, skew: float, calls: list):
    """f(x) = size·(cos t + skew·sin²t/2), t = x − centre, as (f, f′, f″): top at the
    centre, f″ = −size(1 − skew) < 0 there; each call's size is appended to ``calls``."""
    def fun(x):
        calls.append(np.size(x))
        t = x - centre
        return (size * (np.cos(t) + 0.5 * skew * np.sin(t) ** 2),
                size * (-np.sin(t) + skew * np.sin(t) * np.cos(t)),
                size * (-np.cos(t) + skew * np.cos(2.0 * t)))
    return fun


@settings(max_examples=60, deadline=None)
@given(centre=st.floats(-3.0, 3.0, **finite), offset=st.floats(0.01, 0.99, **finite),
       width=st.floats(0.01, 0.3, **finite), size=st.floats(0.1, 1e4, **finite),
       skew=st.floats(-0.9, 0.9, **finite))
def test_newton_maximum_finds_a_known_maximum(centre, offset, width, size, skew):
    """A skewed peak f(x) = size·(cos(x − c) + skew·sin²(x − c)/2), whose top is at c
    exactly (f′(c) = 0, f″(c) = −size(1 − skew) < 0): found to the tolerance in at most
    five evaluations, from a cell of a 64-sample grid or coarser."""
    calls = []
    fun = skewed_peak(centre, size, skew, calls)
    lo, hi, v_lo, v_hi, s_lo, s_hi = _cell(fun, centre, width, offset)
    calls.clear()
    x, value = newton_maximum(fun, np.array([lo]), np.array([hi]), np.array([v_lo]),
                              np.array([v_hi]), np.array([s_lo]), np.array([s_hi]))
    assert abs(x[0] - centre) <= 2e-12 * (1.0 + abs(centre))
    assert value[0] == pytest.approx(size, rel=1e-15)
    assert len(calls) <= 5


def test_newton_maximum_ends_on_a_flat_top_and_on_nan():
    """A quartic top (zero curvature: Newton gains only a third a step) still ends, at its
    top to within its flatness; a curve that turns NaN inside the cell ends by bisection."""
    def quartic(x):
        return -(x - 0.3) ** 4, -4.0 * (x - 0.3) ** 3, -12.0 * (x - 0.3) ** 2
    lo, hi = np.array([0.25]), np.array([0.35])
    (v_lo, s_lo, _), (v_hi, s_hi, _) = quartic(lo), quartic(hi)
    x, value = newton_maximum(quartic, lo, hi, v_lo, v_hi, s_lo, s_hi)
    assert abs(x[0] - 0.3) < 1e-5 and value[0] > -1e-20

    def broken(x):
        nan = np.full(np.shape(x), np.nan)
        return nan, nan, nan
    x, value = newton_maximum(broken, lo, hi, np.array([1.0]), np.array([1.0]),
                              np.array([1.0]), np.array([-1.0]), iterations=200)
    assert lo[0] <= x[0] <= hi[0] and np.isnan(value[0])


def test_sweep_peaks_equal_the_bracketed_search_in_three_or_four_evaluations(monkeypatch):
    """The rod-ratio × guide family: every peak within 2e-14 (relative) of the bracketed
    search's (Chandrupatla's method on the slope, then the value: seven evaluations), here
    in at most four evaluations of the curves. Both land within the tolerance of the slope's
    zero, at different points: the values differ by their rounding (a few ulps; a 40-digit
    reference put both within 7 ulps of the truth, neither closer on the whole)."""
    good = rod_family(30)
    sizes = []
    curves = metrics._ram_curves
    monkeypatch.setattr(metrics, "_ram_curves",
                        lambda t, *a, side: sizes.append(t.size) or curves(t, *a, side=side))
    newton = metrics.cycle_peaks(good)
    assert 2 <= len(sizes) <= 4

    def bracketed(fun, *args, **kwargs):
        kwargs["newton"] = False
        return grid_argmax(lambda t, *a: fun(t, *a)[:2], *args, **kwargs)
    monkeypatch.setattr(metrics, "grid_argmax", bracketed)
    old = metrics.cycle_peaks(good)
    for name in ("v_work", "v_return", "a_max"):
        a, b = getattr(newton, name), getattr(old, name)
        np.testing.assert_allclose(a, b, rtol=2e-14, atol=0)
    for name in ("v_work_at", "v_return_at"):
        np.testing.assert_allclose(getattr(newton, name), getattr(old, name), rtol=0, atol=1e-10)


def test_reasons_read_each_rule_flattened_once(monkeypatch):
    """Verdict.error reads a rule's values (and a message's numbers) from arrays flattened
    once per rule, not once per invalid design; the errors are those of the designs alone."""
    from core.linkage import designs as designs_module
    from core.linkage import verdict as verdict_module
    from core.linkage.geometry import synthesize
    k, stroke = np.meshgrid(np.linspace(1.05, 4.95, 40), np.linspace(150.0, 600.0, 30))
    _, verdict = designs_module.synthesize_many(100.0, k, stroke, rod_ratio=0.3)  # 2-D
    bad = np.flatnonzero(~verdict.ok.reshape(-1))
    assert bad.size > 300
    calls = []
    broadcast = np.broadcast_to
    monkeypatch.setattr(verdict_module.np, "broadcast_to",
                        lambda *a, **kw: calls.append(1) or broadcast(*a, **kw))
    errors = [verdict.error(int(i)) for i in bad]
    monkeypatch.undo()
    assert len(calls) <= 2 * len(verdict.rules)
    for i in bad[::17]:
        with pytest.raises(Exception) as single:
            synthesize(100.0, float(k.reshape(-1)[i]), float(stroke.reshape(-1)[i]), rod_ratio=0.3)
        assert str(single.value) == str(errors[list(bad).index(i)])
