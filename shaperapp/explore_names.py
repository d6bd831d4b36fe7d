"""The Explore tab's names of figures and parameters, translated (context "ExploreView",
the tab's own, so the catalogue keeps its entries)."""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication

translate = QCoreApplication.translate   # lupdate extracts translate("Context", "text")


def figure_names() -> dict[str, str]:
    return {"pressure-angle": translate("ExploreView", "Max pressure angle (°)"),
            "accel": translate("ExploreView", "Max |acceleration|, fastest speed (m/s²)"),
            "v-work": translate("ExploreView", "Max cutting speed, fastest speed (m/s)"),
            "v-return": translate("ExploreView", "Max return speed, fastest speed (m/s)"),
            "peak-torque": translate("ExploreView", "Peak crank torque, worst speed (N·m)"),
            "flywheel": translate("ExploreView", "Flywheel J_F, slowest speed (kg·m²)")}


def figure_titles() -> dict[str, str]:
    """Short titles of the figures, for the colour bar beside the map."""
    return {"pressure-angle": translate("ExploreView", "pressure angle (°)"),
            "accel": translate("ExploreView", "max |a| (m/s²)"),
            "v-work": translate("ExploreView", "cutting speed (m/s)"),
            "v-return": translate("ExploreView", "return speed (m/s)"),
            "peak-torque": translate("ExploreView", "peak torque (N·m)"),
            "flywheel": translate("ExploreView", "J_F (kg·m²)")}


def parameter_names() -> dict[str, str]:
    return {"crank": translate("ExploreView", "Crank L1 (mm)"),
            "time_ratio": translate("ExploreView", "Time ratio K"),
            "stroke": translate("ExploreView", "Stroke H (mm)"),
            "frame": translate("ExploreView", "Frame L2 (mm)"),
            "lever": translate("ExploreView", "Lever L3 (mm)"),
            "guide": translate("ExploreView", "Guide above O4 (mm)"),
            "rod_ratio": translate("ExploreView", "Rod ratio L4/L3"),
            "rod": translate("ExploreView", "Rod L4 (mm)")}
