"""Kinetostatics of the shaper: joint forces, crank torque and power at each crank angle.

The values over a cycle (peak torque, energy fluctuation, flywheel) are in
:mod:`core.forces.flywheel`, which integrates what this module solves.

A level beside ``metrics``: it imports ``geometry`` and ``kinematics`` only.
The crank turns at constant speed ω, so every acceleration is ω² times a
closed-form second derivative from :func:`core.linkage.kinematics.shape` and every
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

from dataclasses import dataclass

import numpy as np

from core.linkage.cut import cutting_force
from core.base.errors import DesignError
from core.linkage.geometry import Design
from .guide import end_forces, guide_ends
from core.linkage.kinematics import Shape, check_request, check_rpms, rpm_to_omega, shape
from .masses import MM, MassProperties

ENERGY_INTERVALS = 3600      # uniform φ intervals per cycle for the energy integral

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
    guide_rear_mm: np.ndarray
    """x of the guide's rear end relative to C, (n,) mm (:func:`core.forces.guide.guide_ends`)."""
    guide_front_mm: np.ndarray
    """x of the guide's front end relative to C, (n,) mm."""
    guide_rear_N: np.ndarray
    """Normal force of the guide's rear end on the ram, (m, n) N, up +: the ram bears on
    both ends where ``guide_tilted``; elsewhere the resultant's statically equivalent split."""
    guide_front_N: np.ndarray
    """Same at the guide's front end, (m, n) N."""
    guide_tilted: np.ndarray
    """Where the resultant's line of action falls outside the guide (or the guide carries
    a pure couple), so the ram tilts and bears on the guide's two ends, (m, n) bool."""
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
    flywheel_inertia_needed_kg_m2: float
    """J_F − J_c, the task book's flywheel: what the flywheel must add to the other rotating
    parts reduced to the crank (``MassProperties.rotors``); 0 when they hold δ on their own
    (``flywheel_needed`` False), never negative."""
    flywheel_needed: bool
    """False when J_c ≥ J_F: the rotating parts alone keep the speed within δ."""
    flywheel_inertia_net_kg_m2: float
    """max(J_F − J_c − J_e_mean, 0): what a flywheel must add to the rotating parts and the
    mechanism's own mean inertia."""


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
    rotor_inertia_kg_m2: float
    """J_c = Σ J_i·(ω_i/ω2)², the other rotating parts reduced to the crank, kg·m²."""
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
    rear, front = guide_ends(design, sh.ram_joint[0], masses.guide_length(design))
    ends = end_forces(out["guide_normal"], out["guide_moment"], offset, rear, front)  # type: ignore[arg-type]
    torque = out.pop("crank_torque")
    return Dynamics(
        design=design, masses=masses, crank_angle=sh.phi, rpm=rpm, omega=omega,
        crank_torque=torque, power=torque * omega[:, None],  # type: ignore[operator]
        guide_offset_mm=offset, guide_rear_mm=rear, guide_front_mm=front, guide_rear_N=ends[0],
        guide_front_N=ends[1], guide_tilted=ends[2], cut_force=np.broadcast_to(p_cut, (omega.size, n_count)).copy(),
        equivalent_inertia=equivalent_inertia(design, sh, masses), **out,  # type: ignore[arg-type]
    )


def _eliminate(design: Design, sh: Shape, masses: MassProperties, w2: np.ndarray,
               g: np.ndarray, p_cut: np.ndarray) -> dict[str, np.ndarray | None]:
    """Newton–Euler of ram, rod, lever, block and crank, eliminated in that order.

    ``w2`` scales the shape's second derivatives into accelerations, ``g`` is
    gravity and ``p_cut`` the cutting force; all broadcast against (n,).
    Units SI; see docs/forces.md for the equations.
    """
    m4, m5, m6 = masses.lever_mass_kg, masses.rod_mass_kg, masses.ram_mass_kg
    m3, m2 = masses.block_mass_kg, masses.crank_mass_kg
    dx, dy = (v * MM for v in masses.ram_cg_mm)
    y_cut = masses.cut_height_mm * MM

    ax_, ay_ = sh.crank_pin * MM
    bx, by = sh.lever_tip * MM
    cx, cy = sh.ram_joint * MM
    b2x, b2y = w2 * (sh.tip2[0] * MM), w2 * (sh.tip2[1] * MM)
    c2x = w2 * (sh.ram2 * MM)

    # Ram: the x-equation gives the drive force, y and moment about C the guide reaction.
    hx = m6 * c2x + p_cut
    moment = -dy * m6 * c2x + y_cut * p_cut + m6 * g * dx
    if design.rod is None:
        fbx, fby = hx, np.zeros_like(hx)               # tip block on the ram, horizontal at B
        hy = None
        normal = m6 * g + np.zeros_like(hx)
        moment = moment - (design.guide * MM - by) * hx
    else:
        # Rod BC (link 5): moments about its centre S5 give Hy (ram's pin force), forces give B.
        ex, ey = cx - bx, cy - by
        s5x, s5y = (b2x + c2x) / 2.0, b2y / 2.0 + g    # a_S5 − g_vec
        j5 = m5 * (design.rod * MM) ** 2 / 12.0
        rhs = -j5 * (w2 * sh.rod2) - m5 * _cross(ex, ey, s5x, s5y) / 2.0
        hy = (rhs + ey * hx) / ex
        fbx, fby = m5 * s5x + hx, m5 * s5y + hy        # lever on rod at B
        normal = m6 * g - hy

    # Lever: moments about the fixed pivot O4 give the block's normal force.
    slide = sh.slide * MM
    ux, uy = ax_ / slide, ay_ / slide
    ratio = masses.lever_cg(design) / design.lever
    s4x, s4y = ratio * bx, ratio * by
    a4x, a4y = ratio * b2x, ratio * b2y + g            # a_S4 − g_vec
    tipx, tipy = -fbx, -fby                            # on the lever at B
    normal_a = (_cross(bx, by, tipx, tipy) - m4 * _cross(s4x, s4y, a4x, a4y)
                + masses.lever_inertia_kg_m2 * (w2 * sh.lever2)) / slide
    fax, fay = normal_a * uy, -normal_a * ux           # block on lever, along n
    o4x, o4y = m4 * a4x - fax - tipx, m4 * a4y - fay - tipy

    # Block (point mass at A) and crank (balanced, constant speed).
    pin_x = m3 * (w2 * (sh.pin2[0] * MM)) + fax
    pin_y = m3 * (w2 * (sh.pin2[1] * MM) + g) + fay
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
