"""The driving torque's largest and smallest value per design and speed over a cycle, exactly.

Below :mod:`core.forces.flywheel`, which samples the torque's speed-independent parts
(:mod:`core.forces.jet`) and hands them here. The torque is two smooth curves, with the cut
and without it, switched at the cut's two ends; each curve's maxima lie in the cells between
samples where its slope turns from rising to falling, and each such cell is polished by
Newton's method (:func:`core.linkage.polish.newton_maximum`) on the closed-form slope and
curvature, from the top of the quintic through the cell's ends: mostly one evaluation, where
Brent's method on the torque alone took eight or more. Which cells turn at which speed comes
from one binary search per sample (the slope is affine in ω²), so the per-speed work scales
with the cells found; and a cell is polished only where the chord of its largest value,
convex in ω², reaches the candidates already known at that speed (:func:`chord_bounds`).
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from core.linkage.designs import Designs
from core.linkage.polish import newton_maximum
from core.linkage.turns import TURN, wrap_turn
from .jet import TorqueJet, torque_jet
from .masses import MassProperties

def reaches(lo: np.ndarray, hi: np.ndarray, on: np.ndarray, off: np.ndarray,
            cutting: bool) -> np.ndarray:
    """Which cells [lo, hi] (rad, hi − lo < 2π, either may lie beyond [0, 2π)) reach into the
    cut [on, off] (``cutting``) or into the rest of the cycle: those where an extremum or a
    zero of that piece can lie (the pieces take the crank angle modulo 2π). Kept with a
    margin of 1e-9 rad, so one on a switch angle is never lost to rounding."""
    first = wrap_turn(lo)
    last = first + (hi - lo)                       # beyond 2π where the cell wraps
    slack = 1e-9
    if cutting:
        return ((first <= off + slack) & (last >= on - slack)) | \
            (last - TURN >= on - slack)
    return ~((first > on + slack) & (last < off - slack))


def on_arc(t: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """t (rad, any turn) lies on the arc from a to b."""
    return wrap_turn(t - a) <= wrap_turn(b - a)


def pair_extremes(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(larger, smaller) of the two entries along the last axis of ``values`` (a value at each
    switch angle): the same as ``max``/``min`` over that axis, NaN included, some 30 times
    faster than numpy's reduction over an axis of length 2 (numpy 2.4)."""
    first, second = values[..., 0], values[..., 1]
    return np.maximum(first, second), np.minimum(first, second)


def gather(array: np.ndarray, design: np.ndarray, column: np.ndarray) -> np.ndarray:
    """``array[design, column]`` for a (designs, samples) array, by its flat index: a take
    from a C-contiguous array costs a third of the 2-D fancy index (numpy 2.4; the loaded
    sweep gathers some 10^6 values per 500 designs at 16 speeds)."""
    return array.ravel().take(design * array.shape[-1] + column)


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
    # Positions fit a byte for the sweep's speeds (at most 16): integer arithmetic on bytes
    # runs some ten times faster than on 8-byte integers, and the selections below are such.
    small = np.int8 if n <= 100 else np.intp
    with np.errstate(all="ignore"):
        zero = -a / b
    below = np.zeros(zero.shape, dtype=small)            # speeds with ω² < zero: [0, below)
    for w in ws:                                          # a pass per speed beats a binary search
        below += w < zero
    if np.all(ws[1:] > ws[:-1]):                          # first speed with ω² > zero
        above = below + (ws.take(np.minimum(below, n - 1)) == zero)
    else:
        above = below.copy()
        for w in ws:
            above += w == zero
    # Where b is finite and not 0 (a zero −a/b that is finite), the sign of b says which side:
    # b > 0 gives [above, n) positive and [0, below) negative, b < 0 the other way round.
    up = b > 0.0
    rest = (n - below) * up
    pos = [above * up, below + rest]
    neg = [above - pos[0], n - rest]
    odd = np.flatnonzero(~(np.isfinite(zero) & np.isfinite(b)))
    if odd.size:                                          # b = 0, a non-finite value, overflow
        for out, fixed in zip(pos + neg, _odd_ranges(a.reshape(-1)[odd], b.reshape(-1)[odd], ws)):
            out.reshape(-1)[odd] = fixed
    return tuple(pos), tuple(neg)


def _odd_ranges(a: np.ndarray, b: np.ndarray, ws: np.ndarray) -> tuple[np.ndarray, ...]:
    """:func:`_signed_speeds`' (start, stop) of the positive, then of the negative speeds for
    samples (flat arrays) whose zero −a/b is not finite: all or none of the sorted ω² ``ws``
    where b = 0, none where a or b is not finite (no sign: in neither set)."""
    n = ws.size
    with np.errstate(all="ignore"):
        zero = np.where(b != 0.0, -a / b, 0.0)
    above = np.searchsorted(ws, zero, side="right")       # first speed with ω² > zero
    below = np.searchsorted(ws, zero, side="left")        # speeds with ω² < zero: [0, below)
    flat = b == 0.0
    full = np.full(a.shape, n)
    bad = ~(np.isfinite(a) & np.isfinite(b))
    # An empty range is [0, 0): the difference of ranges in turning_cells needs that form.
    return (np.where(flat | bad | (b < 0.0), 0, above),
            np.where(bad, 0, np.where(flat, np.where(a > 0.0, n, 0), np.where(b > 0.0, full, below))),
            np.where(flat | bad | (b > 0.0), 0, above),
            np.where(bad, 0, np.where(flat, np.where(a < 0.0, n, 0), np.where(b > 0.0, below, full))))


# A torque peak is done when Newton's next step would raise it by at most this fraction
# (core.linkage.polish.newton_maximum's ``gain``): far below the 1e-9 the sweep's figures
# are held to against the single design's summary, which takes the same path.
PEAK_GAIN = 1e-15

# Up to this many speeds the signs are taken on (designs, speeds, samples) arrays directly:
# fewer passes than the ranges' binary searches and selections per (design, sample).
DIRECT_SPEEDS = 3


class Cells(NamedTuple):
    """Turning cells, one entry per (cell, speed), flat arrays: the design, the speed's index,
    the samples either side (columns of the samples' φ) and their angles (rad, ``hi`` a turn
    on where the cell wraps). The speeds at which one cell turns are one run of the speeds
    sorted by ω², and its entries lie together in that order: ``rank`` is an entry's place in
    its run and ``count`` the run's length; ``below`` and ``above`` are the indices of the
    nearest speeds outside the run (where the cell does not turn), -1 where the run reaches
    the slowest or the fastest speed (and always with ``DIRECT_SPEEDS`` or fewer speeds,
    where every run is one speed)."""

    design: np.ndarray
    speed: np.ndarray
    left: np.ndarray
    right: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    rank: np.ndarray
    count: np.ndarray
    below: np.ndarray
    above: np.ndarray


class Window(NamedTuple):
    """The cut's switch angles (rad, (designs,)) and what the torque's and the energy's
    searches both take from them: the jet there (each field (designs, 2): at on, at off),
    and per piece, the cut then the rest, the cells between samples that reach into it
    (:func:`piece_cells`)."""

    on: np.ndarray
    off: np.ndarray
    jet: TorqueJet
    cells: tuple[list, list]


def switch_window(d: Designs, samples: tuple, on: np.ndarray, off: np.ndarray,
                  masses: MassProperties) -> Window:
    """The :class:`Window` of the switch angles ``on``, ``off`` over ``samples`` (φ, jet,
    segments: :func:`core.forces.flywheel._torque_samples`')."""
    x, _, segments = samples
    jet = torque_jet(d.column(), np.stack([on, off], axis=-1), masses)
    return Window(on, off, jet, (piece_cells(x, segments, (on, off), True),
                                 piece_cells(x, segments, (off, on), False)))


def piece_cells(x: np.ndarray, segments, piece: tuple[np.ndarray, np.ndarray],
                cutting: bool) -> list[tuple[np.ndarray, ...]]:
    """Per segment of the samples φ ``x`` (designs, n) (``segments`` as in
    :func:`core.linkage.extrema.grid_argmax`): its cells' left and right sample (columns of
    ``x``), their angles lo and hi (rad, (designs, cells); ``hi`` a turn on where the cell
    wraps) and which of them reach into ``piece`` ((start, stop) per design; the cut if
    ``cutting``: :func:`reaches`)."""
    start, stop = piece
    out = []
    for first, last, period in segments:
        left = np.arange(first, last if period > 0.0 else last - 1)
        right = np.where(left + 1 < last, left + 1, first)
        lo = np.take(x, left, axis=1)              # C order (x[:, left] is Fortran's)
        hi = np.take(x, right, axis=1) + np.where(left + 1 < last, 0.0, period)
        out.append((left, right, lo, hi, reaches(lo, hi, start[:, None], stop[:, None], cutting)))
    return out


def turning_cells(parts: tuple[np.ndarray, np.ndarray], w2: np.ndarray,
                  cells: list[tuple[np.ndarray, ...]]) -> list[tuple[int, Cells]]:
    """The cells between samples where the curve a + ω²·b (``parts``, (designs, n) at the
    samples) falls through zero (kind 0: positive, then not) or rises through it (kind 1:
    negative, then not) at each speed (ω² ``w2``), among those of ``cells`` that reach into
    their piece (:func:`piece_cells`): a list of (kind, :class:`Cells`).

    Beyond ``DIRECT_SPEEDS`` nothing of shape (designs, speeds, samples) is formed: per
    cell, the speeds where the left sample has the sign and the right one has not are one
    range of the sorted speeds (:func:`_signed_speeds`), expanded only where a cell has any."""
    direct = w2.size <= DIRECT_SPEEDS
    if direct:
        values = parts[0][:, None, :] + w2[:, None] * parts[1][:, None, :]
        signs = (values > 0.0, values < 0.0)          # both False for NaN
    else:
        order = np.argsort(w2, kind="stable")
        signs = _signed_speeds(parts, w2)
    out = []
    for left, right, lo, hi, reach in cells:
        for kind, sign in enumerate(signs):
            if direct:
                design, speed, cell = np.nonzero((sign[..., left] > sign[..., right])
                                                 & reach[:, None, :])
                one, none = np.zeros_like(design), np.full(design.size, -1)
                out.append((kind, Cells(design, speed, left[cell], right[cell],
                                        gather(lo, design, cell), gather(hi, design, cell),
                                        one, one + 1, none, none)))
                continue
            # [a1, b1) minus [a2, b2) = [a1, min(b1, a2)) ∪ [max(a1, b2), b1), of which one
            # is empty (each signed set is a prefix or a suffix of the sorted speeds, or [0, 0)).
            a1, b1, a2, b2 = (_columns(v, i) for i in (left, right) for v in sign)
            end = np.minimum(b1, a2)
            first = end > a1
            # where(first, a1, max(a1, b2)) and where(first, end, b1), in integer arithmetic
            begin, end = np.maximum(a1, b2 * ~first), b1 + (end - b1) * first
            design, cell = np.divmod(np.flatnonzero(reach & (end > begin)), reach.shape[-1])
            begin = gather(begin, design, cell)
            counts = gather(end, design, cell) - begin
            total = int(counts.sum())
            if total == 0:
                continue
            owner = np.repeat(np.arange(design.size), counts)
            rank = np.arange(total) - np.repeat(np.cumsum(counts) - counts, counts)
            design, cell = design[owner], cell[owner]
            low, high = begin[owner], begin[owner] + counts[owner]     # the run, sorted
            below = np.where(low > 0, order[np.maximum(low - 1, 0)], -1)
            above = np.where(high < w2.size, order[np.minimum(high, w2.size - 1)], -1)
            out.append((kind, Cells(design, order[low + rank], left[cell], right[cell],
                                    gather(lo, design, cell), gather(hi, design, cell),
                                    rank, counts[owner].astype(np.intp), below, above)))
    return out


def _columns(array: np.ndarray, index: np.ndarray) -> np.ndarray:
    """``array[:, index]``: a view where ``index`` is a run of consecutive columns (a segment's
    left samples, and its right ones unless it wraps), else a copy."""
    if index.size and np.array_equal(index, np.arange(index[0], index[0] + index.size)):
        return array[:, index[0]:index[0] + index.size]
    return np.take(array, index, axis=1)


def piece_peaks(d: Designs, samples: tuple, omega: np.ndarray, masses: MassProperties,
                window: Window) -> tuple[np.ndarray, np.ndarray]:
    """(largest, smallest) driving torque per design and speed, N·m, each (designs, speeds).

    ``samples`` are :func:`core.forces.flywheel._torque_samples`' (φ, jet, segments) and
    ``window`` the cut's switch angles with the jet there and the cells of each piece. Candidates: both curves' values
    at both switch angles, the samples beside each turning cell that lie inside the piece,
    and each polished maximum or minimum that lands inside its piece (a smooth curve's
    extremum over an arc is at an end or where its slope turns).

    A turning cell is polished unless :func:`chord_bounds` shows that it cannot beat the
    candidates already known at its speed; the bound is exact (convexity in ω²), not a
    guess from the cell's end tangents, which missed a rod's minimum torque by 2e-4 of the
    peak (K near 5, a crank of 6 mm, a short trailing rod) in the hypothesis test at 16
    speeds. A cell whose run of turning speeds reaches the slowest or the fastest speed is
    polished there first, so that the chord has two ends; the rest follow in a second pass.
    """
    x, jet, _ = samples
    on, off, ends = window.on, window.off, window.jet
    w2 = omega ** 2
    rest = ends.static[:, None, :] + w2[:, None] * ends.inertial[:, None, :]   # (designs, speeds, 2)
    cut = rest + ends.cut[:, None, :]
    (cut_top, cut_bottom), (rest_top, rest_bottom) = pair_extremes(cut), pair_extremes(rest)
    best = np.stack([np.maximum(cut_top, rest_top), -np.minimum(cut_bottom, rest_bottom)])   # (2, designs, speeds)
    flat = best.reshape(-1)
    pieces = ((on, off), (off, on))
    found = []
    for k, cutting in enumerate((1.0, 0.0)):
        values = (jet.static + cutting * jet.cut, jet.inertial)
        slopes = (jet.static1 + cutting * jet.cut1, jet.inertial1)
        first, last = pieces[k]
        inside_piece = on_arc(x, first[:, None], last[:, None]).ravel()     # per sample
        for kind, cells in turning_cells(slopes, w2, window.cells[k]):
            sign = 1.0 - 2.0 * kind
            design, speed = cells.design, cells.speed
            owner = (kind * on.size + design) * w2.size + speed
            # Each end's flat index, taken once: its a and b give the value at the cell's
            # speed and at the speeds either side of its run (the chord's ends), and the
            # slopes and curvatures are gathered only for the cells polished.
            index = cell_index(x.shape[-1], cells)
            ends = cell_ends(values, index)
            entry = [np.full(design.size, k), np.full(design.size, kind), design, speed,
                     cells.lo, cells.hi]
            for i, (a, b) in zip(index, ends):
                value = sign * (a + w2[speed] * b)
                inside = inside_piece.take(i)
                np.fmax.at(flat, owner[inside], value[inside])
                entry.append(value)
            entry += index + [cells.rank, cells.count, cells.below, cells.above]
            entry += [cell_top(ends, w2, sign, side) for side in (cells.below, cells.above)]
            found.append(entry)
    if not found:
        return best[0], -best[1]
    (k, kind, design, speed, lo, hi, v_lo, v_hi, i_lo, i_hi, rank, count, below,
     above, top_below, top_above) = (np.concatenate(v) for v in zip(*found))
    owner = (kind * on.size + design) * w2.size + speed
    lengths = [np.broadcast_to(v, on.shape) for v in d.lengths()]
    polished = np.full(owner.size, np.nan)

    def fun(t, w2, sign, cutting, *lengths):
        one = torque_jet(d.with_lengths(lengths), t, masses)
        static, inertial, cut = one[0:3], one[3:6], one[6:9]
        return tuple(sign * (s + w2 * i + cutting * c) for s, i, c in zip(static, inertial, cut))

    def polish(which: np.ndarray) -> None:
        """Polish the cells ``which`` (indices into the entries) and count the peaks inside."""
        if which.size == 0:
            return
        i = which
        w, sign, cutting = w2[speed[i]], 1.0 - 2.0 * kind[i], 1.0 - k[i]
        ends = [sign * ((static.ravel().take(at) + cutting * cut.ravel().take(at))
                        + w * inertial.ravel().take(at))
                for static, inertial, cut in ((jet.static1, jet.inertial1, jet.cut1),
                                              (jet.static2, jet.inertial2, jet.cut2))
                for at in (i_lo[i], i_hi[i])]
        root, value = newton_maximum(fun, lo[i], hi[i], v_lo[i], v_hi[i], ends[0], ends[1],
                                     [w, sign, cutting] + [v[design[i]] for v in lengths],
                                     gain=PEAK_GAIN, curvatures=(ends[2], ends[3]))
        polished[i] = value
        start = np.where(k[i] == 0, on[design[i]], off[design[i]])
        stop = np.where(k[i] == 0, off[design[i]], on[design[i]])
        inside = on_arc(root, start, stop)
        np.fmax.at(flat, owner[i][inside], value[inside])

    # First the runs' ends at the slowest and the fastest speed, which no chord covers.
    index = np.arange(owner.size)
    slowest, fastest = (rank == 0) & (below < 0), (rank == count - 1) & (above < 0)
    polish(np.flatnonzero(slowest | fastest))
    low, high = index - rank, index - rank + count - 1           # each run's first and last
    bound = chord_bounds(w2, speed, (np.where(below < 0, speed[low], below), top_below, polished[low]),
                         (np.where(above < 0, speed[high], above), top_above, polished[high]),
                         (below < 0, above < 0))
    polish(np.flatnonzero(~(slowest | fastest) & ~(bound <= flat[owner])))   # NaN: polished
    return best[0], -best[1]


def cell_index(n: int, cells: Cells) -> list[np.ndarray]:
    """The flat indices of the cells' left and right samples in (designs, ``n``) arrays."""
    return [cells.design * n + column for column in (cells.left, cells.right)]


def cell_ends(values: tuple[np.ndarray, np.ndarray],
              index: list[np.ndarray]) -> list[tuple[np.ndarray, np.ndarray]]:
    """(a, b) of ``values`` (a, b), C-contiguous arrays (designs, samples), at the flat
    ``index`` of each cell's two samples (:func:`cell_index`)."""
    return [(values[0].ravel().take(i), values[1].ravel().take(i)) for i in index]


def cell_top(ends: list[tuple[np.ndarray, np.ndarray]], w2: np.ndarray, sign: float,
             side: np.ndarray) -> np.ndarray:
    """The larger of sign·(a + ω²·b) at a cell's two samples (``ends``, :func:`cell_ends`), at
    the speeds ``side`` (its largest value over the cell where it does not turn there), NaN
    where ``side`` is -1."""
    w = w2.take(np.maximum(side, 0))
    (a0, b0), (a1, b1) = ends
    top = np.maximum(sign * (a0 + w * b0), sign * (a1 + w * b1))
    return np.where(side >= 0, top, np.nan)


def chord_bounds(w2: np.ndarray, speed: np.ndarray, lower: tuple, upper: tuple,
                 polished: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """An upper bound on a turning cell's largest value at ``speed`` (indices into ω² ``w2``),
    from two speeds on either side of it.

    The cell's largest value M(ω²) = max over φ in the cell of sign·(a(φ) + ω²·b(φ)) is the
    largest of affine functions of ω², so it is convex in ω² and lies below its chord
    between any two speeds on either side. ``lower`` and ``upper`` are each (speed index,
    M from the samples, M polished) of the chord's ends, and ``polished`` says per end which
    of the two to take: the nearest speed where the cell does not turn, where M is the larger
    of the cell's end samples (the bracketing grid's premise: at most one turn per cell), or
    the run's own end, polished, where the run reaches the slowest or the fastest speed. A
    margin of 1e-12 of the ends' values covers the rounding; NaN where an end is NaN.
    """
    (s0, top0, peak0), (s1, top1, peak1) = lower, upper
    m0, m1 = np.where(polished[0], peak0, top0), np.where(polished[1], peak1, top1)
    w0, w1 = w2[s0], w2[s1]
    with np.errstate(all="ignore"):
        t = (w2[speed] - w0) / (w1 - w0)
        return m0 * (1.0 - t) + m1 * t + 1e-12 * (np.abs(m0) + np.abs(m1))
