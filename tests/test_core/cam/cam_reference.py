"""Independent checks of a cam: nothing here is taken from core.cam's derivation.

The mechanism is restated from its definition (the cam's frame: cam centre at the origin,
pivot on +x at the centre distance at cam angle 0, cam turning clockwise; the roller centre
at l from the pivot, at the angle ψ0 + ψ from the pivot→centre line, on the arm's side k:
+1 above the x axis). Positions come from that statement, the follower's angle from the law's
ψ(δ) only; every direction is a finite difference and every contact a numeric search.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar


def roller_centre(a, l, psi0, k, psi):
    """Roller centre in the fixed frame (cam centre at the origin, pivot at (a, 0))."""
    beta = psi0 + np.asarray(psi, dtype=float)
    return np.stack([a - l * np.cos(beta), k * l * np.sin(beta)])


def rotate(points, angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * points[0] - s * points[1], s * points[0] + c * points[1]])


def pitch_points(a, l, psi0, k, psi_of, delta):
    """The roller centre carried onto the cam (the cam turns clockwise by δ, so the point
    on the cam is the fixed-frame point turned back by +δ)."""
    return rotate(roller_centre(a, l, psi0, k, psi_of(delta)), np.asarray(delta, dtype=float))


def numeric_pressure(a, l, psi0, k, psi_of, delta, h=1e-5):
    """Pressure angle (rad): the pitch curve's normal by central differences against the
    roller's direction of motion (a central difference of its path in ψ), both on the cam."""
    delta = np.asarray(delta, dtype=float)
    tangent = (pitch_points(a, l, psi0, k, psi_of, delta + h)
               - pitch_points(a, l, psi0, k, psi_of, delta - h)) / (2 * h)
    normal = np.stack([-tangent[1], tangent[0]]) / np.hypot(*tangent)
    psi = psi_of(delta)
    move = (roller_centre(a, l, psi0, k, psi + h) - roller_centre(a, l, psi0, k, psi - h)) / (2 * h)
    move = rotate(move, delta)
    move = move / np.hypot(*move)
    return np.arccos(np.clip(np.abs(np.sum(normal * move, axis=0)), 0.0, 1.0))


def contact_angle(profile_of, a, l, psi0, k, roller, delta, guess, grid=4001):
    """The follower angle ψ at which the roller touches the profile turned to cam angle
    ``delta``: the root of (distance from the roller centre to the profile) − roller.

    ``profile_of(u)`` gives the profile's points (2, n) in the cam's frame at parameters u
    (rad, one turn); the distance is a dense search refined by a bounded minimization."""
    u = np.linspace(0.0, 2 * math.pi, grid)
    coarse = rotate(profile_of(u), -delta)
    step = u[1] - u[0]

    def distance(psi):
        centre = roller_centre(a, l, psi0, k, psi)
        i = int(np.argmin(np.hypot(coarse[0] - centre[0], coarse[1] - centre[1])))

        def d(t):
            q = rotate(profile_of(np.array([t])), -delta)[:, 0]
            return math.hypot(q[0] - centre[0], q[1] - centre[1])
        best = minimize_scalar(d, bounds=(u[i] - 2 * step, u[i] + 2 * step), method="bounded",
                               options={"xatol": 1e-13})
        return best.fun - roller
    # The distance is unsigned: once the centre has passed through the profile (2r away on
    # the cutting side) it is positive again. The first window therefore moves the centre at
    # most one roller radius along its arc, so that a small roller (a synthesized cam's can
    # come out at hundredths of a millimetre) is bracketed by cutting in and clear; it is
    # widened from there until the roller goes from cutting in to clear.
    window = min(1e-3, roller / l)
    while distance(guess - window) > 0 or distance(guess + window) < 0:
        window *= 2
        if window > 0.2:
            raise AssertionError(f"no contact within 0.2 rad of {guess} at cam angle {delta}")
    return brentq(distance, guess - window, guess + window, xtol=1e-14, rtol=1e-14)


def worst_pressure(r0, l, k, psi_of, rise, back, psi0s):
    """The largest pressure angles on the rise and the return (rad) of every cam of base
    radius ``r0`` whose arm starts at ψ0 in ``psi0s`` (both roots of the centre distance)."""
    out = []
    for psi0 in psi0s:
        disc = r0 * r0 - (l * math.sin(psi0)) ** 2
        if disc < 0:
            continue
        for a in (l * math.cos(psi0) + math.sqrt(disc), l * math.cos(psi0) - math.sqrt(disc)):
            if a <= 1e-9:
                continue
            out.append((a, psi0, numeric_pressure(a, l, psi0, k, psi_of, rise).max(),
                        numeric_pressure(a, l, psi0, k, psi_of, back).max()))
    return out
