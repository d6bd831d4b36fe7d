"""The gear sheet's words in the user's language (``core.drawing.gear_sheet.ENGLISH``'s keys)."""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from .labels import title_labels

translate = QCoreApplication.translate   # lupdate extracts translate("Drawing", "…")


def gear_labels() -> dict[str, str]:
    """Every text of the meshing sheet."""
    return {
        **title_labels(),
        "title": translate("Drawing", "Gear meshing"),
        "mesh": translate("Drawing", "The gear pair in mesh, μ_l = {mu} m/mm ({scale})"),
        "mesh_note": translate("Drawing", "Teeth as the rack cuts them; the pinion 1 drives counter-clockwise"),
        "figures": translate("Drawing", "Gear pair data and results"),
        "quantity": translate("Drawing", "Quantity"),
        "gear1": translate("Drawing", "Pinion 1"),
        "gear2": translate("Drawing", "Gear 2"),
        "teeth": translate("Drawing", "Teeth z"),
        "module": translate("Drawing", "Module m"),
        "rack": translate("Drawing", "Rack α, h*_a, c*"),
        "shift": translate("Drawing", "Shift factor x"),
        "least": translate("Drawing", "Least shift x_min"),
        "d": translate("Drawing", "Reference diameter d"),
        "db": translate("Drawing", "Base diameter d_b"),
        "da": translate("Drawing", "Tip diameter d_a"),
        "df": translate("Drawing", "Root diameter d_f"),
        "dw": translate("Drawing", "Working diameter d′"),
        "s": translate("Drawing", "Thickness s"),
        "e": translate("Drawing", "Space e"),
        "sa": translate("Drawing", "Tip thickness s_a"),
        "centre": translate("Drawing", "Centre distance a′ (a)"),
        "angle_w": translate("Drawing", "Working pressure angle α′"),
        "y": translate("Drawing", "Centre shift y, reduction Δy"),
        "pb": translate("Drawing", "Base pitch p_b"),
        "lines": translate("Drawing", "Lines of action N_1N_2, B_1B_2"),
        "eps": translate("Drawing", "Contact ratio ε"),
        "rule": translate("Drawing", "Shifts"),
        "given": translate("Drawing", "given"),
        "from_centre": translate("Drawing", "from a′"),
        "balanced": translate("Drawing", "x_2 = −x_1"),
        "positive": translate("Drawing", "positive pair"),
        "undercut": translate("Drawing", "No undercut"),
        "tip": translate("Drawing", "Tip s_a ≥ {k}"),
        "contact": translate("Drawing", "ε ≥ {k}"),
        "interference": translate("Drawing", "No root interference"),
        "ok": translate("Drawing", "ok"),
        "fails": translate("Drawing", "FAILS"),
        "double": translate("Drawing", "double contact"),
        "single": translate("Drawing", "single contact"),
        "line": translate("Drawing", "Actual line of action B_2B_1 and the contact zones, μ_l = {mu} m/mm ({scale})"),
    }
