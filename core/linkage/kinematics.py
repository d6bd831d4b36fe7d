"""Exact kinematics of the shaper, vectorized over crank angles and speeds.

The second level of core. With the crank at constant speed ω every velocity
is ω times a derivative with respect to the crank angle φ and every
acceleration ω² times a second derivative. So the cycle's *shape* (position
and its first two φ-derivatives) is computed once, in closed form, and
scaled per speed; nothing is differenced.

Conventions (see README and docs/methods.md): φ = 0 at the limit position that begins the working
stroke, increasing in the direction of rotation; the ram displacement is
measured from its position at φ = 0 and is positive in the cutting direction;
the lever angle ψ is measured from the line O4→O2, positive toward the
cutting direction.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .designs import Designs
from core.base.errors import DesignError, require_range
from .geometry import Design
# the bounds and the checks of a request, in a module without numpy; re-exported here,
# where every caller has always found them
from .limits import (MAX_ANGLES, MAX_FILE_SAMPLES, MAX_RPM, MAX_SAMPLES, MAX_SPEEDS,  # noqa: F401
                     MAX_STEP_DEG, MIN_RPM, MIN_STEP_DEG, angle_steps, angle_count, check_file_samples,
                     check_request, smallest_step)


def rpm_to_omega(rpm: np.ndarray | float) -> np.ndarray:
    """Crank speed r/min → rad/s."""
    return np.asarray(rpm, dtype=float) * (2.0 * math.pi / 60.0)


@dataclass(frozen=True)
class Shape:
    """Speed-independent cycle of one design over crank angles ``phi`` (n,).

    Suffix ``1`` is d/dφ (per rad), suffix ``2`` is d²/dφ² (per rad²).
    Lengths in mm, angles in rad.
    """

    phi: np.ndarray
    crank_pin: np.ndarray     # A, (2, n) mm
    lever_tip: np.ndarray     # B, (2, n) mm
    ram_joint: np.ndarray     # C, (2, n) mm: rod end on the guide, or the ram point above B
    lever: np.ndarray         # ψ, (n,) rad
    lever1: np.ndarray
    lever2: np.ndarray
    slide: np.ndarray         # O4A, distance of the block along the lever, (n,) mm
    slide1: np.ndarray
    slide2: np.ndarray
    tip1: np.ndarray          # dB/dφ, (2, n) mm/rad
    tip2: np.ndarray          # d²B/dφ², (2, n)
    ram1: np.ndarray          # dCx/dφ, (n,) mm/rad
    ram2: np.ndarray          # d²Cx/dφ², (n,) mm/rad²
    pin1: np.ndarray          # dA/dφ, (2, n)
    pin2: np.ndarray          # d²A/dφ², (2, n)
    rod: np.ndarray | None    # λ, angle of B→C from +x, (n,) rad; None for the block variant
    rod1: np.ndarray | None
    rod2: np.ndarray | None


def crank_angles(step_deg: float = 1.0) -> np.ndarray:
    """0, step, …, up to and including 360°, in rad (the cycle closes)."""
    step, steps, closing = angle_steps(step_deg)
    degrees = np.arange(steps + 1) * step
    if closing:
        degrees = np.append(degrees, 360.0)
    return np.radians(degrees)


def check_angles(angles_deg: np.ndarray) -> np.ndarray:
    """Validate explicit crank angles in degrees; return them in rad."""
    angles = np.asarray(angles_deg, dtype=float).ravel()
    if angles.size == 0 or angles.size > MAX_ANGLES:
        raise DesignError("angles", angles.size, f"must list 1 to {MAX_ANGLES} crank angles")
    bad = ~np.isfinite(angles)
    if bad.any():
        raise DesignError("angles", float(angles[bad][0]), "must be finite numbers in degrees")
    if np.abs(angles).max() > 36000.0:
        raise DesignError("angles", float(np.abs(angles).max()), "must lie within ±36000°")
    return np.radians(angles)


def check_rpms(rpms) -> np.ndarray:
    """Validate 1 to ``MAX_SPEEDS`` crank speeds in [MIN_RPM, MAX_RPM] r/min; return them as floats."""
    values = np.atleast_1d(np.asarray(rpms, dtype=object)).ravel()
    if values.size == 0 or values.size > MAX_SPEEDS:
        raise DesignError("rpm", values.size, f"give 1 to {MAX_SPEEDS} crank speeds")
    return np.array([require_range("rpm", v, MIN_RPM, MAX_RPM, "r/min", low_open=False)
                     for v in values])


def shape(design: Design | Designs, phi: np.ndarray) -> Shape:
    """Closed-form positions and φ-derivatives for all ``phi`` at once.

    ``design`` is one :class:`Design` or many :class:`~core.linkage.designs.Designs`
    whose length arrays broadcast against ``phi`` (give designs of shape
    (d, 1) and angles (n,) or (d, n) for (d, n) results).
    """
    phi = np.asarray(phi, dtype=float)
    # Absolute crank direction: clockwise from the left limit position.
    beta = math.pi + np.asarray(design.theta) / 2.0 - phi
    return shape_at(design, phi, np.cos(beta), np.sin(beta))


def shape_at(design: Design | Designs, phi: np.ndarray, cos_beta: np.ndarray,
             sin_beta: np.ndarray) -> Shape:
    """:func:`shape` from the cosine and sine of the crank's absolute direction
    β = π + θ/2 − φ, which a caller sampling many designs can share between them.

    Every (2, …) pair is written into its rows where it is computed, not stacked
    afterwards: each pass over the angles and each allocation counts at 3 601 angles.
    """
    lv = _lever_terms(design, cos_beta, sin_beta)
    tip = _tip_terms(design, lv)
    pin, lever1, lever2, slide, slide1, slide2 = lv[:6]   # A = (L1·cos β, L2 + L1·sin β)
    del lv   # u and s² are not in the Shape: free them before the rod's terms (the peak)
    ram = _ram_terms(design, tip)
    lever = np.arctan2(pin[0], pin[1])
    pin1 = np.empty_like(pin)                           # dA/dφ = (L1·sin β, −L1·cos β)
    np.multiply(design.crank, sin_beta, out=pin1[0, ...])
    np.negative(pin[0], out=pin1[1, ...])
    pin2 = np.empty_like(pin)                           # d²A/dφ² = O2 − A
    np.negative(pin[0], out=pin2[0, ...])
    np.subtract(design.frame, pin[1], out=pin2[1, ...])
    if design.rod is None:
        rod = rod1 = rod2 = None
    else:
        sign, length = design.rod_sign, design.rod
        rod = np.arctan2(ram.depth, sign * ram.reach)
        if sign < 0:  # keep a trailing rod's angle near 180° instead of jumping at ±180°
            if np.ndim(rod):   # np.mod's result in a third of its time
                np.add(rod, 2.0 * math.pi, out=rod, where=rod < 0.0)
            else:
                rod = np.mod(rod, 2.0 * math.pi)
        # λ′ = sign·(r·d′ − d·r′)/L4² with d′ = −By′, λ″ alike (sign flips are exact)
        rod1 = -sign * (ram.reach * ram.rise1 + ram.depth * ram.reach1) / length ** 2
        rod2 = -sign * (ram.reach * ram.rise2 + ram.depth * ram.reach2) / length ** 2
    return Shape(
        phi=phi, crank_pin=pin, lever_tip=tip.b, ram_joint=ram.joint,
        lever=lever, lever1=lever1, lever2=lever2,
        slide=slide, slide1=slide1, slide2=slide2,
        tip1=tip.b1, tip2=tip.b2, ram1=ram.c1, ram2=ram.c2, pin1=pin1, pin2=pin2,
        rod=rod, rod1=rod1, rod2=rod2,
    )


class _Lever(NamedTuple):
    pin: np.ndarray         # crank pin A, (2, …) mm
    lever1: np.ndarray      # ψ′
    lever2: np.ndarray      # ψ″
    slide: np.ndarray       # s = |O4A|
    slide1: np.ndarray
    slide2: np.ndarray
    u: np.ndarray           # along the lever: (sin ψ, cos ψ), (2, …); n = (uy, −ux)
    q: np.ndarray           # s²


class _Tip(NamedTuple):
    b: np.ndarray           # B, (2, …) mm
    b1: np.ndarray          # dB/dφ
    b2: np.ndarray          # d²B/dφ²


class _Ram(NamedTuple):
    joint: np.ndarray            # C, (2, …): (Cx, guide)
    c1: np.ndarray
    c2: np.ndarray
    depth: np.ndarray | None     # d = guide − By, the rod's rise (rod variant)
    rise1: np.ndarray | None     # By′ = −d′ (a view, not a copy)
    rise2: np.ndarray | None     # By″ = −d″
    reach: np.ndarray | None     # r = sqrt(L4² − d²), the rod's horizontal reach
    reach1: np.ndarray | None
    reach2: np.ndarray | None


def _lever_terms(design, cb: np.ndarray, sb: np.ndarray) -> _Lever:
    """The lever through the crank pin A = (L1·cos β, L2 + L1·sin β), with φ-derivatives.

    In closed form, with q = s² = L1² + L2² + 2·L1·L2·sin β and dβ/dφ = −1:
    s′ = −L1·L2·cos β/s, ψ′ = L1(L1 + L2·sin β)/q, ψ″ = −L1·L2(L2² − L1²)·cos β/q²
    and s″ = s·ψ′(ψ′ − 1); every per-point product is one of these few terms.
    The unit vector u = A/s reuses A's coordinates, which the caller keeps as the pin.
    """
    l1, l2 = design.crank, design.frame
    l12 = l1 * l2
    pin = np.empty((2,) + np.broadcast_shapes(np.shape(l1), np.shape(l2), np.shape(cb)))
    np.multiply(l1, cb, out=pin[0, ...])
    np.add(l2, l1 * sb, out=pin[1, ...])
    q = (l1 * l1 + l2 * l2) + (2.0 * l12) * sb
    slide = np.sqrt(q)                          # |O4A| ≥ L2 − L1 > 0
    u = pin / slide
    lever1 = l1 * (l1 + l2 * sb) / q
    lever2 = -(l12 * (l2 * l2 - l1 * l1)) * cb / (q * q)
    slide1 = -l12 * cb / slide
    slide2 = slide * lever1 * (lever1 - 1.0)
    return _Lever(pin, lever1, lever2, slide, slide1, slide2, u, q)


def _tip_terms(design, lv: _Lever) -> _Tip:
    """Lever tip B = L3·u, u = (sin ψ, cos ψ), with φ-derivatives B′ = L3·ψ′·n and
    B″ = L3(ψ″·n − ψ′²·u), n = (uy, −ux)."""
    l3, (ux, uy), w1, w2 = design.lever, lv.u, lv.lever1, lv.lever2
    b = l3 * lv.u
    b1, b2 = np.empty_like(b), np.empty_like(b)
    lw, sq = l3 * w1, w1 ** 2
    np.multiply(lw, uy, out=b1[0, ...])
    np.multiply(-lw, ux, out=b1[1, ...])
    np.multiply(l3, w2 * uy - sq * ux, out=b2[0, ...])
    np.multiply(-l3, w2 * ux + sq * uy, out=b2[1, ...])    # L3(−ψ″ux − ψ′²uy)
    return _Tip(b, b1, b2)


def _ram_terms(design, tip: _Tip) -> _Ram:
    """Ram joint C: above B (block variant) or at the rod's end on the guide line."""
    (bx, by), (bx1, by1), (bx2, by2) = tip
    joint = np.empty_like(tip.b)
    joint[1] = design.guide
    if design.rod is None:
        joint[0] = bx
        return _Ram(joint, bx1, bx2, None, None, None, None, None, None)
    sign, length = design.rod_sign, design.rod
    d = design.guide - by
    with np.errstate(invalid="ignore"):
        r = np.sqrt(length ** 2 - d ** 2)  # NaN where the rod cannot reach
    # r′ = −d·d′/r and r″ = −(r′² + d′² + d·d″)/r, with d′ = −By′, d″ = −By″ (sign flips are exact)
    r1 = d * by1 / r
    r2 = -(r1 ** 2 + by1 ** 2 - d * by2) / r
    np.add(bx, sign * r, out=joint[0, ...])
    return _Ram(joint, bx1 + sign * r1, bx2 + sign * r2, d, by1, by2, r, r1, r2)


# Offsets (rad) of samples crowding geometrically toward the angles where a rod variant's
# curves can change sharply (see sharp_angles), down to ~1e-5 rad.
CROWD_OFFSETS = np.concatenate([-(0.05 * 5.0 ** -np.arange(0, 7)), [0.0],
                                (0.05 * 5.0 ** -np.arange(0, 7))[::-1]])


# Where the rod's reach sqrt(L4² − d²) at every sharp angle stays above this fraction of L4,
# its motion is smooth on the scale of uniform samples and no crowding is needed.
CROWD_BELOW = 0.2


def needs_crowding(design: Design | Designs) -> np.ndarray:
    """Per design: does the rod come close to upright (reach < CROWD_BELOW·L4) at a sharp angle?"""
    if design.rod is None:
        return np.zeros(np.shape(design.theta), dtype=bool)
    at = shape(design.column() if isinstance(design, Designs) else design, sharp_angles(design))
    return np.abs(np.cos(at.rod)).min(axis=-1) < CROWD_BELOW     # r/L4 = |cos λ|


def sharp_angles(design: Design | Designs) -> np.ndarray:
    """Crank angles φ (rad) of the two dead points and of the lever's two vertical
    crossings (ψ = 0), shape design + (4,).

    The rod's rise |d| = |guide − L3·cos ψ| is monotonic in |ψ|, so its reach
    sqrt(L4² − d²) is smallest, and the rod variant's velocity, acceleration
    and forces can change sharply, only at these angles.
    """
    half = np.asarray(design.theta)[..., None] / 2.0
    return np.array([0.0, math.pi, math.pi / 2.0, 1.5 * math.pi]) + np.array([0.0, 2.0, 1.0, 1.0]) * half


def pressure_angle(rod_angle: np.ndarray) -> np.ndarray:
    """Angle between the rod line and the ram guide (0 … π/2), whichever way the rod points, rad."""
    return np.abs(np.arctan(np.tan(rod_angle)))


def ram_origin(design: Design | Designs) -> float | np.ndarray:
    """x of the ram joint at φ = 0, the zero of the ram displacement, mm (one per design).

    Only the joint's terms, not a whole :class:`Shape`: a Shape's assembly for one angle
    took a sixth of the kinematics cycle's time."""
    x = ram_position(design, np.zeros(1))
    return x if isinstance(design, Designs) else float(x[0])


def ram_position(design: Design | Designs, phi: np.ndarray) -> np.ndarray:
    """Cx, the ram joint's x at crank angles ``phi``, mm: the joint's terms alone."""
    beta = math.pi + np.asarray(design.theta) / 2.0 - np.asarray(phi, dtype=float)
    lever = _lever_terms(design, np.cos(beta), np.sin(beta))
    return _ram_terms(design, _tip_terms(design, lever)).joint[0]


@dataclass(frozen=True)
class Motion:
    """The full cycle at several crank speeds.

    Shapes: ``(n,)`` over crank angles for positions, ``(m, n)`` over speeds
    and angles for rates. Units are in the field names' docstrings.
    """

    design: Design
    shape: Shape
    crank_angle: np.ndarray   # φ, (n,) rad
    rpm: np.ndarray           # (m,) r/min
    omega: np.ndarray         # (m,) rad/s
    time: np.ndarray          # (m, n) s, t = 0 at φ = 0
    ram_x: np.ndarray         # (n,) mm, from the φ = 0 position, + in the cutting direction
    ram_v: np.ndarray         # (m, n) m/s
    ram_a: np.ndarray         # (m, n) m/s²
    lever_angle: np.ndarray   # ψ, (n,) rad
    lever_omega: np.ndarray   # dψ/dt, (m, n) rad/s: + clockwise (toward the cut), as the crank
    lever_alpha: np.ndarray   # d²ψ/dt², (m, n) rad/s², + clockwise
    slide_v: np.ndarray       # d(O4A)/dt, (m, n) m/s: + while the block moves away from O4
                              # (the polygon's v_A4A3 is its negative)
    coriolis: np.ndarray      # 2·ω4·slide_v, (m, n) m/s²: the block's Coriolis acceleration
                              # relative to the lever along n = (cos ψ, −sin ψ), the direction
                              # of increasing ψ (the polygon's a^k_A4A3 is its negative)
    rod_angle: np.ndarray | None   # λ, direction of B→C from +x, counter-clockwise, (n,) rad
    rod_omega: np.ndarray | None   # dλ/dt, (m, n) rad/s, + counter-clockwise
    rod_alpha: np.ndarray | None   # d²λ/dt², (m, n) rad/s², + counter-clockwise
    pressure_angle: np.ndarray | None  # angle of the rod to the guide, (n,) rad


def solve(design: Design, crank_angle: np.ndarray, rpms) -> Motion:
    """Positions, velocities and accelerations for all angles and speeds.

    Each (speeds, angles) rate is its own array of one pass. One block holding them
    all measured faster only while glibc adapts its mmap threshold: with that frozen
    (``MALLOC_TRIM_THRESHOLD_`` set) the block was mapped and unmapped on every call,
    0.72 ms instead of 0.30 (docs/performance.md, issue 24).
    """
    phi = np.asarray(crank_angle, dtype=float)
    rpm = check_rpms(rpms)
    check_request(phi.size, rpm.size, "angles")
    omega = rpm_to_omega(rpm)
    w1 = omega[:, None]
    w2 = w1 ** 2
    v1, v2 = w1 / 1000.0, w2 / 1000.0       # mm → m
    sh = shape(design, phi)
    rod_omega = rod_alpha = pressure = None
    if sh.rod is not None:
        rod_omega, rod_alpha = w1 * sh.rod1, w2 * sh.rod2
        pressure = pressure_angle(sh.rod)
    coriolis = 2.0 * sh.slide1
    coriolis *= sh.lever1
    # The ram's zero is its x at φ = 0: the first sample when the angles start there, as
    # crank_angles does (the same arithmetic on the same number), else solved apart.
    starts_at_zero = phi.ndim == 1 and phi.size > 0 and phi[0] == 0.0
    ram_x = sh.ram_joint[0] - (sh.ram_joint[0, 0] if starts_at_zero else ram_origin(design))
    return Motion(
        design=design, shape=sh, crank_angle=phi, rpm=rpm, omega=omega,
        time=phi[None, :] / w1, ram_x=ram_x, ram_v=v1 * sh.ram1, ram_a=v2 * sh.ram2,
        lever_angle=sh.lever, lever_omega=w1 * sh.lever1, lever_alpha=w2 * sh.lever2,
        slide_v=v1 * sh.slide1, coriolis=v2 * coriolis,
        rod_angle=sh.rod, rod_omega=rod_omega, rod_alpha=rod_alpha,
        pressure_angle=pressure,
    )
