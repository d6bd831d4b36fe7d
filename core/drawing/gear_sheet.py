"""The gear pair's meshing sheet (齿轮啮合图), the course design's fourth, on a GB paper.

Left the pair in mesh at the working centre distance a′ to a standard scale, the pinion's
centre O1 at the origin of the model and the gear's O2 on +x: for each gear five teeth about
the pitch point P as the rack cuts them (true involutes and generated fillets, from
:mod:`core.gear.profile`), the rest as its circles (reference dash-dot, working pitch
dashed, base, tip and root thin); the line of action N1N2 tangent to both base circles, the
actual one B1B2 thick, the base pitch pb stepped from both ends (double contact within pb of
either end, single contact between), the working pressure angle α′ against the common tangent
at P. The pinion turns counter-clockwise and drives, so contact runs from B2 to B1. Right the
results and the checks above the title block.

Texts are looked up in ``labels`` (keys of :data:`ENGLISH`); numbers are formatted here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

import numpy as np

from core.base.figure_text import dimension_text, figure_text
from core.gear import GearPair, pair_checks
from core.gear.mesh import line_points, mesh_angles, placed
from core.gear.profile import tooth_outline
from core.gear.table import tip_limit_text

from .charts import arrow
from .dxf import CENTER, DASHED, OUTLINE, THIN
from .labels import Room
from .motion import CAPTION, GAP, TABLE_ROW, caption
from .sheet import (Box, Circle, Item, Paper, Placement, Sheet, fit, frame_items, line, marked,
                    marked_text, number_text, standard_scale)
from .cells import table
from .title_block import TITLE_ENGLISH, TITLE_WIDTH, TitleBlock, sheet_title_block, title_block_box
from .cam_sheet import ENLARGEMENTS, ratio_text

ENGLISH = {
    "title": "Gear meshing",
    "mesh": "The gear pair in mesh, μ_l = {mu} m/mm ({scale})",
    "mesh_note": "Teeth as the rack cuts them; the pinion 1 drives counter-clockwise",
    "figures": "Gear pair data and results", "quantity": "Quantity", "gear1": "Pinion 1",
    "gear2": "Gear 2",
    "teeth": "Teeth z", "module": "Module m", "rack": "Rack α, h*_a, c*",
    "shift": "Shift factor x", "least": "Least shift x_min",
    "d": "Reference diameter d", "db": "Base diameter d_b", "da": "Tip diameter d_a",
    "df": "Root diameter d_f", "dw": "Working diameter d′", "s": "Thickness s", "e": "Space e",
    "sa": "Tip thickness s_a", "centre": "Centre distance a′ (a)",
    "angle_w": "Working pressure angle α′", "y": "Centre shift y, reduction Δy",
    "pb": "Base pitch p_b", "lines": "Lines of action N_1N_2, B_1B_2", "eps": "Contact ratio ε",
    "rule": "Shifts", "given": "given", "from_centre": "from a′", "balanced": "x_2 = −x_1",
    "positive": "positive pair",
    "undercut": "No undercut", "tip": "Tip s_a ≥ {k}", "contact": "ε ≥ {k}",
    "interference": "No root interference", "ok": "ok", "fails": "FAILS",
    "double": "double contact", "single": "single contact",
    "line": "Actual line of action B_2B_1 and the contact zones, μ_l = {mu} m/mm ({scale})",
    **TITLE_ENGLISH,
}
TEETH_EACH_SIDE = 2             # teeth drawn beside the one at P: five per gear
SMALL_ROW = 6.0
CENTRE_MARK = 4.0               # paper mm of a centre's cross beyond its point
ANGLE_RADIUS = 18.0             # paper mm of α′'s arc about P
LINE_HEIGHT = 3.2 * CAPTION + 50.0     # paper mm the straightened line of action needs
MODES = {"given": "given", "centre": "from_centre", "balanced": "balanced", "positive": "positive"}


@dataclass(frozen=True)
class GearSheet:
    """The sheet and what the tests measure on it: ``scale`` model mm per paper mm,
    ``placement`` model → paper, ``rows`` the table, ``areas`` name → (box, items)."""
    sheet: Sheet
    scale: float
    placement: Placement
    rows: list[tuple[str, str, str]]
    areas: dict[str, tuple[Box, tuple[Item, ...]]]


def gear_sheet(pair: GearPair, paper: Paper, *, labels: Mapping[str, str] = ENGLISH,
               block: TitleBlock | None = None) -> GearSheet:
    """The meshing sheet of ``pair`` on ``paper``."""
    lab = {**ENGLISH, **labels}
    bx0, by0, bx1, by1 = paper.border
    title = title_block_box(paper)
    areas: dict[str, tuple[Box, tuple[Item, ...]]] = {}
    rows = figure_rows(pair, lab)
    cells = [(lab["quantity"], lab["gear1"], lab["gear2"])] + list(rows)
    row = TABLE_ROW if paper.height > 500.0 else SMALL_ROW
    table_w = TITLE_WIDTH
    top = min(by1 - GAP - 2 * CAPTION, title[3] + GAP + row * len(cells))
    row = min(row, (top - title[3] - GAP) / len(cells))
    table_area = (bx1 - table_w, title[3] + GAP, bx1, top + 2 * CAPTION)
    items = table((bx1 - table_w, top), (0.46 * table_w, 0.27 * table_w, 0.27 * table_w), cells,
                  row, 3.5, aligns="lcc", spans=True)
    items.append(caption(lab["figures"], ((table_area[0] + bx1) / 2.0, table_area[3]), table_w, CAPTION))
    areas["figures"] = (table_area, tuple(items))
    line_area = (bx1 - table_w, table_area[3] + GAP, bx1, by1 - GAP)
    mesh_area = (bx0 + GAP, by0 + GAP, table_area[0] - GAP, by1 - GAP)
    if line_area[3] - line_area[1] < LINE_HEIGHT:     # A3: below the pair instead
        line_area = (bx0 + GAP, by0 + GAP, bx0 + GAP + table_w, by0 + GAP + LINE_HEIGHT)
        mesh_area = (bx0 + GAP, line_area[3] + GAP, table_area[0] - GAP, by1 - GAP)
    areas["line"] = (line_area, tuple(_line_of_action(pair, line_area, lab)))
    scale, place, items = _mesh(pair, mesh_area, lab)
    areas["mesh"] = (mesh_area, tuple(items))
    areas["title"] = sheet_title_block(paper, block, lab, ratio_text(scale))
    everything = [*frame_items(paper), *(it for _, group in areas.values() for it in group)]
    return GearSheet(Sheet(paper, tuple(everything), model=place), scale, place, rows, areas)


def _scale(bounds: Box, room_w: float, room_h: float, enlargements=ENLARGEMENTS) -> float:
    """The largest standard scale at which ``bounds`` fit (an enlargement up to 5:1, or
    the largest of ``enlargements``)."""
    scale = max(standard_scale(bounds[2] - bounds[0], room_w), standard_scale(bounds[3] - bounds[1], room_h))
    if scale == 1.0:
        fits = [k for k in enlargements if (bounds[2] - bounds[0]) * k <= room_w
                and (bounds[3] - bounds[1]) * k <= room_h]
        scale = 1.0 / max(fits, default=1.0)
    return scale


def teeth_outline(pair: GearPair, k: int) -> np.ndarray:
    """Gear k's teeth about P in the model (mm, O1 at the origin, O2 on +x), in contact at P:
    the pinion's counter-clockwise flank and the gear's clockwise one pass through P."""
    gear = pair.gear1 if k == 1 else pair.gear2
    one = tooth_outline(pair.inputs, gear)
    pitch = 2 * math.pi / gear.teeth
    axis = float(mesh_angles(pair, 0.0)[k - 1])      # a flank through P at r′
    centre = (0.0, 0.0) if k == 1 else (pair.centre_mm, 0.0)
    return np.vstack([placed(one, axis + j * pitch, centre)
                      for j in range(-TEETH_EACH_SIDE, TEETH_EACH_SIDE + 1)])


def window(pair: GearPair) -> Box:
    """The model window a teacher draws: the pinion whole, the line of action N1N2, and as
    much of the gear beside P as the pinion's tip radius again (all of it when that is
    nearly all of it)."""
    g1, g2, a = pair.gear1, pair.gear2, pair.centre_mm
    pts = np.array(list(line_points(pair).values()))
    x1 = max(float(pts[:, 0].max()), g1.rw + g1.ra)
    half = max(g1.ra, float(np.abs(pts[:, 1]).max()))
    if a + g2.ra <= 1.5 * x1:
        return (-g1.ra, -max(half, g2.ra), a + g2.ra, max(half, g2.ra))
    return (-g1.ra, -half, x1, half)


def _circle(centre: np.ndarray, radius: float, layer: str, box: Box) -> list[Item]:
    """A circle, or the arcs of it inside ``box`` (paper mm) as polylines."""
    if (centre[0] - radius >= box[0] and centre[0] + radius <= box[2]
            and centre[1] - radius >= box[1] and centre[1] + radius <= box[3]):
        return [Circle(tuple(centre), radius, layer)]
    t = np.linspace(0.0, 2.0 * math.pi, max(int(2.0 * math.pi * radius / 0.5), 64))
    pts = centre + radius * np.column_stack([np.cos(t), np.sin(t)])
    inside = ((pts[:, 0] >= box[0]) & (pts[:, 0] <= box[2]) & (pts[:, 1] >= box[1])
              & (pts[:, 1] <= box[3]))
    edges = np.flatnonzero(np.diff(np.concatenate([[0], inside.astype(int), [0]])))
    return [line(pts[a:b], layer) for a, b in zip(edges[::2], edges[1::2]) if b - a > 1]


def _mesh(pair: GearPair, area: Box, lab: Mapping[str, str]) -> tuple[float, Placement, list[Item]]:
    """The pair in mesh in ``area`` with its captions (the scale, how the teeth are cut)."""
    box = (area[0], area[1], area[2], area[3] - 3.2 * CAPTION)
    scale = mesh_scale(pair, box[2] - box[0], box[3] - box[1])
    place, items = mesh_items(pair, box, scale)
    middle = (area[0] + area[2]) / 2.0
    items.append(caption(lab["mesh"].format(mu=number_text(scale / 1000.0), scale=ratio_text(scale)),
                         (middle, area[3]), area[2] - area[0]))
    items.append(caption(lab["mesh_note"], (middle, area[3] - 1.8 * CAPTION), area[2] - area[0], 3.5))
    return scale, place, items


def mesh_scale(pair: GearPair, width: float, height: float) -> float:
    """The largest standard scale (model mm per paper mm) at which the pair's window and its
    centre marks fit ``width`` × ``height`` paper mm."""
    return _scale(window(pair), width - 2 * CENTRE_MARK, height - 2 * CENTRE_MARK)


def mesh_items(pair: GearPair, box: Box, scale: float) -> tuple[Placement, list[Item]]:
    """The pair in mesh at ``scale``, its window centred in ``box`` (paper mm), without
    captions: the circles, the teeth, the centre lines, the line of action with N1, N2,
    B1, B2 and the pb steps, α′ at P, and the point labels (symbols only, in no language).
    The sheet and the report's gear figure both draw this."""
    g1, g2, a = pair.gear1, pair.gear2, pair.centre_mm
    place = fit(window(pair), box, scale)
    o1, o2 = place([0.0, 0.0]), place([a, 0.0])
    inner = (box[0] + 1.0, box[1] + 1.0, box[2] - 1.0, box[3] - 1.0)
    items: list[Item] = []
    for centre, gear in ((o1, g1), (o2, g2)):
        for radius, layer in ((gear.r, CENTER), (gear.rw, DASHED), (gear.rb, THIN), (gear.ra, THIN),
                              (gear.rf, THIN)):
            items += _circle(centre, place.length(radius), layer, inner)
    for k in (1, 2):
        items.append(line(place(teeth_outline(pair, k)), OUTLINE))
    mark = CENTRE_MARK
    right = min(float(o2[0]) + place.length(g2.ra) + mark, inner[2])
    items.append(line([o1 - (place.length(g1.ra) + mark, 0.0), (right, float(o1[1]))], CENTER))
    for centre, gear in ((o1, g1), (o2, g2)):
        if centre[0] < inner[2]:
            half = min(place.length(gear.rf) * 0.3, 12.0)
            items.append(line([centre - (0.0, half), centre + (0.0, half)], CENTER))
    pts = {name: place(p) for name, p in line_points(pair).items()}
    u = (pts["N2"] - pts["N1"]) / np.linalg.norm(pts["N2"] - pts["N1"])
    items.append(line([pts["N1"] - 6.0 * u, pts["N2"] + 6.0 * u], THIN))
    items.append(line([pts["B2"], pts["B1"]], OUTLINE))
    n = np.array([-u[1], u[0]])
    for name in ("N1", "N2", "B1", "B2", "K1", "K2"):
        items.append(line([pts[name] - 1.5 * n, pts[name] + 1.5 * n], THIN))
    p = pts["P"]
    tangent = max(ANGLE_RADIUS + 8.0, 0.25 * place.length(g1.ra))
    items.append(line([p - (0.0, tangent), p + (0.0, tangent)], THIN))
    arc = np.linspace(math.pi / 2, math.pi / 2 - pair.alpha_w, 24)
    ring = p + ANGLE_RADIUS * np.column_stack([np.cos(arc), np.sin(arc)])
    items.append(line(ring, THIN))
    items += arrow(ring[-4], ring[-1], THIN)
    room = Room(items, within=box)
    for name, text, away in (("O1", "O_1", (-1.0, -1.0)), ("O2", "O_2", (1.0, -1.0)),
                             ("P", "P", (1.0, -1.0)), ("N1", "N_1", -u), ("N2", "N_2", u),
                             ("B1", "B_1", n), ("B2", "B_2", -n)):
        at = {"O1": o1, "O2": o2}.get(name, pts.get(name))
        if at[0] > inner[2]:                # the gear's centre beyond the window
            continue
        plain, spans = marked(text)
        items += room.place(plain, (float(at[0]), float(at[1])), 3.5, tuple(away), gap=1.0, rings=6,
                            subscripts=spans, leader_gap=0.5)
    mid = ring[len(ring) // 2]
    plain, spans = marked(f"α′ = {dimension_text(math.degrees(pair.alpha_w))}°")
    items += room.place(plain, (float(mid[0]), float(mid[1])), 3.5, (0.4, 1.0), gap=1.0, rings=6,
                        subscripts=spans)
    return place, items


def _line_of_action(pair: GearPair, area: Box, lab: Mapping[str, str]) -> list[Item]:
    """The actual line of action B2B1 laid out straight, to the largest standard scale that
    fits: the points on it above; below, as dimensions, the contact zones (double within pb
    of either end, single between) and the base pitch stepped from B2 and from B1."""
    x0, y0, x1, y1 = area
    scale = _scale((0.0, 0.0, pair.b1b2, 1.0), x1 - x0 - 40.0, 1e9, (*ENLARGEMENTS, 10.0))
    left = (x0 + x1) / 2.0 - pair.b1b2 / scale / 2.0 - pair.n1b2 / scale
    base_y = y1 - 3.2 * CAPTION - 12.0
    along = {"N1": 0.0, "B2": pair.n1b2, "K1": pair.n1b2 + pair.pb, "P": pair.n1p,
             "K2": pair.n1b1 - pair.pb, "B1": pair.n1b1, "N2": pair.n1n2}
    x = {k: left + v / scale for k, v in along.items()}
    # B2 before N1 (or B1 past N2) is interference: the line is drawn to it all the same
    ends = (max(min(x["N1"], x["B2"]), x0 + 4.0), min(max(x["N2"], x["B1"]), x1 - 4.0))
    items: list[Item] = [line([(ends[0], base_y), (ends[1], base_y)], THIN),
                         line([(x["B2"], base_y), (x["B1"], base_y)], OUTLINE)]
    # a limit point beyond the strip (the scale is B2B1's) is named at its end, an arrow
    # pointing on to it: N2 of a long line of action was left unnamed (issue 42)
    for name, end, out in (("N1", ends[0], -1.0), ("N2", ends[1], 1.0)):
        if (x[name] - end) * out > 1e-9:
            x[name] = end
            items += arrow((end - 6.0 * out, base_y), (end, base_y), THIN)
    stepped = pair.contact_ratio >= 1.0
    names = [n for n in ("N1", "B2", "K1", "P", "K2", "B1", "N2")
             if ends[0] <= x[n] <= ends[1] and (stepped or n not in ("K1", "K2"))]
    for name in names:
        items.append(line([(x[name], base_y - 1.5), (x[name], base_y + 1.5)], THIN))
    rows: list[tuple[float, list[tuple]]] = [(base_y - 8.0, _zones(pair, x))]
    if stepped:
        split = max(((x["B2"], x["K2"]), (x["K2"], x["K1"])), key=lambda ab: ab[1] - ab[0])
        rows += [(base_y - 18.0, [(x["B2"], x["K1"], "pb", split)]),
                 (base_y - 28.0, [(x["K2"], x["B1"], "pb")])]
    depth = {x["B2"]: rows[-1][0], x["B1"]: rows[-1][0]}
    if stepped:
        depth.update({x["K1"]: base_y - 18.0, x["K2"]: rows[-1][0]})
    for at, y in depth.items():
        items.append(line([(at, base_y - 2.0), (at, y - 1.5)], THIN))
    texts: list[tuple[str, float, float, float]] = []
    for y, spans in rows:
        for a, b, key, *part in spans:
            items += arrow(((a + b) / 2.0, y), (a, y), THIN) + arrow(((a + b) / 2.0, y), (b, y), THIN)
            mid = sum(part[0]) / 2.0 if part else (a + b) / 2.0
            texts.append((f"p_b = {dimension_text(pair.pb)}" if key == "pb" else lab[key], mid, y, b - a))
    room = Room(items, within=area)
    for text, mid, y, span in texts:
        plain, subs = marked(text)
        label = marked_text(text, (mid, y + 1.8), 2.5, "cb")
        if label.width <= span - 1.0 and room.first_free([label]) is not None:
            items.append(label)
        else:
            items += room.place(plain, (mid, y), 2.5, (0.0, -1.0), gap=0.8, rings=4, subscripts=subs)
    for name in names:
        if name in ("K1", "K2"):
            continue
        plain, spans = marked({"N1": "N_1", "N2": "N_2", "B1": "B_1", "B2": "B_2"}.get(name, name))
        items += room.place(plain, (x[name], base_y + 1.5), 3.5, (0.0, 1.0), gap=0.5, rings=4,
                            subscripts=spans)
    items.append(caption(lab["line"].format(mu=number_text(scale / 1000.0), scale=ratio_text(scale)),
                         ((x0 + x1) / 2.0, y1), x1 - x0, 3.5))
    return items


def _zones(pair: GearPair, pts: dict) -> list[tuple]:
    """(start, end, "double" | "single") along B2 → B1: double within pb of either end."""
    if pair.contact_ratio < 1.0:
        return [(pts["B2"], pts["B1"], "single")]
    if pair.contact_ratio >= 2.0:
        return [(pts["B2"], pts["B1"], "double")]
    return [(pts["B2"], pts["K2"], "double"), (pts["K2"], pts["K1"], "single"),
            (pts["K1"], pts["B1"], "double")]


def figure_rows(pair: GearPair, lab: Mapping[str, str]) -> list[tuple[str, str, str]]:
    """The table's rows: (quantity, pinion, gear) or (quantity, the pair's value, "")."""
    p, g1, g2 = pair.inputs, pair.gear1, pair.gear2

    def both(label: str, f) -> tuple[str, str, str]:
        return (lab[label], f(g1), f(g2))
    # each figure as ``shaper gear``, the report and the answer key write it (figure_text's kinds)
    length = lambda v: figure_text("gear_length", v)      # noqa: E731
    mm = lambda v: f"{length(v)} mm"                      # noqa: E731  (the unit after each length)
    factor = lambda v: figure_text("gear_factor", v)      # noqa: E731
    checks = {c.name: c for c in pair_checks(pair)}
    verdict = lambda name: lab["ok"] if checks[name].ok else lab["fails"]     # noqa: E731
    return [
        both("teeth", lambda g: str(g.teeth)),
        (lab["module"], f"{number_text(p.module_mm)} mm", ""),
        (lab["rack"], f"{number_text(p.pressure_angle_deg)}°, {number_text(p.addendum)}, "
                      f"{number_text(p.clearance)}", ""),
        (lab["rule"], lab[MODES[pair.mode]], ""),
        both("shift", lambda g: factor(g.shift)), both("least", lambda g: factor(g.least_shift)),
        both("d", lambda g: mm(2 * g.r)), both("db", lambda g: mm(2 * g.rb)),
        both("da", lambda g: mm(2 * g.ra)), both("df", lambda g: mm(2 * g.rf)),
        both("dw", lambda g: mm(2 * g.rw)), both("s", lambda g: mm(g.s)), both("e", lambda g: mm(g.e)),
        both("sa", lambda g: mm(g.sa)),
        (lab["centre"], f"{length(pair.centre_mm)} ({length(pair.reference_centre_mm)}) mm", ""),
        (lab["angle_w"], f"{figure_text('gear_angle', math.degrees(pair.alpha_w))}°", ""),
        (lab["y"], f"{factor(pair.y)}, {factor(pair.dy)}", ""),
        (lab["pb"], mm(pair.pb), ""), (lab["lines"], f"{length(pair.n1n2)}, {length(pair.b1b2)} mm", ""),
        (lab["eps"], factor(pair.contact_ratio), ""),
        (lab["undercut"], verdict("undercut1"), verdict("undercut2")),
        (lab["tip"].format(k=tip_limit_text(p)), verdict("tip1"), verdict("tip2")),
        (lab["contact"].format(k=number_text(p.contact_limit)), verdict("contact"), ""),
        (lab["interference"], verdict("interference1"), verdict("interference2")),
    ]
