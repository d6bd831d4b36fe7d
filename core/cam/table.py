"""A cam's rows per cam angle and its key figures, with units in every name (for the CSV,
the JSON and the GUI's export alike)."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from .cam import Cam
from .follower import pitch, pressure_angle, profile

CAM_COLUMNS = ("cam_angle_deg", "follower_angle_deg", "follower_omega_rad_s",
               "follower_alpha_rad_s2", "pressure_angle_deg", "pitch_x_mm", "pitch_y_mm",
               "profile_x_mm", "profile_y_mm")


def cam_table(cam: Cam, delta: np.ndarray, rpm: float) -> tuple[tuple[str, ...], np.ndarray]:
    """One row per cam angle ``delta`` (rad) at the crank (and cam) speed ``rpm`` (r/min):
    the follower's angle from its lowest position, its angular velocity and acceleration
    (positive outward), the pressure angle, and the pitch and profile points in the cam's
    frame."""
    omega = rpm * 2.0 * math.pi / 60.0
    p = pitch(cam.follower, cam.program, delta)
    q = profile(p, cam.roller_mm)
    m = p.motion
    data = np.column_stack([np.degrees(delta), np.degrees(m.psi), m.psi1 * omega,
                            m.psi2 * omega ** 2, np.degrees(pressure_angle(cam.follower, p)),
                            p.point[0], p.point[1], q[0], q[1]])
    return CAM_COLUMNS, data


def cam_summary(cam: Cam) -> dict[str, Any]:
    """The cam's figures: the synthesized (or checked) geometry, the pressure angles, the
    curvature and the roller, and the timing against the linkage if there is one."""
    f, inputs, prog = cam.follower, cam.inputs, cam.program
    doc: dict[str, Any] = {
        "base_radius_mm": cam.base_radius_mm,
        "center_distance_mm": f.distance_mm,
        "arm_mm": f.arm_mm,
        "initial_angle_deg": f.initial_deg,
        "arm_side": "above" if f.side > 0 else "below",
        "cam_turns": "clockwise",
        "synthesized": inputs.base_mm is None,
        "max_pressure_angle_rise_deg": cam.max_pressure_rise_deg,
        "max_pressure_angle_return_deg": cam.max_pressure_return_deg,
        "allowed_pressure_angle_rise_deg": inputs.pressure_deg,
        "allowed_pressure_angle_return_deg": inputs.return_pressure_deg,
        "within_allowance": cam.within_allowance,
        "min_curvature_radius_mm": cam.min_curvature_radius_mm,
        "roller_mm": cam.roller_mm,
        "largest_roller_mm": cam.largest_roller_mm,
        "profile_base_radius_mm": cam.profile_min_radius_mm,
        "profile_max_radius_mm": cam.profile_max_radius_mm,
        "pitch_max_radius_mm": cam.pitch_max_radius_mm,
        "hub_mm": inputs.hub_mm, "boss_mm": inputs.boss_mm, "clearance_mm": inputs.clearance_mm,
        "base_raised_from_mm": cam.base_raised_from_mm,
        "swing_deg": prog.swing_deg,
        "rise_deg": prog.rise_deg, "outer_dwell_deg": prog.dwell_deg,
        "return_deg": prog.return_deg, "inner_dwell_deg": prog.inner_dwell_deg,
        "rise_law": prog.rise_law, "return_law": prog.return_law,
    }
    if cam.timing is not None:
        doc.update(phase_deg=cam.timing.phase_deg, cut_end_deg=cam.timing.clear_from_deg,
                   clear_span_deg=cam.timing.clear_span_deg)
    return doc


def follower_peaks(cam: Cam, rpm: float) -> dict[str, float]:
    """The follower's largest angular velocity and acceleration at ``rpm`` (r/min), from the
    laws' closed-form peaks (``Program.peaks``; the dwells are at rest)."""
    omega = rpm * 2.0 * math.pi / 60.0
    speed, acceleration = cam.program.peaks()
    return {"rpm": float(rpm), "follower_omega_max_rad_s": speed * omega,
            "follower_alpha_max_rad_s2": acceleration * omega ** 2}
