"""The rod's drive: how near each design's rod comes to lying in line with the lever (a dead
centre), and the least rod that keeps clear of it.

Below :mod:`core.linkage.designs`, whose dead-centre rule is :func:`jams` and whose refusal
names :func:`least_rod`. It reads a :class:`~core.linkage.designs.Designs` (the fields
:class:`Designs` here names), never builds one, so it does not import that module.
"""
from __future__ import annotations

from typing import Protocol

import numpy as np

from core.base.arrays import sorted_unique
from .extrema import grid_maximum, grid_minimum


class Designs(Protocol):
    """What this module reads of :class:`core.linkage.designs.Designs` (the rod variant's
    arrays, mm and rad), stated here so that it imports nothing above it: ``designs``
    imports this module, and an import back, even for type checking only, is a cycle."""

    crank: np.ndarray
    frame: np.ndarray
    lever: np.ndarray
    guide: np.ndarray
    rod: np.ndarray

    @property
    def theta(self) -> np.ndarray: ...

    @property
    def rod_sign(self) -> float: ...

    def take(self, which: np.ndarray) -> "Designs": ...

    def lengths(self) -> list[np.ndarray]: ...

    def with_lengths(self, lengths: list[np.ndarray], theta: np.ndarray | None = None) -> "Designs": ...


# The rod must keep a horizontal reach |Cx − Bx| and a drive margin of this fraction of
# L4 (a pressure angle below 89.94°), so forces and accelerations stay finite and exact.
ROD_MARGIN = 1e-3
# Unit offsets of the ψ grid on [−1, 1] (times θ/2): uniform, plus points crowding
# geometrically toward ψ = 0 and the two ends, where the rod can stand nearly upright and
# the drive margin can dip sharply (see drive_margin).
_CROWD = 5.0 ** -np.arange(2, 9)
_PSI_UNIT = sorted_unique(np.concatenate([np.linspace(-1.0, 1.0, 33), _CROWD, -_CROWD,
                                          1.0 - _CROWD, _CROWD - 1.0]))
# The least rod's ψ grid: the least rod at each ψ (_least_at) is smooth, without the margin's
# sharp dips, and on 51 493 random jammed designs (tests/test_core/test_drive.py's
# random_rods) 9, 17 or 33 uniform samples found the same maximum as _PSI_UNIT, to the bit.
_LEAST_UNIT = np.linspace(-1.0, 1.0, 17)
_CHUNK = 4096
# The least rod is stated this far (relative) past the length where the margin is exactly
# ROD_MARGIN·L4, which the rule refuses: far below the six digits it is printed to, far
# above the margin's round-off (its slope in L4 is at least cos(θ/2) − ROD_MARGIN ≥ 0.499).
_PAST = 1e-9


def largest_rise(d: "Designs") -> np.ndarray:
    """The largest |guide − By| over the swing, mm: the rod's rise d = guide − L3·cos ψ is
    largest in size at ψ = 0 (By = L3) or at a limit position (By = L3·cos(θ/2))."""
    with np.errstate(all="ignore"):
        tip_low = d.lever * np.sqrt(1.0 - np.minimum(d.crank / d.frame, 1.0) ** 2)
        return np.maximum(d.guide - tip_low, d.lever - d.guide)


def drive_margin(d: "Designs") -> np.ndarray:
    """min over the swing of r·cos ψ − s·d·sin ψ, mm, per design (rod variant).

    r·cos ψ − s·d·sin ψ is the rod's extent measured square to the lever (the
    cross product of the lever's and the rod's directions, times L4): zero where
    the rod lies in line with the lever, which then has no arm to drive it (a
    dead centre). d = guide − L3·cos ψ is largest in size at ψ = 0 or an end of the
    swing, so the rod's reach r = sqrt(L4² − d²) is smallest, and the margin
    can dip sharply, only there: the grid over ψ ∈ [−θ/2, θ/2] crowds toward
    those points. The smallest sample is then polished to the zero of the
    margin's analytic slope (see :mod:`core.linkage.extrema`), so a narrow dip between
    samples is not missed.
    """
    sign = d.rod_sign

    def drive(psi, rod, guide, lever):
        cos, sin = np.cos(psi), np.sin(psi)
        depth = guide - lever * cos
        reach = np.sqrt(np.maximum(rod ** 2 - depth ** 2, 0.0))
        depth1 = lever * sin
        with np.errstate(all="ignore"):
            reach1 = np.where(reach > 0.0, -depth * depth1 / reach, 0.0)
        return (reach * cos - sign * depth * sin,
                reach1 * cos - reach * sin - sign * (depth1 * sin + depth * cos))

    return _over_swing(d, drive, grid_minimum, (d.rod, d.guide, d.lever), _PSI_UNIT)


def jams(d: "Designs", among: np.ndarray) -> np.ndarray:
    """Which of the designs marked in ``among`` come within ROD_MARGIN·L4 of a dead centre:
    a drive margin (:func:`drive_margin`) ≤ ROD_MARGIN·L4. Where the margin's floor
    r_min·cos(θ/2) − |d|_max·sin(θ/2) already clears twice that, the exact minimum is not
    needed (it changes no verdict) and is not computed."""
    rod = np.broadcast_to(d.rod, among.shape)
    margin = np.full(among.shape, np.inf)
    todo = among & ~(_margin_floor(d) > 2.0 * ROD_MARGIN * rod)
    if todo.any():
        margin[todo] = drive_margin(d.take(todo))
    return margin <= ROD_MARGIN * rod


def least_rod(d: "Designs") -> np.ndarray:
    """The least rod length, mm, that :func:`jams` passes, for each design (rod variant),
    the rest of the design as it is; a length past MAX_LENGTH_MM where that is what it takes.

    The drive margin grows with L4 faster than ROD_MARGIN·L4 at every ψ (∂/∂L4 of
    r·cos ψ − s·d·sin ψ is (L4/r)·cos ψ ≥ cos(θ/2) ≥ 1/2), so a rod passes from one length
    on. At each ψ, r·cos ψ − s·d·sin ψ = ROD_MARGIN·L4 is a quadratic in L4 (squared), whose
    root is the least rod at that ψ (:func:`_least_at`); the least rod is its maximum over
    the swing, found as the drive margin's minimum is. A rod ``_PAST`` longer is then
    checked by the rule itself, and any design it refuses (a maximum the grid missed)
    bisected by the rule between that rod and one the margin's floor vouches for."""
    sign = d.rod_sign
    start = _over_swing(d, lambda psi, guide, lever: _least_at(psi, guide, lever, sign),
                        grid_maximum, (d.guide, d.lever), _LEAST_UNIT)
    return _settled(d, np.maximum(start, d.rod))


def _settled(d: "Designs", start: np.ndarray, steps: int = 60) -> np.ndarray:
    """``start``·(1 + _PAST) where the rule passes it; elsewhere the least rod that passes,
    by bisection (``steps`` halvings at most, to 1e-12 of the rod) from ``start`` up to the
    rod whose margin's floor clears twice ROD_MARGIN·L4 (which passes without the exact
    minimum; see :func:`jams`)."""
    out = start * (1.0 + _PAST)
    left = np.flatnonzero(jams(_with_rod(d, out), np.ones(out.shape, dtype=bool)))
    if left.size:
        sub = d.take(left)
        ratio = sub.crank / sub.frame
        rise = largest_rise(sub)
        lo = out[left]
        hi = np.maximum(lo, _root(np.sqrt(1.0 - ratio ** 2), rise, rise * ratio,
                                  2.0 * ROD_MARGIN) * (1.0 + _PAST))
        for _ in range(steps):
            if np.all(hi - lo <= 1e-12 * hi):
                break
            mid = 0.5 * (lo + hi)
            bad = jams(_with_rod(sub, mid), np.ones(mid.shape, dtype=bool))
            lo, hi = np.where(bad, mid, lo), np.where(bad, hi, mid)
        out[left] = hi
    return out


def _with_rod(d: "Designs", rod: np.ndarray) -> "Designs":
    return d.with_lengths(d.lengths()[:4] + [rod])


def _margin_floor(d: "Designs") -> np.ndarray:
    """r_min·cos(θ/2) − |d|_max·sin(θ/2) ≤ r·cos ψ − s·d·sin ψ over the swing, mm."""
    rise = largest_rise(d)
    with np.errstate(all="ignore"):
        ratio = d.crank / d.frame
        return np.sqrt(np.maximum(d.rod ** 2 - rise ** 2, 0.0)) * np.sqrt(1.0 - ratio ** 2) \
            - rise * ratio


def _root(cos, depth, shift, margin: float = ROD_MARGIN) -> np.ndarray:
    """The positive L4 with sqrt(L4² − depth²)·cos = margin·L4 + shift: the root of
    (cos² − margin²)·L4² − 2·margin·shift·L4 − (depth²·cos² + shift²) = 0 (the equation
    squared; the one positive root, since the constant term is ≤ 0). It solves the
    equation itself where margin·L4 + shift ≥ 0."""
    a = cos ** 2 - margin ** 2
    return (margin * shift + np.sqrt((margin * shift) ** 2 + a * (depth ** 2 * cos ** 2 + shift ** 2))) / a


def _least_at(psi, guide, lever, sign: float) -> tuple[np.ndarray, np.ndarray]:
    """The least L4 with r·cos ψ − s·d·sin ψ ≥ ROD_MARGIN·L4 at ψ, and its slope d/dψ.

    That is the root of :func:`_root` with shift s·d·sin ψ, where it solves the unsquared
    equation; elsewhere every L4 ≥ |d| passes at ψ and the least is |d| (the reach rule asks
    more). The slope is −h_ψ/h_L4 for h = r·cos ψ − s·d·sin ψ − ROD_MARGIN·L4, both
    multiplied by r so that it stays finite where r → 0."""
    cos, sin = np.cos(psi), np.sin(psi)
    depth, depth1 = guide - lever * cos, lever * sin
    shift = sign * depth * sin
    length = _root(cos, depth, shift)
    reach = np.sqrt(np.maximum(length ** 2 - depth ** 2, 0.0))
    with np.errstate(all="ignore"):
        slope = (depth * depth1 * cos + reach ** 2 * sin + sign * reach * (depth1 * sin + depth * cos)) \
            / (length * cos - ROD_MARGIN * reach)
    solved = ROD_MARGIN * length + shift >= 0.0
    return (np.where(solved, length, np.abs(depth)),
            np.where(solved, slope, np.sign(depth) * depth1))


def _over_swing(d: "Designs", curve, extreme, args: tuple[np.ndarray, ...],
                unit: np.ndarray) -> np.ndarray:
    """``extreme`` (grid_minimum or grid_maximum) over ψ ∈ [−θ/2, θ/2] of ``curve(ψ, *args)``
    (value, slope), per design (1-D designs), sampled at ψ = ``unit``·θ/2."""
    half = (d.theta / 2.0)[..., None]
    out = np.empty(np.shape(half)[:-1])
    for i in range(0, out.shape[0], _CHUNK):       # chunks bound the grid's memory
        part = slice(i, i + _CHUNK)
        psi = half[part] * unit
        sub = tuple(a[part, None] for a in args)
        values, slopes = curve(psi, *sub)
        out[part] = extreme(curve, psi, values, slopes, args=sub)
    return out
