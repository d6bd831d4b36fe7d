"""The sheets' words in the user's language: core.drawing lays out, this names.

Each function returns the mapping a ``core.drawing`` layout takes (its keys are
those of the layout's English table), translated through Qt's catalogue.
"""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication


def _t(text: str) -> str:
    return QCoreApplication.translate("Drawing", text)


def title_labels() -> dict[str, str]:
    """The title block's labels (GB/T 10609.1)."""
    return {"design": _t("Design"), "scale": _t("Scale"), "sheet": _t("Sheet"),
            "drawn": _t("Drawn"), "date": _t("Date"), "checked": _t("Checked"),
            "approved": _t("Approved")}


def motion_labels() -> dict[str, str]:
    """Every text of the motion sheet (``core.drawing.motion.ENGLISH``'s keys)."""
    return {
        **title_labels(),
        "title": _t("Motion analysis"),
        "mechanism": _t("Kinematic diagram at {count} positions, μl = {mu} m/mm ({scale})"),
        "curves": _t("Ram displacement, velocity and acceleration, n = {rpm} r/min"),
        "s": _t("s/mm"), "v": _t("v/(m/s)"), "a": _t("a/(m/s²)"), "phi": _t("φ/(°)"),
        "mu_s": _t("μs = {mu} m/mm"), "mu_v": _t("μv = {mu} (m/s)/mm"),
        "mu_a": _t("μa = {mu} (m/s²)/mm"), "mu_phi": _t("μφ = {mu} °/mm"),
        "velocity": _t("Velocity polygon, φ = {angle}°, μv = {mu} (m/s)/mm"),
        "acceleration": _t("Acceleration polygon, φ = {angle}°, μa = {mu} (m/s²)/mm"),
        "dimensions": _t("Main dimensions"), "quantity": _t("Quantity"), "value": _t("Value"),
        "L1": _t("Crank O2A, L1"), "L2": _t("Frame O2O4, L2"), "L3": _t("Lever O4B, L3"),
        "L4": _t("Rod BC, L4"), "h": _t("Guide above O2, h"), "H": _t("Stroke H"),
        "K": _t("Time ratio K"), "theta": _t("Extreme-position angle θ"), "n": _t("Crank speed n"),
    }
