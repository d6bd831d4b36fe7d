"""The forces sheet's words in the user's language (``core.drawing.forces.ENGLISH``'s keys)."""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from .labels import title_labels

translate = QCoreApplication.translate   # lupdate extracts translate("Drawing", "…")


def forces_labels() -> dict[str, str]:
    """Every text of the kinetostatic sheet."""
    return {
        **title_labels(),
        "title": translate("Drawing", "Kinetostatic analysis"),
        "mechanism": translate("Drawing", "Loads and joint forces, φ = {angle}°"),
        "mechanism_scales": translate("Drawing", "μ_l = {mu} m/mm ({scale}), μ_F = {mu_f} N/mm"),
        "polygon_ram": translate("Drawing", "Force polygon of the ram group, φ = {angle}°, μ_F = {mu_f} N/mm"),
        "polygon_lever": translate("Drawing", "Force polygon of the lever (link 4), φ = {angle}°, μ_F = {mu_f} N/mm"),
        "torque": translate("Drawing", "Driving torque on the crank M over φ, mean M_m dashed, n = {rpm} r/min"),
        "energy": translate("Drawing", "Energy ∫(M − M_m)dφ over φ, ΔW_max = {dw} J"),
        "M": translate("Drawing", "M/(N·m)"), "E": translate("Drawing", "E/J"), "phi": translate("Drawing", "φ/(°)"),
        "mu_M": translate("Drawing", "μ_M = {mu} (N·m)/mm"), "mu_E": translate("Drawing", "μ_E = {mu} J/mm"),
        "mu_phi": translate("Drawing", "μ_φ = {mu} °/mm"),
        "flywheel": translate("Drawing", "Flywheel"), "quantity": translate("Drawing", "Quantity"),
        "value": translate("Drawing", "Value"), "n": translate("Drawing", "Crank speed n"),
        "M_mean": translate("Drawing", "Mean driving torque M_m"),
        "M_max": translate("Drawing", "Largest driving torque"),
        "P_mean": translate("Drawing", "Mean power (before efficiency)"),
        "dW": translate("Drawing", "Energy fluctuation ΔW_max"),
        "delta": translate("Drawing", "Coefficient of speed fluctuation δ"),
        "J_F": translate("Drawing", "Flywheel J_F = ΔW_max/(ω²δ)"),
        "J_e": translate("Drawing", "Mean reduced inertia J_e"),
        "J_net": translate("Drawing", "Flywheel to add J_F − J_e"),
        "J_c": translate("Drawing", "Rotating parts J_c at the crank"),
        "J_needed": translate("Drawing", "Flywheel needed J_F − J_c"),
        "J_net_rotors": translate("Drawing", "Flywheel to add J_F − J_c − J_e"),
        "none_needed": translate("Drawing", "none needed (J_c ≥ J_F)"),
        "guide_at": translate("Drawing", "Guide reaction N, φ = {angle}°"),
        "guide_inside": translate("Drawing", "{n} N, {x} mm from C"),
        "not_to_scale": translate("Drawing", "Drawn {mm} mm long, not to μ_F:"),
        "guide_ends_at": translate("Drawing", "Guide ends rear / front, φ = {angle}°"),
        "guide_ends": translate("Drawing", "{rear} N / {front} N"),
    }
