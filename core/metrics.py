"""Cycle metrics measured from the motion itself, not echoed from the inputs.

The third level of core. Limit positions are found as the zeros of the ram
velocity (sign changes on a dense grid, refined with Brent's method on the
closed-form velocity), so a measured K or stroke that disagrees with the
design's nominal values exposes a fault in the kinematics.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .geometry import Design
from .kinematics import check_rpms, pressure_angle, ram_origin, rpm_to_omega, shape

GRID = 7200


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


def limit_angles(design: Design) -> tuple[float, float]:
    """Crank angles (rad, in [0, 2π)) where the ram is at its two dead points.

    Returns (start of the working stroke, end of the working stroke). Each
    zero of dC/dφ is bracketed on a grid and polished by Newton steps on the
    closed-form second derivative, kept inside its bracket.
    """
    step = 2.0 * math.pi / GRID
    phi = (np.arange(GRID) + 0.5) * step - math.pi / 4.0  # no grid point on a limit
    rate = shape(design, phi).ram1
    nxt = np.roll(rate, -1)
    starts = np.nonzero((rate < 0) & (nxt >= 0))[0]
    ends = np.nonzero((rate > 0) & (nxt <= 0))[0]
    if starts.size != 1 or ends.size != 1:
        raise RuntimeError("the ram does not have exactly two dead points")
    low = phi[[starts[0], ends[0]]]
    high = low + step
    x = (low + high) / 2.0
    for _ in range(30):
        sh = shape(design, x)
        nxt_x = np.clip(x - sh.ram1 / sh.ram2, low, high)
        if np.all(np.abs(nxt_x - x) < 1e-15):
            break
        x = nxt_x
    start, end = (float(v) % (2.0 * math.pi) for v in x)
    return start, end


def analyze(design: Design, rpms) -> CycleMetrics:
    rpm = check_rpms(rpms)
    start, end = limit_angles(design)
    work = (end - start) % (2.0 * math.pi)
    back = 2.0 * math.pi - work
    ends = shape(design, np.array([start, end]))
    x_min, x_max = (float(v) for v in ends.ram_joint[0])
    origin = ram_origin(design)

    phi = np.linspace(0.0, 2.0 * math.pi, GRID, endpoint=False)
    sh = shape(design, phi)
    in_work = ((phi - start) % (2.0 * math.pi)) <= work
    v_work = float(sh.ram1[in_work].max())
    v_back = float(np.abs(sh.ram1[~in_work]).max())
    a_max = float(np.abs(sh.ram2).max())
    lever1 = float(np.abs(sh.lever1).max())
    lever2 = float(np.abs(sh.lever2).max())
    pressure = None
    if sh.rod is not None:
        pressure = math.degrees(float(pressure_angle(sh.rod).max()))
    stroke = x_max - x_min

    speeds = []
    for r, w in zip(rpm, rpm_to_omega(rpm)):
        w = float(w)
        speeds.append(SpeedMetrics(
            rpm=float(r), cycle_time_s=2.0 * math.pi / w,
            work_time_s=work / w, return_time_s=back / w,
            v_work_max_m_s=w * v_work / 1000.0, v_return_max_m_s=w * v_back / 1000.0,
            v_work_mean_m_s=stroke / 1000.0 / (work / w),
            a_max_m_s2=w * w * a_max / 1000.0,
            lever_omega_max_rad_s=w * lever1, lever_alpha_max_rad_s2=w * w * lever2,
        ))
    return CycleMetrics(
        theta_deg=math.degrees(design.theta), time_ratio=work / back, stroke_mm=stroke,
        work_angle_deg=math.degrees(work), return_angle_deg=math.degrees(back),
        work_start_deg=_signed_deg(start), work_end_deg=math.degrees(end),
        ram_min_mm=x_min - origin, ram_max_mm=x_max - origin,
        pressure_angle_max_deg=pressure, speeds=tuple(speeds),
    )


def _signed_deg(angle: float) -> float:
    """Report a limit just below 360° as a small negative angle."""
    deg = math.degrees(angle)
    return deg - 360.0 if deg > 180.0 else deg
