"""An oracle for a cam's extremes, written apart from core.cam (issue 34, item 7).

The motion laws are restated from the textbook; the pitch curve is the roller centre B(ψ)
turned onto the cam, P(δ) = R(δ)·B(ψ(δ)), with its first and second derivatives by the chain
rule on that statement (R′ = R·J, R″ = −R, J the quarter turn), never a finite difference.
The pressure angle is the angle between the pitch curve's normal and the roller's direction
of motion dB/dψ (from their dot and cross products, not from a tangent formula); the
curvature is (P′ × P″)/|P′|³, positive where the curve turns the way the cam's own circles
do (convex). Each extreme is the best of a dense grid (DENSE points per phase, per smooth
piece where the law's acceleration jumps) and of scipy's bounded minimizer around the three
best samples; the grid holds each piece's ends, so a maximum at an end is exact too.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import minimize_scalar

DENSE = 200_001


def law(name, u, first_half=None):
    """s, s′, s″ of a normalized rise at u ∈ [0, 1]; ``first_half`` forces the parabolic
    law's half (its acceleration's one-sided value at u = ½)."""
    u = np.asarray(u, dtype=float)
    if name == "parabolic":
        first = (u < 0.5) if first_half is None else np.full(u.shape, first_half)
        return (np.where(first, 2 * u ** 2, 1 - 2 * (1 - u) ** 2),
                np.where(first, 4 * u, 4 - 4 * u), np.where(first, 4.0, -4.0))
    if name == "cosine":
        return 0.5 - 0.5 * np.cos(np.pi * u), 0.5 * np.pi * np.sin(np.pi * u), \
            0.5 * np.pi ** 2 * np.cos(np.pi * u)
    if name == "sine":
        return u - np.sin(2 * np.pi * u) / (2 * np.pi), 1 - np.cos(2 * np.pi * u), \
            2 * np.pi * np.sin(2 * np.pi * u)
    if name == "poly345":
        return 10 * u ** 3 - 15 * u ** 4 + 6 * u ** 5, 30 * u ** 2 - 60 * u ** 3 + 30 * u ** 4, \
            60 * u - 180 * u ** 2 + 120 * u ** 3
    raise ValueError(name)


def pieces(name):
    """(lo, hi, first_half) of the law's smooth pieces of u."""
    return [(0.0, 0.5, True), (0.5, 1.0, False)] if name == "parabolic" else [(0.0, 1.0, None)]


def follower_angle(sheet, phase, u, first_half=None):
    """ψ, dψ/dδ, d²ψ/dδ² (rad) at fraction u of the rise (phase 0) or the return (1)."""
    swing = math.radians(sheet["swing"])
    span = math.radians(sheet["rise"] if phase == 0 else sheet["back"])
    s, s1, s2 = law(sheet["laws"][phase], u, first_half)
    if phase == 0:
        return swing * s, swing * s1 / span, swing * s2 / span ** 2
    return swing * (1 - s), -swing * s1 / span, -swing * s2 / span ** 2


def _cross(p, q):
    return p[0] * q[1] - p[1] * q[0]


def _parts(cam, psi):
    """B and its ψ-derivatives in the fixed frame (cam centre at the origin, pivot (a, 0))."""
    a, l, k = cam["a"], cam["l"], cam["k"]
    beta = cam["psi0"] + psi
    c, s = np.cos(beta), np.sin(beta)
    return (np.stack([a - l * c, k * l * s]), np.stack([l * s, k * l * c]),
            np.stack([l * c, -k * l * s]))


def pressure(cam, sheet, phase, u):
    """Pressure angle (rad) at fraction u of the phase."""
    psi, psi1, _ = follower_angle(sheet, phase, u)
    b, b1, _ = _parts(cam, psi)
    v = np.stack([-b[1], b[0]]) + b1 * psi1          # R⁻¹·P′ = J·B + B_ψ·ψ′
    return np.arctan2(np.abs(np.sum(v * b1, axis=0)), np.abs(_cross(v, b1)))


def convex_curvature(cam, sheet, phase, u, first_half=None):
    """Curvature of the pitch curve (1/mm), positive where convex."""
    psi, psi1, psi2 = follower_angle(sheet, phase, u, first_half)
    b, b1, b2 = _parts(cam, psi)
    jb1 = np.stack([-b1[1], b1[0]])
    v = np.stack([-b[1], b[0]]) + b1 * psi1
    w = -b + 2 * jb1 * psi1 + b2 * psi1 ** 2 + b1 * psi2   # R⁻¹·P″
    return _cross(v, w) / np.hypot(v[0], v[1]) ** 3


def dense_max(curve, lo=0.0, hi=1.0, n=DENSE):
    """max of curve(u) over [lo, hi]: the grid's best, and the bounded minimizer's around the
    three best samples."""
    u = np.linspace(lo, hi, n)
    values = curve(u)
    best = float(values.max())
    for i in np.argpartition(values, -3)[-3:]:
        a, b = u[max(i - 1, 0)], u[min(i + 1, n - 1)]
        res = minimize_scalar(lambda t: -float(curve(np.array([t]))[0]), bounds=(a, b),
                              method="bounded", options={"xatol": 1e-14})
        best = max(best, -float(res.fun))
    return best


def extremes(cam, sheet):
    """The cam's extremes: the largest pressure angles of the rise and the return (°) and the
    pitch curve's smallest convex radius (mm, the dwells' arcs included)."""
    out = {}
    for phase, key in ((0, "rise_deg"), (1, "return_deg")):
        out[key] = math.degrees(dense_max(lambda u, p=phase: pressure(cam, sheet, p, u)))
    kappa = []
    for phase in (0, 1):
        for lo, hi, first in pieces(sheet["laws"][phase]):
            kappa.append(dense_max(lambda u, p=phase, f=first: convex_curvature(cam, sheet, p, u, f),
                                   lo, hi))
    if 360.0 - sheet["rise"] - sheet["dwell"] - sheet["back"] > 0:
        kappa.append(1.0 / float(np.hypot(*_parts(cam, 0.0)[0])))      # the inner dwell's arc
    if sheet["dwell"] > 0:
        kappa.append(1.0 / float(np.hypot(*_parts(cam, math.radians(sheet["swing"]))[0])))
    out["rho_min_mm"] = 1.0 / max(kappa)
    return out


def motion_extremes(sheet):
    """The largest |dψ/dδ| and |d²ψ/dδ²| over the turn (rad, per rad and per rad²)."""
    out, speed, accel = {}, [], []
    for phase in (0, 1):
        speed.append(dense_max(lambda u, p=phase: np.abs(follower_angle(sheet, p, u)[1])))
        for lo, hi, first in pieces(sheet["laws"][phase]):
            accel.append(dense_max(lambda u, p=phase, f=first: np.abs(follower_angle(sheet, p, u, f)[2]),
                                   lo, hi))
    out["speed_max"], out["accel_max"] = max(speed), max(accel)
    return out
