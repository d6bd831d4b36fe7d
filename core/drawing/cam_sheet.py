"""The feed cam's sheet (凸轮机构设计图), the course design's third, on a GB paper.

Upper left the cam to a standard scale in its own frame, as the graphical inversion method
draws it: the actual profile thick, the pitch curve thin dash-dot, the base circle thin, the
follower arm and roller at cam angle 0 (the start of the rise) with the pivot, the line of
centres, the turning sense, and the rise, outer-dwell, return and inner-dwell sectors marked
with their angles (measured against the cam's turning, as the inverted follower moves);
lower left the inputs and the synthesized figures; on the right the follower's ψ, ω and α
and the pressure angle with its allowances over the cam angle δ, each to a stated scale μ.
Every number comes from :mod:`core.cam` at the first crank speed (the cam turns with the
crank).

Texts are looked up in ``labels`` (keys of :data:`ENGLISH`), so the caller chooses the
language; numbers are formatted here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

import numpy as np

from core.base.figure_text import figure_text
from core.cam import Cam
from core.cam.follower import pitch, pressure_angle, profile
from core.cam.table import follower_peaks

from . import sheet_dims as sd
from .charts import ARROW, Curve, arrow, chart, scale_notes
from .dxf import CENTER, OUTLINE, THIN
from .labels import Room, box_distance, boxes_meet
from .motion import CAPTION, GAP, TABLE_ROW, caption
from .segments import crossings_each, strokes
from .sheet import (Box, Circle, Item, Paper, Placement, Sheet, fit, frame_items, line, marked,
                    number_text, scale_text, standard_scale, symbol)
from .cells import table
from .sheet_dims import Dimension
from .title_block import TITLE_ENGLISH, TitleBlock, sheet_title_block, title_block_box

ENGLISH = {
    "title": "Feed cam",
    "profile": "Cam profile by inversion, μ_l = {mu} m/mm ({scale})",
    "profile_note": "Actual profile thick, pitch curve dash-dot, the follower at δ = 0; the cam turns clockwise",
    "curves": "Follower angle, angular velocity and acceleration over the cam angle, n = {rpm} r/min",
    "pressure": "Pressure angle over the cam angle, allowances [α] dashed",
    "psi": "ψ/(°)", "omega": "ω/(rad/s)", "alpha": "α/(rad/s²)", "angle": "α/(°)", "delta": "δ/(°)",
    "mu_psi": "μ_ψ = {mu} °/mm", "mu_omega": "μ_ω = {mu} (rad/s)/mm", "mu_alpha": "μ_α = {mu} (rad/s²)/mm",
    "mu_angle": "μ_α = {mu} °/mm", "mu_delta": "μ_δ = {mu} °/mm",
    "rise_sector": "δ_0 = {deg}°", "dwell_sector": "δ_s = {deg}°", "return_sector": "δ_0′ = {deg}°",
    "inner_sector": "δ_s′ = {deg}°",
    "figures": "Cam data and results", "quantity": "Quantity", "value": "Value",
    "arm": "Follower arm l", "swing": "Swing ψ_max", "rise": "Rise δ_0, law",
    "dwell": "Outer dwell δ_s", "return": "Return δ_0′, law", "inner": "Inner dwell δ_s′",
    "allowed": "Allowed pressure angle rise / return", "n": "Cam speed n",
    "base": "Base radius r_0 (pitch curve)", "distance": "Centre distance a",
    "initial": "Initial arm angle ψ_0", "side": "Roller side of the line of centres",
    "above": "above", "below": "below",
    "max_pressure": "Max pressure angle rise / return", "rho": "Min convex radius ρ_min",
    "roller": "Roller radius r", "profile_base": "Profile base radius r_0 − r",
    "allowance": "Pressure angle allowance", "exceeded": "EXCEEDED",
    "peaks": "Follower ω_max / α_max", "phase": "Rise starts at crank angle",
    "parabolic": "parabolic", "cosine": "cosine", "sine": "sine", "poly345": "3-4-5",
    **TITLE_ENGLISH,
}
POINTS = 1440                 # a quarter degree of cam angle apart, as the cam's DXF
CURVE_STEP_DEG = 0.5
NAMED_CLEAR = 2.0              # paper mm a dimension's text keeps off a point named after it
SECTOR_ROOM = (22.0, 10.0)    # paper mm beside and above/below the cam for the sectors' angles
ENLARGEMENTS = (2.0, 2.5, 4.0, 5.0)     # GB/T 14690's enlargements up to 5:1 (10:1 is for details)
SMALL_ROW = 6.0               # table rows on A2 and A3, mm (3.5 mm text still fits)
PIVOT_MM = 1.5                # radius of the pivot's and the centre's circles on the paper


@dataclass(frozen=True)
class CamSheet:
    """The sheet and what the tests measure on it."""

    sheet: Sheet
    scale: float                      # cam mm per paper mm: 1:scale (< 1 an enlargement)
    placement: Placement              # cam-frame mm → paper mm
    base_circle: Circle               # as drawn
    pivot: tuple[float, float]        # the follower pivot A on the paper
    centre: tuple[float, float]       # the cam centre O on the paper
    charts: dict[str, tuple[float, float, tuple[float, float]]]
    """ψ, ω, α, pressure: (μy, μδ, paper origin)."""
    rows: list[tuple[str, str]]
    areas: dict[str, tuple[Box, tuple[Item, ...]]]


def cam_sheet(cam: Cam, rpm: float, paper: Paper, *, labels: Mapping[str, str] = ENGLISH,
              block: TitleBlock | None = None) -> CamSheet:
    """The sheet of ``cam`` turning at ``rpm`` (the crank's speed) on ``paper``."""
    lab = {**ENGLISH, **labels}
    bx0, by0, bx1, by1 = paper.border
    split_x = bx0 + 0.5 * (bx1 - bx0)
    areas: dict[str, tuple[Box, tuple[Item, ...]]] = {}

    rows = figure_rows(cam, rpm, lab)
    cells = [(lab["quantity"], lab["value"])] + rows
    table_w = min(split_x - bx0 - 2 * GAP, 200.0)
    row = TABLE_ROW if paper.height > 500.0 else SMALL_ROW      # A2, A3: the cam needs the room
    table_top = by0 + GAP + row * len(cells)
    table_area = (bx0 + GAP, by0 + GAP, bx0 + GAP + table_w, table_top + 2 * CAPTION)
    items = table((bx0 + GAP, table_top), (0.6 * table_w, 0.4 * table_w), cells, row, 3.5,
                  aligns="lc")
    items.append(caption(lab["figures"], ((table_area[0] + table_area[2]) / 2.0, table_area[3]),
                         table_w, CAPTION))
    areas["figures"] = (table_area, tuple(items))

    profile_area = (bx0 + GAP, table_area[3] + GAP, split_x - GAP, by1 - GAP)
    scale, place, items, dims = _profile(cam, profile_area, lab)
    areas["profile"] = (profile_area, tuple(items))

    charts: dict[str, tuple[float, float, tuple[float, float]]] = {}
    curves_area = (split_x + GAP, title_block_box(paper)[3] + GAP, bx1 - GAP, by1 - GAP)
    items = _curves(cam, rpm, curves_area, lab, charts)
    areas["curves"] = (curves_area, tuple(items))

    areas["title"] = sheet_title_block(paper, block, lab, ratio_text(scale))
    everything = [*frame_items(paper), *(it for _, group in areas.values() for it in group)]
    base = next(it for it in areas["profile"][1] if isinstance(it, Circle) and it.layer == THIN)
    f = cam.follower
    return CamSheet(Sheet(paper, tuple(everything), dimensions=tuple(dims)), scale, place, base,
                    tuple(place([f.distance_mm, 0.0])), tuple(place([0.0, 0.0])), charts, rows, areas)


def ratio_text(scale: float) -> str:
    """The scale as GB/T 14690 writes it: 1:2.5 for a reduction, 2:1 for an enlargement."""
    return scale_text(scale) if scale >= 1.0 else f"{number_text(round(1.0 / scale, 6))}:1"


def _sector_edges(cam: Cam) -> list[float]:
    """Cam angles (°) where the phases meet: 0, rise, + outer dwell, + return."""
    p = cam.program
    return [0.0, p.rise_deg, p.rise_deg + p.dwell_deg, p.feed_deg]


def _profile(cam: Cam, area: Box, lab: Mapping[str, str]) -> tuple[float, Placement, list[Item]]:
    """The cam drawn by inversion in ``area``: the largest standard scale that fits."""
    f = cam.follower
    delta = np.linspace(0.0, 2.0 * math.pi, POINTS, endpoint=False)
    p = pitch(f, cam.program, delta)
    actual = profile(p, cam.roller_mm)
    reach = float(np.hypot(*p.point).max()) + cam.roller_mm        # the roller's outer side
    a, r0 = f.distance_mm, cam.base_radius_mm
    bounds = (-reach, -reach, max(a, reach), reach)
    box = (area[0], area[1], area[2], area[3] - 3.2 * CAPTION)
    room_w = box[2] - box[0] - 2 * SECTOR_ROOM[0]
    room_h = box[3] - box[1] - 2 * SECTOR_ROOM[1]
    scale = max(standard_scale(bounds[2] - bounds[0], room_w), standard_scale(bounds[3] - bounds[1], room_h))
    if scale == 1.0:               # a small cam: the largest enlargement that fits
        fits = [k for k in ENLARGEMENTS if (bounds[2] - bounds[0]) * k <= room_w
                and (bounds[3] - bounds[1]) * k <= room_h]
        scale = 1.0 / max(fits, default=1.0)
    place = fit(bounds, box, scale)
    o, pivot, b0 = place([0.0, 0.0]), place([a, 0.0]), place(p.point[:, 0])
    outer = place.length(reach)
    items: list[Item] = [line(place(actual.T), OUTLINE, closed=True),
                         line(place(p.point.T), CENTER, closed=True),
                         Circle(tuple(o), place.length(r0), THIN)]
    # the line of centres through O and A, the other centre line across O
    items.append(line([o - (outer + 4.0, 0.0), pivot + (6.0, 0.0)], CENTER))
    items.append(line([o - (0.0, outer + 4.0), o + (0.0, outer + 4.0)], CENTER))
    # the follower at δ = 0: the roller, the arm from the pivot, the pivot on its support
    items.append(Circle(tuple(b0), place.length(cam.roller_mm), OUTLINE))
    items.append(line([pivot, b0], OUTLINE))
    for centre in (pivot, o):
        items.append(Circle(tuple(centre), PIVOT_MM, OUTLINE))
    foot = pivot - (0.0, PIVOT_MM)
    items.append(line([foot, foot + (-3.0, -5.0), foot + (3.0, -5.0)], THIN, closed=True))
    items.append(line([foot + (-5.0, -5.0), foot + (5.0, -5.0)], OUTLINE))
    # the sectors: rays at the phase edges, measured counter-clockwise (against the cam's turn)
    edges = _sector_edges(cam)
    ray_out = outer + 4.0
    names = ("rise_sector", "dwell_sector", "return_sector", "inner_sector")
    spans = np.diff(edges + [360.0])
    for edge in edges:
        u = np.array([math.cos(math.radians(edge)), math.sin(math.radians(edge))])
        items.append(line([o, o + ray_out * u], THIN))
    sectors = []
    for start, span, key in zip(edges, spans, names):
        if span <= 0.0:
            continue
        items += sector_arc(o, ray_out - 2.0, start, span)
        sectors.append((math.radians(start + span / 2.0), lab[key].format(deg=number_text(round(float(span), 3)))))
    # the turning sense: a clockwise arc with its head, inside the base circle (before the
    # dimensions, which keep their texts off it)
    r_arrow = 0.45 * place.length(r0)
    arc = np.radians(np.linspace(150.0, 60.0, 24))
    pts = o + r_arrow * np.column_stack([np.cos(arc), np.sin(arc)])
    items.append(line(pts[:-3], THIN))
    items += arrow(pts[-4], pts[-1], THIN)
    mids = [o + (ray_out - 2.0) * np.array([math.cos(mid), math.sin(mid)]) for mid, _ in sectors]
    dims = cam_dimensions(o, pivot, b0, place.length(r0), outer, scale, items, box, np.array(mids))
    for dim in dims:
        items += [*dim.parts, *dim.kept]
    room = Room(items, within=box, taken=[d.text.box() for d in dims])   # the labels after all the lines
    room.name(mids)                            # each angle read as its own arc's
    for (mid, caption_text), at in zip(sectors, mids):
        u = np.array([math.cos(mid), math.sin(mid)])
        text, spans = marked(caption_text)
        items += room.place(text, (float(at[0]), float(at[1])), 3.5, tuple(u), gap=1.0, rings=4,
                            subscripts=spans)
    for name, at, away in (("O", o, (-1.0, -1.0)), ("A", pivot, (1.0, 1.0)),
                           (("B", "0"), b0, tuple(b0 - pivot)), ("ω", pts[len(pts) // 2], (1.0, 1.0))):
        text, spans = symbol(name)
        items += room.place(text, (float(at[0]), float(at[1])), 3.5, away, gap=PIVOT_MM + 0.5,
                            subscripts=spans, leader_gap=PIVOT_MM + 0.3)
    middle = (area[0] + area[2]) / 2.0
    width = area[2] - area[0]
    items.append(caption(lab["profile"].format(mu=number_text(scale / 1000.0), scale=ratio_text(scale)),
                         (middle, area[3]), width))
    items.append(caption(lab["profile_note"], (middle, area[3] - 1.8 * CAPTION), width, 3.5))
    return scale, place, items, dims


def sector_arc(o: np.ndarray, radius: float, start: float, span: float) -> list[Item]:
    """A phase's arc at ``radius`` round ``o`` from ``start`` over ``span`` (°, counter-
    clockwise) with an arrowhead at each end on its edge ray: an angle's dimension line, so
    that the four arcs read as the sectors' angles, not as one more circle of the cam."""
    arc = np.radians(np.linspace(start, start + span, max(int(span), 2) + 1))
    pts = o + radius * np.column_stack([np.cos(arc), np.sin(arc)])
    size = min(ARROW[0], 0.3 * radius * math.radians(span))    # a short sector keeps its heads apart
    back = size / 0.6 / radius          # arrow() draws a head 0.6 of a short line: this one's all head
    tip0, tip1 = pts[0], pts[-1]
    b0 = o + radius * np.array([math.cos(arc[0] + back), math.sin(arc[0] + back)])
    b1 = o + radius * np.array([math.cos(arc[-1] - back), math.sin(arc[-1] - back)])
    return [line(pts, THIN)] + arrow(b0, tip0, THIN)[1:] + arrow(b1, tip1, THIN)[1:]


def cam_dimensions(o: np.ndarray, pivot: np.ndarray, b0: np.ndarray, r0: float, outer: float,
                   scale: float, drawn: list[Item], within: Box,
                   named: np.ndarray = np.empty((0, 2))) -> list[Dimension]:
    """The cam's three sizes a teacher checks on the drawing, with their true values (the
    sheet is 1:scale): the centre distance a = OA beyond the cam (under it, else over it),
    the arm l = AB0 beside the arm and the base radius r0 from O to the base circle, each
    the first of its spots whose text no line crosses (of ``drawn``, of the dimensions
    before it, nor its own: a led text can lie across its own dimension line), whose lines
    cross no text of the dimensions before it, and which lies ``within`` (else the least
    crossed); of those, the one whose leader crosses the fewest lines. A text over one of
    the points ``named`` later (the sectors' arcs, whose angles are placed after the
    dimensions) counts as crossed: the arm's text, narrower once set at its font's widths, sat
    on the rise sector's arc and left its angle no spot (a random cam on A3)."""
    ways = np.radians(np.r_[240.0:360.0:15.0, 225.0:90.0:-15.0, 0.0:90.0:15.0])
    options = {
        "a": [sd.aligned(tuple(pivot), tuple(o), off, "a", scale) for off in (outer + 8.0, -(outer + 8.0))],
        "l": [sd.aligned(tuple(pivot), tuple(b0), off, "l", scale) for off in (-8.0, 8.0, -14.0, 14.0)],
        "r0": [sd.aligned(tuple(o), tuple(o + r0 * np.array([math.cos(t), math.sin(t)])), 0.0, "r0", scale)
               for t in ways]}
    segs = strokes(drawn)
    chosen: list[Dimension] = []

    def cost(dim: Dimension) -> tuple[int, int, int]:
        box = dim.text.box()
        inside = within[0] <= box[0] and box[2] <= within[2] and within[1] <= box[1] and box[3] <= within[3]
        apart = not any(boxes_meet(box, d.text.box()) for d in chosen)
        own = strokes([*dim.parts, *dim.kept])
        crossed = (sd.text_crossings(dim.text, np.vstack([segs, own]))
                   + sum(sd.text_crossings(d.text, own) for d in chosen)
                   + int(np.sum(box_distance(box, named) <= NAMED_CLEAR)))
        return (0 if inside and apart else 1, crossed, int(crossings_each(strokes(dim.kept), segs).sum()))

    for candidates in options.values():
        best = min(candidates, key=cost)        # the first of the least crossed
        if cost(best)[:2] != (0, 0):            # its text out beyond the cam on a leader, the nearest first
            corners = sorted((o + (outer + 6.0) * np.array([math.cos(t), math.sin(t)]) for t in ways),
                             key=lambda c: math.dist(c, best.text.position))
            led = [sd.led(best, tuple(c)) for c in corners]
            best = min([best] + led, key=cost)
        chosen.append(best)
        segs = np.vstack([segs, strokes([*best.parts, *best.kept])])
    return chosen


def _curves(cam: Cam, rpm: float, box: Box, lab: Mapping[str, str],
            charts: dict[str, tuple[float, float, tuple[float, float]]]) -> list[Item]:
    """ψ, ω and α over δ in three panels on one δ scale, then the pressure angle with the
    allowances over the rise and the return."""
    x0, y0, x1, y1 = box
    items: list[Item] = [caption(lab["curves"].format(rpm=number_text(rpm)), ((x0 + x1) / 2.0, y1),
                                 x1 - x0, 3.5)]
    top = y1 - 2 * CAPTION
    panel = (top - y0) / 4.0
    deg = np.arange(0.0, 360.0 + CURVE_STEP_DEG / 2.0, CURVE_STEP_DEG)
    delta = np.radians(deg)
    p = pitch(cam.follower, cam.program, delta)
    w = rpm * 2.0 * math.pi / 60.0
    edges = _sector_edges(cam)
    # a tick per phase edge; the chart leaves out a number that would stand too near the last
    # one written (charts.spaced_labels)
    ticks = [(e, f"{e:g}") for e in dict.fromkeys(edges + [360.0])]
    series = (("psi", np.degrees(p.motion.psi)), ("omega", p.motion.psi1 * w),
              ("alpha", p.motion.psi2 * w * w), ("angle", np.degrees(pressure_angle(cam.follower, p))))
    prog, inputs = cam.program, cam.inputs
    for k, (key, y) in enumerate(series):
        pbox = (x0, top - (k + 1) * panel, x1, top - k * panel)
        levels = ()
        if key == "angle":
            items.append(caption(lab["pressure"], ((x0 + x1) / 2.0, pbox[3] - 1.0), x1 - x0, 3.5))
            pbox = (pbox[0], pbox[1], pbox[2], pbox[3] - 2 * CAPTION)
            levels = ((0.0, prog.rise_deg, inputs.pressure_deg),
                      (edges[2], edges[3], inputs.return_pressure_deg))
        drawn = chart(pbox, deg, [Curve(y)], lab["delta"], lab[key], ticks, levels=levels,
                      notes=scale_notes(lab["mu_" + key], lab["mu_delta"] if k == 0 else None))
        items += drawn.items
        charts[key] = (drawn.y_scale, drawn.x_scale, drawn.origin)
    return items


def figure_values(cam: Cam, lab: Mapping[str, str]) -> dict[str, str]:
    """The cam's figures that do not depend on the speed, as texts by their word's key in
    ``lab``: each as ``shaper cam``, the report and the answer key write it (figure_text's
    kinds). The sheet's table prints them, the cam's DXF notes some of them."""
    f, prog, inputs = cam.follower, cam.program, cam.inputs
    mm = lambda v: f"{figure_text('length', v)} mm"                     # noqa: E731
    deg = lambda v: f"{figure_text('angle', v)}°"                       # noqa: E731
    return {"arm": mm(f.arm_mm), "swing": f"{prog.swing_deg:g}°",
            "rise": f"{prog.rise_deg:g}°, {lab[prog.rise_law]}", "dwell": f"{prog.dwell_deg:g}°",
            "return": f"{prog.return_deg:g}°, {lab[prog.return_law]}",
            "inner": f"{prog.inner_dwell_deg:g}°",
            "allowed": f"{inputs.pressure_deg:g}° / {inputs.return_pressure_deg:g}°",
            "base": mm(cam.base_radius_mm), "distance": mm(f.distance_mm), "initial": deg(f.initial_deg),
            "side": lab["above"] if f.side > 0 else lab["below"],
            "max_pressure": f"{deg(cam.max_pressure_rise_deg)} / {deg(cam.max_pressure_return_deg)}",
            "rho": mm(cam.min_curvature_radius_mm), "roller": mm(cam.roller_mm),
            "profile_base": mm(cam.base_radius_mm - cam.roller_mm)}


def figure_rows(cam: Cam, rpm: float, lab: Mapping[str, str]) -> list[tuple[str, str]]:
    """The data sheet's inputs, then the synthesized figures, as the table prints them."""
    values = figure_values(cam, lab)
    peaks = follower_peaks(cam, rpm)
    rows = [(lab[k], values[k]) for k in ("arm", "swing", "rise", "dwell", "return", "inner", "allowed")]
    rows.append((lab["n"], f"{number_text(rpm)} r/min"))
    rows += [(lab[k], values[k]) for k in ("base", "distance", "initial", "side", "max_pressure", "rho",
                                          "roller", "profile_base")]
    rows.append((lab["peaks"], f"{peaks['follower_omega_max_rad_s']:.4g} rad/s / "
                               f"{peaks['follower_alpha_max_rad_s2']:.4g} rad/s²"))
    if not cam.within_allowance:            # a checked cam (--base, --distance) may exceed it
        rows.append((lab["allowance"], lab["exceeded"]))
    if cam.timing is not None:
        rows.append((lab["phase"], f"{figure_text('angle', cam.timing.phase_deg)}°"))
    return rows
