"""Translated titles of the table columns and special positions, shared by the
Positions tab and the design report (one table of names, not two)."""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication

translate = QCoreApplication.translate   # lupdate extracts translate("Context", "text")


def yes_no(flag: bool) -> str:
    """A yes/no value in a table (the ram tilted, a gear undercut), in the UI's language."""
    return translate("Columns", "yes") if flag else translate("Columns", "no")


def column_titles() -> dict[str, str]:
    """CSV column name → short title with symbol and unit (course notation)."""
    return {
        "rpm": translate("Columns", "n (r/min)"),
        "crank_deg": translate("Columns", "φ (°)"),
        "time_s": translate("Columns", "t (s)"),
        "ram_x_mm": translate("Columns", "ram x (mm)"),
        "ram_v_m_s": translate("Columns", "ram v (m/s)"),
        "ram_a_m_s2": translate("Columns", "ram a (m/s²)"),
        "lever_deg": translate("Columns", "lever ψ (°)"),
        "lever_omega_rad_s": translate("Columns", "lever ω4 (rad/s)"),
        "lever_alpha_rad_s2": translate("Columns", "lever α4 (rad/s²)"),
        "slide_v_m_s": translate("Columns", "block v_A3A4 (m/s)"),
        "coriolis_m_s2": translate("Columns", "Coriolis a^k (m/s²)"),
        "rod_deg": translate("Columns", "rod λ (°)"),
        "rod_omega_rad_s": translate("Columns", "rod ω5 (rad/s)"),
        "rod_alpha_rad_s2": translate("Columns", "rod α5 (rad/s²)"),
        "pressure_angle_deg": translate("Columns", "pressure angle (°)"),
        "crank_torque_N_m": translate("Columns", "crank torque M (N·m)"),
        "power_W": translate("Columns", "power (W)"),
        "O2_x_N": translate("Columns", "O2 x (N)"), "O2_y_N": translate("Columns", "O2 y (N)"),
        "pin_A_x_N": translate("Columns", "pin A x (N)"), "pin_A_y_N": translate("Columns", "pin A y (N)"),
        "A_x_N": translate("Columns", "A x (N)"), "A_y_N": translate("Columns", "A y (N)"),
        "A_normal_N": translate("Columns", "A normal (N)"),
        "O4_x_N": translate("Columns", "O4 x (N)"), "O4_y_N": translate("Columns", "O4 y (N)"),
        "B_x_N": translate("Columns", "B x (N)"), "B_y_N": translate("Columns", "B y (N)"),
        "C_x_N": translate("Columns", "C x (N)"), "C_y_N": translate("Columns", "C y (N)"),
        "guide_normal_N": translate("Columns", "guide N (N)"),
        "guide_moment_N_m": translate("Columns", "guide moment (N·m)"),
        "guide_offset_mm": translate("Columns", "N offset (mm)"),
        "guide_rear_N": translate("Columns", "guide rear end (N)"),
        "guide_front_N": translate("Columns", "guide front end (N)"),
        "guide_tilted": translate("Columns", "ram tilted on the guide ends"),
        "cut_force_N": translate("Columns", "cutting force P (N)"),
    }


def special_titles() -> dict[str, str]:
    """Special position name → translated description."""
    return {
        "limit_work_start": translate("Columns", "limit position, start of working stroke"),
        "limit_work_end": translate("Columns", "limit position, end of working stroke"),
        "cut_start": translate("Columns", "cut starts (cutting)"),
        "cut_end": translate("Columns", "cut ends (cutting)"),
        "v_work_max": translate("Columns", "max cutting speed"),
        "v_return_max": translate("Columns", "max return speed"),
    }


def group_titles() -> dict[str, str]:
    """``core.course_design.positions.COLUMN_GROUPS`` name → translated heading."""
    return {"ram": translate("Columns", "Ram"), "lever": translate("Columns", "Lever and block"), "rod": translate("Columns", "Connecting rod"),
            "torque": translate("Columns", "Crank torque, cutting force and guide"),
            "joints_crank": translate("Columns", "Joint forces at O2 and A"),
            "joints_lever": translate("Columns", "Joint forces at O4, B and C")}
