"""Whether a cam can be built: its profile clears the camshaft's hub and the follower pivot's boss.

A cam whose profile dips into its own hub, or sweeps into the boss around the follower's
pivot, can be drawn but not made (issue 34). Two conditions, with the profile radii in
closed form (no sampling):

* the hub: the profile's smallest radius r0 − r ≥ hub + clearance. The pitch curve's
  radius |OB| is smallest (r0) where the follower rests at ψ = 0, and there the normal is
  radial (ψ′ = 0 at both ends of every law), so min |B − r·n| = r0 − r exactly (|B − r·n|
  ≥ |B| − r everywhere);
* the boss: the profile's largest radius R1 − r ≤ a − boss − clearance, with R1 the pitch
  curve's largest radius, at ψ = ψmax: R1² = a² + l² − 2·a·l·cos(ψ0 + ψmax) (|OB| grows with
  β = ψ0 + ψ on 0 < β < 180°). The cam is the pitch region eroded by the roller, so none of
  it lies beyond R1 − r; the turning cam sweeps that disc, which must miss the boss.

The roller's centre may swing out farther from the cam centre than the pivot (R1 > a, the
path "beyond the pivot" of issue 34's swing-45° cam): nothing collides there, since only
the profile turns with the cam, and the boss condition above keeps the profile clear. It is
reported (``pitch_max_radius_mm``), not refused; a roller no larger than the boss already
keeps R1 ≤ a − clearance.

:func:`raised` finds, in synthesis mode, the smallest base radius whose cam meets them
(the admissible centres of :mod:`synthesis` cut by the two conditions, its pressure
angles polished as the smallest cam's);
:func:`require_buildable` refuses a cam that does not, naming the input that decides it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from core.base.errors import DesignError
from .defaults import BOSS_MM, CLEARANCE_MM, HUB_MM
from .extremes import sampled_min_convex_radius
from .follower import Follower
from .laws import Program
from .synthesis import Allowance, within_allowance

MIN_ROLLER_MM = 3.0
"""The smallest automatic roller (a Ø6 mm roller, about the smallest needle roller made):
a checked cam's shrinks to it at most so that its profile clears the hub, and a synthesized
cam whose pitch curve is too sharp for it is raised until it takes one (``cam._fitted``)."""
CIRCLE_SAMPLES = 3600
"""Centres tried on each circle about the roller's lowest point (every 0.1°)."""
RADIUS_TOLERANCE = 1e-6
"""The raised base radius is the smallest within this share of itself."""
GROWTH = 1.25
"""Successive base radii tried until one fits, before the bisection."""
CURVATURE_SAMPLES = 101
"""Samples a smooth piece of a phase when centres are screened for the pitch curve's
smallest convex radius (``extremes.sampled_min_convex_radius``: 0.06 % above the polished
radius at most, over 120 random cams)."""


@dataclass(frozen=True)
class Room:
    """What the cam must clear (mm): the camshaft's hub radius, the follower pivot's boss
    radius, and the least clearance between them and the profile."""

    hub_mm: float = HUB_MM
    boss_mm: float = BOSS_MM
    clearance_mm: float = CLEARANCE_MM


def pitch_max_radius(f: Follower, program: Program) -> float:
    """R1, the pitch curve's largest radius (mm): the roller's centre at ψ = ψmax."""
    a, l = f.distance_mm, f.arm_mm
    beta = math.radians(f.initial_deg + program.swing_deg)
    return math.sqrt(max(a * a + l * l - 2.0 * a * l * math.cos(beta), 0.0))


def shortfalls(f: Follower, program: Program, roller_mm: float, room: Room) -> dict[str, float]:
    """By how much (mm, > 0: it does not fit) each condition fails: ``hub``, ``boss``."""
    r1, a, c = pitch_max_radius(f, program), f.distance_mm, room.clearance_mm
    return {"hub": room.hub_mm + c - (f.base_radius_mm - roller_mm),
            "boss": (r1 - roller_mm) - (a - room.boss_mm - c)}


def roller_for_hub(biggest_mm: float, f: Follower, room: Room) -> float:
    """The automatic roller of a checked cam: the largest, made smaller (down to
    MIN_ROLLER_MM) when the profile would otherwise dip into the hub's clearance; a cam
    that even that one leaves short is then refused by how much with it."""
    left = f.base_radius_mm - room.hub_mm - room.clearance_mm
    return min(biggest_mm, max(left, MIN_ROLLER_MM))


Wedges = tuple[np.ndarray, np.ndarray, np.ndarray]
"""A convex polygon ready for :func:`_inside`: its vertices' mean, its vertices (n, 2) and
their angles (n,) about the mean, both from the vertex of least angle on."""


def _wedges(ring: np.ndarray) -> Wedges:
    """``ring`` (a convex counter-clockwise polygon) ready for :func:`_inside`: made once
    for all the circles of one search (``_smallest_fit``), not once a circle."""
    centre = ring.mean(axis=0)
    angle = np.arctan2(ring[:, 1] - centre[1], ring[:, 0] - centre[0])
    start = int(np.argmin(angle))
    return centre, np.roll(ring, -start, axis=0), np.roll(angle, -start)


def _inside(wedges: Wedges, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Which points (x, y) lie inside the convex counter-clockwise polygon of ``wedges``:
    each is tested against the one edge whose wedge (seen from the vertices' mean, inside)
    holds it, found by bisection on the vertices' angles."""
    centre, ring, angle = wedges
    k = np.searchsorted(angle, np.arctan2(y - centre[1], x - centre[0]), side="right") - 1
    a, b = ring[k % len(ring)], ring[(k + 1) % len(ring)]
    cross = (b[:, 0] - a[:, 0]) * (y - a[:, 1]) - (b[:, 1] - a[:, 1]) * (x - a[:, 0])
    return cross >= 0.0


_CIRCLE = np.linspace(0.0, 2.0 * math.pi, CIRCLE_SAMPLES, endpoint=False)
_CIRCLE_COS, _CIRCLE_SIN = np.cos(_CIRCLE), np.sin(_CIRCLE)
"""The directions of the centres tried on each circle (:func:`_on_circle`), made once, not
once a circle: an advice's search tries thousands of circles (docs/performance.md, "The
suite's margin")."""

Screen = Callable[[np.ndarray, float], np.ndarray]
"""Which centres (n, 2) of base radius r keep the pitch curve round enough: a mask (n,)."""


def _on_circle(wedges: Wedges, arm: float, swing: float, radius: float, reach: float,
               round_enough: Screen | None = None) -> np.ndarray:
    """The centres (n, 2) at ``radius`` from the roller's lowest point (arm, 0) that lie in
    the polygon and keep a − R1 ≥ ``reach`` (pivot frame: A at the origin, B1 the roller's
    centre at ψmax), and pass ``round_enough`` when given."""
    x, y = arm + radius * _CIRCLE_COS, radius * _CIRCLE_SIN        # whole columns, not a (n, 2) array's
    b1 = arm * np.array([math.cos(swing), -math.sin(swing)])
    keep = np.hypot(x, y) - np.hypot(x - b1[0], y - b1[1]) >= reach
    x, y = x[keep], y[keep]
    keep = _inside(wedges, x, y)
    points = np.column_stack([x[keep], y[keep]])
    return points if round_enough is None or not len(points) else points[round_enough(points, radius)]


def _smallest_fit(ring: np.ndarray, arm: float, swing: float, low: float, reach: float,
                  round_enough: Screen | None = None) -> np.ndarray | None:
    """The centre of the smallest base radius ≥ ``low`` that fits, or None: radii grow by
    GROWTH until one fits, then a bisection (the fitting radii are an interval, the set of
    centres being convex; the centres ``round_enough`` keeps are not known to be convex, so
    the bisection then finds where fitting begins in the first bracket that fits, which
    tests check against circles 1 % smaller)."""
    top = 2.0 * float(np.max(np.hypot(ring[:, 0] - arm, ring[:, 1])))
    wedges = _wedges(ring)

    def on(radius: float) -> np.ndarray:
        return _on_circle(wedges, arm, swing, radius, reach, round_enough)
    found = on(low)
    if found.size:
        return found[np.argmin(np.hypot(found[:, 0], found[:, 1]))]
    lo, hi = low, low * GROWTH
    while hi <= top:
        found = on(hi)
        if found.size:
            break
        lo, hi = hi, hi * GROWTH
    else:
        return None
    while hi - lo > RADIUS_TOLERANCE * hi:
        mid = 0.5 * (lo + hi)
        here = on(mid)
        if here.size:
            hi, found = mid, here
        else:
            lo = mid
    return found[np.argmin(np.hypot(found[:, 0], found[:, 1]))]


def _round_enough(arm_mm: float, program: Program, side: int, need_mm: float) -> Screen:
    """The screen of centres whose pitch curve's smallest convex radius, on the grid, is at
    least ``need_mm`` (centres in the pivot's frame, as ``synthesis``'s)."""
    def screen(points: np.ndarray, radius: float) -> np.ndarray:
        many = Follower(arm_mm, np.hypot(points[:, 0], points[:, 1]),
                        np.degrees(np.arctan2(points[:, 1], points[:, 0])), side)
        rho = sampled_min_convex_radius(many, program, np.full(len(points), radius), CURVATURE_SAMPLES)
        return rho >= need_mm
    return screen


def raised(arm_mm: float, program: Program, allowance: Allowance, roller_mm: float,
           room: Room, least_mm: float, need_mm: float | None = None) -> Follower | None:
    """The follower of smallest base radius (≥ ``least_mm``) within the allowances whose
    cam, with this roller, clears the hub and the pivot boss, and whose pitch curve's
    smallest convex radius is at least ``need_mm`` on the grid when given; None if there is
    none. Both arrangements are tried; the smaller wins."""
    swing = math.radians(program.swing_deg)
    low = max(least_mm, (room.hub_mm + room.clearance_mm + roller_mm) * (1.0 + 1e-12))   # past rounding
    reach = room.boss_mm + room.clearance_mm - roller_mm
    found = []
    for side in (1, -1):        # within_allowance: the fit's pressure angles polished, as the smallest cam's
        screen = None if need_mm is None else _round_enough(arm_mm, program, side, need_mm)
        f = within_allowance(arm_mm, program, allowance, side,
                             lambda ring: _smallest_fit(ring, arm_mm, swing, low, reach, screen))
        if f is not None:
            found.append(f)
    return min(found, key=lambda f: (round(f.base_radius_mm, 9), -f.side)) if found else None


def require_buildable(f: Follower, program: Program, roller_mm: float, room: Room,
                      checked: bool) -> None:
    """FitError (a DesignError) naming the input that decides, and by how much, when the
    cam cannot be built: the base radius or centre distance of a checked cam, else the
    swing (the synthesis found no cam within the allowances that clears the pivot boss)."""
    short = shortfalls(f, program, roller_mm, room)
    tol = 1e-9 * max(f.distance_mm, f.arm_mm)
    profile_min = f.base_radius_mm - roller_mm
    profile_max = pitch_max_radius(f, program) - roller_mm
    if short["hub"] > tol and (checked or short["boss"] <= tol):
        raise FitError("base" if checked else "hub", f.base_radius_mm if checked else room.hub_mm,
                       f"the profile's smallest radius r0 − r = {profile_min:.4g} mm is "
                       f"{short['hub']:.4g} mm short of hub + clearance = "
                       f"{room.hub_mm + room.clearance_mm:.4g} mm")
    if short["boss"] > tol:                       # (a synthesis names the swing first)
        what = (f"the profile's largest radius {profile_max:.4g} mm reaches {short['boss']:.4g} mm "
                f"past a − boss − clearance = {f.distance_mm - room.boss_mm - room.clearance_mm:.4g} mm")
        if checked:
            raise FitError("distance", f.distance_mm, what)
        raise FitError("swing", program.swing_deg,
                       f"no cam within the allowances clears the pivot boss; the smallest: {what}")


class FitError(DesignError):
    """A cam that does not clear its hub or the pivot boss. It names the input that decides;
    a form may mark the field just edited instead (any of the cam's inputs can cause it)."""
