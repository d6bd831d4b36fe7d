"""Involute functions and the GB/T 1356 basic rack: the closed forms every gear length uses.

Angles are in radians here (degrees only at the front ends). Each function is the formula
of the textbook (孙桓《机械原理》, ISO 21771 names in English), small enough to check by eye.
"""
from __future__ import annotations

import math

import numpy as np

NEWTON_TOLERANCE = 1e-15
"""Newton stops when a step changes α by less than this (relative): inv α then agrees to
about 1e-16, well inside the 1e-14 the issue asks for."""

FIRST_SERIES_MM = (0.1, 0.12, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.25, 1.5, 2.0, 2.5,
                   3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0, 32.0, 40.0, 50.0)
"""GB/T 1357-2008, first series of modules, mm (the series preferred for new designs)."""


def inv(alpha):
    """inv α = tan α − α, the involute function (scalar or array)."""
    return np.tan(alpha) - alpha


def inv_inverse(value: float) -> float:
    """The α in (0, π/2) with inv α = ``value`` (> 0), by Newton: f = tan α − α − v is convex
    and increasing there, so Newton from a start right of the root converges monotonically.
    Both starts are right of it: inv α > α³/3 gives α < ∛(3v), and tan α = v + α < v + π/2.
    Iterated in extended precision (numpy's longdouble): tan α − α loses log10(α / inv α)
    digits to cancellation, about 3 at 5°, which double precision cannot spare for 1e-14."""
    if not value > 0.0 or not math.isfinite(value):
        raise ValueError(f"inv α must be a positive finite number, got {value!r}")
    v = np.longdouble(value)
    alpha = np.longdouble(min((3.0 * value) ** (1.0 / 3.0), math.atan(value + math.pi / 2)))
    for _ in range(100):
        tan = np.tan(alpha)
        step = (tan - alpha - v) / (tan * tan)
        alpha -= step
        if abs(step) <= NEWTON_TOLERANCE * alpha:
            break
    return float(alpha)


def least_shift(teeth: float, alpha: float, addendum: float) -> float:
    """x_min = h*a (z_min − z)/z_min with z_min = 2 h*a / sin² α, i.e. h*a − z sin² α / 2: the
    least shift for which the rack's addendum line (h*a − x) m passes no lower than the
    limit point N of the line of action (no undercut). Exact z_min (17.097 at 20°), not 17."""
    return addendum - teeth * math.sin(alpha) ** 2 / 2.0


def least_teeth(alpha: float, addendum: float) -> float:
    """z_min = 2 h*a / sin² α: the fewest teeth a standard (x = 0) gear can have uncut."""
    return 2.0 * addendum / math.sin(alpha) ** 2


def reference_thickness(module: float, shift: float, alpha: float) -> float:
    """s = m (π/2 + 2 x tan α): tooth thickness on the reference circle."""
    return module * (math.pi / 2.0 + 2.0 * shift * math.tan(alpha))


def thickness_at(radius, r: float, s: float, alpha: float, rb: float):
    """s_K = s r_K / r − 2 r_K (inv α_K − inv α) with cos α_K = rb / r_K: the arc thickness of
    the tooth at radius r_K (≥ rb), from its thickness s on the reference circle r."""
    alpha_k = np.arccos(rb / np.asarray(radius, dtype=float))
    return s * radius / r - 2.0 * radius * (inv(alpha_k) - inv(alpha))


def half_angle(radius, r: float, s: float, alpha: float, rb: float):
    """ψ(r_K) = s / (2 r) + inv α − inv α_K: the angle from the tooth's axis to its flank at
    radius r_K (the flank is the involute of the base circle rb)."""
    alpha_k = np.arccos(rb / np.asarray(radius, dtype=float))
    return s / (2.0 * r) + inv(alpha) - inv(alpha_k)
