"""The least rod that clears a dead centre (core.linkage.drive.least_rod), against what it
rests on and against two other methods: the drive margin less ROD_MARGIN·L4 grows with the
rod (so one length separates the rods that jam from those that do not), a bisection of the
rule itself finds the same length, and a brute-force margin on 200 001 angles agrees on both
sides of it. And it is searched only when a refusal's reason is read, once for all designs."""
from __future__ import annotations

import numpy as np
import pytest

from core.linkage import designs as designs_module
from core.linkage.designs import Designs, dimensions_many
from core.linkage.drive import ROD_MARGIN, _settled, drive_margin, jams, largest_rise, least_rod


def random_rods(n: int, seed: int, side: str = "trailing") -> Designs:
    """Rod designs past their reach rule, a quarter of which jam at a dead centre."""
    rng = np.random.default_rng(seed)
    crank = rng.uniform(10.0, 600.0, n)
    frame = crank / rng.uniform(0.05, 0.866, n)
    reach = crank + frame
    lever = reach * rng.uniform(1.0, 2.5, n)
    guide = reach + (1.3 * lever - reach) * rng.uniform(0.0, 1.0, n)
    d = Designs(crank, frame, lever, guide, np.ones(n), side)
    return d.with_lengths(d.lengths()[:4] + [largest_rise(d) * (1.001 + rng.uniform(0.0, 1.0, n) ** 2)])


def stuck(d: Designs) -> Designs:
    return d.take(jams(d, np.ones(d.rod.shape, dtype=bool)))


def test_the_margin_less_rod_margin_grows_with_the_rod():
    """What the least rod rests on: d/dL4 (r·cos ψ − s·d·sin ψ) = (L4/r)·cos ψ ≥ cos(θ/2) at
    every ψ (r = sqrt(L4² − d²) ≤ L4), so the minimum over ψ grows at least that fast, and
    cos(θ/2) ≥ 1/2 > ROD_MARGIN (θ ≤ 120° at K ≤ 5). Here on 60 rods from each design's
    reach up to 20 times it, by finite differences of the margin itself."""
    for side in ("trailing", "leading"):
        d = random_rods(500, 1, side)
        rods = largest_rise(d)[:, None] * (1.0001 + np.geomspace(1e-6, 20.0, 60))
        many = Designs(*(v[:, None] for v in d.lengths()[:4]), rods, side).flat()
        margin = drive_margin(many).reshape(rods.shape) - ROD_MARGIN * rods
        slope = np.diff(margin, axis=1) / np.diff(rods, axis=1)
        floor = np.cos(d.theta / 2.0)[:, None] - ROD_MARGIN
        assert np.all(slope >= floor * (1.0 - 1e-6)), slope.min()


@pytest.mark.parametrize("side", ["trailing", "leading"])
def test_the_least_rod_is_the_rules_own_bisection(side):
    """A second method: bisection of the rule (``jams``) from the rod as given up to one the
    margin's floor vouches for, to 1e-12. The closed form per ψ, maximized over the swing, is
    stated 1e-9 past the exact length, so the two differ by 1e-9 of it and no more."""
    d = stuck(random_rods(3000, 2, side))
    assert d.rod.size > 500
    least = least_rod(d)
    bisected = _settled(d, d.rod)
    assert np.all(least > d.rod)
    assert np.abs(least / bisected - 1.0 - 1e-9).max() < 5e-12


def test_the_least_rod_is_right_by_brute_force():
    """A third: the margin on 200 001 angles over the swing (no polish), at the least rod and
    1e-6 shorter: the rule's margin is cleared at the first and not at the second."""
    d = stuck(random_rods(400, 3))
    least = least_rod(d)
    for rod, clears in ((least, True), (least * (1.0 - 1e-6), False)):
        margin = _brute_margin(d, rod, 200_001)
        assert np.all((margin > ROD_MARGIN * rod) == clears)


def _brute_margin(d: Designs, rod: np.ndarray, angles: int, rows: int = 16) -> np.ndarray:
    """min over ``angles`` ψ across the swing of r·cos ψ − s·d·sin ψ, each design's row by
    the same elementwise arithmetic, ``rows`` designs at a time: the whole (designs × 200 001)
    arrays were some 100 MB each, and the time went into memory, not arithmetic (6.8 s;
    the minimum is exact, so the blocks give the same values bit for bit)."""
    out = np.empty(rod.shape)
    for i in range(0, rod.size, rows):
        part = slice(i, i + rows)
        psi = (d.theta[part] / 2.0)[:, None] * np.linspace(-1.0, 1.0, angles)
        depth = d.guide[part, None] - d.lever[part, None] * np.cos(psi)
        reach = np.sqrt(rod[part, None] ** 2 - depth ** 2)
        out[part] = (reach * np.cos(psi) - d.rod_sign * depth * np.sin(psi)).min(axis=1)
    return out


def test_the_least_rod_is_searched_only_when_a_reason_is_read(monkeypatch):
    """A sweep refuses many designs at a dead centre; the search runs when the first reason is
    read, for all of them at once, and never for a sweep that reads none."""
    calls = []

    def counted(d):
        calls.append(d.rod.size)
        return least_rod(d)

    monkeypatch.setattr(designs_module, "least_rod", counted)
    d = random_rods(2000, 4)
    _, verdict = dimensions_many(d.crank, d.frame, d.lever, guide=d.guide, rod=d.rod)
    refused = np.flatnonzero(~verdict.ok)
    assert refused.size > 300 and calls == []
    texts = [verdict.error(int(i)).allowed for i in refused]
    assert calls == [refused.size]
    assert all("lengthen it to at least" in t for t in texts)
    printed = np.array([float(t.split("at least ")[1].split()[0]) for t in texts])
    least = least_rod(d.take(refused))
    assert np.all((printed >= least) & (printed <= least * (1.0 + 1e-5)))
