"""Exact kinematics of the shaper, vectorized over crank angles and speeds.

The second level of core. With the crank at constant speed ω every velocity
is ω times a derivative with respect to the crank angle φ and every
acceleration ω² times a second derivative. So the cycle's *shape* (position
and its first two φ-derivatives) is computed once, in closed form, and
scaled per speed; nothing is differenced.

Conventions (see README): φ = 0 at the limit position that begins the working
stroke, increasing in the direction of rotation; the ram displacement is
measured from its position at φ = 0 and is positive in the cutting direction;
the lever angle ψ is measured from the line O4→O2, positive toward the
cutting direction.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import DesignError, require_range
from .geometry import Design

MIN_RPM = 0.01
"""Slowest crank speed, r/min (one turn in 100 minutes): every time and rate stays finite."""
MAX_RPM = 1000.0
MAX_SPEEDS = 16
MIN_STEP_DEG = 0.0002
"""Finest crank-angle step, degrees (1 800 001 angles per cycle)."""
MAX_STEP_DEG = 90.0
MAX_SAMPLES = 2_000_000
"""Largest request, crank angles × crank speeds: what one computation may hold in memory."""
MAX_ANGLES = MAX_SAMPLES


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
    step, steps, closing = _steps(step_deg)
    degrees = np.arange(steps + 1) * step
    if closing:
        degrees = np.append(degrees, 360.0)
    return np.radians(degrees)


def angle_count(step_deg: float) -> int:
    """How many angles :func:`crank_angles` gives for ``step_deg`` (validated), without making them."""
    _, steps, closing = _steps(step_deg)
    return steps + 1 + int(closing)


def _steps(step_deg: float) -> tuple[float, int, bool]:
    """The validated step, the whole steps in 360° and whether 360° must be appended."""
    step = require_range("step", step_deg, MIN_STEP_DEG, MAX_STEP_DEG, "°", low_open=False)
    steps = int(math.floor(360.0 / step + 1e-9))
    return step, steps, steps * step < 360.0 - 1e-9


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


def smallest_step(n_speeds: int, limit: int = MAX_SAMPLES) -> float:
    """The finest angle step, °, rounded up to 3 significant digits, whose angles times
    ``n_speeds`` stay within ``limit`` samples."""
    most_angles = limit // max(int(n_speeds), 1)
    # crank_angles gives floor(360/s) + 1 angles, plus 360° when s does not divide it.
    step = 360.0 / max(most_angles - 2, 1)
    scale = 10.0 ** (2 - math.floor(math.log10(step)))
    return max(math.ceil(step * scale) / scale, MIN_STEP_DEG)


def check_request(n_angles: int, n_speeds: int, parameter: str = "step",
                  value: object = None, limit: int = MAX_SAMPLES) -> int:
    """Refuse a request of more than ``limit`` samples (angles × speeds); return the count.

    Every front end calls this before computing, so that no request can
    exhaust memory: the CLI with the option the user typed as ``parameter``
    (and its ``value``, e.g. the step), the GUI with its own, smaller
    ``limit`` if it must stay responsive. For the step the message names the
    finest step allowed with this many speeds.
    """
    samples = int(n_angles) * int(n_speeds)
    if samples > limit:
        advice = "use a larger step or fewer speeds"
        if parameter == "step":
            speeds = "1 speed" if int(n_speeds) == 1 else f"{int(n_speeds)} speeds"
            advice = f"use a step of at least {smallest_step(n_speeds, limit):g}° for {speeds}"
        raise DesignError(parameter, samples if value is None else value,
                          f"gives {samples} samples (angles × speeds), more than {limit}; {advice}")
    return samples


def shape(design: Design, phi: np.ndarray) -> Shape:
    """Closed-form positions and φ-derivatives for all ``phi`` at once."""
    phi = np.asarray(phi, dtype=float)
    l1, l2, l3 = design.crank, design.frame, design.lever
    # Absolute crank direction: clockwise from the left limit position.
    beta = math.pi + design.theta / 2.0 - phi
    cb, sb = np.cos(beta), np.sin(beta)
    ax, ay = l1 * cb, l2 + l1 * sb
    ax1, ay1 = l1 * sb, -l1 * cb
    ax2, ay2 = -l1 * cb, -l1 * sb
    slide = np.hypot(ax, ay)
    ux, uy = ax / slide, ay / slide            # along the lever: (sin ψ, cos ψ)
    nx, ny = uy, -ux                           # ψ-direction:     (cos ψ, −sin ψ)
    lever = np.arctan2(ax, ay)
    slide1 = ax1 * ux + ay1 * uy
    lever1 = (ax1 * nx + ay1 * ny) / slide
    lever2 = (ax2 * nx + ay2 * ny - 2.0 * slide1 * lever1) / slide
    slide2 = ax2 * ux + ay2 * uy + slide * lever1 ** 2
    bx, by = l3 * ux, l3 * uy
    bx1, by1 = l3 * lever1 * nx, l3 * lever1 * ny
    sq = lever1 ** 2
    bx2 = l3 * (lever2 * nx - sq * ux)
    by2 = l3 * (lever2 * ny - sq * uy)
    if design.rod is None:
        cx, cy = bx, np.full_like(bx, design.guide)
        ram1, ram2 = bx1, bx2
        rod = rod1 = rod2 = None
    else:
        sign, length = design.rod_sign, design.rod
        d = design.guide - by
        d1, d2 = -by1, -by2
        with np.errstate(invalid="ignore"):
            r = np.sqrt(length ** 2 - d ** 2)  # NaN where the rod cannot reach
        r1 = -d * d1 / r
        r2 = -(r1 ** 2 + d1 ** 2 + d * d2) / r
        cx, cy = bx + sign * r, np.full_like(bx, design.guide)
        ram1, ram2 = bx1 + sign * r1, bx2 + sign * r2
        rod = np.arctan2(d, sign * r)
        if sign < 0:  # keep a trailing rod's angle near 180° instead of jumping at ±180°
            rod = np.mod(rod, 2.0 * math.pi)
        rod1 = sign * (r * d1 - d * r1) / length ** 2
        rod2 = sign * (r * d2 - d * r2) / length ** 2
    return Shape(
        phi=phi, crank_pin=np.stack([ax, ay]), lever_tip=np.stack([bx, by]),
        ram_joint=np.stack([cx, cy]), lever=lever, lever1=lever1, lever2=lever2,
        slide=slide, slide1=slide1, slide2=slide2,
        tip1=np.stack([bx1, by1]), tip2=np.stack([bx2, by2]),
        ram1=ram1, ram2=ram2, pin1=np.stack([ax1, ay1]), pin2=np.stack([ax2, ay2]),
        rod=rod, rod1=rod1, rod2=rod2,
    )


def pressure_angle(rod_angle: np.ndarray) -> np.ndarray:
    """Angle between the rod line and the ram guide (0 … π/2), whichever way the rod points, rad."""
    return np.abs(np.arctan(np.tan(rod_angle)))


def ram_origin(design: Design) -> float:
    """x of the ram joint at φ = 0, the zero of the ram displacement, mm."""
    return float(shape(design, np.zeros(1)).ram_joint[0, 0])


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
    lever_omega: np.ndarray   # (m, n) rad/s
    lever_alpha: np.ndarray   # (m, n) rad/s²
    slide_v: np.ndarray       # block speed along the lever, away from O4, (m, n) m/s
    coriolis: np.ndarray      # Coriolis acceleration of the block, 2·ω3·v_rel along ψ, (m, n) m/s²
    rod_angle: np.ndarray | None   # (n,) rad
    rod_omega: np.ndarray | None   # (m, n) rad/s
    rod_alpha: np.ndarray | None   # (m, n) rad/s²
    pressure_angle: np.ndarray | None  # angle of the rod to the guide, (n,) rad


def solve(design: Design, crank_angle: np.ndarray, rpms) -> Motion:
    """Positions, velocities and accelerations for all angles and speeds."""
    phi = np.asarray(crank_angle, dtype=float)
    rpm = check_rpms(rpms)
    check_request(phi.size, rpm.size, "angles")
    omega = rpm_to_omega(rpm)
    w1 = omega[:, None]
    w2 = w1 ** 2
    sh = shape(design, phi)
    origin = ram_origin(design)
    rod_omega = rod_alpha = pressure = None
    if sh.rod is not None:
        rod_omega, rod_alpha = w1 * sh.rod1, w2 * sh.rod2
        pressure = pressure_angle(sh.rod)
    return Motion(
        design=design, shape=sh, crank_angle=phi, rpm=rpm, omega=omega,
        time=phi[None, :] / w1,
        ram_x=sh.ram_joint[0] - origin,
        ram_v=(w1 / 1000.0) * sh.ram1,
        ram_a=(w2 / 1000.0) * sh.ram2,
        lever_angle=sh.lever,
        lever_omega=w1 * sh.lever1,
        lever_alpha=w2 * sh.lever2,
        slide_v=(w1 / 1000.0) * sh.slide1,
        coriolis=(w2 / 1000.0) * (2.0 * sh.slide1 * sh.lever1),
        rod_angle=sh.rod, rod_omega=rod_omega, rod_alpha=rod_alpha,
        pressure_angle=pressure,
    )
