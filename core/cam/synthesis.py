"""The smallest cam for the allowed pressure angles, and the largest roller it can carry.

With the pivot A at the origin and the arm's lowest position along +x, the cam centre O
sits at (X, Y) = a·(cos ψ0, sin ψ0). The pressure-angle condition at each follower
position, |l·ψ' + k·(l − a·cos β)| ≤ tan[α]·a·sin β, is a pair of half-planes in (X, Y),
since a·cos β = X·cos ψ − Y·sin ψ and a·sin β = X·sin ψ + Y·cos ψ. The admissible centres
are therefore one convex polygon (the graphical method's region, exactly), and the
smallest base radius is its distance from the roller's lowest point (l, 0): the nearest
point of a convex polygon, found from its vertices, with no iteration.

The arrangement (the side k of the line of centres, i.e. the turning sense relative to the
follower) is chosen by synthesizing both and keeping the one with the smaller base radius.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import DesignError
from .follower import TURN, Follower
from .laws import Program, law

SAMPLES = 2001
"""Follower positions per phase at which the allowance is imposed (uniform in the phase)."""
LP_STRIDE = 20
"""Every this many conditions set the first try of an interior point (see _inside)."""
REACH = 50.0
"""The cam centre is sought within this many arm lengths of the pivot."""
ROLLER_SHARE = 0.8
"""The usual margin: the roller's radius at most this share of the smallest convex radius…"""
MIN_PROFILE_RADIUS_MM = 3.0
"""…and the profile's own smallest convex radius (ρmin − r) at least this, mm."""


@dataclass(frozen=True)
class Allowance:
    """Allowed pressure angles, degrees: ``rise`` on the rise, ``back`` on the return."""

    rise_deg: float = 40.0
    return_deg: float = 70.0


def _phase_samples(program: Program) -> list[tuple[np.ndarray, np.ndarray, float]]:
    """(ψ, dψ/dδ, allowed tan) of the rise and of the return, at SAMPLES positions each."""
    u = np.linspace(0.0, 1.0, SAMPLES)
    swing = math.radians(program.swing_deg)
    out = []
    for name, span, sign in ((program.rise_law, program.rise_deg, 1.0),
                             (program.return_law, program.return_deg, -1.0)):
        s, s1, _ = law(name, u)
        psi = swing * (s if sign > 0 else 1.0 - s)
        out.append((psi, sign * swing * s1 / math.radians(span)))
    return out


def _halfspaces(arm: float, k: int, program: Program, allowance: Allowance) -> np.ndarray:
    """Rows [gx, gy, −h] of g·(X, Y) ≤ h, the pressure-angle conditions and the search box
    (k the side in the counter-clockwise algebra, see ``follower``)."""
    rows = []
    for (psi, psi1), allowed in zip(_phase_samples(program), (allowance.rise_deg, allowance.return_deg)):
        t = math.tan(math.radians(allowed))
        c = arm * psi1 + k * arm
        cp, sp = np.cos(psi), np.sin(psi)
        rows.append(np.column_stack([-k * cp - t * sp, k * sp - t * cp, c]))
        rows.append(np.column_stack([k * cp - t * sp, -k * sp - t * cp, -c]))
    box = REACH * arm
    rows.append(np.array([[1.0, 0.0, -box], [-1.0, 0.0, -box], [0.0, 1.0, -box], [0.0, -1.0, -box]]))
    h = np.concatenate(rows)
    return h / np.hypot(h[:, 0], h[:, 1])[:, None]


def _chebyshev(h: np.ndarray) -> np.ndarray | None:
    # scipy comes in when a cam is synthesized, not with the window (its import pulls in
    # numpy.testing and importlib.metadata, a tenth of a second the first screen does not need)
    from scipy.optimize import linprog
    res = linprog([0.0, 0.0, -1.0], A_ub=np.column_stack([h[:, :2], np.ones(len(h))]),
                  b_ub=-h[:, 2], bounds=[(None, None), (None, None), (0.0, None)], method="highs")
    if res.status != 0 or res.x[2] <= 1e-9 * REACH:
        return None
    return res.x[:2]


def _inside(h: np.ndarray) -> np.ndarray | None:
    """A point well inside the polygon, or None if it is empty: the Chebyshev centre of
    every LP_STRIDE-th condition (neighbouring conditions differ little, and a full LP of
    thousands of rows took 0.6 s), kept if it satisfies them all, else that of all."""
    rows = np.r_[np.arange(0, len(h) - 4, LP_STRIDE), np.arange(len(h) - 4, len(h))]
    point = _chebyshev(h[rows])
    if point is not None and np.all(h[:, :2] @ point + h[:, 2] < 0.0):
        return point
    return _chebyshev(h)


def _nearest(ring: np.ndarray, p: np.ndarray) -> np.ndarray:
    """The point of the convex polygon ``ring`` (its vertices in order) nearest to ``p``
    (outside it)."""
    a, b = ring, np.roll(ring, -1, axis=0)
    ab = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.einsum("ij,ij->i", ab, ab), 0.0, 1.0)
    q = a + t[:, None] * ab
    return q[np.argmin(np.hypot(*(q - p).T))]


def admissible(arm_mm: float, program: Program, allowance: Allowance, side: int) -> np.ndarray | None:
    """The polygon of admissible cam centres on ``side`` in the pivot's frame (its vertices
    (n, 2) mm, counter-clockwise), or None when the allowances leave none."""
    from scipy.spatial import ConvexHull, HalfspaceIntersection
    h = _halfspaces(arm_mm, TURN * side, program, allowance)
    centre = _inside(h)
    if centre is None:
        return None
    vertices = HalfspaceIntersection(h, centre).intersections
    return vertices[ConvexHull(vertices).vertices]


def smallest(arm_mm: float, program: Program, allowance: Allowance, side: int) -> Follower | None:
    """The follower arrangement on ``side`` with the smallest base radius, or None."""
    ring = admissible(arm_mm, program, allowance, side)
    if ring is None:
        return None
    x, y = _nearest(ring, np.array([arm_mm, 0.0]))
    if max(abs(x), abs(y)) >= REACH * arm_mm * (1.0 - 1e-9):
        return None
    return Follower(arm_mm, math.hypot(x, y), math.degrees(math.atan2(y, x)), side)


def synthesize(arm_mm: float, program: Program, allowance: Allowance) -> Follower:
    """The smallest cam for the allowance over both arrangements (the arm above the line
    of centres on equal radii); DesignError naming ``pressure`` when there is none."""
    found = [f for f in (smallest(arm_mm, program, allowance, s) for s in (1, -1)) if f is not None]
    if not found:
        raise DesignError("pressure", allowance.rise_deg,
                          f"is too small: no cam within {REACH:g} arm lengths keeps the pressure "
                          "angle within the allowances")
    return min(found, key=lambda f: (round(f.base_radius_mm, 9), -f.side))


def largest_roller(min_convex_mm: float) -> float:
    """The largest roller with the usual margin: r ≤ 0.8·ρmin and ρmin − r ≥ 3 mm."""
    return min(ROLLER_SHARE * min_convex_mm, min_convex_mm - MIN_PROFILE_RADIUS_MM)
