"""The driving torque's largest and smallest value per design and speed over a cycle, exactly.

Below :mod:`core.forces.flywheel`, which samples the torque's speed-independent parts
(:mod:`core.forces.jet`) and hands them here. The torque is two smooth curves, with the cut
and without it, switched at the cut's two ends; each curve's maxima lie in the cells between
samples where its slope turns from rising to falling, and each such cell is polished by
Newton's method (:func:`core.linkage.polish.newton_maximum`) on the closed-form slope and
curvature, two or three evaluations where Brent's method on the torque alone took eight or
more. A cell is polished only where it could beat what is already known (the samples inside
the piece and the values at its ends): its end tangents' meeting point bounds it
(:func:`core.linkage.extrema.tangent_bound`), so most speeds polish one cell per peak.
"""
from __future__ import annotations

import math

import numpy as np

from core.linkage.designs import Designs
from core.linkage.extrema import tangent_bound
from core.linkage.polish import newton_maximum
from .jet import TorqueJet, torque_jet
from .masses import MassProperties

# The four curves, stacked on a leading axis: (max, min) × (cutting, not cutting).
_SIGN = np.array([1.0, 1.0, -1.0, -1.0])
_CUTTING = np.array([1.0, 0.0, 1.0, 0.0])


def reaches(lo: np.ndarray, hi: np.ndarray, on: np.ndarray, off: np.ndarray,
            cutting: bool) -> np.ndarray:
    """Which cells [lo, hi] (rad, hi − lo < 2π, either may lie beyond [0, 2π)) reach into the
    cut [on, off] (``cutting``) or into the rest of the cycle: those where an extremum or a
    zero of that piece can lie (the pieces take the crank angle modulo 2π). Kept with a
    margin of 1e-9 rad, so one on a switch angle is never lost to rounding."""
    first = np.mod(lo, 2.0 * math.pi)
    last = first + (hi - lo)                       # beyond 2π where the cell wraps
    slack = 1e-9
    if cutting:
        return ((first <= off + slack) & (last >= on - slack)) | \
            (last - 2.0 * math.pi >= on - slack)
    return ~((first > on + slack) & (last < off - slack))


def _inside(t: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """t (rad, any turn) lies on the arc from a to b."""
    period = 2.0 * math.pi
    return np.mod(t - a, period) <= np.mod(b - a, period)


def _curves(jet: TorqueJet, order: int, w2: np.ndarray) -> np.ndarray:
    """The four curves' ``order``-th φ-derivative (0, 1 or 2) from jet arrays (designs, n):
    shape (4, designs, speeds, n) for ``w2`` of shape (speeds, 1)."""
    suffix = "" if order == 0 else str(order)
    static, inertial, cut = (getattr(jet, name + suffix)[:, None, :]
                             for name in ("static", "inertial", "cut"))
    both = static + w2 * inertial
    return np.stack([both + cut, both, -(both + cut), -both])


def piece_peaks(d: Designs, samples: tuple, omega: np.ndarray, masses: MassProperties,
                window: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """(largest, smallest) driving torque per design and speed, N·m, each (designs, speeds).

    ``samples`` are :func:`core.forces.flywheel._torque_samples`' (φ, jet, segments), and
    ``window`` the cut's switch angles (on, off) per design. Candidates: both curves' values
    at both switch angles, the samples inside each curve's piece, and each polished maximum
    that lands inside its piece.
    """
    x, jet, segments = samples
    on, off = window
    count, speeds = on.size, omega.size
    w2 = (omega ** 2)[:, None]
    values, slopes = _curves(jet, 0, w2), _curves(jet, 1, w2)
    start = np.stack([on, off, on, off])                        # each curve's piece, (4, designs)
    stop = np.stack([off, on, off, on])
    ends = torque_jet(d.column(), np.stack([on, off], axis=-1), masses)
    best = _curves(ends, 0, w2).max(axis=-1)                     # (4, designs, speeds)
    within = _inside(x, start[..., None], stop[..., None])[:, :, None, :]
    best = np.fmax(best, np.max(np.where(within, values, -np.inf), axis=-1))
    floor = np.maximum(best[0::2], best[1::2])[[0, 0, 1, 1]]      # what a cell must beat
    cells = []
    for first, last, period in segments:
        left = np.arange(first, last if period > 0.0 else last - 1)
        right = np.where(left + 1 < last, left + 1, first)
        lo = x[:, left]
        hi = x[:, right] + np.where(left + 1 < last, 0.0, period)
        reach = np.stack([reaches(lo, hi, on[:, None], off[:, None], cutting)
                          for cutting in (True, False)])[[0, 1, 0, 1]]
        turn = (slopes[..., left] > 0.0) & (slopes[..., right] <= 0.0) & reach[:, :, None, :]
        curve, design, speed, cell = np.nonzero(turn)
        at = (curve, design, speed)
        v_lo, v_hi = values[at + (left[cell],)], values[at + (right[cell],)]
        s_lo, s_hi = slopes[at + (left[cell],)], slopes[at + (right[cell],)]
        a, b = lo[design, cell], hi[design, cell]
        keep = tangent_bound(a, b, v_lo, v_hi, s_lo, s_hi) > floor[at]
        cells.append([v[keep] for v in (curve, design, speed, a, b, v_lo, v_hi, s_lo, s_hi)])
    curve, design, speed, a, b, v_lo, v_hi, s_lo, s_hi = (np.concatenate(v) for v in zip(*cells))
    if curve.size:
        lengths = [np.broadcast_to(v, (count,))[design] for v in d.lengths()]

        def fun(t, w2, sign, cutting, *lengths):
            one = torque_jet(d.with_lengths(lengths), t, masses)
            static, inertial, cut = one[0:3], one[3:6], one[6:9]
            return tuple(sign * (s + w2 * i + cutting * c) for s, i, c in zip(static, inertial, cut))

        root, value = newton_maximum(fun, a, b, v_lo, v_hi, s_lo, s_hi,
                                     [w2[speed, 0], _SIGN[curve], _CUTTING[curve]] + lengths)
        inside = _inside(root, start[curve, design], stop[curve, design])
        owner = np.ravel_multi_index((curve, design, speed), best.shape)
        flat = best.reshape(-1)
        np.fmax.at(flat, owner[inside], value[inside])
    top = np.fmax(best[0], best[1])
    return top, -np.fmax(best[2], best[3])
