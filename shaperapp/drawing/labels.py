"""The sheets' words in the user's language: core.drawing lays out, this names.

Each function returns the mapping a ``core.drawing`` layout takes (its keys are
those of the layout's English table), translated through Qt's catalogue.
"""
from __future__ import annotations


def translate(context: str, text: str) -> str:
    """Qt's translation (lupdate extracts translate("Drawing", "…")), with Qt imported at the
    first label: ``shaper drawing --help`` needs none of it (issue 43 item 5)."""
    from PySide6.QtCore import QCoreApplication
    return QCoreApplication.translate(context, text)


def title_labels() -> dict[str, str]:
    """The title block's labels (GB/T 10609.1)."""
    return {
        "design": translate("Drawing", "Design"), "scale": translate("Drawing", "Scale"),
        "sheet": translate("Drawing", "Sheet"), "drawn": translate("Drawing", "Drawn"),
        "date": translate("Drawing", "Date"), "checked": translate("Drawing", "Checked"),
        "approved": translate("Drawing", "Approved"),
        "number": translate("Drawing", "Number"), "class": translate("Drawing", "Class"),
        "supervisor": translate("Drawing", "Supervisor"),
    }


def motion_labels() -> dict[str, str]:
    """Every text of the motion sheet (``core.drawing.motion.ENGLISH``'s keys)."""
    return {
        **title_labels(),
        "title": translate("Drawing", "Motion analysis"),
        "mechanism": translate("Drawing",
                               "Kinematic diagram at {count} positions, μ_l = {mu} m/mm ({scale})"),
        "curves": translate("Drawing", "Ram displacement, velocity and acceleration, n = {rpm} r/min"),
        "s": translate("Drawing", "s/mm"), "v": translate("Drawing", "v/(m/s)"),
        "a": translate("Drawing", "a/(m/s²)"), "phi": translate("Drawing", "φ/(°)"),
        "mu_s": translate("Drawing", "μ_s = {mu} m/mm"),
        "mu_v": translate("Drawing", "μ_v = {mu} (m/s)/mm"),
        "mu_a": translate("Drawing", "μ_a = {mu} (m/s²)/mm"),
        "mu_phi": translate("Drawing", "μ_φ = {mu} °/mm"),
        "position": translate("Drawing", "Position"),
        "velocity": translate("Drawing", "Velocity polygon, φ = {angle}°, μ_v = {mu} (m/s)/mm"),
        "acceleration": translate("Drawing",
                                  "Acceleration polygon, φ = {angle}°, μ_a = {mu} (m/s²)/mm"),
        "dimensions": translate("Drawing", "Main dimensions"),
        "quantity": translate("Drawing", "Quantity"), "value": translate("Drawing", "Value"),
        "L1": translate("Drawing", "Crank O_2A, L_1"), "L2": translate("Drawing", "Frame O_2O_4, L_2"),
        "L3": translate("Drawing", "Lever O_4B, L_3"), "L4": translate("Drawing", "Rod BC, L_4"),
        "h": translate("Drawing", "Guide above O_2, h"), "H": translate("Drawing", "Stroke H"),
        "K": translate("Drawing", "Time ratio K"),
        "theta": translate("Drawing", "Extreme-position angle θ"),
        "n": translate("Drawing", "Crank speed n"),
    }
