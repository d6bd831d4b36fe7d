"""Exact extrema of closed-form curves, for many curves at once.

A level-0 numerical helper (numpy and scipy only; it knows nothing about
mechanisms). A grid only *brackets* an extremum: a local maximum lies between
two neighbouring samples where the curve's analytic slope turns from rising
to falling. The best few such cells per curve are polished by finding the
slope's zero there (a bracketed root, or Newton's method kept inside the cell
when the slope's own slope is known; vectorized over all curves), and the
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


def newton_maximum(fun: Curve, lo: np.ndarray, hi: np.ndarray, v_lo: np.ndarray,
                   v_hi: np.ndarray, s_lo: np.ndarray, s_hi: np.ndarray,
                   args: Sequence[np.ndarray] = (), iterations: int = 60,
                   ) -> tuple[np.ndarray, np.ndarray]:
    """(x, value) of the maximum of each curve in its cell [lo, hi], across which its slope
    turns from rising (``s_lo`` > 0) to falling (``s_hi`` ≤ 0); 1-D arrays.

    ``fun(x, *args)`` returns (value, slope, slope of the slope). The start is the
    top of the cubic through the cell's end values and slopes (for the sweep's ram
    peaks on 64 samples a cycle: a median 3e-6 rad from the maximum, at most 4e-4,
    against 2e-4 and 4e-3 for the secant's zero of the slope), refined by Newton's
    method on the slope: three evaluations where the bracketed search took six and
    one more for the value.
    The bracket is kept: a step that would leave it bisects it instead. Done when
    a step is within 1e-12·(1 + |x|), as for :func:`bracket_root`; x is then
    the last point evaluated (within that of the zero, so its value is the
    maximum's to ~1e-24 relative) and the value is fun's there.
    """
    a, b = np.array(lo, dtype=float), np.array(hi, dtype=float)
    args = [np.broadcast_to(np.asarray(v), a.shape) for v in args]
    x = a + (b - a) * _cubic_top(v_lo, v_hi, s_lo * (b - a), s_hi * (b - a))
    root, value = x.copy(), np.full(a.shape, np.nan)
    live = np.arange(a.size)
    part = list(args)
    for _ in range(iterations):
        if live.size == 0:
            break
        v, g, curve = fun(x, *part)
        root[live], value[live] = x, v
        rising = g > 0.0
        a, b = np.where(rising, x, a), np.where(rising, b, x)     # the zero stays inside
        with np.errstate(all="ignore"):
            step = -g / curve
        ahead = x + step
        inside = (ahead > a) & (ahead < b)                        # False for NaN
        tol = 1e-12 * (1.0 + np.abs(x))
        done = (np.abs(step) <= tol) | (g == 0.0) | ~(b - a > tol)
        x = np.where(inside, ahead, 0.5 * (a + b))
        if done.any():
            keep = ~done
            live, x, a, b = live[keep], x[keep], a[keep], b[keep]
            part = [p[keep] for p in part]
    return root, value


def _cubic_top(v0, v1, m0, m1):
    """Where in [0, 1] the cubic with values v0, v1 and slopes m0 > 0 ≥ m1 at 0 and 1 (per
    unit of t) peaks: the root of its slope a·t² + b·t + c in [0, 1]; the secant's
    zero of the slope where the cubic gives none (a NaN or a root outside)."""
    a = 3.0 * (m0 + m1) + 6.0 * (v0 - v1)
    b = 6.0 * (v1 - v0) - 4.0 * m0 - 2.0 * m1
    with np.errstate(all="ignore"):
        root = np.sqrt(b * b - 4.0 * a * m0)
        big = -0.5 * (b + np.copysign(root, b))              # the stable pair of roots
        first, second = big / a, m0 / big
        secant = m0 / (m0 - m1)
    t = np.where((first >= 0.0) & (first <= 1.0), first, second)
    t = np.where((t >= 0.0) & (t <= 1.0), t, secant)
    return np.where((t >= 0.0) & (t <= 1.0), t, 0.5)


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


def bracket_root(fun: Callable[..., np.ndarray], lo: np.ndarray, hi: np.ndarray,
                 args: Sequence[np.ndarray] = (), iterations: int = 100,
                 f_lo: np.ndarray | None = None, f_hi: np.ndarray | None = None) -> np.ndarray:
    """A zero of ``fun`` in each bracket [lo, hi] across which it changes sign (1-D arrays).

    Chandrupatla's method (inverse quadratic interpolation when it is safe,
    bisection otherwise), vectorized: superlinear on smooth functions and,
    since the bracket always keeps the sign change, convergent for any
    continuous one. Only the brackets still open are evaluated each step.
    ``f_lo``, ``f_hi`` are fun's values at the ends when the caller has them.
    """
    x1, x2 = np.array(lo, dtype=float), np.array(hi, dtype=float)
    args = [np.broadcast_to(np.asarray(v), x1.shape) for v in args]
    f1 = fun(x1, *args) if f_lo is None else np.asarray(f_lo, dtype=float)
    f2 = fun(x2, *args) if f_hi is None else np.asarray(f_hi, dtype=float)
    root = np.where(np.abs(f1) < np.abs(f2), x1, x2)
    live = np.nonzero((f1 != 0.0) & (f2 != 0.0) & (np.sign(f1) != np.sign(f2)))[0]
    x1, x2, f1, f2 = x1[live], x2[live], f1[live], f2[live]
    x3, f3 = x2, f2
    part = [v[live] for v in args]
    t = np.full(live.size, 0.5)
    for _ in range(iterations):
        if live.size == 0:
            break
        xt = x1 + t * (x2 - x1)
        ft = fun(xt, *part)
        same = np.sign(ft) == np.sign(f1)
        x3, f3 = np.where(same, x1, x2), np.where(same, f1, f2)
        x2, f2 = np.where(same, x2, x1), np.where(same, f2, f1)
        x1, f1 = xt, ft
        small = np.abs(f1) < np.abs(f2)
        root[live] = np.where(small, x1, x2)
        # 1e-12 rad on a crank angle: a peak's value is then exact to ~f″·1e-24, far below
        # rounding even for the sharpest accepted peak (f″ ≲ f·1e10).
        tol = 1e-12 * (1.0 + np.abs(root[live]))
        with np.errstate(all="ignore"):
            tl = tol / np.abs(x2 - x1)
            xi = (x1 - x2) / (x3 - x2)
            ph = (f1 - f2) / (f3 - f2)
            quad = (f1 / (f2 - f1)) * (f3 / (f2 - f3)) + \
                ((x3 - x1) / (x2 - x1)) * (f1 / (f3 - f1)) * (f2 / (f3 - f2))
        done = (tl > 0.5) | (f1 == 0.0) | ~np.isfinite(tl)
        t = np.where((ph ** 2 < xi) & ((1.0 - ph) ** 2 < 1.0 - xi) & np.isfinite(quad), quad, 0.5)
        t = np.clip(t, tl, 1.0 - tl)
        keep = ~done
        live, x1, x2, x3, f1, f2, f3, t = (v[keep] for v in (live, x1, x2, x3, f1, f2, f3, t))
        part = [v[keep] for v in part]
    return root


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
    sampled local maximum inside the interval is a valid three-point bracket
    even next to an end. The best few are polished by :func:`polish_minimum`;
    a polished maximum that lands outside the interval is dropped, and the
    values at both ends count. With ``period`` the interval may wrap around.
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
    within = np.broadcast_to(within, np.broadcast_shapes(within.shape, values.shape))
    segments = [(0, n, 0.0)] if segments is None else list(segments)
    brackets: list[list[np.ndarray]] = []
    for start, stop, seg_period in segments:
        seg_x, seg_v = x_all[..., start:stop], values[..., start:stop]
        size = stop - start
        # Each sample between its neighbours; a wrapping segment's ends neighbour each other.
        wraps = seg_period > 0.0
        ext = np.concatenate([seg_v[..., -1:], seg_v, seg_v[..., :1]], axis=-1) if wraps else seg_v
        prev_v, mid_v, next_v = ext[..., :-2], ext[..., 1:-1], ext[..., 2:]
        first = 0 if wraps else 1                           # segment index of mid_v[..., 0]
        seg_in = within[..., start + first:start + first + mid_v.shape[-1]]
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


_GOLD = 0.3819660112501051   # 2 − golden ratio


def polish_minimum(fun: Callable[..., np.ndarray], xl: np.ndarray, xm: np.ndarray,
                   xr: np.ndarray, args: Sequence[np.ndarray] = (),
                   iterations: int = 100,
                   values: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
                   ) -> tuple[np.ndarray, np.ndarray]:
    """A local minimum of ``fun`` inside each bracket xl < xm < xr (1-D arrays).

    For curves without an analytic slope: successive parabolic interpolation
    through the bracket, with a golden-section step whenever the parabola's
    vertex is not safely inside (Brent's rule, vectorized). The bracket keeps
    f(xm) ≤ f(xl), f(xr) and shrinks every step. Returns the minimizer and
    fun's value there. ``values`` are fun at (xl, xm, xr) when the caller has
    them (samples of the same curve); each call of ``fun`` evaluates all open
    brackets at once, so the cost is the number of calls, not of brackets.

    Once one side of a bracket has closed to within the tolerance of its best
    point, the parabola through three points two of which nearly coincide is
    ill-conditioned; instead of shrinking the other side by golden sections
    (a dozen calls), the bracket probes once at the tolerance on that side,
    which closes it when the best point is the minimum.
    """
    a, m, b = (np.array(v, dtype=float) for v in (xl, xm, xr))
    args = [np.broadcast_to(np.asarray(v), m.shape) for v in args]
    if values is None:
        both = fun(np.concatenate([a, m, b]), *[np.concatenate([v] * 3) for v in args])
        fa, fm, fb = np.split(np.asarray(both, dtype=float), 3)
    else:
        fa, fm, fb = (np.array(v, dtype=float) for v in values)
    at, value = m.copy(), fm.copy()
    live = np.nonzero((fm <= fa) & (fm <= fb) & np.isfinite(fm))[0]
    a, m, b, fa, fm, fb = (v[live] for v in (a, m, b, fa, fm, fb))
    probed = np.zeros(live.size, dtype=bool)
    part = [v[live] for v in args]
    for _ in range(iterations):
        if live.size == 0:
            break
        with np.errstate(all="ignore"):
            p = (m - a) ** 2 * (fm - fb) - (m - b) ** 2 * (fm - fa)
            q = (m - a) * (fm - fb) - (m - b) * (fm - fa)
            u = m - 0.5 * p / q
        tol = 2e-9 * (1.0 + np.abs(m))     # in x; the value is then exact to ~1e-16 relative
        right = (b - m) > (m - a)
        golden = np.where(right, m + _GOLD * (b - m), m - _GOLD * (m - a))
        safe = np.isfinite(u) & (u > a + tol) & (u < b - tol)
        # A vertex within tol of m steps tol away instead (Brent), closing the bracket.
        step = np.where(right, tol, -tol)                # toward the wider side
        probe = ~safe & ~probed & (np.minimum(b - m, m - a) <= 2.0 * tol)
        probed |= probe
        u = np.where(safe, np.where(np.abs(u - m) < tol, m + step, u),
                     np.where(probe, m + step, golden))
        fu = fun(u, *part)
        lower = fu < fm
        left_of = u < m
        # New bracket: around u if it is lower, else u becomes the end on its side.
        a, fa, b, fb = (np.where(lower, np.where(left_of, a, m), np.where(left_of, u, a)),
                        np.where(lower, np.where(left_of, fa, fm), np.where(left_of, fu, fa)),
                        np.where(lower, np.where(left_of, m, b), np.where(left_of, b, u)),
                        np.where(lower, np.where(left_of, fm, fb), np.where(left_of, fb, fu)))
        m, fm = np.where(lower, u, m), np.where(lower, fu, fm)
        at[live], value[live] = m, fm
        done = (b - a) <= 4.0 * tol
        keep = ~done
        live, a, m, b, fa, fm, fb, probed = (v[keep] for v in (live, a, m, b, fa, fm, fb, probed))
        part = [v[keep] for v in part]
    return at, value
