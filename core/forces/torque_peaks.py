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


def speed_torque(jet: TorqueJet, omega: np.ndarray, order: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """The torque's ``order``-th φ-derivative (0 or 1) at each speed from jet arrays
    (designs, n): (with the cut, without it), each (designs, speeds, n)."""
    suffix = "" if order == 0 else str(order)
    static, inertial, cut = (getattr(jet, name + suffix)[:, None, :]
                             for name in ("static", "inertial", "cut"))
    rest = static + (omega ** 2)[:, None] * inertial
    return rest + cut, rest


def piece_peaks(d: Designs, samples: tuple, torque: tuple[np.ndarray, np.ndarray],
                omega: np.ndarray, masses: MassProperties,
                window: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """(largest, smallest) driving torque per design and speed, N·m, each (designs, speeds).

    ``samples`` are :func:`core.forces.flywheel._torque_samples`' (φ, jet, segments),
    ``torque`` their :func:`speed_torque` and ``window`` the cut's switch angles (on, off)
    per design. Candidates: both curves' values at both switch angles, the samples inside
    each curve's piece, and each polished maximum or minimum that lands inside its piece.
    """
    x, jet, segments = samples
    on, off = window
    w2 = (omega ** 2)[:, None]
    slopes = speed_torque(jet, omega, 1)
    ends = speed_torque(torque_jet(d.column(), np.stack([on, off], axis=-1), masses), omega)
    top = np.maximum(ends[0].max(axis=-1), ends[1].max(axis=-1))      # (designs, speeds)
    bottom = np.minimum(ends[0].min(axis=-1), ends[1].min(axis=-1))
    pieces = ((on, off), (off, on))                                    # with the cut, without
    for (a, b), values in zip(pieces, torque):
        outside = np.where(_inside(x, a[:, None], b[:, None]), 0.0, np.inf)[:, None, :]
        top = np.fmax(top, (values - outside).max(axis=-1))
        bottom = np.fmin(bottom, (values + outside).min(axis=-1))
    floor = np.stack([top, -bottom])                                   # what a cell must beat
    found = [_cells(x, values, slope, segments, pieces[k], cut_k=k, floor=floor)
             for k, (values, slope) in enumerate(zip(torque, slopes))]
    kind, cut, design, speed, lo, hi, v_lo, v_hi, s_lo, s_hi = (
        np.concatenate(v) for v in zip(*[c for cells in found for c in cells]))
    best = floor.copy()
    if kind.size:
        sign = np.where(kind == 0, 1.0, -1.0)
        cutting = np.where(cut == 0, 1.0, 0.0)
        lengths = [np.broadcast_to(v, on.shape)[design] for v in d.lengths()]

        def fun(t, w2, sign, cutting, *lengths):
            one = torque_jet(d.with_lengths(lengths), t, masses)
            static, inertial, cut = one[0:3], one[3:6], one[6:9]
            return tuple(sign * (s + w2 * i + cutting * c) for s, i, c in zip(static, inertial, cut))

        root, value = newton_maximum(fun, lo, hi, v_lo, v_hi, s_lo, s_hi,
                                     [w2[speed, 0], sign, cutting] + lengths)
        start = np.where(cut == 0, on[design], off[design])
        stop = np.where(cut == 0, off[design], on[design])
        inside = _inside(root, start, stop)
        owner = np.ravel_multi_index((kind, design, speed), best.shape)
        np.fmax.at(best.reshape(-1), owner[inside], value[inside])
    return best[0], -best[1]


def turning_cells(x: np.ndarray, slopes: np.ndarray, segments, piece: tuple[np.ndarray, np.ndarray],
                  cutting: bool) -> list[tuple[int, tuple[np.ndarray, ...]]]:
    """The cells between samples where ``slopes`` (designs, speeds, n) at φ ``x`` (designs, n)
    falls through zero (kind 0: positive, then not) or rises through it (kind 1: negative,
    then not), that reach into ``piece`` ((start, stop) per design; the cut if ``cutting``):
    a list of (kind, (design, speed, left sample, right sample, lo, hi)), flat arrays, the
    samples as flat indices into ``slopes``. ``segments`` as in
    :func:`core.linkage.extrema.grid_argmax`. Found on booleans, flat: at 16 speeds
    these passes over (designs, speeds, samples) are most of a loaded sweep's time."""
    start, stop = piece
    count, speeds, n = slopes.shape
    out = []
    signs = (slopes > 0.0, slopes < 0.0)               # both False for NaN
    for first, last, period in segments:
        wraps = period > 0.0
        m = last - first - (0 if wraps else 1)         # cells in the segment
        left = np.arange(first, first + m)
        right = np.where(left + 1 < last, left + 1, first)
        lo = x[:, left]
        hi = x[:, right] + np.where(left + 1 < last, 0.0, period)
        reach = reaches(lo, hi, start[:, None], stop[:, None], cutting)[:, None, :]
        for kind, strict in enumerate(signs):
            here = strict[..., first:first + m]
            after = strict[..., first + 1:last]
            if wraps:
                after = np.concatenate([after, strict[..., first:first + 1]], axis=-1)
            turn = here > after                        # strictly signed, then not
            turn &= reach
            flat = np.flatnonzero(turn)
            cell = flat % m
            row = flat // m                            # design·speeds + speed
            design = row // speeds
            out.append((kind, (design, row % speeds, row * n + left[cell], row * n + right[cell],
                               lo[design, cell], hi[design, cell])))
    return out


def _cells(x: np.ndarray, values: np.ndarray, slopes: np.ndarray, segments, piece, cut_k: int,
           floor: np.ndarray) -> list[list[np.ndarray]]:
    """The cells of one curve (values and slopes (designs, speeds, n)) that hold a maximum
    (kind 0) or a minimum (kind 1, negated) reaching into ``piece`` (:func:`turning_cells`)
    and whose tangent bound beats ``floor`` (kind, designs, speeds): flat arrays (kind,
    cut_k, design, speed, lo, hi, value and slope at both ends)."""
    out = []
    for kind, (design, speed, left, right, a, b) in turning_cells(x, slopes, segments, piece,
                                                                  cut_k == 0):
        sign = 1.0 - 2.0 * kind
        v_lo, v_hi = sign * values.reshape(-1)[left], sign * values.reshape(-1)[right]
        s_lo, s_hi = sign * slopes.reshape(-1)[left], sign * slopes.reshape(-1)[right]
        keep = tangent_bound(a, b, v_lo, v_hi, s_lo, s_hi) > floor[kind, design, speed]
        out.append([np.full(keep.sum(), kind), np.full(keep.sum(), cut_k)]
                   + [v[keep] for v in (design, speed, a, b, v_lo, v_hi, s_lo, s_hi)])
    return out
