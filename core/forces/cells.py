"""Which cells between the torque's samples turn, at which speeds, and in which piece of the cycle.

Below :mod:`core.forces.torque_peaks` and :mod:`core.forces.flywheel`, whose searches for the
torque's peaks and the energy's extremes both start here. The torque is two smooth curves,
with the cut and without it, switched at the cut's two ends (the :class:`Window`); a curve's
extrema lie in the cells between samples where its slope (for the energy: the torque less
its mean) changes sign. Every part of that slope is the same at all speeds but one, which
scales with ω², so which cells turn at which speed comes from one binary search per sample
(:func:`turning_cells`), and the per-speed work scales with the cells found.
"""
from __future__ import annotations

from typing import Callable, NamedTuple

import numpy as np

from core.linkage.designs import Designs
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
    where every run is one speed); these four are None where :func:`turning_cells` was
    asked for no runs."""

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
    (:func:`piece_cells`) and which samples lie in it (flat, one per sample)."""

    on: np.ndarray
    off: np.ndarray
    jet: TorqueJet
    cells: tuple[list, list]
    inside: tuple[np.ndarray, np.ndarray]


def switch_window(d: Designs, samples: tuple, on: np.ndarray, off: np.ndarray,
                  masses: MassProperties) -> Window:
    """The :class:`Window` of the switch angles ``on``, ``off`` over ``samples`` (φ, jet,
    segments: :func:`core.forces.flywheel._torque_samples`')."""
    x, _, segments = samples
    jet = torque_jet(d.column(), np.stack([on, off], axis=-1), masses)
    cells = segment_cells(x, segments)
    return Window(on, off, jet, (piece_cells(cells, (on, off), True),
                                 piece_cells(cells, (off, on), False)),
                  (on_arc(x, on[:, None], off[:, None]).ravel(),
                   on_arc(x, off[:, None], on[:, None]).ravel()))


def segment_cells(x: np.ndarray, segments) -> list[tuple[np.ndarray, ...]]:
    """Per segment of the samples φ ``x`` (designs, n) (``segments`` as in
    :func:`core.linkage.extrema.grid_argmax`): its cells' left and right sample (columns of
    ``x``) and their angles lo and hi (rad, (designs, cells), C-contiguous; ``hi`` a turn
    on where the cell wraps), the same for both pieces of the cycle."""
    out = []
    for first, last, period in segments:
        left = np.arange(first, last if period > 0.0 else last - 1)
        right = np.where(left + 1 < last, left + 1, first)
        lo = np.ascontiguousarray(_columns(left)(x))      # C order (x[:, left] is Fortran's)
        hi = _columns(right)(x) + np.where(left + 1 < last, 0.0, period)
        out.append((left, right, lo, hi))
    return out


def piece_cells(cells: list[tuple[np.ndarray, ...]], piece: tuple[np.ndarray, np.ndarray],
                cutting: bool) -> list[tuple[np.ndarray, ...]]:
    """Each segment's ``cells`` (:func:`segment_cells`) with which of them reach into
    ``piece`` ((start, stop) per design; the cut if ``cutting``: :func:`reaches`, which
    takes the cut's (on, off) either way)."""
    on, off = piece if cutting else piece[::-1]
    return [(left, right, lo, hi, reaches(lo, hi, on[:, None], off[:, None], cutting))
            for left, right, lo, hi in cells]


def turning_cells(parts: tuple[np.ndarray, np.ndarray], w2: np.ndarray,
                  cells: list[tuple[np.ndarray, ...]], runs: bool = True) -> list[tuple[int, Cells]]:
    """The cells between samples where the curve a + ω²·b (``parts``, (designs, n) at the
    samples) falls through zero (kind 0: positive, then not) or rises through it (kind 1:
    negative, then not) at each speed (ω² ``w2``), among those of ``cells`` that reach into
    their piece (:func:`piece_cells`): a list of (kind, :class:`Cells`).

    Beyond ``DIRECT_SPEEDS`` nothing of shape (designs, speeds, samples) is formed: per
    cell, the speeds where the left sample has the sign and the right one has not are one
    range of the sorted speeds (:func:`_signed_speeds`), expanded only where a cell has any.
    Without ``runs`` the runs' ranks, lengths and neighbours (what a chord bound needs) are
    left None: the energy's search reads none of them."""
    direct = w2.size <= DIRECT_SPEEDS
    if direct:
        values = parts[0][:, None, :] + w2[:, None] * parts[1][:, None, :]
        signs = (values > 0.0, values < 0.0)          # both False for NaN
    else:
        order = np.argsort(w2, kind="stable")
        signs = _signed_speeds(parts, w2)
    out = []
    for left, right, lo, hi, reach in cells:
        pick = [_columns(i) for i in (left, right)]
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
            a1, b1, a2, b2 = (columns(v) for columns in pick for v in sign)
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
            low = begin[owner]                                          # the run, sorted
            run = [None] * 4
            if runs:
                high = low + counts[owner]
                run = [rank, counts[owner].astype(np.intp),
                       np.where(low > 0, order[np.maximum(low - 1, 0)], -1),
                       np.where(high < w2.size, order[np.minimum(high, w2.size - 1)], -1)]
            out.append((kind, Cells(design, order[low + rank], left[cell], right[cell],
                                    gather(lo, design, cell), gather(hi, design, cell), *run)))
    return out


def slope_turns(jet: TorqueJet, w2: np.ndarray, window: Window,
                runs: bool = True) -> tuple[list[tuple[int, Cells]], ...]:
    """Per piece of the cycle (the cut, then the rest): :func:`turning_cells` of the torque's
    slope T′ at the samples' ``jet`` and the squared speeds ``w2``, among the ``window``'s cells
    of that piece. The torque's peaks lie in them, and so do the energy's hidden pairs of
    extrema (:mod:`core.forces.bumps`: E″ = T′), so both searches take them from here, found
    once."""
    return tuple(turning_cells((jet.static1 + cutting * jet.cut1, jet.inertial1), w2,
                               window.cells[k], runs=runs)
                 for k, cutting in enumerate((1.0, 0.0)))


def _columns(index: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
    """What takes ``array[:, index]`` from (designs, samples) arrays, worked out once per
    segment: a view where ``index`` is a run of consecutive columns (a segment's left
    samples, and its right ones unless it wraps), the run's two parts joined where it is a
    run turned by one (a wrapping segment's right samples: a sixth of the time of
    ``np.take`` along the columns, which the sweep spent 0.4 ms a call on), else a copy."""
    size = index.size
    first = int(index[0]) if size else 0
    if size and np.array_equal(index, np.arange(first, first + size)):
        return lambda array: array[:, first:first + size]
    if size > 1 and index[-1] == first - 1 and np.array_equal(index[:-1], np.arange(first, first + size - 1)):
        return lambda array: np.concatenate([array[:, first:first + size - 1],
                                             array[:, first - 1:first]], axis=1)
    return lambda array: np.take(array, index, axis=1)


def cell_index(n: int, cells: Cells) -> list[np.ndarray]:
    """The flat indices of the cells' left and right samples in (designs, ``n``) arrays."""
    return [cells.design * n + column for column in (cells.left, cells.right)]


def cell_ends(values: tuple[np.ndarray, np.ndarray],
              index: list[np.ndarray]) -> list[tuple[np.ndarray, np.ndarray]]:
    """(a, b) of ``values`` (a, b), C-contiguous arrays (designs, samples), at the flat
    ``index`` of each cell's two samples (:func:`cell_index`)."""
    return [(values[0].ravel().take(i), values[1].ravel().take(i)) for i in index]


def straddling(cells: Cells, inside: list[np.ndarray], k: int) -> tuple[np.ndarray, ...]:
    """The turning cells that straddle an end of piece ``k`` (0 the cut, from on to off; 1 the
    rest, from off to on), one sample inside it and one not (``inside``: per cell, whether its
    left and its right sample lie in the piece): their positions among ``cells``, the flat
    index of that switch angle in the :class:`Window`'s (designs, 2) jet, and whether the
    cell leaves the piece there (its left sample inside) or enters it."""
    left, right = inside
    which = np.flatnonzero(left != right)
    leaving = left.take(which)
    return which, cells.design.take(which) * 2 + np.where(leaving, 1 - k, k), leaving


def at_switch(parts: tuple[np.ndarray, np.ndarray], switch: np.ndarray,
              w2: np.ndarray) -> np.ndarray:
    """a + ω²·b of ``parts`` (a, b), each (designs, 2) at the switch angles, at their flat
    indices ``switch`` (:func:`straddling`) and the squared speeds ``w2``, one per index."""
    return parts[0].ravel().take(switch) + w2 * parts[1].ravel().take(switch)


def turns_beyond(slope: np.ndarray, leaving: np.ndarray, sign: float) -> np.ndarray:
    """Which straddling cells (:func:`straddling`) turn beyond their piece, given the slope of
    their curve at the switch angle (:func:`at_switch`): a cell turns where sign·slope stops
    being positive (``sign`` 1 for a maximum, -1 for a minimum), and, by the grid's premise of
    at most one turn per cell, it does so beyond the piece's end when the slope there still
    is, or before the piece's start when the slope there no longer is. Such a cell's
    extremum does not count (the piece's values at the switch do), so it need not be
    polished: 20-40 % of the cells of a loaded sweep's first polish, each with a sample beside
    the cut's start or end, and 20 % of the energy's evaluations, as their polish crossed
    into the other piece."""
    g = sign * slope
    return np.where(leaving, g > 0.0, g <= 0.0)          # NaN: neither, the cell is kept
