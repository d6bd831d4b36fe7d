"""Translated titles of the table columns and special positions, shared by the
Positions tab and the design report (one table of names, not two)."""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication


def _tr(text: str) -> str:
    return QCoreApplication.translate("Columns", text)


def column_titles() -> dict[str, str]:
    """CSV column name → short title with symbol and unit (course notation)."""
    return {
        "rpm": _tr("n (r/min)"),
        "crank_deg": _tr("φ (°)"),
        "time_s": _tr("t (s)"),
        "ram_x_mm": _tr("ram x (mm)"),
        "ram_v_m_s": _tr("ram v (m/s)"),
        "ram_a_m_s2": _tr("ram a (m/s²)"),
        "lever_deg": _tr("lever ψ (°)"),
        "lever_omega_rad_s": _tr("lever ω3 (rad/s)"),
        "lever_alpha_rad_s2": _tr("lever α3 (rad/s²)"),
        "slide_v_m_s": _tr("block v_A2A3 (m/s)"),
        "coriolis_m_s2": _tr("Coriolis a^k (m/s²)"),
        "rod_deg": _tr("rod λ (°)"),
        "rod_omega_rad_s": _tr("rod ω4 (rad/s)"),
        "rod_alpha_rad_s2": _tr("rod α4 (rad/s²)"),
        "pressure_angle_deg": _tr("pressure angle (°)"),
        "crank_torque_N_m": _tr("crank torque M (N·m)"),
        "power_W": _tr("power (W)"),
        "O2_x_N": _tr("O2 x (N)"), "O2_y_N": _tr("O2 y (N)"),
        "pin_A_x_N": _tr("pin A x (N)"), "pin_A_y_N": _tr("pin A y (N)"),
        "A_x_N": _tr("A x (N)"), "A_y_N": _tr("A y (N)"),
        "A_normal_N": _tr("A normal (N)"),
        "O4_x_N": _tr("O4 x (N)"), "O4_y_N": _tr("O4 y (N)"),
        "B_x_N": _tr("B x (N)"), "B_y_N": _tr("B y (N)"),
        "C_x_N": _tr("C x (N)"), "C_y_N": _tr("C y (N)"),
        "guide_normal_N": _tr("guide N (N)"),
        "guide_moment_N_m": _tr("guide moment (N·m)"),
        "guide_offset_mm": _tr("N offset (mm)"),
        "cut_force_N": _tr("cutting force P (N)"),
    }


def special_titles() -> dict[str, str]:
    """Special position name → translated description."""
    return {
        "limit_work_start": _tr("limit position, start of working stroke"),
        "limit_work_end": _tr("limit position, end of working stroke"),
        "cut_start": _tr("cut starts"),
        "cut_end": _tr("cut ends"),
        "v_work_max": _tr("max cutting speed"),
        "v_return_max": _tr("max return speed"),
    }


def group_titles() -> dict[str, str]:
    """``core.positions.COLUMN_GROUPS`` name → translated heading."""
    return {"ram": _tr("Ram"), "lever": _tr("Lever and block"), "rod": _tr("Connecting rod"),
            "torque": _tr("Crank torque, cutting force and guide"),
            "joints_crank": _tr("Joint forces at O2 and A"),
            "joints_lever": _tr("Joint forces at O4, B and C")}
