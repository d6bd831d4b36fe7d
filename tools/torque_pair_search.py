"""Search for a torque peak the loaded sweep hides between two samples:
``python tools/torque_pair_search.py pairs SEED DESIGNS`` or ``… dense SEED BATCHES``.

Why: the sweep (core.forces.torque_peaks) polishes a peak where the torque's slope T′ changes
sign between two samples. Two zeros of T′ in one cell change no sign there: a maximum and a
minimum of T beside each other that no sign change shows (the energy's search had that blind
spot and was fixed: core.forces.bumps). Such a pair is of no account unless its peak is the
cycle's: T′ keeps its sign on both sides of the pair, so T passes the pair's peak again within
about twice the pair's half-width h (h ≤ 0.035 rad to fit a 4° cell), unless a switch angle of
the cut comes first or T′ has a third zero as close. Both searches compare the sweep (90
intervals) and ``summarize`` (3600) with the solver's torque (core.forces.dynamics: no jet, no
polish) on dense angles, its best sample refined on 401 more angles across its two cells: a
lower bound on the true extreme, independent of the bracketing.

``pairs``: for DESIGNS random designs (block and rod, both sides) and random loads, each at 21
cutting forces 0 … 20 kN, the speeds where the torque with the cut or without it has a double
zero of T′ in the working stroke (T′ = T″ = 0: ω² = −S″/I″ where S′ + ω²·I′ crosses 0), moved
so that T′'s extremum there is ∓ε (ε 1e-4, 1e-3, 3e-3 of the torque's size: a pair of
half-width h inside one cell), and the idle fraction that puts a switch angle 1.2, 1.5 or 1.9·h
after the pair or before it, as its piece requires for the pair's peak to be the piece's.
Prints how many it built, how near the pair's region came to the cycle's largest or least
torque (as a share of the torque's size), and every case where the sweep or the summary is
below the dense reference by more than 1e-9 of the torque's size (each case whose pair lies
within 1e-3 of an extreme is compared).

``dense``: BATCHES families of 60 random designs (K 1.02 … 4.5, L1 20 … 200 mm, rod ratios
0.2 … 1.5) with random loads at 16 random speeds of 1 … 400 r/min, every design compared on
20 001 angles, and its energy swing with the closed-form energy sampled on 20 000 intervals.
"""
import math
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests"), str(ROOT / "tests" / "test_core")]

from test_sweep_loaded import _loads  # noqa: E402

from core.base.errors import DesignError  # noqa: E402
from core.forces.dynamics import solve_dynamics  # noqa: E402
from core.forces.flywheel import cycle_summary, summarize  # noqa: E402
from core.forces.jet import torque_jet  # noqa: E402
from core.linkage.designs import Designs, synthesize_many  # noqa: E402
from core.linkage.geometry import Design, synthesize  # noqa: E402
from core.linkage.kinematics import rpm_to_omega, solve  # noqa: E402
from core.space.sweep import SWEEP_INTERVALS  # noqa: E402

TOL = 1e-9


def deficits(design: Design, rpms: np.ndarray, masses, phi: np.ndarray, rows: dict) -> np.ndarray:
    """Per speed, how far the largest of ``rows``' (name → (speeds,) values) maxima and minima
    falls short of the solver's torque on ``phi`` refined about its best sample (sign·T), as a
    share of the torque's size; shape (names, 2, speeds)."""
    t = solve_dynamics(design, phi, rpms, masses).crank_torque
    step = phi[1] - phi[0]
    out = []
    for high, low in rows.values():
        scale = np.maximum(np.abs(high), np.abs(low))
        both = []
        for sign, got in ((1.0, high), (-1.0, low)):
            best = np.argmax(sign * t, axis=1)
            fine = (phi[best][:, None] + np.linspace(-step, step, 401)[None, :]).ravel()
            tf = solve_dynamics(design, fine, rpms, masses).crank_torque.reshape(rpms.size, rpms.size, 401)
            ref = np.maximum(np.max(sign * t, axis=1),
                             np.max(sign * tf[np.arange(rpms.size), np.arange(rpms.size)], axis=1))
            both.append((ref - sign * got) / scale)
        out.append(both)
    return np.array(out)


def random_design(rng) -> Design | None:
    k, crank = rng.uniform(1.1, 4.0), rng.uniform(30.0, 180.0)
    stroke = rng.uniform(2.3, 3.2) * crank * 2.0
    rod = None if rng.random() < 0.4 else rng.uniform(0.25, 1.2)
    try:
        if rod is None:
            return synthesize(crank, k, stroke)
        return synthesize(crank, k, stroke, rod_ratio=rod,
                          rod_side=str(rng.choice(["trailing", "leading"])))
    except DesignError:
        return None


def double_zeros(design: Design, masses, phi: np.ndarray, cutting: float) -> list[tuple]:
    """(index into ``phi``, ω², T‴, I′, torque size) where T = S + ω²·I (with the cut's share if
    ``cutting``) has T′ = T″ = 0 at a speed of 1 … 600 r/min."""
    jet = torque_jet(Designs.of(design).column(), phi[None, :], masses)
    s1, s2 = (jet.static1 + cutting * jet.cut1)[0], (jet.static2 + cutting * jet.cut2)[0]
    i1, i2 = jet.inertial1[0], jet.inertial2[0]
    with np.errstate(all="ignore"):
        w2 = -s2 / i2
        g = s1 + w2 * i1
        rpm = np.sqrt(np.where(w2 > 0.0, w2, np.nan)) * 30.0 / math.pi
    cross = ((g[:-1] > 0.0) != (g[1:] > 0.0)) & (np.abs(g[:-1]) < 1e3 * np.abs(s1).max()) \
        & (rpm[:-1] >= 1.0) & (rpm[:-1] <= 600.0)
    out = []
    for j in np.flatnonzero(cross):
        t3 = np.gradient(s2 + w2[j] * i2, phi)[j]
        size = np.max(np.abs((jet.static + cutting * jet.cut)[0] + w2[j] * jet.inertial[0]))
        out.append((j, w2[j], t3, i1[j], size))
    return out


def pairs(seed: int, designs: int) -> None:
    rng = np.random.default_rng(seed)
    dense = np.linspace(0.0, 2.0 * math.pi, 200_001)
    coarse = np.linspace(0.0, 2.0 * math.pi, 20_001)
    zeros, built, compared, nearest, misses = 0, 0, 0, math.inf, []
    for _ in range(designs):
        design = random_design(rng)
        if design is None:
            continue
        base = _loads(rng, design.rod is not None)
        phi = np.linspace(0.0, math.pi + design.theta, 20_001)
        x = np.ravel(solve(design, phi, [1.0]).ram_x)
        x = x - x[0]
        for force in np.linspace(0.0, 20_000.0, 21):
            masses = replace(base, cut_force_N=float(force))
            for cutting in (0.0, 1.0):
                found = double_zeros(design, masses, phi, cutting)
                zeros += len(found)
                for j, w0, t3, i1, size in found:
                    for share in (1e-4, 1e-3, 3e-3):
                        eps = share * size
                        half = math.sqrt(2.0 * eps / abs(t3))
                        w2 = w0 + (-eps if t3 > 0.0 else eps) / i1
                        if not (half <= 0.035 and w2 > 0.0):
                            continue
                        rpm = np.array([math.sqrt(w2) * 30.0 / math.pi])
                        for gap in (1.2, 1.5, 1.9, -1.2, -1.5, -1.9):
                            travel = float(np.interp(phi[j] + gap * half, phi, x)) / design.stroke
                            # the cut ends (1 − idle)·H after its start; the rest of the cycle is the other way
                            idle = (1.0 - travel if gap > 0 else travel) if cutting else \
                                (travel if gap > 0 else 1.0 - travel)
                            if not 0.0 <= idle < 0.49:
                                continue
                            m = replace(masses, idle_fraction=idle)
                            built += 1
                            t = solve_dynamics(design, coarse, rpm, m).crank_torque[0]
                            near = np.abs(coarse - phi[j]) < 2.5 * half
                            if not near.any():
                                continue
                            top = np.abs(t).max()
                            gap_share = min(t.max() - t[near].max(), t[near].min() - t.min()) / top
                            nearest = min(nearest, gap_share)
                            if gap_share > 1e-3:
                                continue
                            compared += 1
                            got = cycle_summary(Designs.of(design), rpm_to_omega(rpm), m,
                                                intervals=SWEEP_INTERVALS)
                            one = summarize(design, rpm, m).speeds[0]
                            rows = {"sweep": (got["max_torque_N_m"][0], got["min_torque_N_m"][0]),
                                    "summary": (np.array([one.max_torque_N_m]),
                                                np.array([one.min_torque_N_m]))}
                            worst = float(deficits(design, rpm, m, dense, rows).max())
                            if worst > TOL:
                                misses.append((worst, design, m, float(rpm[0])))
    print(f"seed {seed}: {zeros} double zeros of T′ in the working stroke (both curves, 21 "
          f"cutting forces per design); {built} pairs built beside a switch angle; the nearest came within "
          f"{nearest:.3g} of the torque's size to the cycle's largest or least torque; "
          f"{compared} compared; misses: {misses}")


def dense_draw(seed: int, batches: int) -> None:
    rng = np.random.default_rng(seed)
    phi = np.linspace(0.0, 2.0 * math.pi, 20_001)
    count, worst = 0, np.zeros(3)
    for _ in range(batches):
        rod = rng.random() < 0.6
        side = str(rng.choice(["leading", "trailing"]))
        crank = rng.uniform(20.0, 200.0, 60)
        k = np.exp(rng.uniform(math.log(1.02), math.log(4.5), 60))
        theta = math.pi * (k - 1.0) / (k + 1.0)
        stroke = rng.uniform(1.05, 3.0, 60) * 2.0 * crank * (1.0 + np.sin(theta / 2.0))
        extra = dict(rod_ratio=rng.uniform(0.2, 1.5, 60), rod_side=side) if rod else {}
        d, verdict = synthesize_many(crank, k, stroke, **extra)
        d = d.take(np.flatnonzero(verdict.ok))
        masses = _loads(rng, rod)
        rpms = np.sort(np.exp(rng.uniform(0.0, math.log(400.0), 16)))
        got = cycle_summary(d, rpm_to_omega(rpms), masses, intervals=SWEEP_INTERVALS)
        for i in range(d.shape[0]):
            design = Design(crank=float(d.crank[i]), frame=float(d.frame[i]), lever=float(d.lever[i]),
                            guide=float(d.guide[i]), rod=float(d.rod[i]) if rod else None, rod_side=side)
            rows = {"sweep": (got["max_torque_N_m"][i], got["min_torque_N_m"][i])}
            worst[:2] = np.maximum(worst[:2], deficits(design, rpms, masses, phi, rows)[0].max(axis=1))
            swing = np.ptp(summarize(design, rpms, masses, intervals=20_000, peaks=False).energy, axis=1)
            short = (swing - got["energy_fluctuation_J"][i]) / np.maximum(swing, 1e-12)
            worst[2] = max(worst[2], float(short.max()))
            count += rpms.size
    print(f"seed {seed}: {count} (design, speed) pairs; the sweep at most {worst[0]:.3g} (largest "
          f"torque), {worst[1]:.3g} (least torque) of the torque's size and {worst[2]:.3g} of the "
          f"energy swing below the dense reference")


if __name__ == "__main__":
    mode, seed, size = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    (pairs if mode == "pairs" else dense_draw)(seed, size)
