"""The kinetostatic-analysis sheet (动态静力分析图) of the course design on a GB paper.

Upper left the mechanism at the two polygon positions (the report's default, or
``diagram_deg``) with the loads and the joint forces as arrows to one force scale
μF each; upper right the force polygons of the ram group (core.forces.polygons.force_polygon)
and of the lever (lever_force_polygon) at the same two positions; lower left the crank's driving torque over the cycle with
its mean, and the energy curve ∫(M − M_m)dφ; lower right the flywheel result (the
numbers of ``shaper dynamics`` and the report, from core.forces.flywheel.summarize) and the
title block. Every number comes from core at the first crank speed, the speed of the
motion sheet's polygons.

Texts are looked up in ``labels`` (keys of :data:`ENGLISH`), so the caller chooses the
language; numbers are formatted here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

import numpy as np

from core.forces.dynamics import solve_dynamics
from core.forces.masses import MM, MassProperties
from core.base.figure_text import figure_text
from core.forces.flywheel import summarize
from core.linkage.geometry import Design
from core.linkage.kinematics import rpm_to_omega, shape
from core.forces.polygons import FINE_MANTISSAS, force_polygon, lever_force_polygon, nice_scale
from core.course_design.positions import DEFAULT_COUNT, positions, special_angles

from . import mechanism as mech
from .charts import ARROW, Curve, arrow, chart, polygon_extent, polygon_fit_scale, polygon_items, scale_notes
from .dxf import OUTLINE
from .force_values import newtons, value_after, values_table
from .labels import Room
from .motion import CAPTION, GAP, JOINT_GAP, TABLE_ROW, caption, caption_lines
from .motion import nearest_mid_strokes
from .sheet import (Box, Item, Paper, Sheet, fit, frame_items, number_text, scale_text,
                    standard_scale, symbol)
from .cells import table
from .title_block import TITLE_ENGLISH, TITLE_WIDTH, TitleBlock, sheet_title_block, title_block_box

ENGLISH = {
    "title": "Kinetostatic analysis",
    "mechanism": "Loads and joint forces, φ = {angle}°",
    "mechanism_scales": "μ_l = {mu} m/mm ({scale}), μ_F = {mu_f} N/mm",
    "polygon_ram": "Force polygon of the ram group, φ = {angle}°, μ_F = {mu_f} N/mm",
    "polygon_lever": "Force polygon of the lever (link 4), φ = {angle}°, μ_F = {mu_f} N/mm",
    "torque": "Driving torque on the crank M over φ, mean M_m dashed, n = {rpm} r/min",
    "energy": "Energy ∫(M − M_m)dφ over φ, ΔW_max = {dw} J",
    "M": "M/(N·m)", "E": "E/J", "phi": "φ/(°)",
    "mu_M": "μ_M = {mu} (N·m)/mm", "mu_E": "μ_E = {mu} J/mm", "mu_phi": "μ_φ = {mu} °/mm",
    "flywheel": "Flywheel", "quantity": "Quantity", "value": "Value",
    "n": "Crank speed n", "M_mean": "Mean driving torque M_m", "M_max": "Largest driving torque",
    "P_mean": "Mean power (before efficiency)", "dW": "Energy fluctuation ΔW_max",
    "delta": "Coefficient of speed fluctuation δ", "J_F": "Flywheel J_F = ΔW_max/(ω²δ)",
    "J_e": "Mean reduced inertia J_e", "J_net": "Flywheel to add J_F − J_e",
    "J_c": "Rotating parts J_c at the crank",
    "J_needed": "Flywheel needed J_F − J_c", "J_net_rotors": "Flywheel to add J_F − J_c − J_e",
    "none_needed": "none needed (J_c ≥ J_F)",
    "guide_at": "Guide reaction N, φ = {angle}°",
    "guide_inside": "{n} N, {x} mm from C",
    "not_to_scale": "Drawn {mm} mm long, not to μ_F:",
    "guide_ends_at": "Guide ends rear / front, φ = {angle}°", "guide_ends": "{rear} N / {front} N",
    **TITLE_ENGLISH,
}
# core's force keys as the sheet writes them: the letter, and its index as a subscript
FORCE_NAMES = {key: (key.split("_")[0], key.partition("_")[2]) for key in (
    "P", "G_6", "F_I6", "G_5", "F_I5", "N", "R_B", "R_O2", "R_A", "R_O4", "R_C", "G_4", "F_I4", "R_4B")}
ARROW_MM = 30.0             # the largest force on the mechanism drawn this long
N_APART = 6.0               # the guide's N drawn at least this far beside C (G6 acts down through S6) …
RAM_INSIDE = mech.RAM[0] / 2.0 - 2.0   # … and inside the ram body
MIN_ARROW = 2.0 * ARROW[0]  # a shorter force is drawn this long (its head and shaft show), its value named
JOINT_RINGS = 2
"""A joint's name goes at most one text height farther out than its first ring without a
leader: a third ring (3.5 mm text at 10 mm, 方案 I's O2 on A1) left it near nothing, read
as whose only by elimination."""
TORQUE_STEP_DEG = 1.0
# room a mechanism drawing keeps beside the links' extent, paper mm: the guide line runs
# RAM/2 + 6 behind the ram joint's travel and RAM/2 + TOOL_AHEAD + 6 ahead of it (plus a
# margin), the supports and the tool hang below
LEFT_OF_TRAVEL = mech.RAM[0] / 2.0 + 6.0 + 4.0
RIGHT_OF_TRAVEL = mech.RAM[0] / 2.0 + mech.TOOL_AHEAD + 6.0 + 4.0
BELOW = 14.0


@dataclass(frozen=True)
class ForcesSheet:
    """The sheet and what the tests measure on it."""

    sheet: Sheet
    scale: float                            # the mechanism's reduction 1:scale
    diagram_deg: tuple[float, float]
    force_scales: tuple[float, float]       # μF of the two mechanism drawings, N/mm
    polygon_scales: tuple[float, ...]       # μF of the polygons (ram group, then lever), N/mm
    arrows: dict[tuple[int, str], tuple[np.ndarray, np.ndarray]]
    """(drawing, force name) → tail and head on the paper, mm: the force at μF from its point."""
    shown: dict[tuple[int, str], tuple[np.ndarray, np.ndarray]]
    """(drawing, force name) → tail and head of the arrow drawn for it (:func:`shown_arrow`)."""
    torque_chart: tuple[float, float, tuple[float, float]]   # μM, μφ, paper origin
    energy_chart: tuple[float, float, tuple[float, float]]   # μE, μφ, paper origin
    rows: list[tuple[str, str]]             # the flywheel table
    areas: dict[str, tuple[Box, tuple[Item, ...]]]


def forces_sheet(design: Design, rpm: float, masses: MassProperties, paper: Paper, *,
                 diagram_deg: tuple[float, float] | None = None,
                 labels: Mapping[str, str] = ENGLISH, block: TitleBlock | None = None) -> ForcesSheet:
    """The kinetostatic sheet of ``design`` at ``rpm`` with ``masses`` on ``paper``."""
    lab = {**ENGLISH, **labels}
    bx0, by0, bx1, by1 = paper.border
    split_x, split_y = bx0 + 0.5 * (bx1 - bx0), by0 + 0.45 * (by1 - by0)
    diagrams = diagram_deg or default_diagrams(design, masses.idle_fraction)
    areas: dict[str, tuple[Box, tuple[Item, ...]]] = {}

    scale, cells = _mechanism_cells(design, (bx0 + GAP, split_y + GAP, split_x, by1 - GAP))
    room = [(c[0], c[1], c[2], c[3] - 3 * CAPTION) for c in cells]
    arrows: dict[tuple[int, str], tuple[np.ndarray, np.ndarray]] = {}
    shown: dict[tuple[int, str], tuple[np.ndarray, np.ndarray]] = {}
    force_scales = []
    for k, (cell, box, angle) in enumerate(zip(cells, room, diagrams)):
        items, mu_f = _loaded_mechanism(design, rpm, masses, angle, box, scale, (arrows, shown), k,
                                        lab["not_to_scale"].format(mm=number_text(MIN_ARROW)))
        middle = (cell[0] + cell[2]) / 2.0
        items.append(caption(lab["mechanism"].format(angle=number_text(round(angle, 2))),
                             (middle, cell[3]), cell[2] - cell[0], 3.5))
        items.append(caption(lab["mechanism_scales"].format(mu=number_text(scale / 1000.0),
                                                            scale=scale_text(scale), mu_f=number_text(mu_f)),
                             (middle, cell[3] - 1.6 * CAPTION), cell[2] - cell[0], 3.5))
        areas[f"mechanism {k + 1}"] = (cell, tuple(items))
        force_scales.append(mu_f)

    summary = summarize(design, [rpm], masses)
    rows = flywheel_rows(summary, masses, lab) + guide_rows(design, rpm, masses, diagrams, lab)
    cells_rows = [(lab["quantity"], lab["value"])] + rows
    table_top = title_block_box(paper)[3] + GAP + TABLE_ROW * len(cells_rows)
    # the polygons above the flywheel table and its caption (below it on a small sheet)
    poly_bottom = max(split_y, table_top + 2 * CAPTION + GAP)
    poly_w = (bx1 - split_x - GAP) / 2.0
    poly_h = (by1 - poly_bottom - GAP) / 2.0
    polygon_scales = []
    for r, (group, build) in enumerate((("ram", force_polygon), ("lever", lever_force_polygon))):
        for k, angle in enumerate(diagrams):
            cell = (split_x + GAP + k * poly_w, by1 - GAP - (r + 1) * poly_h,
                    split_x + (k + 1) * poly_w, by1 - GAP - r * poly_h - (GAP if r else 0.0))
            poly = build(design, angle, rpm, masses)
            items, mu = _polygon(poly, cell, lab[f"polygon_{group}"])
            areas[f"{group} polygon {k + 1}"] = (cell, tuple(items))
            polygon_scales.append(mu)

    table_w = TITLE_WIDTH
    charts_right = bx1 - table_w - 2 * GAP
    half = (split_y - by0 - GAP) / 2.0
    speed = summary.speeds[0]
    torque_box = (bx0 + GAP, by0 + GAP + half, charts_right, split_y - GAP)
    energy_box = (bx0 + GAP, by0 + GAP, charts_right, by0 + half)
    phi_deg = np.arange(0.0, 360.0 + TORQUE_STEP_DEG / 2, TORQUE_STEP_DEG)
    torque = solve_dynamics(design, np.radians(phi_deg), [rpm], masses).crank_torque[0]
    items, torque_chart = _curve_chart(torque_box, phi_deg, torque, speed.mean_torque_N_m,
                                       lab["torque"].format(rpm=number_text(rpm)), lab["M"], "mu_M", lab)
    areas["torque"] = (torque_box, tuple(items))
    energy_deg = np.degrees(summary.crank_angle)
    items, energy_chart = _curve_chart(energy_box, energy_deg, summary.energy[0], None,
                                       lab["energy"].format(dw=figure_text("energy", speed.energy_fluctuation_J)),
                                       lab["E"], "mu_E", lab)
    areas["energy"] = (energy_box, tuple(items))

    table_box = (bx1 - table_w, table_top - TABLE_ROW * len(cells_rows), bx1, table_top)
    items = list(table((bx1 - table_w, table_top), (115.0, 65.0), cells_rows, TABLE_ROW, 3.5,
                       aligns="lc"))
    items.append(caption(lab["flywheel"], ((table_box[0] + table_box[2]) / 2.0, table_top + 2 * CAPTION),
                         table_w, CAPTION))
    areas["flywheel"] = ((table_box[0], table_box[1], table_box[2], table_top + 2 * CAPTION),
                         tuple(items))
    areas["title"] = sheet_title_block(paper, block, lab, scale_text(scale))
    items = [*frame_items(paper), *(it for _, group in areas.values() for it in group)]
    return ForcesSheet(Sheet(paper, tuple(items)), scale, tuple(diagrams), tuple(force_scales),
                       tuple(polygon_scales), arrows, shown, torque_chart, energy_chart, rows, areas)


def _mechanism_cells(design: Design, area: Box) -> tuple[float, list[Box]]:
    """The two mechanism drawings side by side or one above the other, whichever draws
    them at the larger standard scale (a long rod makes the mechanism wide); the scale."""
    x0, y0, x1, y1 = area
    xm, ym = (x0 + x1) / 2.0, (y0 + y1) / 2.0
    options = [[(x0, y0, xm - GAP / 2.0, y1), (xm + GAP / 2.0, y0, x1, y1)],
               [(x0, ym + GAP / 2.0, x1, y1), (x0, y0, x1, ym - GAP / 2.0)]]
    b = mech.bounds(design)
    best = None
    for cells in options:
        w, h = cells[0][2] - cells[0][0], cells[0][3] - cells[0][1] - 3 * CAPTION
        scale = max(standard_scale(b[2] - b[0], w - LEFT_OF_TRAVEL - RIGHT_OF_TRAVEL),
                    standard_scale(b[3] - b[1], h - 2 * BELOW))
        if best is None or scale < best[0]:
            best = (scale, cells)
    return best


def joint_forces(design: Design, rpm: float, masses: MassProperties, angle_deg: float
                 ) -> list[tuple[str, str, np.ndarray]]:
    """(name, where, force in N) on the mechanism at one angle: the loads on the ram (P at
    the tool, G6 and F_I6 at C, the guide's N) and the joint forces, each on the link the
    README names (R_O2 on the crank, R_A and R_O4 on the lever, R_B by the lever on the next
    link, R_C by the rod on the ram). Zero forces are left out. Where: a joint, "tool", "S"
    (the ram's centre of mass) or "guide" (where the guide's resultant acts)."""
    phi = np.radians([angle_deg])
    d = solve_dynamics(design, phi, [rpm], masses)
    w = float(rpm_to_omega(rpm))
    a_c = w * w * float(shape(design, phi).ram2[0]) * MM
    at = lambda a: float(a[0, 0])          # noqa: E731
    forces = [("P", "tool", np.array([-at(d.cut_force), 0.0])),
              ("G_6", "S", np.array([0.0, -masses.ram_mass_kg * masses.g])),
              ("F_I6", "S", np.array([-masses.ram_mass_kg * a_c, 0.0])),
              ("N", "guide", np.array([0.0, at(d.guide_normal)])),
              ("R_O2", "O2", np.array([at(d.o2_x), at(d.o2_y)])),
              ("R_A", "A", np.array([at(d.a_x), at(d.a_y)])),
              ("R_O4", "O4", np.array([at(d.o4_x), at(d.o4_y)])),
              ("R_B", "B", np.array([at(d.b_x), at(d.b_y)]))]
    if design.rod is not None:
        forces.append(("R_C", "C", np.array([at(d.c_x), at(d.c_y)])))
    return [(name, where, f) for name, where, f in forces if math.hypot(*f) > 0.0]


def _loaded_mechanism(design, rpm, masses, angle, box, scale, arrows, k, note: str) -> tuple[list[Item], float]:
    # the guide line reaches past C's travel by these (mechanism.frame_items): off centre
    place = fit(mech.bounds(design), (box[0] + LEFT_OF_TRAVEL, box[1] + BELOW,
                                      box[2] - RIGHT_OF_TRAVEL, box[3] - BELOW), scale)
    items: list[Item] = mech.frame_items(design, place) + mech.links_at(design, angle, place, OUTLINE)
    forces = joint_forces(design, rpm, masses, angle)
    points = {name: place(p) for name, p in mech.joints(design, angle).items()}
    points["tool"] = np.array(mech.tool_point(points["C"]))
    ram = mech.ram_body(points["C"] if design.rod is not None else np.array([points["B"][0], points["C"][1]]))
    points.update(ram_load_points(design, rpm, masses, angle, points["C"], scale))
    on_ram = {"C", "S", "guide"}
    # μF: the largest force ARROW_MM long, and every arrow and its name inside the box
    need = max((math.hypot(*f) for _, _, f in forces), default=0.0) / ARROW_MM   # no loads: no arrows
    for _, where, force in forces:
        start = shown_arrow(points[where], force, ram if where in on_ram else None)[0]
        need = max(need, math.hypot(*force) / max(_room(start, force, box) - 8.0, 1.0))
    mu_f = nice_scale(need, 1.0, FINE_MANTISSAS)
    heads = []
    for name, where, force in forces:
        tail = points[where]
        arrows[0][(k, name)] = (tail, tail + force / mu_f)
        shown = shown_arrow(tail, force / mu_f, ram if where in on_ram else None)
        arrows[1][(k, name)] = shown
        items += arrow(*shown, OUTLINE)
        magnitude = math.hypot(*force)
        heads.append((name, *shown, magnitude if magnitude / mu_f < MIN_ARROW else None))
    room = Room(items, within=box)             # every label against all the linework
    anchors = mech.joint_anchors(design, angle, place, 3.5)
    room.name([p for _, _, p, _ in anchors] + [head for _, _, head, _ in heads])
    for text, spans, p, way in anchors:         # beside its pin (two rings), else on a leader
        items += room.place(text, tuple(p), 3.5, tuple(way), gap=JOINT_GAP, rings=JOINT_RINGS,
                            subscripts=spans, leader_gap=mech.PIN_RADIUS + 0.3)
    unvalued = []                               # lengthened forces whose value found no room after the name
    for name, tail, head, lengthened in heads:  # crowded (small sheets): left out
        text, spans = symbol(FORCE_NAMES[name])
        placed = room.place(text, (float(head[0]), float(head[1])), 3.5, tuple(head - tail), gap=1.0,
                            subscripts=spans, leader_gap=0.5)
        items += placed
        value = [] if lengthened is None or not placed else value_after(room, placed[0], f"= {newtons(lengthened)} N")
        items += value
        if lengthened is not None and not value:    # not to μF: its value must be read somewhere
            unvalued.append((text, spans, lengthened))
    items += values_table(room, note, unvalued, points["C"])
    return items, mu_f


def ram_load_points(design: Design, rpm: float, masses: MassProperties, angle: float, c: np.ndarray,
                    scale: float) -> dict[str, np.ndarray]:
    """The paper points where the ram's weight and inertia force act (S, drawn at C: the
    ram is a symbol, not to scale) and where the guide's resultant N acts: on its side of
    C, at least N_APART from it (N and G6 are both vertical: on one line they hide each
    other) and inside the ram body."""
    d = solve_dynamics(design, np.radians([angle]), [rpm], masses)
    offset = float(d.guide_offset_mm[0, 0]) / scale
    side = -1.0 if math.isnan(offset) or offset < 0.0 else 1.0
    x = c[0] + side * min(max(abs(0.0 if math.isnan(offset) else offset), N_APART), RAM_INSIDE)
    return {"S": np.asarray(c, dtype=float), "guide": np.array([x, c[1]])}


def shown_arrow(tail: np.ndarray, vector: np.ndarray, body: Box | None) -> tuple[np.ndarray, np.ndarray]:
    """The arrow drawn for a force ``vector`` (paper mm, at μF) acting at ``tail``: slid along
    its line of action out of ``body`` (the ram, whose outline would hide a load at C), and
    at least MIN_ARROW long, so that its shaft and head both show (its label then gives its
    value). A load is a sliding vector on a rigid body: its line of action is kept."""
    length = math.hypot(*vector)
    u = vector / length
    start = np.asarray(tail, dtype=float)
    if body is not None:
        start = start + u * _exit(start, u, body)
    return start, start + u * max(length, MIN_ARROW)


def _exit(p: np.ndarray, u: np.ndarray, box: Box) -> float:
    """How far from ``p`` (inside ``box``) along the unit ``u`` the box's outline lies; 0 outside."""
    if not (box[0] <= p[0] <= box[2] and box[1] <= p[1] <= box[3]):
        return 0.0
    return _room(p, u, box)


def _room(tail: np.ndarray, force: np.ndarray, box: Box) -> float:
    """How far from ``tail`` along ``force`` the box reaches, mm."""
    u = force / math.hypot(*force)
    reach = [((box[2] if u[0] > 0 else box[0]) - tail[0]) / u[0] if abs(u[0]) > 1e-12 else math.inf,
             ((box[3] if u[1] > 0 else box[1]) - tail[1]) / u[1] if abs(u[1]) > 1e-12 else math.inf]
    return max(min(reach), 0.0)


def _polygon(poly, cell: Box, title_text: str) -> tuple[list[Item], float]:
    cw, ch = cell[2] - cell[0], cell[3] - cell[1]
    mu = polygon_fit_scale(poly, cw - 24.0, ch - 3 * CAPTION - 14.0)
    titles = caption_lines(title_text.format(angle=number_text(round(poly.crank_deg, 2)), mu_f=number_text(mu)),
                           ((cell[0] + cell[2]) / 2.0, cell[3]), cw - 4.0, 3.5)
    ex = polygon_extent(poly, mu)
    cx, cy = (cell[0] + cell[2]) / 2.0, (cell[1] + cell[3] - 3 * CAPTION) / 2.0
    pole = (cx - (ex[0] + ex[2]) / 2.0, cy - (ex[1] + ex[3]) / 2.0)
    names = {str(i): str(i) for i in range(len(poly.points))}
    items: list[Item] = list(titles)
    room = Room(within=(cell[0] + 2.0, cell[1], cell[2] - 2.0, cell[3]), taken=[t.box() for t in titles])
    at = {key: (pole[0] + x / mu, pole[1] + y / mu) for key, (x, y) in poly.points.items()}
    room.name(((at[v.tail][0] + at[v.head][0]) / 2.0, (at[v.tail][1] + at[v.head][1]) / 2.0)
              for v in poly.vectors)        # the forces' names, which follow the vertices'
    items += polygon_items(poly, pole, mu, 3.5, names, room=room)
    for v in poly.vectors:                      # each arrow named at its middle
        (tx, ty), (hx, hy) = at[v.tail], at[v.head]
        text, spans = symbol(FORCE_NAMES.get(v.key, v.key))
        items += room.place(text, ((tx + hx) / 2.0, (ty + hy) / 2.0), 3.5, (-(hy - ty), hx - tx),
                            gap=1.5, subscripts=spans)
    return items, mu


def _curve_chart(box: Box, x: np.ndarray, y: np.ndarray, mean: float | None, title: str,
                 y_title: str, mu_key: str, lab) -> tuple[list[Item], tuple[float, float, tuple]]:
    x0, y0, x1, y1 = box
    items: list[Item] = [caption(title, ((x0 + x1) / 2.0, y1), x1 - x0, 3.5)]
    scales = scale_notes(lab[mu_key], lab["mu_phi"])
    drawn = chart((x0, y0, x1, y1 - 2 * CAPTION), x, [Curve(np.asarray(y))], lab["phi"], y_title,
                  [(float(t), f"{t:g}") for t in np.arange(0.0, 361.0, 60.0)], mean=mean, notes=scales)
    items += drawn.items
    return items, (drawn.y_scale, drawn.x_scale, drawn.origin)


def flywheel_rows(summary, masses: MassProperties, lab: Mapping[str, str]) -> list[tuple[str, str]]:
    """The flywheel result at the first speed, formatted as ``shaper dynamics`` prints it;
    with rotating parts (``masses.rotors``) also J_c and the flywheel J_F − J_c they leave."""
    s = summary.speeds[0]
    f = figure_text
    if masses.rotors:
        needed = (f"{f('inertia', s.flywheel_inertia_needed_kg_m2)} kg·m²" if s.flywheel_needed
                  else lab["none_needed"])
        rotors = [(lab["J_c"], f"{f('inertia', summary.rotor_inertia_kg_m2)} kg·m²"), (lab["J_needed"], needed),
                  (lab["J_net_rotors"], f"{f('inertia', s.flywheel_inertia_net_kg_m2)} kg·m²")]
    else:
        rotors = [(lab["J_net"], f"{f('inertia', s.flywheel_inertia_net_kg_m2)} kg·m²")]
    return [(lab["n"], f"{number_text(s.rpm)} r/min"),
            (lab["M_mean"], f"{f('torque', s.mean_torque_N_m)} N·m"),
            (lab["M_max"], f"{f('torque', s.max_torque_N_m)} N·m"),
            (lab["P_mean"], f"{f('power', s.mean_power_W)} W"),
            (lab["dW"], f"{f('energy', s.energy_fluctuation_J)} J"),
            (lab["delta"], f("coefficient", masses.delta)),
            (lab["J_F"], f"{f('inertia', s.flywheel_inertia_kg_m2)} kg·m²"),
            (lab["J_e"], f"{f('inertia', summary.equivalent_inertia_mean_kg_m2)} kg·m²")] + rotors


def guide_rows(design: Design, rpm: float, masses: MassProperties, angles_deg,
               lab: Mapping[str, str]) -> list[tuple[str, str]]:
    """Where the ram bears on its guide at the drawn positions: the resultant N and its
    distance from C where that falls on the guide, else the two end forces it tilts onto
    (core.forces.guide): never a point of action metres off the guide."""
    d = solve_dynamics(design, np.radians(list(angles_deg)), [rpm], masses)
    rows = []
    for k, angle in enumerate(angles_deg):
        at = number_text(round(angle, 2))
        if d.guide_tilted[0, k]:
            rows.append((lab["guide_ends_at"].format(angle=at),
                         lab["guide_ends"].format(rear=f"{d.guide_rear_N[0, k]:.4g}",
                                                  front=f"{d.guide_front_N[0, k]:.4g}")))
        else:
            rows.append((lab["guide_at"].format(angle=at),
                         lab["guide_inside"].format(n=f"{d.guide_normal[0, k]:.4g}",
                                                    x=f"{d.guide_offset_mm[0, k]:.4g}")))
    return rows


def default_diagrams(design: Design, idle_fraction: float) -> tuple[float, float]:
    """The report's and the motion sheet's two positions: the numbered positions (of 12)
    nearest the middle of the working and of the return stroke."""
    where = positions(design, DEFAULT_COUNT, (), idle_fraction)
    special = special_angles(design, idle_fraction)
    return nearest_mid_strokes(where.crank_deg[where.number > 0],
                               (special["limit_work_start"], special["limit_work_end"]))
