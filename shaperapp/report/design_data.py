"""The report's design data beyond the linkage: the loads as typed (weights as weights, in the
task book's numbering: crank 2, block 3, lever 4, rod 5, ram 6), the rotating parts and the
guide, the feed cam's and the gear pair's inputs; and the flywheel's formula, typeset."""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from core.cam import CamInputs
from core.forces.masses import GRAVITY, MassProperties
from core.base.figure_text import figure_text
from core.gear.inputs import GearPairInputs
from core.linkage.geometry import Design


translate = QCoreApplication.translate   # lupdate extracts translate("Report", "…")


def _weight(masses: MassProperties, mass: str) -> str:
    """G as typed (200 N), or m and its weight when a mass was given (20 kg, G = 196.2 N)."""
    weight = getattr(masses, {"lever_mass_kg": "lever_weight_N", "ram_mass_kg": "ram_weight_N"}[mass])
    if weight is not None:
        return f"{weight:g} N"
    return f"{getattr(masses, mass):g} kg (G = {getattr(masses, mass) * GRAVITY:.5g} N)"


def load_rows(masses: MassProperties, design: Design) -> list[tuple[str, str]]:
    """The loads as the user typed them, with the symbols of the task book."""
    dx, dy = masses.ram_cg_mm
    rows = [(translate("Report", "Lever weight G_4"), _weight(masses, "lever_mass_kg")),
            (translate("Report", "Lever centre of mass l_O4S4 (from O4)"),
             f"{masses.lever_cg(design):g} mm"),
            (translate("Report", "Lever inertia J_S4 (about S_4)"), f"{masses.lever_inertia_kg_m2:g} kg·m²"),
            (translate("Report", "Ram weight G_6 (with the tool)"), _weight(masses, "ram_mass_kg")),
            (translate("Report", "Ram centre of mass x_S6, y_S6 (from C, x along the cut, y up)"),
             f"{dx:g} mm, {dy:g} mm")]
    if design.rod is not None:
        rows.append((translate("Report", "Rod mass m_5"), f"{masses.rod_mass_kg:g} kg"))
    if masses.block_mass_kg or masses.crank_mass_kg:
        rows.append((translate("Report", "Block mass, crank mass"),
                     f"{masses.block_mass_kg:g} kg, {masses.crank_mass_kg:g} kg"))
    rows += [(translate("Report", "Cutting force P, tool below the guide y_P"),
              f"{masses.cut_force_N:g} N, {masses.cut_height_mm:g} mm"),
             (translate("Report", "Idle margin at each end of the stroke"), f"{masses.idle_fraction:g} H"),
             (translate("Report", "Gravity"),
              translate("Report", "on") if masses.gravity else translate("Report", "off")),
             (translate("Report", "Ram guide length"),
              f"{masses.guide_length(design):g} mm" + ("" if masses.guide_length_mm is not None
                                                       else translate("Report", " (the stroke H)"))),
             (translate("Report", "Coefficient of speed fluctuation δ"), figure_text("coefficient", masses.delta))]
    if masses.rotors:
        part = translate("Report", "J = %1 kg·m² at %2·ω2")
        parts = translate("Report", "; ").join(part.replace("%1", f"{j:g}").replace("%2", f"{r:g}")
                                               for j, r in masses.rotors)
        rows.append((translate("Report", "Other rotating parts (J, speed)"), parts))
    return rows


def law_name(name: str) -> str:
    """A motion law's name in the report's language (the Cam tab's words; the task sheet's too)."""
    return {"parabolic": translate("Report", "parabolic"), "cosine": translate("Report", "cosine"),
            "sine": translate("Report", "sine (cycloidal)"),
            "poly345": translate("Report", "3-4-5 polynomial")}.get(name, name)


def cam_rows(cam: tuple[CamInputs, float | None]) -> list[tuple[str, str]]:
    """The feed cam's data sheet as typed ('auto' where the program chooses)."""
    inputs, phase = cam
    p = inputs.program
    auto = translate("Report", "auto")
    mm = lambda v: auto if v is None else f"{v:g} mm"  # noqa: E731
    return [(translate("Report", "Cam: follower arm l, swing ψmax"), f"{inputs.arm_mm:g} mm, {p.swing_deg:g}°"),
            (translate("Report", "Cam: rise, outer dwell, return"),
             f"{p.rise_deg:g}°, {p.dwell_deg:g}°, {p.return_deg:g}°"),
            (translate("Report", "Cam: rise law, return law"), f"{law_name(p.rise_law)}, {law_name(p.return_law)}"),
            (translate("Report", "Cam: allowed pressure angle, rise / return"),
             f"{inputs.pressure_deg:g}° / {inputs.return_pressure_deg:g}°"),
            (translate("Report", "Cam: roller, base radius, centre distance"),
             f"{mm(inputs.roller_mm)}, {mm(inputs.base_mm)}, {mm(inputs.distance_mm)}"),
            (translate("Report", "Cam: rise at crank angle"), auto if phase is None else f"{phase:g}°")]


def gear_rows(gear: GearPairInputs) -> list[tuple[str, str]]:
    """The gear pair's inputs as typed ('auto' where the rules choose)."""
    auto = translate("Report", "auto")
    num = lambda v, unit="": auto if v is None else f"{v:g}{unit}"  # noqa: E731
    return [(translate("Report", "Gears: teeth z_1, z_2, module m"),
             f"{gear.z1}, {gear.z2}, {gear.module_mm:g} mm"),
            (translate("Report", "Gears: shifts x_1, x_2, centre distance a′"),
             f"{num(gear.x1)}, {num(gear.x2)}, {num(gear.centre_mm, ' mm')}")]


def flywheel_formula(masses: MassProperties) -> str:
    """The flywheel of the task book, typeset (HTML sub/superscripts)."""
    text = "J<sub>F</sub> = ΔW<sub>max</sub>/(ω<sub>m</sub><sup>2</sup>·[δ])"
    if masses.rotors:
        text += translate("Report", "; the flywheel needed is J<sub>F</sub> − J<sub>c</sub>, with the other "
                          "rotating parts reduced to the crank J<sub>c</sub> = Σ J<sub>i</sub>·"
                          "(ω<sub>i</sub>/ω<sub>2</sub>)<sup>2</sup> (none when J<sub>c</sub> ≥ J<sub>F</sub>)")
    return text
