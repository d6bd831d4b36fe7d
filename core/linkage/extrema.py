"""Exact extrema of closed-form curves, for many curves at once.

A level-0 numerical helper (numpy only; it knows nothing about mechanisms). A grid only *brackets* an extremum: a local maximum lies between
two neighbouring samples where the curve's analytic slope turns from rising
to falling. The best few such cells per curve are polished by finding the
slope's zero there (a bracketed root, or Newton's method kept inside the cell
when the slope's own slope is known; both in :mod:`core.linkage.polish`, vectorized
over all curves), and the
curve's value at that zero is the extremum. A reported extremum is therefore
never the largest sample of a grid, and never smaller than it.

For curves without an analytic slope (the crank torque), :func:`piece_maximum`
polishes with :func:`core.linkage.polish.polish_minimum` (Brent's parabolic and golden
steps, vectorized) on the function itself.
"""
from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

from .polish import bracket_root, newton_maximum, polish_minimum

# Best sampled cells polished per curve and segment: two, so that a second peak the grid
# under-samples (and shows a little lower than the first) is still found.
CANDIDATES = 2
Curve = Callable[..., tuple[np.ndarray, np.ndarray]]


def grid_maximum(fun: Curve, x: np.ndarray, values: np.ndarray, slopes: np.ndarray,
                 args: Sequence[np.ndarray] = (),
                 segments: Sequence[tuple[int, int, float]] | None = None,
                 candidates: int = CANDIDATES) -> np.ndarray:
    """Largest value of each curve, polished from samples; shape values.shape[:-1].
    See :func:`grid_argmax`, which also says where it lies."""
    return grid_argmax(fun, x, values, slopes, args, segments, candidates)[0]


def grid_argmax(fun: Curve, x: np.ndarray, values: np.ndarray, slopes: np.ndarray,
                args: Sequence[np.ndarray] = (),
                segments: Sequence[tuple[int, int, float]] | None = None,
                candidates: int = CANDIDATES, newton: bool = False,
                ) -> tuple[np.ndarray, np.ndarray]:
    """(largest value, x where it lies) of each curve, polished from samples; each of
    shape values.shape[:-1]. The x is a polished slope zero, or the best sample when no
    polished one exceeds it (a maximum at a segment end); it may lie beyond the
    samples' range by up to one period of a wrapping segment.

    With ``newton``, ``fun`` also returns the slope's own slope (value, slope,
    curvature) and each cell is polished by :func:`newton_maximum` instead of
    :func:`bracket_root` on the slope: three or four evaluations instead of seven.

    ``fun(x, *args)`` returns the curve's value and slope d/dx at ``x`` (1-D
    arrays, args subset to match). ``x``, ``values`` and ``slopes`` (…, n) are
    the samples; ``args`` broadcast against (…, 1). ``segments`` lists
    (start, stop, period) index ranges of the last axis, each sorted by x; a
    segment with period > 0 wraps around (its last sample's right neighbour
    is its first plus the period). By default the whole axis is one segment
    that does not wrap; its end samples count as they are.
    """
    values = np.asarray(values, dtype=float)
    lead, n = values.shape[:-1], values.shape[-1]
    x = np.broadcast_to(np.asarray(x, dtype=float), values.shape)     # a view: never copied
    slopes = np.broadcast_to(slopes, values.shape)
    segments = [(0, n, 0.0)] if segments is None else list(segments)
    top = np.argmax(values, axis=-1)[..., None]      # a NaN sample wins, as in np.max
    best = np.take_along_axis(values, top, axis=-1).reshape(-1)
    where = np.take_along_axis(x, top, axis=-1).reshape(-1)
    picks: list[list[np.ndarray]] = []        # per rank: [lo, hi, owner, upper bound]
    for start, stop, period in segments:
        v, s = values[..., start:stop], slopes[..., start:stop]
        m = stop - start
        # Cell j lies between samples j and j + 1 (the last wraps to the first if periodic).
        # A cell ranks by its higher end: a sharp peak just beside the best sample lies in
        # the cell that sample ends, whatever its other end (a tangent bound cannot vouch for
        # a cell whose curve is convex, so the best sample's cell must rank first).
        # Written in place (one float pass for the maxima, one for the rest): each pass over
        # a sweep chunk's grid costs about as much as a step of the root search.
        score = np.empty(v.shape[:-1] + (m if period > 0.0 else max(m - 1, 0),))
        cell = np.empty(score.shape, dtype=bool)
        rising, falling = s > 0.0, s <= 0.0              # both False for NaN
        np.maximum(v[..., :-1], v[..., 1:], out=score[..., :m - 1])
        np.logical_and(rising[..., :-1], falling[..., 1:], out=cell[..., :m - 1])
        if period > 0.0:
            np.maximum(v[..., -1:], v[..., :1], out=score[..., m - 1:])
            np.logical_and(rising[..., -1:], falling[..., :1], out=cell[..., m - 1:])
        np.copyto(score, -np.inf, where=~cell)
        for k in range(min(candidates, score.shape[-1])):   # the best few, by repeated argmax
            j = np.argmax(score, axis=-1)[..., None]
            found = np.isfinite(np.take_along_axis(score, j, axis=-1))[..., 0]
            if k + 1 < candidates:
                np.put_along_axis(score, j, -np.inf, axis=-1)
            index = np.nonzero(found)
            cell = j[..., 0][index]
            inner = cell + 1 < m
            left, right = index + (start + cell,), index + (start + np.where(inner, cell + 1, 0),)
            lo, hi = x[left], x[right] + np.where(inner, 0.0, period)
            s_lo, s_hi = slopes[left], slopes[right]
            v_lo, v_hi = values[left], values[right]
            bound = _tangent_bound(lo, hi, v_lo, v_hi, s_lo, s_hi)
            owner = np.ravel_multi_index(index, lead) if lead else np.zeros(cell.size, dtype=int)
            while len(picks) <= k:
                picks.append([])
            picks[k].append((lo, hi, owner, bound, s_lo, s_hi, v_lo, v_hi))
    # The best cell of each curve, and a lower-ranked cell only if its value could exceed
    # the best sample (its upper bound from the tangents at its ends), all polished at once:
    # one root search, whose fixed cost per step dwarfs its cost per bracket.
    parts = []
    for rank, found in enumerate(picks):
        lo, hi, owner, bound, s_lo, s_hi, v_lo, v_hi = (np.concatenate(v) for v in zip(*found))
        keep = bound > best[owner] if rank else slice(None)
        parts.append((lo[keep], hi[keep], owner[keep], s_lo[keep], s_hi[keep], v_lo[keep],
                      v_hi[keep]))
    if not parts:
        return best.reshape(lead), where.reshape(lead)
    lo, hi, owner, s_lo, s_hi, v_lo, v_hi = (np.concatenate(v) for v in zip(*parts))
    if owner.size:
        flat_args = [np.broadcast_to(a, lead + (1,)).reshape(-1)[owner] for a in args]
        if newton:
            root, value = newton_maximum(fun, lo, hi, v_lo, v_hi, s_lo, s_hi, flat_args)
        else:
            slope = lambda t, *a: fun(t, *a)[1]  # noqa: E731
            root = bracket_root(slope, lo, hi, flat_args, f_lo=s_lo, f_hi=s_hi)
            value = fun(root, *flat_args)[0]
        np.fmax.at(best, owner, value)
        won = value == best[owner]          # the winning root of each curve (ties: any)
        where[owner[won]] = root[won]
    return best.reshape(lead), where.reshape(lead)


def _tangent_bound(lo, hi, v_lo, v_hi, s_lo, s_hi):
    """An upper bound of a curve rising at ``lo`` and falling at ``hi``: where its two end
    tangents meet (exact for a concave cell), with the excess over the samples doubled as
    a margin for cells that are not concave."""
    with np.errstate(all="ignore"):
        meet = (v_hi - v_lo + s_lo * lo - s_hi * hi) / (s_lo - s_hi)
        top = v_lo + s_lo * (np.clip(meet, lo, hi) - lo)
    floor = np.maximum(v_lo, v_hi)
    top = np.where(np.isfinite(top), np.maximum(top, floor), np.inf)
    return top + (top - floor)


def grid_minimum(fun: Curve, x: np.ndarray, values: np.ndarray, slopes: np.ndarray,
                 args: Sequence[np.ndarray] = (),
                 segments: Sequence[tuple[int, int, float]] | None = None,
                 candidates: int = CANDIDATES) -> np.ndarray:
    """Smallest value of each curve; see :func:`grid_maximum`."""
    def negated(t, *a):
        value, slope = fun(t, *a)
        return -value, -slope
    return -grid_maximum(negated, x, -np.asarray(values), -np.asarray(slopes), args, segments,
                         candidates)


def sign_changes(x: np.ndarray, values: np.ndarray,
                 segments: Sequence[tuple[int, int, float]] | None = None,
                 ) -> tuple[np.ndarray, ...]:
    """Every cell between neighbouring samples where a curve changes sign or touches zero.

    For curves that may cross zero many times, all of whose crossings matter (the
    slope of an energy curve, each zero a candidate extremum): :func:`grid_argmax`
    polishes only the best few. Returns flat arrays (owner, lo, hi, value at lo,
    value at hi), ``owner`` indexing ``values.shape[:-1]`` flattened, ready for
    :func:`bracket_root`. ``x``, ``values`` and ``segments`` are as in
    :func:`grid_argmax`; a wrapping cell's ``hi`` is its first sample plus the period.
    """
    values = np.asarray(values, dtype=float)
    lead, n = values.shape[:-1], values.shape[-1]
    x = np.broadcast_to(np.asarray(x, dtype=float), values.shape)
    segments = [(0, n, 0.0)] if segments is None else list(segments)
    found = []
    for start, stop, period in segments:
        left = np.arange(start, stop - 1 if period <= 0.0 else stop)
        right = np.where(left + 1 < stop, left + 1, start)
        shift = np.where(left + 1 < stop, 0.0, period)
        v_lo, v_hi = values[..., left], values[..., right]
        cross = (v_lo <= 0.0) != (v_hi <= 0.0)
        cross |= (v_lo == 0.0) | (v_hi == 0.0)
        index = np.nonzero(cross)
        cell = index[-1]
        owner = np.ravel_multi_index(index[:-1], lead) if lead else np.zeros(cell.size, dtype=int)
        found.append((owner, x[index[:-1] + (left[cell],)],
                      x[index[:-1] + (right[cell],)] + shift[cell],
                      v_lo[index], v_hi[index]))
    return tuple(np.concatenate(v) for v in zip(*found))


def piece_maximum(fun: Callable[..., np.ndarray], x: np.ndarray, values: np.ndarray,
                  lo: np.ndarray, hi: np.ndarray, args: Sequence[np.ndarray] = (),
                  segments: Sequence[tuple[int, int, float]] | None = None, period: float = 0.0,
                  candidates: int = CANDIDATES) -> np.ndarray:
    """Largest value of each curve over its interval [lo, hi], without an analytic slope.

    The curve ``fun(x, *args)`` is smooth on and beyond its interval (a piece
    of a piecewise-smooth function, evaluated by that piece's formula), so a
    sampled local maximum is a valid three-point bracket even next to an end.
    A sampled maximum counts when its bracket reaches into the interval, not
    only when the sample itself lies inside: a peak just inside an end whose
    nearest sample lies just outside is otherwise missed (issue 42). The best
    few are polished by :func:`polish_minimum`; a polished maximum that lands
    outside the interval is dropped, and the values at both ends count. With ``period`` the interval may wrap around.
    Shapes: ``values`` (…, n); ``x`` (…, n) or broadcastable to it; ``lo``,
    ``hi`` (…,) or broadcastable to it; args against (…, 1). ``x``, ``lo`` and
    ``hi`` are used at their own shapes where they can be: which samples lie
    inside an interval is worked out once for all curves that share it.
    """
    values = np.asarray(values, dtype=float)
    lead, n = values.shape[:-1], values.shape[-1]
    x = np.asarray(x, dtype=float)
    lo, hi = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)

    def inside(t, a, b):
        return (np.mod(t - a, period) <= np.mod(b - a, period)) if period > 0.0 else \
            (t >= a) & (t <= b)

    flat_args = [np.broadcast_to(a, lead + (1,)).reshape(lead) for a in args]
    lo_all, hi_all = np.broadcast_to(lo, lead).reshape(-1), np.broadcast_to(hi, lead).reshape(-1)
    ends = fun(np.concatenate([lo_all, hi_all]),
               *[np.concatenate([a.reshape(-1)] * 2) for a in flat_args]).reshape((2,) + lead)
    best = np.fmax(ends[0], ends[1])
    within = inside(x, lo[..., None], hi[..., None])      # at the intervals' own shape
    best = np.fmax(best, np.max(np.where(within, values, -np.inf), axis=-1))
    x_all = np.broadcast_to(x, values.shape)                # views: never copied
    full = np.broadcast_shapes(within.shape, values.shape)
    segments = [(0, n, 0.0)] if segments is None else list(segments)
    brackets: list[list[np.ndarray]] = []

    def neighbours(seg: np.ndarray, wraps: bool) -> tuple[np.ndarray, ...]:
        """(previous, own, next) of each sample with both neighbours; a wrapping segment's
        ends neighbour each other."""
        ext = np.concatenate([seg[..., -1:], seg, seg[..., :1]], axis=-1) if wraps else seg
        return ext[..., :-2], ext[..., 1:-1], ext[..., 2:]

    for start, stop, seg_period in segments:
        seg_x, seg_v = x_all[..., start:stop], values[..., start:stop]
        size = stop - start
        wraps = seg_period > 0.0
        prev_v, mid_v, next_v = neighbours(seg_v, wraps)
        first = 0 if wraps else 1                           # segment index of mid_v[..., 0]
        # The bracket reaches into the interval (at the intervals' own shape, then a view).
        seg_in = np.logical_or.reduce(neighbours(within[..., start:stop], wraps))
        seg_in = np.broadcast_to(seg_in, full[:-1] + seg_in.shape[-1:])
        peak = (mid_v >= prev_v) & (mid_v >= next_v) & ((mid_v > prev_v) | (mid_v > next_v))
        score = np.where(peak & seg_in, mid_v, -np.inf)
        for _ in range(min(candidates, score.shape[-1])):
            i = np.argmax(score, axis=-1)[..., None]
            real = np.isfinite(np.take_along_axis(score, i, axis=-1))[..., 0]
            np.put_along_axis(score, i, -np.inf, axis=-1)
            index = np.nonzero(real)
            k = i[..., 0][index] + first
            left, right = k - 1, k + 1
            shift_l = np.where(left < 0, seg_period, 0.0)
            shift_r = np.where(right >= size, seg_period, 0.0)
            left, right = np.mod(left, size), np.mod(right, size)
            brackets.append([seg_x[index + (left,)] - shift_l, seg_x[index + (k,)],
                             seg_x[index + (right,)] + shift_r,
                             seg_v[index + (left,)], seg_v[index + (k,)], seg_v[index + (right,)],
                             np.flatnonzero(real.reshape(-1))])
    if brackets:
        xl, xm, xr, vl, vm, vr, owner = (np.concatenate(v) for v in zip(*brackets))
        part = [a.reshape(-1)[owner] for a in flat_args]
        at, value = polish_minimum(lambda t, *a: -fun(t, *a), xl, xm, xr, part,
                                   values=(-vl, -vm, -vr))
        keep = inside(at, lo_all[owner], hi_all[owner])
        out = best.reshape(-1).copy()
        np.fmax.at(out, owner[keep], -value[keep])
        best = out.reshape(lead)
    return best
