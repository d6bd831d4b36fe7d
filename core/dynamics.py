"""Kinetostatics of the shaper: joint forces, crank torque, power and flywheel.

A level beside ``metrics``: it imports ``geometry`` and ``kinematics`` only.
The crank turns at constant speed ω, so every acceleration is ω² times a
closed-form second derivative from :func:`core.kinematics.shape` and every
inertia load is ω²·(speed-independent shape) — nothing is differenced.

The joint forces solve the Newton–Euler equations of each link. The chain
is serial (ram ← rod ← lever ← block ← crank), so the linear system is
block-triangular and is eliminated in closed form link by link, from the
ram back to the crank, for all angles and speeds at once. Each step divides
only by a length that a valid design keeps away from zero: the rod's
horizontal reach |Cx − Bx| (no dead centre, see ``geometry.validate``) and
the block's distance O4A ≥ L2 − L1.

Frame as everywhere in core: O4 at the origin, O2 at (0, L2), guide line
y = ``design.guide``, cutting toward +x, gravity toward −y. Forces are in N,
moments and torques in N·m, counter-clockwise positive unless a field says
otherwise. Joints are frictionless (see docs/forces.md).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .designs import Designs
from .errors import DesignError, require_range
from .geometry import MAX_LENGTH_MM, Design
from .kinematics import (CROWD_OFFSETS, Shape, check_request, check_rpms, needs_crowding,
                         ram_origin, rpm_to_omega, shape, sharp_angles)

GRAVITY = 9.81               # m/s², acting toward −y
MM = 1e-3                    # m per mm
ENERGY_INTERVALS = 3600      # uniform φ intervals per cycle for the energy integral
MAX_MASS_KG = 1e6
MAX_INERTIA_KG_M2 = 1e6
MAX_FORCE_N = 1e9
MIN_DELTA = 1e-4             # finest speed fluctuation: keeps J_F = ΔW/(ω²·δ) finite at any speed


@dataclass(frozen=True)
class MassProperties:
    """Masses, loads and the flywheel target: what dynamics adds to a design.

    Every value is validated on construction (DesignError naming the field)
    and stored as a float, so a ``MassProperties`` is always usable.
    """

    lever_mass_kg: float = 0.0
    """Mass of the slotted lever O4B, kg."""
    lever_cg_mm: float | None = None
    """Distance of the lever's centre of mass from O4 along O4→B, mm; None = L3/2."""
    lever_inertia_kg_m2: float = 0.0
    """Lever moment of inertia about its own centre of mass, kg·m²."""
    ram_mass_kg: float = 0.0
    """Ram plus tool, kg."""
    ram_cg_mm: tuple[float, float] = (0.0, 0.0)
    """(dx, dy) of the ram's centre of mass from the ram joint C, mm."""
    rod_mass_kg: float = 0.0
    """Connecting rod BC (rod variant only), a uniform slender bar: cg mid-way, J = m·L4²/12."""
    crank_mass_kg: float = 0.0
    """Crank, balanced (cg at O2): adds its weight to the bearing O2 only, kg."""
    block_mass_kg: float = 0.0
    """Sliding block at the crank pin A, a point mass turning with the lever, kg."""
    cut_force_N: float = 0.0
    """Cutting force P on the tool, acting in −x on the ram while cutting, N."""
    cut_height_mm: float = 0.0
    """Height of the tool point below the ram guide line, mm (negative = above)."""
    idle_fraction: float = 0.05
    """Uncut run-in and run-out, each as a fraction of the stroke H, in [0, 0.5)."""
    gravity: bool = True
    """Whether the links' weights (g = 9.81 m/s² toward −y) are loads."""
    delta: float = 1.0 / 30.0
    """Coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_mean the flywheel must hold, (0, 1)."""

    def __post_init__(self) -> None:
        def put(name: str, value: object) -> None:
            object.__setattr__(self, name, value)

        for name in ("lever_mass_kg", "ram_mass_kg", "rod_mass_kg", "crank_mass_kg",
                     "block_mass_kg"):
            put(name, require_range(name, getattr(self, name), 0.0, MAX_MASS_KG, "kg",
                                    low_open=False))
        put("lever_inertia_kg_m2", require_range("lever_inertia_kg_m2", self.lever_inertia_kg_m2,
                                                 0.0, MAX_INERTIA_KG_M2, "kg·m²", low_open=False))
        if self.lever_cg_mm is not None:
            put("lever_cg_mm", require_range("lever_cg_mm", self.lever_cg_mm, -MAX_LENGTH_MM,
                                             MAX_LENGTH_MM, "mm", low_open=False))
        put("ram_cg_mm", _offset("ram_cg_mm", self.ram_cg_mm))
        put("cut_force_N", require_range("cut_force_N", self.cut_force_N, 0.0, MAX_FORCE_N, "N",
                                         low_open=False))
        put("cut_height_mm", require_range("cut_height_mm", self.cut_height_mm, -MAX_LENGTH_MM,
                                           MAX_LENGTH_MM, "mm", low_open=False))
        put("idle_fraction", require_range("idle_fraction", self.idle_fraction, 0.0, 0.5,
                                           low_open=False, high_open=True))
        put("delta", require_range("delta", self.delta, MIN_DELTA, 1.0, low_open=False,
                                   high_open=True))
        if not isinstance(self.gravity, (bool, np.bool_)):
            raise DesignError("gravity", self.gravity, "must be true or false")
        put("gravity", bool(self.gravity))

    def lever_cg(self, design: Design) -> float:
        """The lever's centre-of-mass distance from O4 for ``design``, mm."""
        return design.lever / 2.0 if self.lever_cg_mm is None else self.lever_cg_mm

    @property
    def g(self) -> float:
        """Gravitational acceleration used, m/s² (0 when gravity is off)."""
        return GRAVITY if self.gravity else 0.0


def masses_for_design(design: Design, masses: MassProperties) -> MassProperties:
    """The loads as solved for ``design``: the block variant has no rod, so a rod mass
    left over from the rod variant (a form or file keeps it) is ignored."""
    if design.rod is None and masses.rod_mass_kg:
        return replace(masses, rod_mass_kg=0.0)
    return masses


def _offset(name: str, value: object) -> tuple[float, float]:
    try:
        dx, dy = value  # type: ignore[misc]
    except (TypeError, ValueError):
        raise DesignError(name, value, "must be a pair (dx, dy) in mm") from None
    return (require_range(name, dx, -MAX_LENGTH_MM, MAX_LENGTH_MM, "mm", low_open=False),
            require_range(name, dy, -MAX_LENGTH_MM, MAX_LENGTH_MM, "mm", low_open=False))


@dataclass(frozen=True)
class Dynamics:
    """Loads of the mechanism over crank angles (n,) at speeds (m,).

    Every force is "the force *on* the named body *by* the other one" and is
    split into x/y components in N, shape (m, n). Components along a guide
    that is frictionless are exactly zero.
    """

    design: Design
    """The mechanism solved."""
    masses: MassProperties
    """The masses and loads it carries."""
    crank_angle: np.ndarray
    """φ, (n,) rad."""
    rpm: np.ndarray
    """Crank speeds, (m,) r/min."""
    omega: np.ndarray
    """Crank speeds, (m,) rad/s."""
    crank_torque: np.ndarray
    """Driving (balancing) torque the motor applies to the crank, (m, n) N·m, positive
    in the direction of crank rotation (clockwise)."""
    power: np.ndarray
    """Instantaneous input power torque·ω, (m, n) W; negative = the mechanism drives the motor."""
    o2_x: np.ndarray
    """Frame bearing O2 on the crank, x, (m, n) N (includes the crank's weight)."""
    o2_y: np.ndarray
    """Frame bearing O2 on the crank, y, (m, n) N."""
    pin_x: np.ndarray
    """Crank pin on the sliding block at A, x, (m, n) N (= a_x for a massless block)."""
    pin_y: np.ndarray
    """Crank pin on the sliding block at A, y, (m, n) N."""
    a_x: np.ndarray
    """Sliding block on the lever at A, x, (m, n) N; perpendicular to the lever."""
    a_y: np.ndarray
    """Sliding block on the lever at A, y, (m, n) N."""
    slot_normal: np.ndarray
    """The same force as a signed magnitude along n = (cos ψ, −sin ψ), the lever's
    direction of increasing ψ, (m, n) N."""
    o4_x: np.ndarray
    """Frame pivot O4 on the lever, x, (m, n) N."""
    o4_y: np.ndarray
    """Frame pivot O4 on the lever, y, (m, n) N."""
    b_x: np.ndarray
    """Lever tip B on the next link, x, (m, n) N: on the ram through the tip block (block
    variant) or on the rod (rod variant)."""
    b_y: np.ndarray
    """Same, y, (m, n) N; exactly 0 for the block variant (frictionless vertical slot)."""
    c_x: np.ndarray | None
    """Rod on the ram at C, x, (m, n) N; None for the block variant."""
    c_y: np.ndarray | None
    """Rod on the ram at C, y, (m, n) N; None for the block variant."""
    guide_normal: np.ndarray
    """Resultant normal force of the guide on the ram, (m, n) N, positive upward (+y)."""
    guide_moment: np.ndarray
    """Moment of the guide's normal forces on the ram about C, (m, n) N·m, counter-clockwise +."""
    guide_offset_mm: np.ndarray
    """x of the resultant guide normal force relative to C (= guide_moment/guide_normal),
    (m, n) mm; NaN where the resultant is zero (the guide then carries a pure couple)."""
    cut_force: np.ndarray
    """Cutting force P on the tool, (m, n) N, acting in −x; 0 outside the cut."""
    equivalent_inertia: np.ndarray
    """Mechanism inertia reduced to the crank, Σ(m·v_G² + J·ω_link²)/ω², (n,) kg·m²."""


@dataclass(frozen=True)
class SpeedSummary:
    """Cycle values of one crank speed, from a uniform φ grid (see :func:`summarize`)."""

    rpm: float
    """Crank speed, r/min."""
    omega_rad_s: float
    """Crank speed ω, rad/s (also the mean speed ω_m of the flywheel formula)."""
    mean_torque_N_m: float
    """Cycle mean of the driving torque = cycle work / 2π."""
    max_torque_N_m: float
    """Largest driving torque on the grid, N·m."""
    min_torque_N_m: float
    """Smallest driving torque on the grid, N·m; negative = the mechanism drives the motor."""
    mean_power_W: float
    """Mean motor power before drive efficiency, mean torque · ω."""
    max_power_W: float
    """Peak instantaneous input power, W."""
    energy_fluctuation_J: float
    """ΔW_max = max − min of ∫(T − T_mean) dφ over the cycle."""
    flywheel_inertia_kg_m2: float
    """J_F = ΔW_max / (ω² δ), on the crank shaft."""
    flywheel_inertia_net_kg_m2: float
    """max(J_F − J_e_mean, 0): what a flywheel must add to the mechanism's own inertia."""


@dataclass(frozen=True)
class DynamicsSummary:
    """Per-speed cycle values and the curves behind them."""

    masses: MassProperties
    """The masses and loads summarized."""
    crank_angle: np.ndarray
    """Uniform grid φ = 0 … 2π, (N + 1,) rad, N = ``intervals``."""
    energy: np.ndarray
    """Cumulative work of (torque − mean torque) from φ = 0, (m, N + 1) J; 0 at both ends."""
    equivalent_inertia: np.ndarray
    """J_e(φ) on the grid, (N + 1,) kg·m²."""
    equivalent_inertia_mean_kg_m2: float
    """Cycle mean of J_e."""
    speeds: tuple[SpeedSummary, ...]
    """One entry per crank speed, in the order given."""


def solve_dynamics(design: Design, crank_angle: np.ndarray, rpms,
                   masses: MassProperties = MassProperties()) -> Dynamics:
    """Joint forces, driving torque and power for all angles and speeds at once."""
    phi, rpm, omega = _check_inputs(design, crank_angle, rpms, masses)
    return _solve(design, shape(design, phi), rpm, omega, masses)


def _check_inputs(design: Design, crank_angle: np.ndarray, rpms,
                  masses: MassProperties) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    if not isinstance(masses, MassProperties):
        raise TypeError("masses must be a MassProperties")
    phi = np.asarray(crank_angle, dtype=float)
    if phi.ndim != 1 or phi.size == 0:
        raise DesignError("angles", phi.shape, "must be a non-empty 1-D array of crank angles")
    if not np.all(np.isfinite(phi)):
        raise DesignError("angles", float(phi[~np.isfinite(phi)][0]), "must be finite")
    if design.rod is None and masses.rod_mass_kg > 0.0:
        raise DesignError("rod_mass_kg", masses.rod_mass_kg,
                          "must be 0 for the block variant, which has no rod")
    rpm = check_rpms(rpms)
    check_request(phi.size, rpm.size, "angles")
    return phi, rpm, rpm_to_omega(rpm)


def _cross(ax, ay, bx, by):
    """z of the 2-D cross product a × b (moment of force b at arm a)."""
    return ax * by - ay * bx


def cutting_force(design: Design, sh: Shape, masses: MassProperties) -> np.ndarray:
    """Cutting force magnitude P over the shape's angles, (n,) N.

    It acts while the ram advances (dC/dφ > 0) between idle·H and (1 − idle)·H
    of its displacement from the φ = 0 dead point, i.e. over the cut only.
    """
    x = sh.ram_joint[0] - ram_origin(design)
    idle = masses.idle_fraction * design.stroke
    active = (sh.ram1 > 0.0) & (x >= idle) & (x <= design.stroke - idle)
    return np.where(active, masses.cut_force_N, 0.0)


def equivalent_inertia(design: Design, sh: Shape, masses: MassProperties) -> np.ndarray:
    """J_e(φ) = Σ (m |dG/dφ|² + J (dθ/dφ)²), kg·m²: kinetic energy / (ω²/2).

    The crank is balanced and its own inertia is not an input, so it is not
    included; the block's rotational inertia is neglected.
    """
    lever1 = sh.lever1
    cg = masses.lever_cg(design) * MM
    je = (masses.lever_mass_kg * cg ** 2 + masses.lever_inertia_kg_m2) * lever1 ** 2
    je = je + masses.block_mass_kg * (design.crank * MM) ** 2   # |dA/dφ| = L1
    je = je + masses.ram_mass_kg * (sh.ram1 * MM) ** 2
    if sh.rod is not None:
        gx1 = (sh.tip1[0] + sh.ram1) * (MM / 2.0)
        gy1 = sh.tip1[1] * (MM / 2.0)
        rod = design.rod * MM
        je = je + masses.rod_mass_kg * (gx1 ** 2 + gy1 ** 2 + rod ** 2 / 12.0 * sh.rod1 ** 2)
    return je


_FORCES = ("crank_torque", "o2_x", "o2_y", "pin_x", "pin_y", "a_x", "a_y", "slot_normal",
           "o4_x", "o4_y", "b_x", "b_y", "c_x", "c_y", "guide_normal", "guide_moment")


def _solve(design: Design, sh: Shape, rpm: np.ndarray, omega: np.ndarray,
           masses: MassProperties) -> Dynamics:
    """Every load is linear in (static loads, ω²·inertia loads): solve both once, combine."""
    n_count = sh.phi.size
    p_cut = cutting_force(design, sh, masses)
    w2 = np.array([[0.0], [1.0]])                      # row 0: static, row 1: per unit ω²
    g = np.array([[masses.g], [0.0]])
    p = np.stack([p_cut, np.zeros(n_count)])
    parts = _eliminate(design, sh, masses, w2, g, p)
    w2 = (omega ** 2)[:, None]
    out: dict[str, np.ndarray | None] = {}
    for name in _FORCES:                                # a few fields, never angles
        both = parts[name]
        if both is None:
            out[name] = None
            continue
        both = np.broadcast_to(both, (2, n_count))
        out[name] = both[0] + w2 * both[1]
    drive = np.abs(out["b_x"]) + np.abs(out["b_y"])   # type: ignore[arg-type]
    offset = _offset_of(out["guide_normal"], out["guide_moment"],  # type: ignore[arg-type]
                        drive + masses.ram_mass_kg * masses.g + masses.cut_force_N)
    torque = out.pop("crank_torque")
    return Dynamics(
        design=design, masses=masses, crank_angle=sh.phi, rpm=rpm, omega=omega,
        crank_torque=torque, power=torque * omega[:, None],  # type: ignore[operator]
        guide_offset_mm=offset, cut_force=np.broadcast_to(p_cut, (omega.size, n_count)).copy(),
        equivalent_inertia=equivalent_inertia(design, sh, masses), **out,  # type: ignore[arg-type]
    )


def _eliminate(design: Design, sh: Shape, masses: MassProperties, w2: np.ndarray,
               g: np.ndarray, p_cut: np.ndarray) -> dict[str, np.ndarray | None]:
    """Newton–Euler of ram, rod, lever, block and crank, eliminated in that order.

    ``w2`` scales the shape's second derivatives into accelerations, ``g`` is
    gravity and ``p_cut`` the cutting force; all broadcast against (n,).
    Units SI; see docs/forces.md for the equations.
    """
    m3, m4, m5 = masses.lever_mass_kg, masses.rod_mass_kg, masses.ram_mass_kg
    mb, m2 = masses.block_mass_kg, masses.crank_mass_kg
    dx, dy = (v * MM for v in masses.ram_cg_mm)
    y_cut = masses.cut_height_mm * MM

    ax_, ay_ = sh.crank_pin * MM
    bx, by = sh.lever_tip * MM
    cx, cy = sh.ram_joint * MM
    b2x, b2y = w2 * (sh.tip2[0] * MM), w2 * (sh.tip2[1] * MM)
    c2x = w2 * (sh.ram2 * MM)

    # Ram: the x-equation gives the drive force, y and moment about C the guide reaction.
    hx = m5 * c2x + p_cut
    moment = -dy * m5 * c2x + y_cut * p_cut + m5 * g * dx
    if design.rod is None:
        fbx, fby = hx, np.zeros_like(hx)               # tip block on the ram, horizontal at B
        hy = None
        normal = m5 * g + np.zeros_like(hx)
        moment = moment - (design.guide * MM - by) * hx
    else:
        # Rod BC: moments about its centre give Hy (ram's pin force), forces give B.
        ex, ey = cx - bx, cy - by
        g4x, g4y = (b2x + c2x) / 2.0, b2y / 2.0 + g    # a_G4 − g_vec
        j4 = m4 * (design.rod * MM) ** 2 / 12.0
        rhs = -j4 * (w2 * sh.rod2) - m4 * _cross(ex, ey, g4x, g4y) / 2.0
        hy = (rhs + ey * hx) / ex
        fbx, fby = m4 * g4x + hx, m4 * g4y + hy        # lever on rod at B
        normal = m5 * g - hy

    # Lever: moments about the fixed pivot O4 give the block's normal force.
    slide = sh.slide * MM
    ux, uy = ax_ / slide, ay_ / slide
    ratio = masses.lever_cg(design) / design.lever
    g3x, g3y = ratio * bx, ratio * by
    a3x, a3y = ratio * b2x, ratio * b2y + g            # a_G3 − g_vec
    tipx, tipy = -fbx, -fby                            # on the lever at B
    normal_a = (_cross(bx, by, tipx, tipy) - m3 * _cross(g3x, g3y, a3x, a3y)
                + masses.lever_inertia_kg_m2 * (w2 * sh.lever2)) / slide
    fax, fay = normal_a * uy, -normal_a * ux           # block on lever, along n
    o4x, o4y = m3 * a3x - fax - tipx, m3 * a3y - fay - tipy

    # Block (point mass at A) and crank (balanced, constant speed).
    pin_x = mb * (w2 * (sh.pin2[0] * MM)) + fax
    pin_y = mb * (w2 * (sh.pin2[1] * MM) + g) + fay
    torque = -_cross(ax_, ay_ - design.frame * MM, pin_x, pin_y)   # clockwise +
    return {"crank_torque": torque, "o2_x": pin_x, "o2_y": pin_y + m2 * g,
            "pin_x": pin_x, "pin_y": pin_y, "a_x": fax, "a_y": fay, "slot_normal": normal_a,
            "o4_x": o4x, "o4_y": o4y, "b_x": fbx, "b_y": fby, "c_x": hx if hy is not None else None,
            "c_y": hy, "guide_normal": normal, "guide_moment": moment}


def _offset_of(normal: np.ndarray, moment: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """moment/normal in mm where the normal force is not negligibly small, else NaN."""
    normal, moment = np.broadcast_arrays(normal, moment)
    keep = np.abs(normal) > 1e-12 * np.broadcast_to(scale, normal.shape)
    out = np.full(normal.shape, np.nan)
    np.divide(moment, normal, out=out, where=keep)
    return out / MM


def summarize(design: Design, rpms, masses: MassProperties = MassProperties(),
              intervals: int = ENERGY_INTERVALS) -> DynamicsSummary:
    """Mean and peak torque, power, ΔW_max and the flywheel per speed.

    :func:`cycle_summary` on this one design, with its curves.
    """
    intervals = _check_intervals(intervals)
    phi = np.linspace(0.0, 2.0 * math.pi, intervals + 1)
    phi, rpm, omega = _check_inputs(design, phi, rpms, masses)
    out = cycle_summary(Designs.of(design), omega, masses, intervals, curves=True)
    je_mean = float(out["equivalent_inertia_mean_kg_m2"][0])
    speeds = []
    for i, w in enumerate(omega):
        jf = float(out["flywheel_inertia_kg_m2"][0, i])
        speeds.append(SpeedSummary(
            rpm=float(rpm[i]), omega_rad_s=float(w),
            mean_torque_N_m=float(out["mean_torque_N_m"][0, i]),
            max_torque_N_m=float(out["max_torque_N_m"][0, i]),
            min_torque_N_m=float(out["min_torque_N_m"][0, i]),
            mean_power_W=float(out["mean_torque_N_m"][0, i] * w),
            max_power_W=float(out["max_torque_N_m"][0, i] * w),
            energy_fluctuation_J=float(out["energy_fluctuation_J"][0, i]),
            flywheel_inertia_kg_m2=jf, flywheel_inertia_net_kg_m2=max(jf - je_mean, 0.0),
        ))
    return DynamicsSummary(masses=masses, crank_angle=phi, energy=out["energy"][0],
                           equivalent_inertia=out["equivalent_inertia"][0],
                           equivalent_inertia_mean_kg_m2=je_mean, speeds=tuple(speeds))


def _check_intervals(intervals) -> int:
    if isinstance(intervals, bool) or not isinstance(intervals, (int, np.integer)) \
            or not 36 <= intervals <= 1_000_000:
        raise DesignError("intervals", intervals, "must be a whole number from 36 to 1000000")
    return int(intervals)


# Samples per chunk of designs (designs × speeds × angles) that bound cycle_summary's memory.
SUMMARY_SAMPLES = 400_000


def cycle_summary(designs: Designs, omega: np.ndarray, masses: MassProperties,
                  intervals: int = ENERGY_INTERVALS, curves: bool = False) -> dict[str, np.ndarray]:
    """Per-speed cycle values of many designs at once (loads ``masses`` shared by all).

    Returns arrays of shape (designs, speeds), keys ``mean_torque_N_m``,
    ``max_torque_N_m``, ``min_torque_N_m``, ``energy_fluctuation_J``,
    ``flywheel_inertia_kg_m2``, and ``equivalent_inertia_mean_kg_m2`` (designs,);
    with ``curves`` also ``energy`` (designs, speeds, N + 1) and
    ``equivalent_inertia`` (designs, N + 1). Designs must be valid (see
    :mod:`core.designs`) and one-dimensional.

    The torque is integrated over a closed uniform grid of ``intervals``
    steps. The cutting force switches on and off, so its share of the work is
    taken exactly from the ram displacement (virtual work: torque·ω = P·v, so
    ∫T_cut dφ = P·Δx) and only the smooth rest goes through the trapezoid
    rule, which is spectrally accurate for a periodic integrand over a cycle.
    The peak torques are extrema of the closed form (see :func:`_torque_peaks`).
    """
    omega = np.asarray(omega, dtype=float)
    size = designs.shape[0] if designs.shape else 1
    chunk = max(1, SUMMARY_SAMPLES // ((intervals + 1) * max(omega.size, 1)))
    parts = [_summary_chunk(designs.take(slice(i, i + chunk)), omega, masses, intervals, curves)
             for i in range(0, size, chunk)]
    return {key: np.concatenate([p[key] for p in parts]) for key in parts[0]}


def _torque_parts(design, sh: Shape, masses: MassProperties) -> tuple[np.ndarray, np.ndarray]:
    """Driving torque without the cut as (static part, part per unit ω²), N·m; the cut
    adds P·dCx/dφ (virtual work) where it acts."""
    lead = (2,) + (1,) * np.ndim(sh.ram1)
    w2 = np.array([0.0, 1.0]).reshape(lead)
    g = np.array([masses.g, 0.0]).reshape(lead)
    torque = np.broadcast_to(_eliminate(design, sh, masses, w2, g, 0.0)["crank_torque"],
                             (2,) + np.shape(sh.ram1))
    return torque[0], torque[1]


def _summary_chunk(d: Designs, omega: np.ndarray, masses: MassProperties, intervals: int,
                   curves: bool) -> dict[str, np.ndarray]:
    col = d.column()
    phi = np.linspace(0.0, 2.0 * math.pi, intervals + 1)
    step = phi[1] - phi[0]
    sh = shape(col, phi)
    static, inertial = _torque_parts(col, sh, masses)
    w2 = (omega ** 2)[None, :, None]
    smooth = static[:, None, :] + w2 * inertial[:, None, :]   # torque less the cut's share
    work = np.zeros_like(smooth)
    work[..., 1:] = np.cumsum((smooth[..., 1:] + smooth[..., :-1]) * (step / 2.0), axis=-1)
    x = sh.ram_joint[0] - ram_origin(col)
    idle = masses.idle_fraction * col.stroke
    reached = np.clip(np.maximum.accumulate(x, axis=-1), idle, col.stroke - idle) - idle
    work = work + masses.cut_force_N * (reached * MM)[:, None, :]   # exact cut work so far
    mean = work[..., -1] / (2.0 * math.pi)
    energy = work - mean[..., None] * phi
    swing = energy.max(axis=-1) - energy.min(axis=-1)
    je = equivalent_inertia(col, sh, masses)
    je = np.broadcast_to(je, sh.ram1.shape)
    top, bottom = _torque_peaks(d, sh, static, inertial, omega, masses)
    out = {"mean_torque_N_m": mean, "max_torque_N_m": top, "min_torque_N_m": bottom,
           "energy_fluctuation_J": swing,
           "flywheel_inertia_kg_m2": swing / (omega[None, :] ** 2 * masses.delta),
           "equivalent_inertia_mean_kg_m2": np.mean(je[:, :-1], axis=-1)}  # periodic: drop the end
    if curves:
        out.update(energy=energy, equivalent_inertia=je)
    return out


def cut_window(d: Designs, idle_fraction: float,
               sh: Shape | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Crank angles (rad, in [0, π + θ]) where the cut starts and ends, each of d's shape:
    the ram, advancing on the working stroke φ ∈ [0, π + θ], reaches idle·H and
    (1 − idle)·H (see :func:`cutting_force`). Used by the cycle summary and the
    positions table's special rows.

    Each is bracketed between the samples of ``sh`` (one-dimensional ``d``, one design
    per row, uniform φ over the cycle; by default ``ENERGY_INTERVALS`` steps) and
    polished as a root of the closed-form displacement. A switch at or before φ = 0
    (idle 0, or an idle·H below round-off) is 0; one never reached is π + θ.
    """
    from .extrema import bracket_root

    if sh is None:
        sh = shape(d.column(), np.linspace(0.0, 2.0 * math.pi, ENERGY_INTERVALS + 1))
    idle = idle_fraction * d.stroke
    origin = ram_origin(d)
    targets = np.stack([idle, d.stroke - idle]) + origin            # Cx at the two switches
    end = np.broadcast_to(math.pi + d.theta, targets.shape)
    phi = sh.phi
    working = phi <= end[..., None]
    reached = (sh.ram_joint[0][None] >= targets[..., None]) & working
    first = np.argmax(reached, axis=-1)
    # Not reached on a grid sample: between the last sample of the working stroke and its
    # end, where the ram is at H (a dead point between samples, or a sample on π + θ that
    # rounds an ulp past it).
    missed = ~reached.any(axis=-1)
    last = np.maximum(np.searchsorted(phi, end, side="right") - 1, 0)
    inner = (~missed & (first > 0)) | (missed & (phi[last] < end))
    lo = np.where(missed, phi[last], phi[np.maximum(first - 1, 0)])
    hi = np.where(missed, end, np.minimum(phi[first], end))
    root = np.where(reached[..., 0], 0.0, end)                      # at or before φ = 0, or never
    lengths = [np.broadcast_to(v, targets.shape) for v in
               (d.crank, d.frame, d.lever, d.guide, d.crank if d.rod is None else d.rod)]

    def travel(phi, target, *lengths):
        one = Designs(*lengths[:4], lengths[4] if d.rod is not None else None, d.rod_side)
        return shape(one, phi).ram_joint[0] - target

    if inner.any():
        root[inner] = bracket_root(travel, lo[inner], hi[inner],
                                   [v[inner] for v in [targets] + lengths])
    return root[0], root[1]


def _torque_peaks(d: Designs, sh: Shape, static: np.ndarray, inertial: np.ndarray,
                  omega: np.ndarray, masses: MassProperties) -> tuple[np.ndarray, np.ndarray]:
    """Largest and smallest driving torque per design and speed, exactly, N·m.

    The torque is T0 = static + ω²·inertial without the cut and T1 = T0 + P·dCx/dφ
    while cutting: two smooth curves, switched at the ends of the cut. The
    peak is the larger of T1's maximum over the cut, T0's over the rest, and
    both one-sided values at each switch. Each maximum is bracketed on the
    energy grid (plus, for the rod variant, samples crowding toward the sharp
    angles) and polished on the closed form (:func:`core.extrema.piece_maximum`).
    """
    from .extrema import piece_maximum

    col = d.column()
    period = 2.0 * math.pi
    phi = sh.phi[:-1]                                   # the grid's periodic samples
    x = [np.broadcast_to(phi, static[:, :-1].shape)]
    stat, iner, ram1 = [static[:, :-1]], [inertial[:, :-1]], [np.broadcast_to(sh.ram1, static.shape)[:, :-1]]
    segments = [(0, phi.size, period)]
    if needs_crowding(d).any():                       # the whole chunk, if any design
        for j in range(4):
            at = sharp_angles(col)[:, 0, j:j + 1] + CROWD_OFFSETS
            crowd = shape(col, at)
            s_j, i_j = _torque_parts(col, crowd, masses)
            start = sum(a.shape[-1] for a in x)
            x.append(at)
            stat.append(s_j)
            iner.append(i_j)
            ram1.append(crowd.ram1)
            segments.append((start, start + CROWD_OFFSETS.size, 0.0))
    x, stat, iner, ram1 = (np.concatenate(v, axis=-1) for v in (x, stat, iner, ram1))
    on, off = cut_window(d, masses.idle_fraction, sh)
    cut = masses.cut_force_N * MM
    w2 = (omega ** 2)[None, :, None]
    lengths = [v[:, None, None] for v in (d.crank, d.frame, d.lever, d.guide,
                                          d.crank if d.rod is None else d.rod)]

    def torque(phi, w2, sign, cutting, *lengths):
        one = Designs(*lengths[:4], lengths[4] if d.rod is not None else None, d.rod_side)
        at = shape(one, phi)
        s, i = _torque_parts(one, at, masses)
        return sign * (s + w2 * i + cutting * cut * at.ram1)

    # Four curves per design and speed, stacked: (max, min) × (cutting, not cutting).
    sign = np.array([1.0, 1.0, -1.0, -1.0])[:, None, None, None]
    cutting = np.array([1.0, 0.0, 1.0, 0.0])[:, None, None, None]
    samples = sign * (stat[:, None, :] + w2 * iner[:, None, :] + cutting * cut * ram1[:, None, :])
    lo = np.stack([on, off, on, off])[:, :, None]
    hi = np.stack([off, on, off, on])[:, :, None]
    best = piece_maximum(torque, x[:, None, :], samples, lo, hi,
                         args=[w2, sign, cutting] + lengths, segments=segments, period=period)
    return np.fmax(best[0], best[1]), -np.fmax(best[2], best[3])
