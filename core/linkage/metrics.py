"""Cycle metrics measured from the motion itself, not echoed from the inputs.

The third level of core. Limit positions are found as the zeros of the ram
velocity (sign changes on a grid, polished by a bracketed root finder on the
closed-form velocity), so a measured K or stroke that disagrees with the
design's nominal values exposes a fault in the kinematics. Every peak is an
extremum of the closed-form curves (see :mod:`core.linkage.extrema`), not the largest
sample of a grid, and the crank angles of the speed peaks are kept (the
positions table's special rows). One code path serves one design
(:func:`analyze`) and many (:func:`cycle_peaks`, used by the sweep).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .designs import Designs
from .extrema import grid_argmax
from .geometry import Design
from .kinematics import (CROWD_BELOW, CROWD_OFFSETS, check_rpms, pressure_angle, rpm_to_omega,
                         shape_at)
from .polish import bracket_root
from .rates import Rates, ram_rates, ram_velocity, rates4_at, rates_at, tip_rates


@dataclass(frozen=True)
class SpeedMetrics:
    """Metrics of one crank speed. Speeds m/s, accelerations m/s², times s."""

    rpm: float
    cycle_time_s: float
    work_time_s: float
    return_time_s: float
    v_work_max_m_s: float      # largest cutting-direction speed on the working stroke
    v_return_max_m_s: float    # largest speed (magnitude) on the return stroke
    v_work_mean_m_s: float     # stroke / working time
    a_max_m_s2: float          # largest |ram acceleration| over the cycle
    lever_omega_max_rad_s: float
    lever_alpha_max_rad_s2: float


@dataclass(frozen=True)
class CycleMetrics:
    """Speed-independent metrics plus one :class:`SpeedMetrics` per speed."""

    theta_deg: float            # extreme-position angle of the design
    time_ratio: float           # measured K = working / return crank angle
    stroke_mm: float            # measured ram stroke
    work_angle_deg: float
    return_angle_deg: float
    work_start_deg: float       # crank angle of the limit that starts cutting (≈ 0)
    work_end_deg: float         # crank angle of the other limit (≈ 180 + θ)
    ram_min_mm: float
    ram_max_mm: float
    pressure_angle_max_deg: float | None   # rod variant only
    speeds: tuple[SpeedMetrics, ...]

    def speed(self, rpm: float) -> SpeedMetrics:
        return min(self.speeds, key=lambda s: abs(s.rpm - rpm))


@dataclass(frozen=True)
class CyclePeaks:
    """Speed-independent cycle figures of many designs; every field has the designs' shape.

    Rates are φ-derivatives: multiply by ω (ω²) and divide by 1000 for m/s (m/s²).
    """

    work_start: np.ndarray    # crank angle of the dead point that starts cutting, rad in [0, 2π)
    work_end: np.ndarray      # crank angle of the other dead point, rad
    ram_min_mm: np.ndarray    # ram displacement at the dead points, from its φ = 0 position
    ram_max_mm: np.ndarray
    v_work: np.ndarray        # max dCx/dφ (cutting direction), mm/rad
    v_return: np.ndarray      # max −dCx/dφ (return), mm/rad
    v_work_at: np.ndarray     # crank angle of the max cutting speed, rad in [0, 2π)
    v_return_at: np.ndarray   # crank angle of the max return speed, rad in [0, 2π)
    a_max: np.ndarray         # max |d²Cx/dφ²|, mm/rad²
    lever1_max: np.ndarray    # max |dψ/dφ|
    lever2_max: np.ndarray    # max |d²ψ/dφ²|, 1/rad
    pressure_max: np.ndarray | None   # max pressure angle, rad; None for the block variant

    @property
    def work_angle(self) -> np.ndarray:
        return np.mod(self.work_end - self.work_start, 2.0 * math.pi)

    @property
    def time_ratio(self) -> np.ndarray:
        work = self.work_angle
        return work / (2.0 * math.pi - work)

    @property
    def stroke_mm(self) -> np.ndarray:
        return self.ram_max_mm - self.ram_min_mm


# Uniform samples of the crank direction β per cycle, shared by every design; the rod
# variant adds samples crowding toward its sharp angles (kinematics.sharp_angles).
SAMPLES = 64
_STEP = 2.0 * math.pi / SAMPLES
_BETA = (np.arange(SAMPLES) + 0.5) * _STEP
# Four times as dense, for a crank longer than FINE_ABOVE·L2 (K ≳ 2.2), whose lever turns
# sharply on the return stroke: features there are ~(1 − λ)/√λ rad wide, λ = L1/L2.
_BETA_FINE = (np.arange(4 * SAMPLES) / 4.0 + 0.5) * _STEP
FINE_ABOVE = 0.6
_OFFSETS = CROWD_OFFSETS
CHUNK = 2048


def cycle_peaks(designs: Designs) -> CyclePeaks:
    """Dead points, stroke, K and every peak of the cycle for each of many designs.

    No Python loop runs per design: designs are processed in chunks of
    ``CHUNK`` (bounding memory), each chunk as arrays. The peaks are extrema of
    the closed-form curves (see :mod:`core.linkage.extrema`), sampled at crank
    directions β = π + θ/2 − φ shared by all designs, plus, for the rod
    variant, samples crowding geometrically (down to ~1e-5 rad) toward the two
    dead points and the two crossings of the vertical (ψ = 0). The rod rises
    furthest, so its reach sqrt(L4² − d²) is smallest and its motion can
    change sharply, only at those four angles: |d| = |guide − L3·cos ψ| is
    monotonic in |ψ|.
    """
    shape = designs.shape
    flat = designs.flat()
    size = int(np.prod(shape))
    parts = [_chunk_peaks(flat.take(slice(i, i + CHUNK))) for i in range(0, size, CHUNK)] or \
        [_chunk_peaks(flat)]
    fields = {name: np.concatenate([getattr(p, name) for p in parts]).reshape(shape)
              for name in CyclePeaks.__dataclass_fields__ if getattr(parts[0], name) is not None}
    return CyclePeaks(pressure_max=fields.pop("pressure_max", None), **fields)


def _specials(d: Designs) -> tuple[np.ndarray, np.ndarray]:
    """cos β, sin β at φ = 0, φ = π + θ (dead points) and at ψ = 0 (β = ±π/2), shape (d, 4)."""
    ratio = d.crank / d.frame                      # sin(θ/2)
    cos_half = np.sqrt(1.0 - ratio ** 2)
    zero, one = np.zeros_like(ratio), np.ones_like(ratio)
    return (np.stack([-cos_half, cos_half, zero, zero], axis=-1),
            np.stack([-ratio, -ratio, one, -one], axis=-1))


def _ram_curves(beta, quantity, crank, frame, lever, guide, rod, *, side):
    """(value, slope d/dβ, the slope's d/dβ) of dCx/dφ, −dCx/dφ or |d²Cx/dφ²| (``quantity``
    0, 1, 2) at β, for Newton's method on the slope (:func:`core.linkage.polish.newton_maximum`)."""
    d = Designs(crank, frame, lever, guide, None if side is None else rod,
                "trailing" if side is None else side)
    ram1, ram2, ram3, ram4 = rates4_at(d, np.cos(beta), np.sin(beta))
    # Quantity 0: dCx/dφ; 1: −dCx/dφ; 2: |d²Cx/dφ²|. d/dβ = −d/dφ.
    sign = np.where(quantity == 0, 1.0, np.where(quantity == 1, -1.0, 0.0))
    size = np.where(quantity == 2, np.sign(ram2), 0.0)
    return (sign * ram1 + size * ram2, -sign * ram2 - size * ram3, sign * ram3 + size * ram4)


def _chunk_peaks(d: Designs) -> CyclePeaks:
    col = d.column()
    special_cos, special_sin = _specials(d)
    pressure = None
    crowd = np.zeros(d.crank.shape, dtype=bool)
    at = shape_at(col, np.zeros((1, 4)), special_cos, special_sin)
    origin = at.ram_joint[0][:, 0]                   # the first sharp angle is φ = 0
    if d.rod is not None:
        pressure = pressure_angle(at.rod).max(axis=-1)
        crowd = np.abs(np.cos(at.rod)).min(axis=-1) < CROWD_BELOW      # r/L4 = |cos λ|
    fine = d.crank / d.frame > FINE_ABOVE
    peaks = np.empty((3,) + d.crank.shape)
    at_beta = np.empty((3,) + d.crank.shape)
    ram1 = np.empty(d.crank.shape + (SAMPLES,))
    for dense in (False, True):
        for crowded in (False, True):
            group = (fine == dense) & (crowd == crowded)
            if group.any():
                specials = (special_cos[group], special_sin[group]) if crowded else None
                peaks[:, group], at_beta[:, group], ram1[group] = \
                    _ram_peaks(d.take(group), dense, specials)
    start, end = _dead_points(d, ram1)
    # Positions at the dead points, from the φ = 0 position (the displacement's zero).
    phi = np.stack([start, end], axis=-1)
    beta_ends = math.pi + (d.theta / 2.0)[:, None] - phi
    ends = shape_at(col, phi, np.cos(beta_ends), np.sin(beta_ends))
    x_ends = ends.ram_joint[0] - origin[:, None]
    lever1, lever2 = lever_peaks(d.crank / d.frame)
    at_phi = np.mod(math.pi + d.theta / 2.0 - at_beta[:2], 2.0 * math.pi)
    return CyclePeaks(work_start=start, work_end=end, ram_min_mm=x_ends.min(axis=-1),
                      ram_max_mm=x_ends.max(axis=-1), v_work=peaks[0], v_return=peaks[1],
                      v_work_at=at_phi[0], v_return_at=at_phi[1],
                      a_max=peaks[2], lever1_max=lever1, lever2_max=lever2,
                      pressure_max=pressure)


def _ram_peaks(d: Designs, fine: bool, specials) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Max dCx/dφ, max −dCx/dφ and max |d²Cx/dφ²| (3, designs), the crank directions β
    where they lie (3, designs), and dCx/dφ at the uniform samples ``_BETA``. ``fine`` samples four times as densely (every fourth sample
    is one of ``_BETA``); with ``specials`` (cos β, sin β of the sharp angles) samples also
    crowd toward those angles."""
    col = d.column()
    uniform = _BETA_FINE if fine else _BETA
    samples = [shared_rates(col, np.cos(uniform), np.sin(uniform))]
    segments = [(0, uniform.size, 2.0 * math.pi)]
    beta = [np.broadcast_to(uniform, samples[0].ram1.shape)]
    if specials is not None:
        # Crowded samples: β = β_s + δ with cos/sin by angle addition (exact at δ = 0).
        special_cos, special_sin = specials
        cd, sd = np.cos(_OFFSETS), np.sin(_OFFSETS)
        base = np.arctan2(special_sin, special_cos)
        for j in range(4):
            c0, s0 = special_cos[:, j:j + 1], special_sin[:, j:j + 1]
            samples.append(rates_at(col, c0 * cd - s0 * sd, s0 * cd + c0 * sd))
            start = uniform.size + j * _OFFSETS.size
            segments.append((start, start + _OFFSETS.size, 0.0))
            beta.append(base[:, j:j + 1] + _OFFSETS)
    rates = samples[0] if len(samples) == 1 else \
        type(samples[0])(*(np.concatenate(v, axis=-1) for v in zip(*samples)))
    quantity = np.arange(3.0)[:, None, None]
    # As _ram_curves, all at once, each written in its row: dCx/dφ, −dCx/dφ, |d²Cx/dφ²|
    # (= sign·d²Cx/dφ², bit for bit) and their slopes d/dβ.
    values, slopes = np.empty((3,) + rates.ram1.shape), np.empty((3,) + rates.ram1.shape)
    values[0], slopes[1] = rates.ram1, rates.ram2
    np.negative(rates.ram1, out=values[1])
    np.abs(rates.ram2, out=values[2])
    np.negative(rates.ram2, out=slopes[0])
    np.multiply(np.sign(rates.ram2), rates.ram3, out=slopes[2])
    np.negative(slopes[2], out=slopes[2])
    args = (quantity,) + tuple(v[None] for v in (col.crank, col.frame, col.lever, col.guide,
                                                 col.crank if d.rod is None else col.rod))
    side = None if d.rod is None else d.rod_side
    x = np.concatenate(beta, axis=-1)[None] if len(beta) > 1 else uniform
    peaks, where = grid_argmax(lambda t, *a: _ram_curves(t, *a, side=side), x, values, slopes,
                               args=args, segments=segments, newton=True)
    return peaks, where, samples[0].ram1[..., ::4] if fine else samples[0].ram1


# Share the lever tip's terms only where designs repeat L1, L2, L3 this often at least:
# gathering them costs a pass per term, computing them a few dozen.
SHARE_BELOW = 0.25


def shared_rates(col: Designs, cos_beta: np.ndarray, sin_beta: np.ndarray) -> Rates:
    """:func:`~core.linkage.rates.rates_at` of designs ``col`` (shape (n, 1)) at samples shared
    by all of them, the lever tip's terms computed once per distinct (L1, L2, L3).

    A sweep of the rod and the guide, the usual question once K and the stroke are fixed,
    has one lever for all its designs: the tip's terms are then half the grid's arithmetic.
    The same operations on the same numbers: the result is that of ``rates_at``, bit for bit.
    """
    keys = [col.crank[:, 0], col.frame[:, 0], col.lever[:, 0]]
    n = keys[0].size
    if n * SHARE_BELOW < 2.0:                       # one design (analyze) or a handful
        return rates_at(col, cos_beta, sin_beta)
    order = np.lexsort(keys[::-1])
    new = np.ones(n, dtype=bool)
    for key in keys:
        ranked = key[order]
        new[1:] &= ranked[1:] == ranked[:-1]
    new = ~new
    new[:1] = True
    if np.count_nonzero(new) > SHARE_BELOW * n:
        return rates_at(col, cos_beta, sin_beta)
    first = order[new]                              # one design per distinct lever
    group = np.empty(n, dtype=np.intp)
    group[order] = np.cumsum(new) - 1
    tip, bx3, d3 = tip_rates(col.take(first), cos_beta, sin_beta)
    if first.size == 1:                             # views: nothing is copied
        spread = lambda v: np.broadcast_to(v, v.shape[:-2] + (n, v.shape[-1]))  # noqa: E731
    else:
        spread = lambda v: v[..., group, :]  # noqa: E731
    tip = type(tip)(*(spread(v) for v in tip))
    return ram_rates(col, tip, spread(bx3), spread(d3))


def _dead_points(d: Designs, ram1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Crank angles (rad, in [0, 2π)) of the ram's two dead points, measured.

    Each zero of dCx/dφ is bracketed between uniform samples and polished as a
    root of the closed-form velocity. A design whose ram does not reverse
    exactly twice gets NaN.
    """
    # β grows as φ falls: the working stroke starts where dCx/dφ turns from − to + in φ,
    # i.e. from + to − in β.
    nxt = np.roll(ram1, -1, axis=-1)
    starts = (ram1 > 0) & (nxt <= 0)
    ends = (ram1 < 0) & (nxt >= 0)
    good = (starts.sum(axis=-1) == 1) & (ends.sum(axis=-1) == 1)
    lo = _BETA[np.stack([np.argmax(starts, axis=-1), np.argmax(ends, axis=-1)], axis=-1)]
    col = d.column()
    args = [np.broadcast_to(v, lo.shape).reshape(-1)
            for v in (col.crank, col.frame, col.lever, col.guide,
                      col.crank if d.rod is None else col.rod)]

    def rate(beta, crank, frame, lever, guide, rod):
        one = Designs(crank, frame, lever, guide, None if d.rod is None else rod, d.rod_side)
        return ram_velocity(one, np.cos(beta), np.sin(beta))

    # The closed form puts the dead points where the lever stands square to the crank
    # (β = π + θ/2 and −θ/2): a tight bracket there is used when the velocity does change
    # sign across it, else the grid's cell.
    guess = np.mod(np.stack([math.pi + d.theta / 2.0, -d.theta / 2.0], axis=-1), 2.0 * math.pi)
    near = (guess >= lo) & (guess <= lo + _STEP)
    width = 1e-9 * (1.0 + guess)
    a, b = np.where(near, guess - width, lo), np.where(near, guess + width, lo + _STEP)
    f_a, f_b = rate(a.reshape(-1), *args), rate(b.reshape(-1), *args)
    tight = near.reshape(-1) & (np.sign(f_a) != np.sign(f_b))
    a = np.where(tight, a.reshape(-1), lo.reshape(-1))
    b = np.where(tight, b.reshape(-1), (lo + _STEP).reshape(-1))
    wide = np.flatnonzero(~tight)                   # the grid's cells: evaluate their ends
    if wide.size:
        sub = [v[wide] for v in args]
        f_a[wide], f_b[wide] = rate(a[wide], *sub), rate(b[wide], *sub)
    beta = bracket_root(rate, a, b, args, f_lo=f_a, f_hi=f_b).reshape(lo.shape)
    phi = np.mod(math.pi + (d.theta / 2.0)[:, None] - beta, 2.0 * math.pi)
    phi = np.where(good[:, None], phi, np.nan)
    return phi[:, 0], phi[:, 1]


def lever_peaks(ratio: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Largest |dψ/dφ| and |d²ψ/dφ²| of the slotted lever, in closed form.

    With λ = L1/L2 and u = sin β, dψ/dφ = λ(λ + u)/q and |d²ψ/dφ²| =
    λ(1 − λ²)|cos β|/q², q = 1 + λ² + 2λu. The first is monotonic in u, largest
    in size at u = −1 (crank pin between O2 and O4): λ/(1 − λ). The second is
    largest where 2λu² − (1 + λ²)u − 4λ = 0, at the root in [−1, 0].
    """
    lam = np.asarray(ratio, dtype=float)
    a = 1.0 + lam ** 2
    u = -8.0 * lam / (a + np.sqrt(a ** 2 + 32.0 * lam ** 2))
    q = a + 2.0 * lam * u
    return lam / (1.0 - lam), lam * (1.0 - lam ** 2) * np.sqrt(1.0 - u ** 2) / q ** 2


def speed_figures(peaks: CyclePeaks, omega: np.ndarray) -> dict[str, np.ndarray]:
    """Per-speed figures of many designs: arrays of shape designs + (speeds,), SI units."""
    w = np.asarray(omega, dtype=float)
    work = peaks.work_angle[..., None]
    back = 2.0 * math.pi - work
    return {
        "cycle_time_s": np.broadcast_to(2.0 * math.pi / w, work.shape[:-1] + w.shape),
        "work_time_s": work / w, "return_time_s": back / w,
        "v_work_max_m_s": w * peaks.v_work[..., None] / 1000.0,
        "v_return_max_m_s": w * peaks.v_return[..., None] / 1000.0,
        "v_work_mean_m_s": peaks.stroke_mm[..., None] / 1000.0 / (work / w),
        "a_max_m_s2": w * w * peaks.a_max[..., None] / 1000.0,
        "lever_omega_max_rad_s": w * peaks.lever1_max[..., None],
        "lever_alpha_max_rad_s2": w * w * peaks.lever2_max[..., None],
    }


def analyze(design: Design, rpms) -> CycleMetrics:
    """Cycle metrics of one design: :func:`cycle_peaks` and :func:`speed_figures` on it."""
    rpm = check_rpms(rpms)
    peaks = cycle_peaks(Designs.of(design))
    if not np.isfinite(peaks.work_start[0]):
        raise RuntimeError("the ram does not have exactly two dead points")
    figures = speed_figures(peaks, rpm_to_omega(rpm))
    speeds = tuple(SpeedMetrics(rpm=float(r), **{k: float(v[0, i]) for k, v in figures.items()})
                   for i, r in enumerate(rpm))
    start, end = float(peaks.work_start[0]), float(peaks.work_end[0])
    work = float(peaks.work_angle[0])
    pressure = None if peaks.pressure_max is None else math.degrees(float(peaks.pressure_max[0]))
    return CycleMetrics(
        theta_deg=math.degrees(design.theta), time_ratio=float(peaks.time_ratio[0]),
        stroke_mm=float(peaks.stroke_mm[0]),
        work_angle_deg=math.degrees(work), return_angle_deg=math.degrees(2.0 * math.pi - work),
        work_start_deg=_signed_deg(start), work_end_deg=math.degrees(end),
        ram_min_mm=float(peaks.ram_min_mm[0]), ram_max_mm=float(peaks.ram_max_mm[0]),
        pressure_angle_max_deg=pressure, speeds=speeds,
    )


def _signed_deg(angle: float) -> float:
    """Report a limit just below 360° as a small negative angle."""
    deg = math.degrees(angle)
    return deg - 360.0 if deg > 180.0 else deg
