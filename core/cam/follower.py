"""The oscillating roller follower on a disc cam: pitch curve, profile, pressure angle, curvature.

Frame (the cam's own): the cam centre O at the origin and, at cam angle δ = 0, the follower
pivot A on the +x axis at the centre distance a. The cam turns clockwise by δ, as the crank
on its shaft does in the scheme; a point fixed to the cam is drawn where it is at δ = 0, so
the pitch curve is the roller centre B carried back by +δ (the inversion method).

In the fixed frame B = A + l·(−cos β, side·sin β) with β = ψ0 + ψ the angle AO→AB and
side = ±1 the side of the line of centres the arm lies on (its arrangement). The algebra is
done for a counter-clockwise cam (with k = −side) and mirrored in y at the end, which turns
it into the clockwise one. Every derivative is the closed form of that expression, with
dψ/dδ and d²ψ/dδ² from the law, so the pressure angle, the curvature and the profile's
normal are exact.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from core.base.errors import DesignError
from core.linkage.verdict import round_text
from .laws import Motion, Program

TURN = -1
"""The cam's sense in its frame: −1 clockwise (the crank's, seen as in the scheme)."""


@dataclass(frozen=True)
class Follower:
    """Where the follower sits against the cam (mm, degrees): arm length l, centre
    distance a, the arm's angle ψ0 from the line AO at the lowest position, and the side
    ``side`` (+1: the roller above the line of centres at δ = 0, −1: below, in the cam's
    frame)."""

    arm_mm: float
    distance_mm: float
    initial_deg: float
    side: int = 1

    @property
    def k(self) -> int:
        """The side in the counter-clockwise algebra (mirrored in y for a clockwise cam)."""
        return TURN * self.side

    @property
    def base_radius_mm(self) -> float:
        """Radius of the pitch curve's base circle: O to the roller centre at ψ = 0."""
        a, l, c = self.distance_mm, self.arm_mm, math.cos(math.radians(self.initial_deg))
        return math.sqrt(max(a * a + l * l - 2.0 * a * l * c, 0.0))


class Pitch(NamedTuple):
    """The pitch curve over cam angles: points, first and second δ-derivatives (2, n) mm,
    in the cam's frame; ``beta`` the arm's angle β = ψ0 + ψ (rad); ``motion`` the law."""

    point: np.ndarray
    d1: np.ndarray
    d2: np.ndarray
    beta: np.ndarray
    motion: Motion


def _turn_back(delta: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """(x, y) rotated by −δ (from the fixed frame into a counter-clockwise cam's), then
    mirrored in y for a clockwise cam."""
    c, s = np.cos(delta), np.sin(delta)
    return np.stack([c * x + s * y, TURN * (-s * x + c * y)])


def pitch(f: Follower, program: Program, delta: np.ndarray) -> Pitch:
    """The roller centre's path on the cam at cam angles ``delta`` (rad)."""
    delta = np.asarray(delta, dtype=float)
    return pitch_of_motion(f, delta, program.motion(delta))


def pitch_of_motion(f: Follower, delta: np.ndarray, m: Motion) -> Pitch:
    """The pitch curve at cam angles ``delta`` (rad) for the follower's motion ``m`` there:
    :func:`pitch` with the motion given, for a one-sided value at a jump of the law's
    acceleration (see ``laws.law_piece``). The follower's centre distance and angle may be
    arrays of many cam centres, broadcast against the angles (``build`` screens centres so)."""
    l, a, k = f.arm_mm, f.distance_mm, float(f.k)
    beta = np.radians(f.initial_deg) + m.psi
    cb, sb = np.cos(beta), np.sin(beta)
    bx, by = a - l * cb, k * l * sb                     # B in the fixed frame
    vx, vy = sb, k * cb                                 # dB/dβ / l: the roller's direction of motion
    # t = dB/dδ − J·B (J turns by +90°): the pitch curve's tangent before the turn back.
    tx, ty = l * m.psi1 * vx + by, l * m.psi1 * vy - bx
    # dt/dδ, then t' − J·t gives the second derivative before the turn back.
    wx, wy = cb, -k * sb                                # dv/dβ
    dtx = l * (m.psi2 * vx + m.psi1 ** 2 * wx) + l * m.psi1 * vy
    dty = l * (m.psi2 * vy + m.psi1 ** 2 * wy) - l * m.psi1 * vx
    return Pitch(_turn_back(delta, bx, by), _turn_back(delta, tx, ty),
                 _turn_back(delta, dtx + ty, dty - tx), beta, m)


def pressure_angle(f: Follower, p: Pitch) -> np.ndarray:
    """Pressure angle (rad, 0 … π/2) between the cam's push, along the pitch curve's
    normal, and the roller's velocity: tan α = |l·ψ' + k·(l − a·cos β)| / (a·sin β)
    with k = −side for the clockwise cam."""
    l, a = f.arm_mm, f.distance_mm
    num = l * p.motion.psi1 + f.k * (l - a * np.cos(p.beta))
    return np.arctan2(np.abs(num), a * np.sin(p.beta))


def curvature_radius(p: Pitch) -> np.ndarray:
    """Signed radius of curvature of the pitch curve (mm): positive where it is convex,
    negative where concave (the curve runs against the cam's sense as δ grows)."""
    d1, d2 = p.d1, p.d2
    cross = d1[0] * d2[1] - d1[1] * d2[0]
    speed = np.hypot(d1[0], d1[1])
    with np.errstate(divide="ignore"):
        return np.where(cross == 0.0, np.inf, -TURN * speed ** 3 / np.where(cross == 0.0, 1.0, cross))


def outward_normal(p: Pitch) -> np.ndarray:
    """Unit normal of the pitch curve pointing away from the cam centre (2, n)."""
    speed = np.hypot(p.d1[0], p.d1[1])
    return TURN * np.stack([-p.d1[1], p.d1[0]]) / speed


def profile(p: Pitch, roller_mm: float) -> np.ndarray:
    """The actual profile (2, n) mm: the inner envelope of the roller, one roller radius
    inside the pitch curve along its normal."""
    return p.point - roller_mm * outward_normal(p)


def check_follower(f: Follower, program: Program) -> None:
    """The arm must stay on one side of the line of centres over its whole swing."""
    if not f.initial_deg + program.swing_deg < 180.0:    # past it at the end of the swing: r0 too large
        a, l = f.distance_mm, f.arm_mm
        most = math.sqrt(a * a + l * l + 2.0 * a * l * math.cos(math.radians(program.swing_deg)))
        raise DesignError("base", f.base_radius_mm, "gives an arm that crosses the line of centres at the end "
                          f"of its swing; give a base radius below {round_text(most, 4, down=True)} mm")
    if not 0.0 < f.initial_deg:
        raise DesignError("base", f.base_radius_mm,
                          "gives an arm that crosses the line of centres; choose another base radius")
