"""Exact extrema of closed-form curves, for many curves at once.

A level-0 numerical helper (numpy and scipy only; it knows nothing about
mechanisms). A grid only *brackets* an extremum: a local maximum lies between
two neighbouring samples where the curve's analytic slope turns from rising
to falling. The best few such cells per curve are polished by finding the
slope's zero there (a bracketed root, vectorized over all curves), and the
curve's value at that zero is the extremum. A reported extremum is therefore
never the largest sample of a grid, and never smaller than it.

For curves without an analytic slope (the crank torque), :func:`polish_minimum`
uses scipy's elementwise bracketing minimizer on the function itself.
"""
from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

# Best sampled cells polished per curve and segment: two, so that a second peak the grid
# under-samples (and shows a little lower than the first) is still found.
CANDIDATES = 2
Curve = Callable[..., tuple[np.ndarray, np.ndarray]]


def grid_maximum(fun: Curve, x: np.ndarray, values: np.ndarray, slopes: np.ndarray,
                 args: Sequence[np.ndarray] = (),
                 segments: Sequence[tuple[int, int, float]] | None = None,
                 candidates: int = CANDIDATES) -> np.ndarray:
    """Largest value of each curve, polished from samples; shape values.shape[:-1].

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
    x = np.broadcast_to(np.asarray(x, dtype=float), values.shape)
    slopes = np.broadcast_to(slopes, values.shape)
    segments = [(0, n, 0.0)] if segments is None else list(segments)
    best = np.max(values, axis=-1)
    picks_lo, picks_hi, picks_args = [], [], []
    for start, stop, period in segments:
        seg_x, seg_v, seg_s = (a[..., start:stop] for a in (x, values, slopes))
        if period > 0.0:
            next_x = np.concatenate([seg_x[..., 1:], seg_x[..., :1] + period], axis=-1)
            next_v, next_s = np.roll(seg_v, -1, axis=-1), np.roll(seg_s, -1, axis=-1)
        else:
            next_x, next_v, next_s = seg_x[..., 1:], seg_v[..., 1:], seg_s[..., 1:]
            seg_x, seg_v, seg_s = seg_x[..., :-1], seg_v[..., :-1], seg_s[..., :-1]
        if seg_x.shape[-1] == 0:
            continue
        turn = (seg_s > 0.0) & (next_s <= 0.0)
        score = np.where(turn, np.maximum(seg_v, next_v), -np.inf)
        picks, found = [], []
        for j in range(min(candidates, score.shape[-1])):   # the best few, by repeated argmax
            best_i = np.argmax(score, axis=-1)[..., None]
            picks.append(best_i)
            found.append(np.isfinite(np.take_along_axis(score, best_i, axis=-1)))
            if j + 1 < candidates:
                np.put_along_axis(score, best_i, -np.inf, axis=-1)
        pick, real = np.concatenate(picks, axis=-1), np.concatenate(found, axis=-1)
        index = np.nonzero(real)
        flat_pick = pick[index]
        picks_lo.append(seg_x[index[:-1] + (flat_pick,)])
        picks_hi.append(next_x[index[:-1] + (flat_pick,)])
        picks_args.append(np.ravel_multi_index(index[:-1], lead) if lead else
                          np.zeros(flat_pick.size, dtype=int))
    if not picks_lo:
        return best
    lo, hi, owner = (np.concatenate(v) for v in (picks_lo, picks_hi, picks_args))
    flat_args = [np.broadcast_to(a, lead + (1,)).reshape(-1)[owner] for a in args]
    slope = lambda t, *a: fun(t, *a)[1]  # noqa: E731
    root = bracket_root(slope, lo, hi, flat_args)
    peak = fun(root, *flat_args)[0]
    out = best.reshape(-1).copy()
    np.fmax.at(out, owner, peak)
    return out.reshape(lead)


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


def bracket_root(fun: Callable[..., np.ndarray], lo: np.ndarray, hi: np.ndarray,
                 args: Sequence[np.ndarray] = ()) -> np.ndarray:
    """A zero of ``fun`` in each bracket [lo, hi] across which it changes sign (1-D arrays).

    scipy's elementwise Chandrupatla root finder: superlinear on smooth
    functions and, since the bracket always keeps the sign change, convergent
    for any continuous one. Only the brackets still open are evaluated.
    """
    from scipy.optimize import elementwise

    if np.size(lo) == 0:
        return np.zeros(0)
    res = elementwise.find_root(fun, (lo, hi), args=tuple(args),
                                tolerances={"xrtol": 1e-13, "xatol": 1e-13})
    return res.x


def polish_minimum(fun: Callable[..., np.ndarray], xl: np.ndarray, xm: np.ndarray,
                   xr: np.ndarray, args: Sequence[np.ndarray] = ()) -> np.ndarray:
    """A local minimum of ``fun`` inside each bracket xl < xm < xr (1-D arrays).

    For curves without an analytic slope: scipy's elementwise Chandrupatla
    minimizer on the function itself. Returns fun's value at the minimizer,
    never more than fun(xm) (an invalid, flat bracket keeps fun(xm)).
    """
    from scipy.optimize import elementwise

    if xm.size == 0:
        return np.zeros(0)
    res = elementwise.find_minimum(fun, (xl, xm, xr), args=tuple(args),
                                   tolerances={"xrtol": 1e-10, "frtol": 1e-13})
    return np.fmin(res.f_x, fun(xm, *args))
