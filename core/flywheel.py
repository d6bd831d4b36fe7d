"""Cycle values of the kinetostatics: mean and peak crank torque, energy fluctuation
and the flywheel, for one design or many at once.

A level above :mod:`core.dynamics`, whose per-angle elimination it integrates
over a closed uniform grid. The peaks are exact extrema of the closed-form
torque (:mod:`core.extrema`); the cut's share of the work is taken exactly
from the ram displacement.
"""
from __future__ import annotations

import math

import numpy as np

from .designs import Designs
from .dynamics import (ENERGY_INTERVALS, MM, DynamicsSummary, MassProperties, SpeedSummary,
                       _check_inputs, _eliminate, equivalent_inertia)
from .errors import DesignError
from .geometry import Design
from .kinematics import CROWD_OFFSETS, Shape, needs_crowding, ram_origin, shape, sharp_angles


def summarize(design: Design, rpms, masses: MassProperties = MassProperties(),
              intervals: int = ENERGY_INTERVALS, peaks: bool = True) -> DynamicsSummary:
    """Mean and peak torque, power, ΔW_max and the flywheel per speed.

    :func:`cycle_summary` on this one design, with its curves. ``peaks=False`` leaves
    out the exact torque peaks (max/min torque and peak power are NaN), most of the
    cost, for a caller that shows only the energy, the means and the flywheel.
    """
    intervals = _check_intervals(intervals)
    phi = np.linspace(0.0, 2.0 * math.pi, intervals + 1)
    phi, rpm, omega = _check_inputs(design, phi, rpms, masses)
    out = cycle_summary(Designs.of(design), omega, masses, intervals, curves=True, peaks=peaks)
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
                  intervals: int = ENERGY_INTERVALS, curves: bool = False,
                  peaks: bool = True) -> dict[str, np.ndarray]:
    """Per-speed cycle values of many designs at once (loads ``masses`` shared by all).

    Returns arrays of shape (designs, speeds), keys ``mean_torque_N_m``,
    ``max_torque_N_m``, ``min_torque_N_m``, ``energy_fluctuation_J``,
    ``flywheel_inertia_kg_m2``, and ``equivalent_inertia_mean_kg_m2`` (designs,);
    with ``curves`` also ``energy`` (designs, speeds, N + 1) and
    ``equivalent_inertia`` (designs, N + 1). Designs must be valid (see
    :mod:`core.designs`) and one-dimensional. ``peaks=False`` skips the exact torque
    peaks: ``max_torque_N_m`` and ``min_torque_N_m`` are NaN.

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
    parts = [_summary_chunk(designs.take(slice(i, i + chunk)), omega, masses, intervals, curves, peaks)
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
                   curves: bool, peaks: bool = True) -> dict[str, np.ndarray]:
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
    if peaks:
        top, bottom = _torque_peaks(d, sh, static, inertial, omega, masses)
    else:
        top = bottom = np.full(mean.shape, np.nan)
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
