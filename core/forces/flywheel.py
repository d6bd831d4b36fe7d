"""Cycle values of the kinetostatics: mean and peak crank torque, energy fluctuation
and the flywheel, for one design or many at once.

A level above :mod:`core.forces.dynamics`, whose per-angle elimination it integrates
over a closed uniform grid. The peaks are exact extrema of the closed-form
torque (:mod:`core.linkage.extrema`); the cut's share of the work is taken exactly
from the ram displacement.
"""
from __future__ import annotations

import math

import numpy as np

from core.linkage.cut import cut_window
from core.linkage.designs import Designs
from core.linkage.turns import wrap_turn
from .dynamics import ENERGY_INTERVALS, DynamicsSummary, SpeedSummary, _check_inputs
from .bumps import bump_cells, split_bumps
from .cells import (DIRECT_SPEEDS, Cells, Window, at_switch, cell_ends, cell_index, on_arc,
                    pair_extremes, slope_turns, straddling, switch_window, turning_cells,
                    turns_beyond)
from .jet import TorqueJet, grid_trig, torque_jet
from .masses import MM, MassProperties
from .torque_peaks import PEAK_GAIN, piece_peaks
from core.base.errors import DesignError
from core.linkage.geometry import Design
from core.linkage.kinematics import needs_crowding, sharp_angles

# Crank-to-frame ratio L1/L2 above which a rod variant's torque is crowded too, however far
# the rod leans: near the lever's vertical crossing the pin passes within L2 − L1 of O4, the
# lever whips round (ψ′ up to L1/(L2 − L1)·ω) and the rod's inertia turns the torque through
# extrema a degree or two apart, inside one of the coarse sweep's 4° cells (a random search,
# 3208 rod designs at L1/L2 0.3 … 0.995: one such miss, 7 % of the peak, at 0.841; the
# hypothesis corners found 1.3e-3 at 0.854). Below it the 90 cells resolve the torque.
LEVER_WHIP_RATIO = 0.7

# Offsets (rad) of the torque's crowding samples about each sharp angle, for a whipping lever
# and for a rod near upright alike: halving from 0.1 rad (a bit over one 4° cell) down to
# 1.2e-5 rad, so that extrema 0.5 … 3° from a sharp angle each get a cell of their own
# (the kinematics' CROWD_OFFSETS, fifths from 0.05 rad, leave a gap from 0.57° to 2.9°: a
# whipping lever's torque extrema fell in it, and a 45.7 mm rod's peak under a 1150 mm lever).
WHIP_OFFSETS = np.concatenate([-(0.1 * 2.0 ** -np.arange(0, 14)), [0.0],
                               (0.1 * 2.0 ** -np.arange(0, 14))[::-1]])


def lever_whips(d: Designs) -> np.ndarray:
    """Per design: a rod variant whose lever whips round (L1/L2 above LEVER_WHIP_RATIO)."""
    if d.rod is None:
        return np.zeros(np.shape(d.crank), dtype=bool)
    return np.asarray(d.crank / d.frame) > LEVER_WHIP_RATIO


def crowd_offsets(d: Designs) -> np.ndarray | None:
    """The offsets (rad) of the torque's samples crowding toward the sharp angles for a
    chunk of designs, or None where none of them needs any (one size for the whole chunk)."""
    if lever_whips(d).any() or needs_crowding(d).any():
        return WHIP_OFFSETS
    return None


def summarize(design: Design, rpms, masses: MassProperties = MassProperties(),
              intervals: int = ENERGY_INTERVALS, peaks: bool = True) -> DynamicsSummary:
    """Mean and peak torque, power, ΔW_max and the flywheel per speed.

    The flywheel of the task book: J_F = ΔW_max/(ω_m²·δ) at the crank, less the other
    rotating parts reduced to it, J_c = Σ J_i·(ω_i/ω2)² (their kinetic energy
    ½·J_i·ω_i² = ½·J_i·(ω_i/ω2)²·ω2²); when J_c ≥ J_F no flywheel is needed.

    :func:`cycle_summary` on this one design, with its curves. ``peaks=False`` leaves
    out the exact torque peaks (max/min torque and peak power are NaN), most of the
    cost, for a caller that shows only the energy, the means and the flywheel.
    """
    intervals = _check_intervals(intervals)
    phi = np.linspace(0.0, 2.0 * math.pi, intervals + 1)
    phi, rpm, omega = _check_inputs(design, phi, rpms, masses)
    out = cycle_summary(Designs.of(design), omega, masses, intervals, curves=True, peaks=peaks)
    je_mean = float(out["equivalent_inertia_mean_kg_m2"][0])
    jc = masses.rotor_inertia_kg_m2
    speeds = []
    for i, w in enumerate(omega):
        jf = float(out["flywheel_inertia_kg_m2"][0, i])
        needed = jf - jc
        speeds.append(SpeedSummary(
            rpm=float(rpm[i]), omega_rad_s=float(w),
            mean_torque_N_m=float(out["mean_torque_N_m"][0, i]),
            max_torque_N_m=float(out["max_torque_N_m"][0, i]),
            min_torque_N_m=float(out["min_torque_N_m"][0, i]),
            mean_power_W=float(out["mean_torque_N_m"][0, i] * w),
            max_power_W=float(out["max_torque_N_m"][0, i] * w),
            energy_fluctuation_J=float(out["energy_fluctuation_J"][0, i]),
            flywheel_inertia_kg_m2=jf, flywheel_inertia_needed_kg_m2=max(needed, 0.0),
            flywheel_needed=bool(needed > 0.0),
            flywheel_inertia_net_kg_m2=max(needed - je_mean, 0.0),
        ))
    return DynamicsSummary(masses=masses, crank_angle=phi, energy=out["energy"][0],
                           equivalent_inertia=out["equivalent_inertia"][0],
                           equivalent_inertia_mean_kg_m2=je_mean, rotor_inertia_kg_m2=jc,
                           speeds=tuple(speeds))


def _check_intervals(intervals) -> int:
    if isinstance(intervals, bool) or not isinstance(intervals, (int, np.integer)) \
            or not 36 <= intervals <= 1_000_000:
        raise DesignError("intervals", intervals, "must be a whole number from 36 to 1000000")
    return int(intervals)


# Samples per chunk of designs (designs × speeds × angles) that bound cycle_summary's memory.
SUMMARY_SAMPLES = 400_000
# The largest remainder of designs (a fraction of a chunk) that joins the last full chunk
# rather than making a chunk of its own (see cycle_summary).
TAIL_SHARE = 0.125


def cycle_summary(designs: Designs, omega: np.ndarray, masses: MassProperties,
                  intervals: int = ENERGY_INTERVALS, curves: bool = False,
                  peaks: bool = True) -> dict[str, np.ndarray]:
    """Per-speed cycle values of many designs at once (loads ``masses`` shared by all).

    Returns arrays of shape (designs, speeds), keys ``mean_torque_N_m``,
    ``max_torque_N_m``, ``min_torque_N_m``, ``energy_fluctuation_J``,
    ``flywheel_inertia_kg_m2``, and ``equivalent_inertia_mean_kg_m2`` (designs,);
    with ``curves`` also ``energy`` (designs, speeds, N + 1) and
    ``equivalent_inertia`` (designs, N + 1). Designs must be valid (see
    :mod:`core.linkage.designs`) and one-dimensional. ``peaks=False`` skips the exact torque
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
    # Arrays over designs × speeds × angles are formed only for the curves and for a few
    # speeds (core.forces.cells.DIRECT_SPEEDS); otherwise the per-speed arrays are
    # the cells found, some 5 per design and speed for the torque alone, each evaluated
    # through the jet's temporaries: a chunk shrinks with a quarter of the speeds (at 16
    # speeds, 10^4 designs peaked at 199 MB without it, 104 MB before).
    per_design = max(omega.size, 1) if curves or omega.size <= DIRECT_SPEEDS \
        else -(-omega.size // 4)
    chunk = max(1, SUMMARY_SAMPLES // ((intervals + 1) * per_design))
    starts = list(range(0, size, chunk))
    # A chunk costs some 7 ms of numpy calls before its first design counts (issue 42: a
    # loaded block's tail of 48 designs at 16 speeds took as long as 170 designs in a full
    # chunk), so a tail of at most TAIL_SHARE of a chunk joins the chunk before it, which
    # then holds at most that much more than SUMMARY_SAMPLES.
    if len(starts) > 1 and size - starts[-1] <= chunk * TAIL_SHARE:
        starts.pop()
    parts = [_summary_chunk(designs.take(slice(a, b)), omega, masses, intervals, curves, peaks)
             for a, b in zip(starts, starts[1:] + [size])]
    return {key: np.concatenate([p[key] for p in parts]) for key in parts[0]}


def _summary_chunk(d: Designs, omega: np.ndarray, masses: MassProperties, intervals: int,
                   curves: bool, peaks: bool = True) -> dict[str, np.ndarray]:
    col = d.column()
    phi = np.linspace(0.0, 2.0 * math.pi, intervals + 1)
    grid = torque_jet(col, phi, masses, trig=grid_trig(col, phi))  # (designs, intervals + 1)
    samples = _torque_samples(d, grid, masses)
    on, off = cut_window(d, masses.idle_fraction, (phi, grid.ram_x))
    mean = cut_work(d, masses) / (2.0 * math.pi)                 # (designs,)
    start = (grid.kinetic[:, :1], grid.potential[:, :1], grid.ram_x[:, :1])  # φ = 0: the first
    window = switch_window(d, samples, on, off, masses)
    turns = slope_turns(samples[1], omega ** 2, window, runs=peaks)   # the torque's and E″'s
    top, bottom = _energy_extremes(d, samples, start, omega, mean, (window, turns), masses)
    swing = top - bottom
    je = 2.0 * grid.kinetic                                       # the kinetic energy is ½·J_e
    if peaks:
        high, low = _torque_peaks(d, samples, omega, masses, window, turns)
    else:
        high = low = np.full(top.shape, np.nan)
    out = {"mean_torque_N_m": np.repeat(mean[:, None], omega.size, axis=1),
           "max_torque_N_m": high, "min_torque_N_m": low,
           "energy_fluctuation_J": swing,
           "flywheel_inertia_kg_m2": swing / (omega[None, :] ** 2 * masses.delta),
           "equivalent_inertia_mean_kg_m2": np.mean(je[:, :-1], axis=-1)}  # periodic: drop the end
    if curves:
        out.update(energy=_energy(col, phi, grid, (omega ** 2)[None, :, None],
                                  mean[:, None, None], masses, start), equivalent_inertia=je)
    return out


def cut_work(d: Designs, masses: MassProperties) -> np.ndarray:
    """Work of the cutting force over one cycle, J, one per design: P·(1 − 2·idle)·H.

    With frictionless joints the weights and inertia loads need no work over a
    cycle (they are conservative), so this is the whole cycle work and the mean
    driving torque is exactly cut_work / 2π.
    """
    return masses.cut_force_N * (1.0 - 2.0 * masses.idle_fraction) * np.asarray(d.stroke) * MM


def _energy(d, phi: np.ndarray, stored: TorqueJet, w2, mean, masses: MassProperties,
            start: tuple[np.ndarray, np.ndarray, np.ndarray]) -> np.ndarray:
    """E(φ) = work of (driving torque − mean torque) from φ = 0, J, at angles ``phi``.

    The driving torque less the cut is the rate of change of the energy the links store,
    ω²·K + V (energy balance of a frictionless chain at constant crank speed; the ram moves
    level, so its weight stores nothing, and the crank is balanced and turns steadily, so
    its energy is constant), so the work done up to any angle is a difference of two
    closed-form values: the energy curve needs no quadrature and is exact at any angle, not
    only on a grid. E is the stored energy gained since φ = 0, plus the cut's work so far
    (P times the distance cut, exact at any angle: torque·ω = P·v while cutting), less the
    mean torque's work. ``stored`` is the :class:`~core.forces.jet.TorqueJet` at ``phi``
    (its kinetic, potential and ram_x are read), ``start`` its (kinetic, potential, ram_x)
    at φ = 0 (the ram's x there is the zero of its travel); ``w2`` and ``mean`` broadcast
    against the angles' shape with a speed axis before it (or elementwise, for flat arrays
    of points).
    """
    kinetic, potential = stored.kinetic, stored.potential
    x = stored.ram_x - start[2]
    idle = masses.idle_fraction * d.stroke
    turn = np.broadcast_to(wrap_turn(phi), np.shape(x))
    travel = np.where(turn <= math.pi + d.theta, np.clip(x, idle, d.stroke - idle) - idle,
                      d.stroke - 2.0 * idle)
    if np.ndim(w2) > np.ndim(kinetic):                           # a speed axis before the angles
        kinetic, potential, travel, turn = (v[:, None] for v in (kinetic, potential, travel, turn))
        start = tuple(v[:, None] for v in start)
    return (w2 * (kinetic - start[0]) + (potential - start[1])
            + masses.cut_force_N * MM * travel - mean * turn)


def _energy_extremes(d: Designs, samples: tuple, start: tuple[np.ndarray, ...], omega: np.ndarray,
                     mean: np.ndarray, windows: tuple[Window, tuple[list, list]],
                     masses: MassProperties) -> tuple[np.ndarray, np.ndarray]:
    """Largest and smallest E(φ) per design and speed, exactly, J, each (designs, speeds).

    E is continuous and smooth except at the cut's two switch angles, where the torque
    jumps and E has a kink, so its extremes lie at a kink or at a zero of its slope
    T − T_mean inside a smooth piece. The slope of each piece (torque with and without the
    cut) is smooth over the whole cycle and affine in ω², so its sign changes at every speed
    are found on the samples at once (:func:`core.forces.cells.turning_cells`: the
    grid's, plus the rod variant's samples crowding toward its sharp angles), and each is
    polished by Newton's method on the closed-form slope (every one: E may have several
    nearly equal peaks, and skipping cells by their end tangents missed some near a rod's
    sharp angles, unless it turns beyond its piece), from the zero of the quintic through
    E′, E″ and E‴ at the cell's samples (:func:`core.linkage.polish.newton_crossing`),
    until the next step would change E by at most ``PEAK_GAIN`` of itself (two to five
    evaluations and one more for E before the quintics, 1.6 from the top of E's own quintic,
    1.2 from this one); a zero counts only inside its own piece. ``samples`` are :func:`_torque_samples`'s,
    ``start`` the stored energy (kinetic, potential) and the ram's x at φ = 0, ``mean`` the
    mean torque (designs,), ``windows`` the cut's switch angles with the jet there and the
    cells of each piece (:func:`core.forces.cells.switch_window`), with the cells of each
    piece where T′ = E″ changes sign (:func:`core.forces.cells.slope_turns`).

    Two zeros of E′ in one cell (a small bump of E′ through zero) change no sign at the
    samples: E′ then turns inside the cell, so E″ changes sign there, and such cells are
    split at E′'s polished extremum where it lies beyond zero (:mod:`core.forces.bumps`;
    a rod's swing was 4.3e-4 J, 3e-6 of itself, low without it).
    """
    from core.linkage.polish import newton_crossing

    window, turns = windows
    on, off = window.on, window.off
    count, speeds = mean.size, omega.size
    col = d.column()
    x, jet, _ = samples
    w2 = omega ** 2
    kinks = np.stack([on, off], axis=-1)
    at_ends = _energy(col, kinks, window.jet, w2[None, :, None],
                      mean[:, None, None], masses, start)         # the kinks, (designs, speeds, 2)
    top, bottom = (v.reshape(-1) for v in pair_extremes(at_ends))
    lengths = [np.broadcast_to(v, on.shape) for v in d.lengths()]
    start = tuple(v[:, 0] for v in start)

    def fun(phi, w2, mean, sign, cutting, k0, v0, x0, theta, *lengths):
        one = d.with_lengths(lengths, theta)
        stored = torque_jet(one, phi, masses, curvature=False)
        g = stored.static + w2 * stored.inertial + cutting * stored.cut - mean
        slope = stored.static1 + w2 * stored.inertial1 + cutting * stored.cut1
        value = _energy(one, phi, stored, w2, mean, masses, (k0, v0, x0))
        return sign * value, sign * g, sign * slope

    found, bumps = [], []
    for k, (cutting, piece) in enumerate(((1.0, (on, off)), (0.0, (off, on)))):
        parts = (jet.static + cutting * jet.cut - mean[:, None], jet.inertial)   # E′ = T − mean
        slopes = (jet.static1 + cutting * jet.cut1, jet.inertial1)               # E″
        curvatures = (jet.static2 + cutting * jet.cut2, jet.inertial2)           # E‴
        at = (window.jet.static + cutting * window.jet.cut - mean[:, None], window.jet.inertial)
        for kind, cells in turning_cells(parts, w2, window.cells[k], runs=False):
            index = cell_index(x.shape[-1], cells)                # each end's, taken once
            cells, index = _within_piece(cells, index, window.inside[k], k, at, w2,
                                         1.0 - 2.0 * kind)
            sign = np.full(cells.design.size, 1.0 - 2.0 * kind)    # E's maximum, or its minimum
            design, speed = cells.design, cells.speed
            w = w2[speed]
            found.append([design, speed, cells.lo, cells.hi, sign, np.full(sign.size, cutting),
                          piece[0][design], piece[1][design]]
                         + [sign * (a + w * b) for p in (parts, slopes, curvatures)
                            for a, b in cell_ends(p, index)])
        # Two zeros of E′ in one cell show no sign change: E′ turns there (core.forces.bumps).
        bumps += bump_cells((parts, slopes, curvatures), w2, cutting, piece, turns[k])
    found += split_bumps(d, masses, w2, mean, bumps)
    if not found:
        return top.reshape(count, speeds), bottom.reshape(count, speeds)
    design, speed, lo, hi, sign, cutting, first, last, g_lo, g_hi, c_lo, c_hi, r_lo, r_hi = (
        np.concatenate(v) for v in zip(*found))
    roots, value = newton_crossing(
        fun, lo, hi, (g_lo, g_hi), (c_lo, c_hi), (r_lo, r_hi),
        [w2[speed], mean[design], sign, cutting] + [v[design] for v in start]
        + [np.broadcast_to(d.theta, on.shape)[design]] + [v[design] for v in lengths],
        gain=PEAK_GAIN)
    inside = on_arc(roots, first, last)
    owner, value = (design * speeds + speed)[inside], (sign * value)[inside]
    np.fmax.at(top, owner, value)
    np.fmin.at(bottom, owner, value)
    return top.reshape(count, speeds), bottom.reshape(count, speeds)


def _within_piece(cells: Cells, index: list[np.ndarray], inside: np.ndarray, k: int,
                  at: tuple[np.ndarray, np.ndarray], w2: np.ndarray,
                  sign: float) -> tuple[Cells, list[np.ndarray]]:
    """``cells`` and their samples' flat ``index`` less the cells that straddle an end of
    piece ``k`` and turn beyond it (:func:`core.forces.cells.turns_beyond`; E′'s (a, b) ``at``
    the switch angles, ``inside`` per sample whether it lies in the piece): their zero of E′
    lies in the other piece and would not count (a fifth of the energy's evaluations went to
    them, three or four each, their E′ and E belonging to different pieces)."""
    which, switch, leaving = straddling(cells, [inside.take(i) for i in index], k)
    beyond = turns_beyond(at_switch(at, switch, w2.take(cells.speed.take(which))), leaving, sign)
    if not beyond.any():
        return cells, index
    keep = np.ones(cells.design.size, dtype=bool)
    keep[which[beyond]] = False
    return Cells(*(None if v is None else v[keep] for v in cells)), [i[keep] for i in index]


def _torque_samples(d: Designs, grid: TorqueJet, masses: MassProperties) -> tuple:
    """The torque's samples that bracket its extrema and those of the energy: (φ, its
    :class:`~core.forces.jet.TorqueJet` there, segments), each array (designs, samples).

    The grid's periodic samples (``grid``, the jet on a closed uniform grid: one wrapping
    segment; its closing sample lies in no cell) and, where any design of the chunk needs
    them, samples crowding toward the rod variant's sharp angles (one segment each), where its
    torque can change faster than the grid resolves. Every array is the same at all
    speeds: a speed's torque and slope are sums of them, taken by flat index
    (:func:`core.forces.cells.gather`), so each is C-contiguous.
    """
    col = d.column()
    n = grid.static.shape[-1] - 1
    shape = (d.shape[0], n + 1)
    offsets = crowd_offsets(d)                        # the whole chunk, if any design
    if offsets is None:               # the closed grid as it is: no field copied
        x = np.ascontiguousarray(np.broadcast_to(np.linspace(0.0, 2.0 * math.pi, n + 1), shape))
        return (x, TorqueJet(*(np.ascontiguousarray(np.broadcast_to(v, shape)) for v in grid)),
                [(0, n, 2.0 * math.pi)])
    x = [np.broadcast_to(np.linspace(0.0, 2.0 * math.pi, n + 1)[:-1], (d.shape[0], n))]
    jets = [TorqueJet(*(np.broadcast_to(v, shape)[:, :-1] for v in grid))]
    segments = [(0, n, 2.0 * math.pi)]
    sharp = sharp_angles(col)[:, 0, :]
    for j in range(4):
        x.append(sharp[:, j:j + 1] + offsets)
        jets.append(TorqueJet(*(np.broadcast_to(v, x[-1].shape)
                                for v in torque_jet(col, x[-1], masses))))
        start = segments[-1][1]
        segments.append((start, start + offsets.size, 0.0))
    return (np.concatenate(x, axis=-1),
            TorqueJet(*(np.concatenate(v, axis=-1) for v in zip(*jets))), segments)


def _torque_peaks(d: Designs, samples: tuple, omega: np.ndarray, masses: MassProperties,
                  window: Window, turns: tuple[list, list]) -> tuple[np.ndarray, np.ndarray]:
    """Largest and smallest driving torque per design and speed, exactly, N·m.

    The torque is T0 = static + ω²·inertial without the cut and T1 = T0 + cut while
    cutting (:class:`~core.forces.jet.TorqueJet`): two smooth curves, switched at the ends of
    the cut (``window``, from :func:`cut_window`). The peak is the larger of T1's maximum over
    the cut, T0's over the rest, and both one-sided values at each switch: see
    :func:`core.forces.torque_peaks.piece_peaks`, which brackets each maximum where the
    slope sampled by :func:`_torque_samples` turns and polishes it by Newton's method.
    """
    return piece_peaks(d, samples, omega, masses, window, turns)
