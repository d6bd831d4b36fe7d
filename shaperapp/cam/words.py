"""The cam's drawing words in the user's language (``core.drawing.cam_sheet.ENGLISH``'s keys
but the title block's): the cam sheet's and the cam DXF's notes (the Cam tab's export)."""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication

translate = QCoreApplication.translate   # lupdate extracts translate("Drawing", "…")


def cam_words() -> dict[str, str]:
    """Every text of the feed cam's sheet but its title block's."""
    return {
        "title": translate("Drawing", "Feed cam"),
        "profile": translate("Drawing", "Cam profile by inversion, μ_l = {mu} m/mm ({scale})"),
        "profile_note": translate("Drawing", "Actual profile thick, pitch curve dash-dot, the follower at δ = 0; the cam turns clockwise"),
        "curves": translate("Drawing", "Follower angle, angular velocity and acceleration over the cam angle, n = {rpm} r/min"),
        "pressure": translate("Drawing", "Pressure angle over the cam angle, allowances [α] dashed"),
        "psi": translate("Drawing", "ψ/(°)"),
        "omega": translate("Drawing", "ω/(rad/s)"),
        "alpha": translate("Drawing", "α/(rad/s²)"),
        "angle": translate("Drawing", "α/(°)"),
        "delta": translate("Drawing", "δ/(°)"),
        "mu_psi": translate("Drawing", "μ_ψ = {mu} °/mm"),
        "mu_omega": translate("Drawing", "μ_ω = {mu} (rad/s)/mm"),
        "mu_alpha": translate("Drawing", "μ_α = {mu} (rad/s²)/mm"),
        "mu_angle": translate("Drawing", "μ_α = {mu} °/mm"),
        "mu_delta": translate("Drawing", "μ_δ = {mu} °/mm"),
        "rise_sector": translate("Drawing", "δ_0 = {deg}°"),
        "dwell_sector": translate("Drawing", "δ_s = {deg}°"),
        "return_sector": translate("Drawing", "δ_0′ = {deg}°"),
        "inner_sector": translate("Drawing", "δ_s′ = {deg}°"),
        "figures": translate("Drawing", "Cam data and results"),
        "quantity": translate("Drawing", "Quantity"),
        "value": translate("Drawing", "Value"),
        "arm": translate("Drawing", "Follower arm l"),
        "swing": translate("Drawing", "Swing ψ_max"),
        "rise": translate("Drawing", "Rise δ_0, law"),
        "dwell": translate("Drawing", "Outer dwell δ_s"),
        "return": translate("Drawing", "Return δ_0′, law"),
        "inner": translate("Drawing", "Inner dwell δ_s′"),
        "allowed": translate("Drawing", "Allowed pressure angle rise / return"),
        "n": translate("Drawing", "Cam speed n"),
        "base": translate("Drawing", "Base radius r_0 (pitch curve)"),
        "distance": translate("Drawing", "Centre distance a"),
        "initial": translate("Drawing", "Initial arm angle ψ_0"),
        "side": translate("Drawing", "Roller side of the line of centres"),
        "above": translate("Drawing", "above"),
        "below": translate("Drawing", "below"),
        "max_pressure": translate("Drawing", "Max pressure angle rise / return"),
        "rho": translate("Drawing", "Min convex radius ρ_min"),
        "roller": translate("Drawing", "Roller radius r"),
        "profile_base": translate("Drawing", "Profile base radius r_0 − r"),
        "allowance": translate("Drawing", "Pressure angle allowance"),
        "exceeded": translate("Drawing", "EXCEEDED"),
        "peaks": translate("Drawing", "Follower ω_max / α_max"),
        "phase": translate("Drawing", "Rise starts at crank angle"),
        "parabolic": translate("Drawing", "parabolic"),
        "cosine": translate("Drawing", "cosine"),
        "sine": translate("Drawing", "sine"),
        "poly345": translate("Drawing", "3-4-5"),
    }
