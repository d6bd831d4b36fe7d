"""Translated names of core's key figures (``core.space.figures``), shared by the library
pane and the compare view so a figure is called the same everywhere."""
from __future__ import annotations

import math

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from core.base.figure_text import figure_kind, figure_text

_LABELS = {
    "name": QT_TRANSLATE_NOOP("figures", "Name"),
    "notes": QT_TRANSLATE_NOOP("figures", "Notes"),
    "tags": QT_TRANSLATE_NOOP("figures", "Tags"),
    "created": QT_TRANSLATE_NOOP("figures", "Created (UTC)"),
    "modified": QT_TRANSLATE_NOOP("figures", "Modified (UTC)"),
    "variant": QT_TRANSLATE_NOOP("figures", "Variant"),
    "rod_side": QT_TRANSLATE_NOOP("figures", "Rod side"),
    "K": QT_TRANSLATE_NOOP("figures", "K"),
    "stroke_mm": QT_TRANSLATE_NOOP("figures", "H (mm)"),
    "theta_deg": QT_TRANSLATE_NOOP("figures", "θ (°)"),
    "crank_mm": QT_TRANSLATE_NOOP("figures", "L1 (mm)"),
    "frame_mm": QT_TRANSLATE_NOOP("figures", "L2 (mm)"),
    "lever_mm": QT_TRANSLATE_NOOP("figures", "L3 (mm)"),
    "rod_mm": QT_TRANSLATE_NOOP("figures", "L4 (mm)"),
    "guide_mm": QT_TRANSLATE_NOOP("figures", "Guide (mm)"),
    "pressure_angle_max_deg": QT_TRANSLATE_NOOP("figures", "Max pressure angle (°)"),
    "rpm": QT_TRANSLATE_NOOP("figures", "Speed (r/min)"),
    "v_work_max_m_s": QT_TRANSLATE_NOOP("figures", "Max cutting speed (m/s)"),
    "v_work_mean_m_s": QT_TRANSLATE_NOOP("figures", "Mean cutting speed (m/s)"),
    "v_return_max_m_s": QT_TRANSLATE_NOOP("figures", "Max return speed (m/s)"),
    "a_max_m_s2": QT_TRANSLATE_NOOP("figures", "Max |a| (m/s²)"),
    "mean_torque_N_m": QT_TRANSLATE_NOOP("figures", "Mean torque (N·m)"),
    "max_torque_N_m": QT_TRANSLATE_NOOP("figures", "Peak torque (N·m)"),
    "flywheel_inertia_kg_m2": QT_TRANSLATE_NOOP("figures", "Flywheel J_F (kg·m²)"),
}
_TIPS = {
    "K": QT_TRANSLATE_NOOP("figures", "Time ratio K, measured from the motion"),
    "stroke_mm": QT_TRANSLATE_NOOP("figures", "Ram stroke H, measured from the motion"),
    "theta_deg": QT_TRANSLATE_NOOP("figures", "Extreme-position angle θ"),
    "crank_mm": QT_TRANSLATE_NOOP("figures", "Crank O2A"),
    "frame_mm": QT_TRANSLATE_NOOP("figures", "Frame O2O4"),
    "lever_mm": QT_TRANSLATE_NOOP("figures", "Lever O4B"),
    "rod_mm": QT_TRANSLATE_NOOP("figures", "Connecting rod BC (rod variant)"),
    "guide_mm": QT_TRANSLATE_NOOP("figures", "Ram guide line above the lever pivot O4"),
    "pressure_angle_max_deg": QT_TRANSLATE_NOOP(
        "figures", "Largest pressure angle at the ram (rod variant); lower is better"),
    "a_max_m_s2": QT_TRANSLATE_NOOP("figures", "Largest |ram acceleration| over the cycle; lower is better"),
    "mean_torque_N_m": QT_TRANSLATE_NOOP("figures", "Mean crank torque (needs loads); lower is better"),
    "max_torque_N_m": QT_TRANSLATE_NOOP("figures", "Peak crank torque (needs loads); lower is better"),
    "flywheel_inertia_kg_m2": QT_TRANSLATE_NOOP(
        "figures", "Flywheel inertia on the crank shaft (needs loads); lower is better"),
}
_WORDS = {
    "block": QT_TRANSLATE_NOOP("figures", "block"),
    "rod": QT_TRANSLATE_NOOP("figures", "rod"),
    "trailing": QT_TRANSLATE_NOOP("figures", "trailing"),
    "leading": QT_TRANSLATE_NOOP("figures", "leading"),
}


def _tr(text: str) -> str:
    return QCoreApplication.translate("figures", text)


def figure_label(key: str) -> str:
    """A short column or row title with its unit, e.g. ``Max |a| (m/s²)``."""
    return _tr(_LABELS[key]) if key in _LABELS else key


def figure_tip(key: str) -> str:
    """A longer explanation for tooltips."""
    return _tr(_TIPS[key]) if key in _TIPS else figure_label(key)


def variant_label(value: str | None) -> str:
    return _tr(_WORDS[value]) if value in _WORDS else (value or "—")


def format_figure(key: str, value: object) -> str:
    """A figure as shown in tables: fixed decimals per kind, ``—`` when there is none."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "—"
    if isinstance(value, str):
        return variant_label(value) if key in ("variant", "rod_side") else value
    if key == "rpm":
        return f"{value:g}"
    return figure_text(figure_kind(key), float(value))
