"""Searches inside brackets, vectorized over many brackets at once: a root, a maximum
whose slope and curvature are known, and a minimum without a slope.

Level-0 numerics (numpy only). :mod:`core.linkage.extrema` finds the brackets on a grid
and polishes them with these; the cut's switch angles, the metrics' closed-form
peaks and the flywheel's energy extremes call :func:`bracket_root` directly. They
stand apart from the grid work because each is a method with its own convergence
argument: Chandrupatla's root search (:func:`bracket_root`), Newton's method kept
inside its cell (:func:`newton_maximum`) and Brent's parabolic/golden minimizer
(:func:`polish_minimum`). Each evaluates only the brackets still open, so the cost
is the number of calls, not of brackets.
"""
from __future__ import annotations

from typing import Callable, Sequence

import numpy as np


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


def newton_maximum(fun: Callable[..., tuple[np.ndarray, np.ndarray, np.ndarray]],
                   lo: np.ndarray, hi: np.ndarray, v_lo: np.ndarray, v_hi: np.ndarray,
                   s_lo: np.ndarray, s_hi: np.ndarray,
                   args: Sequence[np.ndarray] = (), iterations: int = 60,
                   gain: float = 0.0,
                   curvatures: tuple[np.ndarray, np.ndarray] | None = None,
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

    With ``gain`` > 0 a curve is also done when the step's predicted rise of the value,
    slope²/(2·|curvature|) (exact for the quadratic the step solves), is at most ``gain``
    times the value's size: its value is then the maximum's to about that, one evaluation
    sooner (the loaded sweep's torque peaks: ``gain`` 1e-15, three evaluations became two).

    With ``curvatures`` (the slope's slope at ``lo`` and ``hi``) the start is the top of the
    quintic through the ends' values, slopes and curvatures (:func:`_quintic_top`): on the
    loaded sweep's torque peaks a median 1e-10 to 5e-9 rad from the maximum against 1e-6 to
    2e-5 for the cubic's, so that with ``gain`` 1e-15 most curves are done after one
    evaluation (83-100 % of the cells of the 16-speed rod benchmark; two before).
    """
    a, b = np.array(lo, dtype=float), np.array(hi, dtype=float)
    width = b - a
    t = _cubic_top(v_lo, v_hi, s_lo * width, s_hi * width)
    if curvatures is not None:
        t = _quintic_top(v_lo, v_hi, s_lo * width, s_hi * width,
                         curvatures[0] * width * width, curvatures[1] * width * width, t)
    return newton_zero(fun, a, b, a + width * t, args, iterations, gain)


def newton_crossing(fun: Callable[..., tuple[np.ndarray, np.ndarray, np.ndarray]],
                    lo: np.ndarray, hi: np.ndarray, slopes: tuple[np.ndarray, np.ndarray],
                    rates: tuple[np.ndarray, np.ndarray], curvatures: tuple[np.ndarray, np.ndarray],
                    args: Sequence[np.ndarray] = (), iterations: int = 60, gain: float = 0.0,
                    ) -> tuple[np.ndarray, np.ndarray]:
    """(x, value) where each curve's slope g falls through zero in [lo, hi], by
    :func:`newton_zero` from the zero of the quintic through g, g′ and g″ at both ends
    (``slopes``, ``rates``, ``curvatures``: each (at lo, at hi)), for a curve whose slope has
    two derivatives in closed form (the loaded sweep's energy, whose slope is the torque less
    its mean). Its zero lies a median 1e-9 rad from the slope's (the top of the quintic
    through the curve's own values, slopes and curvatures: 1e-8 to 4e-8, and 1e-2 where a
    cell's values belong to two pieces of the cycle), so that most curves are done after one
    evaluation with ``gain`` 1e-15, and the curve's values at the ends are not needed."""
    a, b = np.array(lo, dtype=float), np.array(hi, dtype=float)
    width = b - a
    t = _quintic_zero(slopes[0], slopes[1], rates[0] * width, rates[1] * width,
                      curvatures[0] * width * width, curvatures[1] * width * width)
    return newton_zero(fun, a, b, a + width * t, args, iterations, gain)


def newton_zero(fun: Callable[..., tuple[np.ndarray, np.ndarray, np.ndarray]],
                lo: np.ndarray, hi: np.ndarray, start: np.ndarray,
                args: Sequence[np.ndarray] = (), iterations: int = 60, gain: float = 0.0,
                ) -> tuple[np.ndarray, np.ndarray]:
    """(x, value) where the slope of each curve falls through zero in [lo, hi] (positive at
    ``lo``, not at ``hi``), by Newton's method from ``start`` kept inside the bracket;
    ``fun`` and the result as in :func:`newton_maximum`, which is this from the cubic's top.
    A zero of any function g with a known slope is such a point of a curve whose slope is
    g: ``fun`` may return (anything, g, g′)."""
    a, b = np.array(lo, dtype=float), np.array(hi, dtype=float)
    args = [np.broadcast_to(np.asarray(v), a.shape) for v in args]
    x = np.array(start, dtype=float)
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
        if gain > 0.0:
            done |= inside & (np.abs(0.5 * g * step) <= gain * np.abs(v))   # False for NaN
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


def _quintic_top(v0, v1, m0, m1, c0, c1, t, steps: int = 3):
    """Where in [0, 1] the quintic with values v0, v1, slopes m0, m1 and curvatures c0, c1
    at 0 and 1 (per unit of t) peaks, by Newton's method on its slope from ``t`` (the cubic's
    top, :func:`_cubic_top`), each step kept in [0, 1]; ``t`` where that gives no finite
    point. Hermite's quintic is v0 + m0·t + c0/2·t² + p3·t³ + p4·t⁴ + p5·t⁵ with, for the
    ends' residues A = v1 − v0 − m0 − c0/2, B = m1 − m0 − c0, C = c1 − c0:
    p3 = 10A − 4B + C/2, p4 = −15A + 7B − C, p5 = 6A − 3B + C/2."""
    big_a, big_b, big_c = v1 - v0 - m0 - 0.5 * c0, m1 - m0 - c0, c1 - c0
    p3 = 10.0 * big_a - 4.0 * big_b + 0.5 * big_c
    p4 = -15.0 * big_a + 7.0 * big_b - big_c
    p5 = 6.0 * big_a - 3.0 * big_b + 0.5 * big_c
    u = t
    with np.errstate(all="ignore"):
        for _ in range(steps):
            slope = m0 + u * (c0 + u * (3.0 * p3 + u * (4.0 * p4 + u * (5.0 * p5))))
            curve = c0 + u * (6.0 * p3 + u * (12.0 * p4 + u * (20.0 * p5)))
            u = np.clip(u - slope / curve, 0.0, 1.0)
    return np.where(np.isfinite(u), u, t)


def _quintic_zero(g0, g1, m0, m1, c0, c1, steps: int = 4):
    """Where in [0, 1] the quintic with values g0 > 0 ≥ g1, slopes m0, m1 and curvatures c0,
    c1 at 0 and 1 (per unit of t) falls through zero: Newton's method on it from the secant's
    zero, each step kept in [0, 1] (Hermite's quintic as in :func:`_quintic_top`); the
    secant's zero where that gives no finite point, and 0.5 where neither does."""
    big_a, big_b, big_c = g1 - g0 - m0 - 0.5 * c0, m1 - m0 - c0, c1 - c0
    p3 = 10.0 * big_a - 4.0 * big_b + 0.5 * big_c
    p4 = -15.0 * big_a + 7.0 * big_b - big_c
    p5 = 6.0 * big_a - 3.0 * big_b + 0.5 * big_c
    with np.errstate(all="ignore"):
        start = g0 / (g0 - g1)
        start = np.where((start >= 0.0) & (start <= 1.0), start, 0.5)
        u = start
        for _ in range(steps):
            value = g0 + u * (m0 + u * (0.5 * c0 + u * (p3 + u * (p4 + u * p5))))
            slope = m0 + u * (c0 + u * (3.0 * p3 + u * (4.0 * p4 + u * (5.0 * p5))))
            u = np.clip(u - value / slope, 0.0, 1.0)
    return np.where(np.isfinite(u), u, start)


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
