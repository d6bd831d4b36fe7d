"""The smallest cam for the allowed pressure angles, and the largest roller it can carry.

With the pivot A at the origin and the arm's lowest position along +x, the cam centre O
sits at (X, Y) = a·(cos ψ0, sin ψ0). The pressure-angle condition at each follower
position, |l·ψ' + k·(l − a·cos β)| ≤ tan[α]·a·sin β, is a pair of half-planes in (X, Y),
since a·cos β = X·cos ψ − Y·sin ψ and a·sin β = X·sin ψ + Y·cos ψ. The admissible centres
are therefore one convex region (the graphical method's, exactly), and the smallest base
radius is its distance from the roller's lowest point (l, 0). The region is first the
polygon of SAMPLES positions per phase, whose nearest point is found from its vertices;
between two samples the allowance can still be exceeded, so that point's worst pressure
angles are solved (``extremes``) and the polygon cut at those positions until none is
exceeded (see :func:`smallest`).

The arrangement (the side k of the line of centres, i.e. the turning sense relative to the
follower) is chosen by synthesizing both and keeping the one with the smaller base radius.
"""
from __future__ import annotations

import importlib
import math
from functools import lru_cache
from dataclasses import dataclass
from typing import Callable

import numpy as np

from core.base.errors import DesignError
from .extremes import PHASES, SIGNS, PressurePeaks, phase_motion, pressure_peaks
from .follower import TURN, Follower
from .laws import Program, law

SAMPLES = 2001
"""Follower positions per phase at which the allowance is imposed (uniform in the phase)."""
LP_STRIDE = 20
"""Every this many conditions set the first try of an interior point (see _inside)."""
GRID_REACHES = (0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0)
GRID_DIRECTIONS = 36
"""The polar grid about the pivot (reaches in arm lengths, directions over a turn) whose
point deepest inside a part of the conditions starts that part's polygon (see _deep_point)."""
CUTS = 8
"""At most this many nearest points are tried, each with the conditions at the last one's
worst follower positions added (see smallest); three cuts at most were needed for 200
random cams (both arrangements each). Were they all used, the last nearest point would be
kept, over its allowance by what the last cut left."""
MARGIN_DEG = 1e-10
"""How far below each allowance the synthesis aims (°), so that the polished maximum, with
its rounding (~1e-13°), never exceeds the allowance."""
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


def import_solvers() -> None:
    """Import now what a synthesis takes from scipy (``linprog``, the convex hull and the
    half-plane intersection). Why: they come in at the first synthesis, not with the
    window; a window calls this while idle once its Cam tab is built, so that the tab's
    first visit does not wait for the import, 0.2-0.5 s quiet (issue 40 item 5).
    By name, as a side effect: an import statement would bind a name nothing uses."""
    for module in ("scipy.optimize", "scipy.spatial"):
        importlib.import_module(module)


def _halfspaces(arm: float, k: int, program: Program, allowance: Allowance) -> np.ndarray:
    """Rows [gx, gy, −h] of g·(X, Y) ≤ h, the pressure-angle conditions and the search box
    (k the side in the counter-clockwise algebra, see ``follower``)."""
    rows = []
    for (psi, psi1), allowed in zip(_phase_samples(program), (allowance.rise_deg, allowance.return_deg)):
        t = math.tan(math.radians(allowed))
        rows += [_pressure_rows(arm, k, psi, psi1, t, 1.0), _pressure_rows(arm, k, psi, psi1, t, -1.0)]
    box = REACH * arm
    rows.append(np.array([[1.0, 0.0, -box], [-1.0, 0.0, -box], [0.0, 1.0, -box], [0.0, -1.0, -box]]))
    h = np.concatenate(rows)
    return h / np.hypot(h[:, 0], h[:, 1])[:, None]


def _pressure_rows(arm: float, k: int, psi: np.ndarray, psi1: np.ndarray, t,
                   sign) -> np.ndarray:
    """Rows [gx, gy, −h] of sign·N ≤ t·D at follower angles ψ with speeds ψ′: the cam
    pushing outward (sign +1) or inward (−1) within the allowed tan α = t."""
    c = arm * psi1 + k * arm
    cp, sp = np.cos(psi), np.sin(psi)
    return np.column_stack([-sign * k * cp - t * sp, sign * k * sp - t * cp, sign * c])


def _chebyshev(h: np.ndarray) -> np.ndarray | None:
    # scipy comes in when a cam is synthesized, not with the window (its import pulls in
    # numpy.testing and importlib.metadata, a tenth of a second the first screen does not need)
    from scipy.optimize import linprog
    res = linprog([0.0, 0.0, -1.0], A_ub=np.column_stack([h[:, :2], np.ones(len(h))]),
                  b_ub=-h[:, 2], bounds=[(None, None), (None, None), (0.0, None)], method="highs")
    if res.status != 0 or res.x[2] <= 1e-9 * REACH:
        return None
    return res.x[:2]


def _rows(h: np.ndarray) -> np.ndarray:
    """Every LP_STRIDE-th condition and the search box: the conditions of the first try of
    an interior point (see _inside)."""
    return np.r_[np.arange(0, len(h) - 4, LP_STRIDE), np.arange(len(h) - 4, len(h))]


def _grid_point(rows: np.ndarray, arm: float) -> np.ndarray | None:
    """The point of the polar grid about the pivot (GRID_REACHES arm lengths, GRID_DIRECTIONS)
    whose least margin to every fifth of ``rows`` is largest, if it lies inside them all."""
    t = np.linspace(0.0, 2.0 * math.pi, GRID_DIRECTIONS, endpoint=False)
    reach = arm * np.array(GRID_REACHES)[:, None]
    x, y = (reach * np.cos(t)).ravel(), (reach * np.sin(t)).ravel()
    few = rows[::5]
    margin = np.min(-(few[:, :1] * x + few[:, 1:2] * y + few[:, 2:]), axis=0)
    best = np.array([x[np.argmax(margin)], y[np.argmax(margin)]])
    return best if np.all(rows[:, :2] @ best + rows[:, 2] < 0.0) else None


def _centroid(ring: np.ndarray) -> np.ndarray:
    """The centroid of the convex polygon ``ring``: at least a third of the polygon's width
    from each of its edges, whatever its shape."""
    x, y = ring[:, 0], ring[:, 1]
    xn, yn = np.roll(x, -1), np.roll(y, -1)
    cross = x * yn - xn * y
    return np.array([np.sum((x + xn) * cross), np.sum((y + yn) * cross)]) / (3.0 * np.sum(cross))


def _deep_point(rows: np.ndarray, arm: float) -> tuple[np.ndarray | None, np.ndarray | None]:
    """A point well inside the polygon of the conditions ``rows`` (None: it is empty), and
    that polygon (None if none was made).

    Why not their Chebyshev centre: its LP was a sixth of a Cam edit (two of them, ~7 ms
    each, most of it scipy's setting up). The polygon is made about the grid's deepest
    point, and its centroid, as deep inside as the LP's centre in practice, is the point;
    the LP only where the grid finds none inside (a tight allowance) or its polygon fails."""
    start = _grid_point(rows, arm)
    ring = None if start is None else _part_polygon(rows, start)
    if ring is not None and len(ring) >= 3:
        middle = _centroid(ring)
        if np.all(rows[:, :2] @ middle + rows[:, 2] < 0.0):
            return middle, ring
    centre = _chebyshev(rows)           # a tight allowance: no point of the grid inside
    return (None, None) if centre is None else (centre, _part_polygon(rows, centre))


def _part_polygon(rows: np.ndarray, centre: np.ndarray) -> np.ndarray | None:
    """The polygon of ``rows`` about ``centre``, None where qhull fails on it."""
    from scipy.spatial import QhullError
    try:
        return _polygon(rows, centre)
    except QhullError:
        return None


def _inside(h: np.ndarray, first: np.ndarray | None) -> np.ndarray | None:
    """A point well inside the polygon, or None if it is empty: ``first``, a point well
    inside the conditions ``_rows`` (``_deep_point``: neighbouring conditions differ little,
    and an LP of thousands of rows took 0.6 s), kept if it satisfies them all, else the
    Chebyshev centre of all."""
    if first is not None and np.all(h[:, :2] @ first + h[:, 2] < 0.0):
        return first
    return _chebyshev(h)


def _ring(vertices: np.ndarray) -> np.ndarray:
    """The convex polygon with these vertices as a ring of corners (m, 2), in order."""
    from scipy.spatial import ConvexHull
    return vertices[ConvexHull(vertices).vertices]


def _nearest(ring: np.ndarray, p: np.ndarray) -> np.ndarray:
    """The point of the convex polygon ``ring`` (its vertices in order) nearest to ``p``
    (outside it)."""
    a, b = ring, np.roll(ring, -1, axis=0)
    ab = b - a
    with np.errstate(invalid="ignore"):          # a corner repeated by a clip: its edge is a point
        t = np.nan_to_num(np.clip(np.einsum("ij,ij->i", p - a, ab) / np.einsum("ij,ij->i", ab, ab),
                                  0.0, 1.0))
    q = a + t[:, None] * ab
    return q[np.argmin(np.hypot(*(q - p).T))]


def _aim(allowance: Allowance) -> Allowance:
    """The allowances the sampled conditions impose: MARGIN_DEG below the given ones."""
    return Allowance(allowance.rise_deg - MARGIN_DEG, allowance.return_deg - MARGIN_DEG)


@lru_cache(maxsize=16)
def _conditions(arm_mm: float, side: int, program: Program, aim: Allowance
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray | None, np.ndarray | None]:
    """The sampled conditions of ``side`` at the allowances ``aim`` (:func:`_halfspaces`),
    those of the first try (:func:`_rows`), and that try's interior point and polygon
    (:func:`_deep_point`), read-only.

    Kept for the last inputs (frozen values; some 0.2 MB each): the synthesis asks for
    both sides, and the raise (``build.raised``) then for the same design's again, up to
    ``cam.FIT_ROUNDS`` times, in each of a search's probes."""
    h = _halfspaces(arm_mm, TURN * side, program, aim)
    rows = h[_rows(h)]
    first, part = _deep_point(rows, arm_mm)
    return tuple(_read_only(a) for a in (h, rows, first, part))


def _read_only(a: np.ndarray | None) -> np.ndarray | None:
    """``a`` made read-only: a kept array shared between callers must not be changed."""
    if a is not None:
        a.flags.writeable = False
    return a


@lru_cache(maxsize=16)
def admissible(arm_mm: float, program: Program, allowance: Allowance, side: int) -> np.ndarray | None:
    """The polygon of admissible cam centres on ``side`` in the pivot's frame, from the
    sampled conditions at ``_aim(allowance)`` (its vertices (n, 2) mm, in order, read-only),
    or None when the allowances leave none. It can be a little larger than the true region:
    see :func:`within_allowance`. Kept as :func:`_conditions` is, for the raise."""
    h, _, first, _ = _conditions(arm_mm, side, program, _aim(allowance))
    return _read_only(_polygon(h, _inside(h, first)))


def _polygon(h: np.ndarray, centre: np.ndarray | None) -> np.ndarray | None:
    """The polygon of the conditions ``h`` (a ring of corners) about the interior point
    ``centre``; None without one."""
    from scipy.spatial import HalfspaceIntersection
    return None if centre is None else _ring(HalfspaceIntersection(h, centre).intersections)


def _clip(ring: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """The convex polygon ``ring`` cut by the half-planes ``rows`` ([gx, gy, −h] of
    g·(X, Y) ≤ h): each keeps the corners inside it and adds the points where an edge
    crosses it (Sutherland–Hodgman); an empty ring when nothing is left."""
    for g in rows:
        d = ring @ g[:2] + g[2]
        ahead, d_ahead = np.roll(ring, -1, axis=0), np.roll(d, -1)
        inside, crosses = d <= 0.0, (d <= 0.0) != (d_ahead <= 0.0)
        with np.errstate(invalid="ignore", divide="ignore"):
            cut = ring + (d / (d - d_ahead))[:, None] * (ahead - ring)
        ring = np.stack([ring, cut], axis=1)[np.column_stack([inside, crosses])]
    return ring


def within_allowance(arm_mm: float, program: Program, allowance: Allowance, side: int,
                     pick: Callable[[np.ndarray], np.ndarray | None]) -> Follower | None:
    """The follower whose cam centre ``pick(polygon)`` chooses in the admissible polygon
    (None: no choice there), its polished pressure angles within the allowances.

    The sampled conditions bound a polygon a little larger than the true region (between
    two samples the allowance can be exceeded by up to 3e-5°), so the chosen centre's
    polished worst pressure angles are checked, and while one exceeds its allowance the
    polygon is cut by the conditions at those very follower positions and the choice made
    again (a cutting plane: the true region's boundary is the envelope of the conditions).
    The conditions aim MARGIN_DEG below the allowances, and the search stops once the
    polished maxima are within the allowances themselves: a cut brings them to within
    ~1e-14 of the aim, so they end between MARGIN_DEG below each allowance and it. The
    smallest cam (:func:`smallest`) and the cam raised to clear its hub and the pivot boss
    (``build.raised``) are both chosen so."""
    ring = admissible(arm_mm, program, allowance, side)
    return None if ring is None else _cut_until_within(arm_mm, program, allowance, side, pick, ring)


def _cut_until_within(arm_mm: float, program: Program, allowance: Allowance, side: int,
                      pick: Callable[[np.ndarray], np.ndarray | None], ring: np.ndarray) -> Follower | None:
    """:func:`within_allowance` on the admissible polygon ``ring`` already found."""
    f = None
    for _ in range(CUTS):
        centre = pick(ring) if len(ring) else None
        if centre is None:
            return None
        f = _follower(arm_mm, centre, side)
        peaks = pressure_peaks(f, program)
        if np.all(np.max(peaks.tan, axis=1) <= _allowed_tan(allowance)):
            break
        ring = _clip(ring, _cuts(arm_mm, TURN * side, program, _aim(allowance), peaks))
    return f


def _follower(arm_mm: float, centre: np.ndarray, side: int) -> Follower:
    x, y = centre
    return Follower(arm_mm, math.hypot(x, y), math.degrees(math.atan2(y, x)), side)


def _nearest_pick(arm_mm: float) -> Callable[[np.ndarray], np.ndarray | None]:
    """The choice of the smallest cam: the admissible centre nearest to the roller's
    lowest point (arm, 0), or None beyond the search's reach."""
    def nearest(ring: np.ndarray) -> np.ndarray | None:
        x, y = _nearest(ring, np.array([arm_mm, 0.0]))
        return None if max(abs(x), abs(y)) >= REACH * arm_mm * (1.0 - 1e-9) else np.array([x, y])
    return nearest


def smallest(arm_mm: float, program: Program, allowance: Allowance, side: int) -> Follower | None:
    """The follower arrangement on ``side`` with the smallest base radius, or None: the
    admissible centre nearest to the roller's lowest point (arm, 0)."""
    return within_allowance(arm_mm, program, allowance, side, _nearest_pick(arm_mm))


def _allowed_tan(allowance: Allowance) -> np.ndarray:
    return np.tan(np.radians([allowance.rise_deg, allowance.return_deg]))


def _cuts(arm: float, k: int, program: Program, allowance: Allowance,
          peaks: PressurePeaks) -> np.ndarray:
    """The conditions (normalized rows, see _halfspaces) at the follower positions where a
    candidate's pressure angle is largest, per phase and sense of push."""
    _, m = phase_motion(program, PHASES[:, None], peaks.u)
    t = _allowed_tan(allowance)[:, None]
    rows = _pressure_rows(arm, k, m.psi.ravel(), m.psi1.ravel(), np.broadcast_to(t, peaks.u.shape).ravel(),
                          np.broadcast_to(SIGNS, peaks.u.shape).ravel())
    return rows / np.hypot(rows[:, 0], rows[:, 1])[:, None]


@lru_cache(maxsize=32)
def synthesize(arm_mm: float, program: Program, allowance: Allowance) -> Follower:
    """The smallest cam for the allowance over both arrangements (the arm above the line
    of centres on equal radii); DesignError naming ``pressure`` when there is none.

    Kept for the last inputs (all frozen values): a class's students usually share the
    cam's data, and ``shaper class`` designs each row's cam (about 0.7 s a search) in
    one process before the students are forked; a refusal is not kept."""
    found = _smallest_of_both(arm_mm, program, allowance)
    if not found:
        raise DesignError("pressure", allowance.rise_deg,
                          f"is too small: no cam within {REACH:g} arm lengths keeps the pressure "
                          "angle within the allowances")
    return min(found, key=lambda f: (round(f.base_radius_mm, 9), -f.side))


def largest_roller(min_convex_mm: float) -> float:
    """The largest roller with the usual margin: r ≤ 0.8·ρmin and ρmin − r ≥ 3 mm."""
    return min(ROLLER_SHARE * min_convex_mm, min_convex_mm - MIN_PROFILE_RADIUS_MM)


def convex_radius_for(roller_mm: float) -> float:
    """The smallest convex radius ρmin a pitch curve needs to take this roller with the
    usual margin (:func:`largest_roller`'s inverse): ρmin ≥ r/0.8 and ρmin ≥ r + 3 mm."""
    return max(roller_mm / ROLLER_SHARE, roller_mm + MIN_PROFILE_RADIUS_MM)


SURE_MM = 1e-6
"""How much farther than the cam found a side's nearest admissible centre must be for
that side to be left out (mm, besides 1e-9 of the radius): far above the ~1e-12 by which
rounding can bring a polygon's corner outside the larger polygon it lies in."""


def _smallest_of_both(arm_mm: float, program: Program, allowance: Allowance) -> list[Follower]:
    """:func:`smallest` of each side (those that have one), except a side that cannot win.

    Why: the losing side's polygon of all its conditions, its pressure peaks and cuts were
    about a quarter of the synthesis. A side's cam is never nearer than the nearest point
    of the polygon of a part of its conditions (``_rows``, whose interior point is found
    first anyway): that polygon holds the side's polygon, and cuts only shrink that. The
    side nearer by that bound is synthesized first, each side exactly as :func:`smallest`
    does, and the other only if its bound is not already farther than the cam found (by
    SURE_MM, so that the nine-decimal comparison of :func:`synthesize` is the same as with
    both synthesized)."""
    pick, sides = _nearest_pick(arm_mm), []
    for side in (1, -1):
        _, rows, _, part = _conditions(arm_mm, side, program, _aim(allowance))
        sides.append((_bound(arm_mm, side, rows, part, pick), side))
    found: list[Follower] = []
    for bound, side in sorted(sides, key=lambda s: s[0]):
        best = min((f.base_radius_mm for f in found), default=math.inf)
        if bound > best + SURE_MM + 1e-9 * best:
            continue
        ring = admissible(arm_mm, program, allowance, side)
        f = None if ring is None else _cut_until_within(arm_mm, program, allowance, side, pick, ring)
        if f is not None:
            found.append(f)
    return found


def _bound(arm_mm: float, side: int, rows: np.ndarray, ring: np.ndarray | None,
           pick: Callable[[np.ndarray], np.ndarray | None]) -> float:
    """The base radius no cam on ``side`` is below: that of the nearest point of the
    polygon ``ring`` of the conditions ``rows`` to the roller's lowest point (arm, 0); 0
    when that polygon gives none, or holds that point (then its nearest edge bounds nothing)."""
    if ring is None or not len(ring) or np.all(rows[:, :2] @ np.array([arm_mm, 0.0]) + rows[:, 2] <= 0.0):
        return 0.0
    chosen = pick(ring)
    return 0.0 if chosen is None else _follower(arm_mm, chosen, side).base_radius_mm
