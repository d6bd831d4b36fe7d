"""Translated names of core's key figures (``core.figures``), shared by the library
pane and the compare view so a figure is called the same everywhere."""
from __future__ import annotations

import math

from PySide6.QtCore import QCoreApplication


def figure_label(key: str) -> str:
    """A short column or row title with its unit, e.g. ``Max |a| (m/s²)``."""
    labels = {
        "name": QCoreApplication.translate("figures", "Name"), "notes": QCoreApplication.translate("figures", "Notes"), "tags": QCoreApplication.translate("figures", "Tags"),
        "created": QCoreApplication.translate("figures", "Created (UTC)"), "modified": QCoreApplication.translate("figures", "Modified (UTC)"),
        "variant": QCoreApplication.translate("figures", "Variant"), "rod_side": QCoreApplication.translate("figures", "Rod side"),
        "K": QCoreApplication.translate("figures", "K"), "stroke_mm": QCoreApplication.translate("figures", "H (mm)"), "theta_deg": QCoreApplication.translate("figures", "θ (°)"),
        "crank_mm": QCoreApplication.translate("figures", "L1 (mm)"), "frame_mm": QCoreApplication.translate("figures", "L2 (mm)"), "lever_mm": QCoreApplication.translate("figures", "L3 (mm)"),
        "rod_mm": QCoreApplication.translate("figures", "L4 (mm)"), "guide_mm": QCoreApplication.translate("figures", "Guide (mm)"),
        "pressure_angle_max_deg": QCoreApplication.translate("figures", "Max pressure angle (°)"), "rpm": QCoreApplication.translate("figures", "Speed (r/min)"),
        "v_work_max_m_s": QCoreApplication.translate("figures", "Max cutting speed (m/s)"),
        "v_work_mean_m_s": QCoreApplication.translate("figures", "Mean cutting speed (m/s)"),
        "v_return_max_m_s": QCoreApplication.translate("figures", "Max return speed (m/s)"),
        "a_max_m_s2": QCoreApplication.translate("figures", "Max |a| (m/s²)"),
        "mean_torque_N_m": QCoreApplication.translate("figures", "Mean torque (N·m)"), "max_torque_N_m": QCoreApplication.translate("figures", "Peak torque (N·m)"),
        "flywheel_inertia_kg_m2": QCoreApplication.translate("figures", "Flywheel J_F (kg·m²)"),
    }
    return labels.get(key, key)


def figure_tip(key: str) -> str:
    """A longer explanation for tooltips."""
    tips = {
        "K": QCoreApplication.translate("figures", "Time ratio K, measured from the motion"),
        "stroke_mm": QCoreApplication.translate("figures", "Ram stroke H, measured from the motion"),
        "theta_deg": QCoreApplication.translate("figures", "Extreme-position angle θ"),
        "crank_mm": QCoreApplication.translate("figures", "Crank O2A"), "frame_mm": QCoreApplication.translate("figures", "Frame O2O4"), "lever_mm": QCoreApplication.translate("figures", "Lever O4B"),
        "rod_mm": QCoreApplication.translate("figures", "Connecting rod BC (rod variant)"),
        "guide_mm": QCoreApplication.translate("figures", "Ram guide line above the lever pivot O4"),
        "pressure_angle_max_deg": QCoreApplication.translate("figures", "Largest pressure angle at the ram (rod variant); lower is better"),
        "a_max_m_s2": QCoreApplication.translate("figures", "Largest |ram acceleration| over the cycle; lower is better"),
        "mean_torque_N_m": QCoreApplication.translate("figures", "Mean crank torque (needs loads); lower is better"),
        "max_torque_N_m": QCoreApplication.translate("figures", "Peak crank torque (needs loads); lower is better"),
        "flywheel_inertia_kg_m2": QCoreApplication.translate("figures", "Flywheel inertia on the crank shaft (needs loads); lower is better"),
    }
    return tips.get(key, figure_label(key))


def variant_label(value: str | None) -> str:
    return {"block": QCoreApplication.translate("figures", "block"), "rod": QCoreApplication.translate("figures", "rod"), "trailing": QCoreApplication.translate("figures", "trailing"),
            "leading": QCoreApplication.translate("figures", "leading")}.get(value or "", value or "—")


def format_figure(key: str, value: object) -> str:
    """A figure as shown in tables: fixed decimals per kind, ``—`` when there is none."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "—"
    if isinstance(value, str):
        return variant_label(value) if key in ("variant", "rod_side") else value
    digits = {"K": 4, "theta_deg": 3, "pressure_angle_max_deg": 3, "rpm": 6}.get(key)
    if key.endswith("_m_s") or key.endswith("_m_s2"):
        digits = 4
    if key == "rpm":
        return f"{value:g}"
    if digits is None:
        return f"{value:.5g}" if key in ("flywheel_inertia_kg_m2", "mean_torque_N_m",
                                         "max_torque_N_m") else f"{value:.2f}"
    return f"{value:.{digits}f}"
