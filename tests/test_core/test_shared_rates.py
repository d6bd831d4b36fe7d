"""The sweep's grid shares the lever tip's terms between designs with the same L1, L2, L3
(core.metrics.shared_rates, issue 24): the rates are rates_at's, bit for bit."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from core import metrics
from core.designs import Designs
from core.kinematics import rates_at
from core.metrics import _BETA, _BETA_FINE, cycle_peaks, shared_rates
from core.spec import Spec
from core.sweep import grid, spec_designs


def _designs(levers: int, count: int, rod: bool, side: str = "trailing", seed: int = 0):
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
    col = _designs(levers, 1000, rod, side)
    _same(col, _BETA)
    _same(col, _BETA_FINE)
    assert np.isnan(rates_at(col, np.cos(_BETA), np.sin(_BETA)).ram1).any() == rod


@settings(max_examples=30, deadline=None)
@given(levers=st.integers(1, 12), count=st.integers(1, 300), seed=st.integers(0, 2 ** 32 - 1),
       rod=st.booleans())
def test_shared_rates_hypothesis(levers, count, seed, rod):
    _same(_designs(levers, count, rod, seed=seed), _BETA)


def test_the_sweep_of_rod_and_guide_shares_one_lever(monkeypatch):
    """The rod-ratio × guide family (the sweep benchmark's) computes the tip's terms for one
    design per chunk, and its peaks are those computed without sharing."""
    spec = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant="rod", rod_ratio=0.3)
    designs, verdict = spec_designs(spec, grid({"rod_ratio": (0.25, 1.15, 40),
                                                "guide": (480.0, 680.0, 40)}))
    good = designs.flat().take(np.flatnonzero(verdict.ok.reshape(-1)))
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
