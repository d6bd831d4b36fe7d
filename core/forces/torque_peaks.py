"""The driving torque's largest and smallest value per design and speed over a cycle, exactly.

Below :mod:`core.forces.flywheel`, which samples the torque's speed-independent parts
(:mod:`core.forces.jet`) and hands them here. The torque is two smooth curves, with the cut
and without it, switched at the cut's two ends; each curve's maxima lie in the cells between
samples where its slope turns from rising to falling, and each such cell is polished by
Newton's method (:func:`core.linkage.polish.newton_maximum`) on the closed-form slope and
curvature, two evaluations where Brent's method on the torque alone took eight or more.
Which cells turn at which speed comes from one binary search per sample (the slope is
affine in ω²), so the per-speed work scales with the cells found.
"""
from __future__ import annotations

import math

import numpy as np

from core.linkage.designs import Designs
from core.linkage.polish import newton_maximum
from .jet import torque_jet
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


def on_arc(t: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """t (rad, any turn) lies on the arc from a to b."""
    period = 2.0 * math.pi
    return np.mod(t - a, period) <= np.mod(b - a, period)


def affine_at(parts: tuple[np.ndarray, np.ndarray], w2: np.ndarray, design: np.ndarray,
              column: np.ndarray, speed: np.ndarray) -> np.ndarray:
    """a + ω²·b at the given (design, sample column, speed) triples, for ``parts`` (a, b),
    arrays (designs, samples) the same at all speeds, and ω² ``w2`` (speeds,)."""
    return parts[0][design, column] + w2[speed] * parts[1][design, column]


def _signed_speeds(parts: tuple[np.ndarray, np.ndarray], w2: np.ndarray) -> tuple:
    """For each (design, sample): the ranges [start, stop) of positions in the speeds sorted
    by ω² where a + ω²·b is positive, and where it is negative, each (designs, samples).

    a + ω²·b is affine in ω², so each set is the speeds on one side of the zero −a/b: a
    prefix or a suffix of the sorted speeds, all or none when b = 0. Found by a binary
    search per sample, so a loaded sweep's per-speed work scales with the cells found,
    not with designs × speeds × samples (issue 42)."""
    a, b = parts
    n = w2.size
    ws = np.sort(w2)
    with np.errstate(all="ignore"):
        zero = np.where(b != 0.0, -a / b, 0.0)
    above = np.searchsorted(ws, zero, side="right")       # first speed with ω² > zero
    below = np.searchsorted(ws, zero, side="left")        # speeds with ω² < zero: [0, below)
    flat = b == 0.0
    full = np.full(a.shape, n)
    bad = ~(np.isfinite(a) & np.isfinite(b))              # no sign: in neither set
    # An empty range is [0, 0): the difference of ranges in turning_cells needs that form.
    pos = (np.where(flat | bad | (b < 0.0), 0, above),
           np.where(bad, 0, np.where(flat, np.where(a > 0.0, n, 0), np.where(b > 0.0, full, below))))
    neg = (np.where(flat | bad | (b > 0.0), 0, above),
           np.where(bad, 0, np.where(flat, np.where(a < 0.0, n, 0), np.where(b > 0.0, below, full))))
    return pos, neg


# A torque peak is done when Newton's next step would raise it by at most this fraction
# (core.linkage.polish.newton_maximum's ``gain``): far below the 1e-9 the sweep's figures
# are held to against the single design's summary, which takes the same path.
PEAK_GAIN = 1e-15

# Up to this many speeds the signs are taken on (designs, speeds, samples) arrays directly:
# fewer passes than the ranges' binary searches and selections per (design, sample).
DIRECT_SPEEDS = 3


def turning_cells(x: np.ndarray, parts: tuple[np.ndarray, np.ndarray], w2: np.ndarray, segments,
                  piece: tuple[np.ndarray, np.ndarray],
                  cutting: bool) -> list[tuple[int, tuple[np.ndarray, ...]]]:
    """The cells between samples where the curve a + ω²·b (``parts``, (designs, n) at φ ``x``)
    falls through zero (kind 0: positive, then not) or rises through it (kind 1: negative,
    then not) at each speed (ω² ``w2``), and that reach into ``piece`` ((start, stop) per
    design; the cut if ``cutting``): a list of (kind, (design, speed, left sample, right
    sample, lo, hi)), flat arrays, the samples as columns of ``x``. ``segments`` as in
    :func:`core.linkage.extrema.grid_argmax`.

    Beyond ``DIRECT_SPEEDS`` nothing of shape (designs, speeds, samples) is formed: per
    cell, the speeds where the left sample has the sign and the right one has not are one
    range of the sorted speeds (:func:`_signed_speeds`), expanded only where a cell has any."""
    start, stop = piece
    direct = w2.size <= DIRECT_SPEEDS
    if direct:
        values = parts[0][:, None, :] + w2[:, None] * parts[1][:, None, :]
        signs = (values > 0.0, values < 0.0)          # both False for NaN
    else:
        order = np.argsort(w2, kind="stable")
        signs = _signed_speeds(parts, w2)
    out = []
    for first, last, period in segments:
        left = np.arange(first, last if period > 0.0 else last - 1)
        right = np.where(left + 1 < last, left + 1, first)
        lo = x[:, left]
        hi = x[:, right] + np.where(left + 1 < last, 0.0, period)
        reach = reaches(lo, hi, start[:, None], stop[:, None], cutting)
        for kind, sign in enumerate(signs):
            if direct:
                design, speed, cell = np.nonzero((sign[..., left] > sign[..., right])
                                                 & reach[:, None, :])
                out.append((kind, (design, speed, left[cell], right[cell], lo[design, cell],
                                   hi[design, cell])))
                continue
            # [a1, b1) minus [a2, b2) = [a1, min(b1, a2)) ∪ [max(a1, b2), b1)
            a1, b1 = sign[0][:, left], sign[1][:, left]
            a2, b2 = sign[0][:, right], sign[1][:, right]
            for begin, end in ((a1, np.minimum(b1, a2)), (np.maximum(a1, b2), b1)):
                counts = np.where(reach, np.maximum(end - begin, 0), 0)
                design, cell = np.nonzero(counts)
                counts, begin = counts[design, cell], begin[design, cell]
                total = int(counts.sum())
                if total == 0:
                    continue
                owner = np.repeat(np.arange(design.size), counts)
                rank = np.arange(total) - np.repeat(np.cumsum(counts) - counts, counts)
                design, cell = design[owner], cell[owner]
                out.append((kind, (design, order[begin[owner] + rank], left[cell], right[cell],
                                   lo[design, cell], hi[design, cell])))
    return out


def piece_peaks(d: Designs, samples: tuple, omega: np.ndarray, masses: MassProperties,
                window: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """(largest, smallest) driving torque per design and speed, N·m, each (designs, speeds).

    ``samples`` are :func:`core.forces.flywheel._torque_samples`' (φ, jet, segments) and
    ``window`` the cut's switch angles (on, off) per design. Candidates: both curves' values
    at both switch angles, the samples beside each turning cell that lie inside the piece,
    and each polished maximum or minimum that lands inside its piece (a smooth curve's
    extremum over an arc is at an end or where its slope turns). Every turning cell is
    polished: skipping those whose end tangents' meeting point (doubled margin) could not
    beat the samples missed a rod's minimum torque by 2e-4 of the peak (K near 5, a
    crank of 6 mm, a short trailing rod), which the hypothesis test at 16 speeds found.
    """
    x, jet, segments = samples
    on, off = window
    w2 = omega ** 2
    ends = torque_jet(d.column(), np.stack([on, off], axis=-1), masses)
    rest = ends.static[:, None, :] + w2[:, None] * ends.inertial[:, None, :]   # (designs, speeds, 2)
    cut = rest + ends.cut[:, None, :]
    best = np.stack([np.maximum(cut.max(axis=-1), rest.max(axis=-1)),
                     -np.minimum(cut.min(axis=-1), rest.min(axis=-1))])         # (2, designs, speeds)
    flat = best.reshape(-1)
    pieces = ((on, off), (off, on))
    found = []
    for k, cutting in enumerate((1.0, 0.0)):
        values = (jet.static + cutting * jet.cut, jet.inertial)
        slopes = (jet.static1 + cutting * jet.cut1, jet.inertial1)
        first, last = pieces[k]
        for kind, (design, speed, left, right, lo, hi) in turning_cells(x, slopes, w2, segments,
                                                                          pieces[k], k == 0):
            sign = 1.0 - 2.0 * kind
            owner = (kind * on.size + design) * w2.size + speed
            cell = [k, kind, design, speed, lo, hi]
            for column in (left, right):
                value = sign * affine_at(values, w2, design, column, speed)
                inside = on_arc(x[design, column], first[design], last[design])
                np.fmax.at(flat, owner[inside], value[inside])
                cell.append(value)
            cell += [sign * affine_at(slopes, w2, design, column, speed) for column in (left, right)]
            found.append(cell)
    if not found:
        return best[0], -best[1]
    k, kind, design, speed, lo, hi, v_lo, v_hi, s_lo, s_hi = (
        np.concatenate([np.broadcast_to(c[i], c[2].shape) for c in found]) for i in range(10))
    owner = (kind * on.size + design) * w2.size + speed
    if owner.size:
        sign = 1.0 - 2.0 * kind
        cutting = 1.0 - k
        lengths = [np.broadcast_to(v, on.shape)[design] for v in d.lengths()]

        def fun(t, w2, sign, cutting, *lengths):
            one = torque_jet(d.with_lengths(lengths), t, masses)
            static, inertial, cut = one[0:3], one[3:6], one[6:9]
            return tuple(sign * (s + w2 * i + cutting * c) for s, i, c in zip(static, inertial, cut))

        root, value = newton_maximum(fun, lo, hi, v_lo, v_hi, s_lo, s_hi,
                                     [w2[speed], sign, cutting] + lengths, gain=PEAK_GAIN)
        start = np.where(k == 0, on[design], off[design])
        stop = np.where(k == 0, off[design], on[design])
        inside = on_arc(root, start, stop)
        np.fmax.at(flat, owner[inside], value[inside])
    return best[0], -best[1]
