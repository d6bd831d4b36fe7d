"""The motion-analysis sheet (运动分析图) of the course design, laid out on a GB paper.

Upper left the mechanism to a standard scale at the N numbered positions (thin)
and the two limit positions (thick), with the tool's path and the positions
numbered as in the positions table; upper right the ram's s, v and a over one
φ axis (at the first crank speed: the speed of the positions table and the
polygons, so every number on the sheet belongs to one speed); lower left the
velocity and acceleration polygons at two positions; lower right the main
dimensions and the title block. Every drawing states its scale the course
design's way, μ in units per mm of paper.

Texts are looked up in ``labels`` (keys of :data:`ENGLISH`), so the caller
chooses the language; numbers are formatted here.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Mapping, Sequence

import numpy as np

from core.base.errors import DesignError
from core.base.figure_text import figure_text
from core.linkage.geometry import Design
from core.linkage.kinematics import solve
from core.forces.polygons import acceleration_polygon, velocity_polygon
from core.course_design.positions import positions, special_angles

from . import mechanism as mech
from . import mechanism_dims, path_numbers
from .charts import (TICK, Curve, chart, polygon_extent, polygon_fit_scale, polygon_items, polygon_notes,
                     scale_notes, spaced_labels)
from .dxf import OUTLINE, THIN
from .labels import Room
from .sheet import (TEXT_HEIGHTS, Box, Circle, Item, Paper, Placement, Sheet, Text, fit, frame_items,
                    item_box, marked, marked_text, number_text, scale_text, smaller_height,
                    standard_scale, text_width)
from .cells import fitting_height, table
from .sheet_dims import Dimension
from .title_block import TITLE_ENGLISH, TITLE_WIDTH, TitleBlock, sheet_title_block, title_block_box

ENGLISH = {
    "title": "Motion analysis",
    "mechanism": "Kinematic diagram at {count} positions, μ_l = {mu} m/mm ({scale})",
    "curves": "Ram displacement, velocity and acceleration, n = {rpm} r/min",
    "s": "s/mm", "v": "v/(m/s)", "a": "a/(m/s²)", "phi": "φ/(°)",
    "mu_s": "μ_s = {mu} m/mm", "mu_v": "μ_v = {mu} (m/s)/mm", "mu_a": "μ_a = {mu} (m/s²)/mm",
    "mu_phi": "μ_φ = {mu} °/mm", "position": "Position",
    "velocity": "Velocity polygon, φ = {angle}°, μ_v = {mu} (m/s)/mm",
    "acceleration": "Acceleration polygon, φ = {angle}°, μ_a = {mu} (m/s²)/mm",
    "dimensions": "Main dimensions", "quantity": "Quantity", "value": "Value",
    "L1": "Crank O_2A, L_1", "L2": "Frame O_2O_4, L_2", "L3": "Lever O_4B, L_3", "L4": "Rod BC, L_4",
    "h": "Guide above O_2, h", "H": "Stroke H", "K": "Time ratio K",
    "theta": "Extreme-position angle θ", "n": "Crank speed n",
    **TITLE_ENGLISH,
}
# The polygons' points as textbooks name them (a₃′: an index as a subscript, then the prime)
POINT_NAMES = {"p": "p", "a3": ("a", "3"), "a4": ("a", "4"), "b": "b", "c": "c", "p'": "p′",
               "a3'": [("a", "3"), "′"], "k'": "k′", "n4'": [("n", "4"), "′"], "a4'": [("a", "4"), "′"],
               "b'": "b′", "c'": "c′", "n5'": [("n", "5"), "′"]}
GAP = 6.0                     # mm between the areas of the sheet
MAX_POSITIONS = 72            # more thin mechanisms than this fill the drawing with ink
CAPTION = 5.0                 # caption text height
LINE_PITCH = 1.5              # a caption's lines apart, in text heights (GB/T 14691: at least 1.4)
TABLE_ROW = 7.0
JOINT_GAP = mech.PIN_RADIUS + 1.0   # a joint's label (or a position's number) off its pin, mm
LABEL_ROOM = 3.0              # around the mechanism's linework, for the joints' names
MARK_RADIUS = 0.8             # a marked point of a curve (the working stroke's end), mm
ROW_ROOM = 1.5                # under the s chart's degrees, for the positions' numbers


@dataclass(frozen=True)
class MotionSheet:
    """The sheet and what the tests measure on it."""

    sheet: Sheet
    scale: float              # the mechanism's reduction 1:scale
    placement: Placement      # model mm → paper mm of the mechanism
    diagram_deg: tuple[float, float]
    areas: dict[str, tuple[Box, tuple[Item, ...]]]
    """Each drawing's area on the paper and its items: the areas do not overlap, and
    each drawing stays inside its own."""
    dimensions: tuple[Dimension, ...] = ()
    """The mechanism's dimensions (their pictures are among the mechanism's items)."""


def motion_sheet(design: Design, rpm: float, paper: Paper, *, count: int = 12,
                 diagram_deg: tuple[float, float] | None = None, idle_fraction: float = 0.05,
                 labels: Mapping[str, str] = ENGLISH, block: TitleBlock | None = None) -> MotionSheet:
    """The motion sheet of ``design`` at ``rpm`` on ``paper``; DesignError for more than
    MAX_POSITIONS positions."""
    if not 1 <= count <= MAX_POSITIONS:
        raise DesignError("positions", count, f"must be 1 to {MAX_POSITIONS} on a drawing sheet")
    lab = {**ENGLISH, **labels}
    bx0, by0, bx1, by1 = paper.border
    width, height = bx1 - bx0, by1 - by0
    split_x, split_y = bx0 + 0.5 * width, by0 + 0.42 * height
    where = positions(design, count, (), idle_fraction)
    numbered = where.number > 0
    angles = where.crank_deg[numbered]
    special = special_angles(design, idle_fraction)
    limits = (special["limit_work_start"], special["limit_work_end"])
    diagrams = diagram_deg or nearest_mid_strokes(angles, limits)
    areas: dict[str, tuple[Box, tuple[Item, ...]]] = {}

    mech_area = (bx0 + GAP, split_y + GAP, split_x - GAP, by1 - GAP)
    mech_box = mech_area[:3] + (mech_area[3] - 2 * CAPTION,)
    scale, place, mech_items, dims = _mechanism(design, mech_box, angles, limits)
    mech_items.append(caption(lab["mechanism"].format(count=count, mu=number_text(scale / 1000.0),
                                                      scale=scale_text(scale)),
                              ((mech_box[0] + mech_box[2]) / 2.0, mech_area[3]), mech_box[2] - mech_box[0]))
    areas["mechanism"] = (mech_area, tuple(mech_items))
    motion = solve(design, np.radians(np.linspace(0.0, 360.0, 721)), [rpm])
    end = limit_mark(design, rpm, angles, float(limits[1]))
    rows = [(lab["quantity"], lab["value"])] + _dimension_rows(design, rpm, lab)
    table_top = title_block_box(paper)[3] + GAP + TABLE_ROW * len(rows)
    # the curves above the dimensions' table (on A3 it reaches above the split)
    curves_area = (split_x + GAP, max(split_y, table_top) + GAP, bx1 - GAP, by1 - GAP)
    areas["curves"] = (curves_area, tuple(_curves(motion, curves_area, angles, where.number[numbered],
                                                  lab, rpm, end)))
    polygons_area = (bx0 + GAP, by0 + GAP, bx1 - TITLE_WIDTH - 2 * GAP, split_y - GAP)
    areas["polygons"] = (polygons_area, tuple(_polygons(design, rpm, diagrams, polygons_area, lab)))
    areas["dimensions"] = ((bx1 - TITLE_WIDTH, table_top - TABLE_ROW * len(rows), bx1, table_top),
                           tuple(table((bx1 - TITLE_WIDTH, table_top), (120.0, 60.0), rows,
                                       TABLE_ROW, 3.5, aligns="lc")))
    areas["title"] = sheet_title_block(paper, block, lab, scale_text(scale))
    items = [*frame_items(paper), *(it for _, group in areas.values() for it in group)]
    return MotionSheet(Sheet(paper, tuple(items), dimensions=tuple(dims)), scale, place, diagrams, areas,
                       tuple(dims))


def caption(text: str, top_centre: tuple[float, float], room: float, largest: float = CAPTION) -> Text:
    """A drawing's caption hanging from ``top_centre``, as large as fits ``room`` (≤ ``largest``),
    its indices subscripts (the index notation of ``sheet.marked``: M_m, μ_l)."""
    h = fitting_height(marked(text)[0], room, largest)
    x, y = top_centre
    return marked_text(text, (x, y - 0.2 * h), h, "ct", room)     # the accents' room above h


def caption_lines(text: str, top_centre: tuple[float, float], room: float, largest: float = CAPTION) -> list[Text]:
    """:func:`caption`, or where even the smallest height would cut it short (a polygon's
    caption in an A3 sheet's cell), its clauses (each ending in a comma) on as many lines as
    they need at that height, one under another: a scale cut to "μ_a = 0.06 (m/…", or left
    out with the angle, is no scale. A clause still too long for a line is cut."""
    height = TEXT_HEIGHTS[0]
    if text_width(marked(text)[0], height) <= room:
        return [caption(text, top_centre, room, largest)]
    parts = re.split(r"(?<=[,，])(\s*)", text)        # clause, space, clause …
    lines = [parts[0]]
    for space, clause in zip(parts[1::2], parts[2::2]):
        if text_width(marked(lines[-1] + space + clause)[0], height) <= room:
            lines[-1] += space + clause
        else:
            lines.append(clause)
    x, y = top_centre
    return [marked_text(line, (x, y - 0.2 * height - k * LINE_PITCH * height), height, "ct", room)
            for k, line in enumerate(lines)]


def nearest_mid_strokes(angles: np.ndarray, limits: tuple[float, float]) -> tuple[float, float]:
    """The numbered positions nearest the middle of the working and of the return stroke."""
    work = (limits[1] - limits[0]) % 360.0
    mids = ((limits[0] + work / 2.0) % 360.0, (limits[1] + (360.0 - work) / 2.0) % 360.0)
    near = lambda t: float(angles[np.argmin(np.abs((angles - t + 180.0) % 360.0 - 180.0))])  # noqa: E731
    return near(mids[0]), near(mids[1])


SERIES_APART = 3.5          # mm between a crank number and a tool path number


def _mechanism(design: Design, box: Box, angles: np.ndarray, limits: Sequence[float]):
    """The mechanism at ``angles`` (thin) and ``limits`` (thick) with its dimensions, at the
    largest standard scale at which all of it fits ``box``, centred there; its scale,
    placement, items and dimensions."""
    bounds = mech.bounds(design)
    room_w = box[2] - box[0] - mech.RAM[0] - 2 * mech.TOOL_AHEAD - 10.0
    room_h = box[3] - box[1] - 2 * mech.SUPPORT - 2 * mech.RAM[1] - 2 * mech.TOOL_DROP
    scale = max(standard_scale(bounds[2] - bounds[0], room_w),
                standard_scale(bounds[3] - bounds[1], room_h))
    fits = False
    while not fits:             # the dimensions' room is known once they are placed
        for compact in (False, True):
            place = fit(bounds, box, scale)
            items, dims, asked = _linework(design, place, angles, limits, compact)
            x0, y0, x1, y1 = _extent(items)
            fits = x1 - x0 <= box[2] - box[0] - 2 * LABEL_ROOM and y1 - y0 <= box[3] - box[1] - 2 * LABEL_ROOM
            if fits or not asked:       # compact would change nothing: the same items, no fit
                break
        if not fits:
            scale = standard_scale(scale * (1.0 + 1e-9), 1.0)     # the next of the series
    shift = ((box[0] + box[2] - x0 - x1) / 2.0, (box[1] + box[3] - y0 - y1) / 2.0)
    place = Placement(scale, (place.origin[0] + shift[0], place.origin[1] + shift[1]), place.anchor)
    items, dims, _ = _linework(design, place, angles, limits, compact)
    taken: list[Box] = mechanism_dims.obstacles(dims)
    numbers = path_numbers.tool_path_numbers(design, place, angles, items, taken, box,
                                             mechanism_dims.obstacles(dims, texts_only=True))
    items += numbers
    room = Room(items, within=box, taken=taken)      # the names after all the lines, clear of them
    o2 = place([0.0, design.frame])
    pins = place(mech.joints(design, angles)["A"].T)
    moving = mech.joints(design, np.concatenate([angles, limits]))
    joints = mech.joint_anchors(design, float(limits[0]), place, 5.0)
    # a joint's name is read as its own: nearer it than any pin or joint drawn at another position
    room.name([p for _, _, p, _ in joints] + list(pins) + list(place(moving["B"].T)) + list(place(moving["C"].T)))
    for text, spans, p, way in joints:
        items += room.place(text, tuple(p), 5.0, tuple(way), gap=JOINT_GAP, subscripts=spans,
                            leader_gap=mech.PIN_RADIUS + 0.3)
    # a crank number keeps a text height off the tool path's numbers: side by side, the two
    # series read as one row ("4 6 5 7 9")
    room.taken += [(b[0] - SERIES_APART, b[1] - SERIES_APART, b[2] + SERIES_APART, b[3] + SERIES_APART)
                   for b in (t.box() for t in numbers if isinstance(t, Text))]
    for k, p in enumerate(pins, start=1):      # a number with no free spot is left out
        items += room.place(str(k), (float(p[0]), float(p[1])), 3.5, tuple(p - o2), gap=JOINT_GAP,
                            leader_gap=mech.PIN_RADIUS + 0.3, shrink=False)
    return scale, place, items, dims


def _linework(design: Design, place: Placement, angles: np.ndarray, limits: Sequence[float],
              compact: bool = False):
    """The frame, the tool path, the links at ``angles`` (thin) and ``limits`` (thick) and the
    dimensions' pictures (``mechanism_dims.dimensions``' ``compact``), as items; the
    dimensions; and whether ``compact`` counted (``mechanism_dims.dimensions``)."""
    items: list[Item] = mech.frame_items(design, place)
    items += mech.tool_path(design, place, angles)
    for phi in angles:
        items += mech.links_at(design, float(phi), place, THIN, bodies=False)
    for phi in limits:
        items += mech.links_at(design, float(phi), place, OUTLINE)
    dims, asked = mechanism_dims.dimensions(design, place, items, limits, compact)
    return items + [part for dim in dims for part in (*dim.parts, *dim.kept)], dims, asked


def _extent(items: Sequence[Item]) -> Box:
    boxes = np.array([item_box(it) for it in items])
    return (float(boxes[:, 0].min()), float(boxes[:, 1].min()), float(boxes[:, 2].max()),
            float(boxes[:, 3].max()))


def limit_mark(design: Design, rpm: float, angles: np.ndarray, limit_deg: float
               ) -> tuple[float, str, tuple[float, float, float]]:
    """The working stroke's end as the curves mark it: its crank angle (°), its name k′ after
    the last numbered position before it (8′ of 12 positions, as the course design names
    it) and the ram's s (mm), v (m/s) and a (m/s²) there, from core at that angle."""
    k = int(np.count_nonzero(np.asarray(angles) <= limit_deg + 1e-9))
    at = solve(design, np.radians([limit_deg]), [rpm])
    return limit_deg, f"{k}′", (float(at.ram_x[0]), float(at.ram_v[0, 0]), float(at.ram_a[0, 0]))


def _curves(motion, box: Box, angles: np.ndarray, numbers: np.ndarray,
            lab: Mapping[str, str], rpm: float,
            mark: tuple[float, str, tuple[float, float, float]] | None = None) -> list[Item]:
    """s, v and a over φ in three panels on one φ scale, stacked in ``box``: each φ axis
    ticked at the numbered positions and labelled in degrees (its title φ/(°)), and under
    the s axis, where no curve goes (s ≥ 0), the positions' numbers in a row of their own;
    ``mark`` (:func:`limit_mark`): the working stroke's end as a point on each curve, named."""
    x0, y0, x1, y1 = box
    items: list[Item] = [caption(lab["curves"].format(rpm=number_text(rpm)), ((x0 + x1) / 2.0, y1),
                                 x1 - x0)]
    top = y1 - 2 * CAPTION
    panel = (top - y0) / 3.0
    phi = np.degrees(motion.crank_angle)
    ticks = [(float(a), number_text(round(float(a), 1))) for a in angles]
    series = (("s", "mu_s", motion.ram_x, 1e-3), ("v", "mu_v", motion.ram_v[0], 1.0),
              ("a", "mu_a", motion.ram_a[0], 1.0))
    for k, (key, mu_key, y, unit) in enumerate(series):
        pbox = (x0, top - (k + 1) * panel, x1, top - k * panel)
        below = ROW_ROOM if k == 0 else 0.0
        notes = scale_notes(lab[mu_key], lab["mu_phi"] if k == 0 else None, unit)
        drawn = chart(pbox, phi, [Curve(np.asarray(y))], lab["phi"], lab[key], ticks, notes=notes,
                      below=below)
        crossed = _crossed_ticks(drawn, phi, np.asarray(y), ticks)
        if crossed:             # a degree the curve runs through is left out, its tick kept
            drawn = chart(pbox, phi, [Curve(np.asarray(y))], lab["phi"], lab[key],
                          [(a, "" if i in crossed else t) for i, ((a, _), t) in enumerate(zip(ticks, drawn.x_labels))],
                          notes=notes, below=below)
        items += drawn.items
        if k == 0:
            items += _position_row(drawn, phi[0], angles, numbers, lab["position"], pbox)
        if mark is not None:
            items += _marked_point(drawn, items, phi[0], mark[0], mark[2][k], mark[1], pbox)
    return items


def _marked_point(drawn, items: Sequence[Item], phi0: float, phi: float, value: float, name: str,
                  panel: Box) -> list[Item]:
    """A point of a chart's curve (at ``phi``, ``value`` in the chart's unit) as a small
    circle with its ``name`` placed clear of the chart's lines and texts."""
    left, zero = drawn.origin
    at = (left + (phi - phi0) / drawn.x_scale, zero + value / drawn.y_scale)
    dot = Circle(at, MARK_RADIUS, OUTLINE)
    room = Room(within=panel)
    room.draw([*items, dot])
    return [dot, *room.place(name, at, 3.5, (1.0, 1.0), gap=MARK_RADIUS + 0.8, leader_gap=MARK_RADIUS)]


def _crossed_ticks(drawn, phi: np.ndarray, y: np.ndarray, ticks) -> set[int]:
    """The tick labels of the chart ``drawn`` that its curve (``y`` over ``phi``) or its y axis
    (down to 2 mm under the lowest value) crosses."""
    from .sheet_dims import crossings
    left, zero = drawn.origin
    pts = np.column_stack([left + (phi - phi[0]) / drawn.x_scale, zero + y / drawn.y_scale])
    axis = [left, zero + min(float(y.min()), 0.0) / drawn.y_scale - 2.0, left, zero]
    segs = np.vstack([np.hstack([pts[:-1], pts[1:]]), axis])
    return {i for i, (a, text) in enumerate(ticks)
            if crossings(Text(text, (left + (a - phi[0]) / drawn.x_scale, zero - TICK - 1.0),
                              smaller_height(3.5), "ct").box(), segs)}


def _position_row(drawn, phi0: float, angles: np.ndarray, numbers: np.ndarray, title: str,
                  panel: Box) -> list[Item]:
    """The positions' numbers in a row under the degrees of the chart ``drawn`` (as many as
    stand a word space apart, the degrees' way: :func:`charts.spaced_labels`), titled at its
    left."""
    height = smaller_height(3.5)
    left, zero = drawn.origin
    row = zero - TICK - 1.0 - 1.35 * height - 0.5          # under the degrees' row
    xs = [left + (float(a) - phi0) / drawn.x_scale for a in angles]
    items: list[Item] = []
    for px, label in zip(xs, spaced_labels([(px, str(int(n))) for px, n in zip(xs, numbers)], height)):
        text = Text(label, (px, row), height, "ct")
        if label and text.box()[1] >= panel[1]:
            items.append(text)
    name = Text(title, (left - TICK - 1.0, row), height, "rt")
    if items and name.box()[0] >= panel[0]:
        items.append(name)
    return items


def _polygons(design: Design, rpm: float, diagrams: Sequence[float], box: Box,
              lab: Mapping[str, str]) -> list[Item]:
    """Velocity (top row) and acceleration (bottom row) polygons at the two angles, each
    to the largest round scale that fits its cell."""
    x0, y0, x1, y1 = box
    cw, ch = (x1 - x0) / 2.0, (y1 - y0) / 2.0
    items: list[Item] = []
    rows = (("velocity", velocity_polygon), ("acceleration", acceleration_polygon))
    for r, (kind, build) in enumerate(rows):
        polys = [build(design, float(a), rpm) for a in diagrams]
        for c, (angle, poly) in enumerate(zip(diagrams, polys)):
            cell = (x0 + c * cw, y1 - (r + 1) * ch, x0 + (c + 1) * cw, y1 - r * ch)
            # its equations and magnitudes at the cell's right, as the report lists them
            notes = _fitting_notes(poly, cell, 2 * CAPTION)
            side = max((t.box()[2] for t in notes), default=cell[2]) - min((t.box()[0] for t in notes),
                                                                          default=cell[2])
            room_w = cw - 24.0 - (side + 4.0 if notes else 0.0)
            # each its own scale: a slow position stays legible; labels need a margin
            mu = polygon_fit_scale(poly, room_w, ch - 2 * CAPTION - 14.0)
            titles = caption_lines(lab[kind].format(angle=number_text(round(angle, 2)), mu=number_text(mu)),
                                   ((cell[0] + cell[2]) / 2.0, cell[3] - 1.0), cw - 6.0, 3.5)
            ex = polygon_extent(poly, mu)
            cx = cell[0] + (cw - (side + 4.0 if notes else 0.0)) / 2.0
            cy = (cell[1] + cell[3] - 2 * CAPTION) / 2.0
            pole = (cx - (ex[0] + ex[2]) / 2.0, cy - (ex[1] + ex[3]) / 2.0)
            items += titles
            items += notes
            drawing = (cell[0] + 2.0, cell[1], cell[2] - 2.0 - (side + 2.0 if notes else 0.0), cell[3])
            items += polygon_items(poly, pole, mu, 3.5, POINT_NAMES, [t.box() for t in titles], within=drawing)
    return items


def _fitting_notes(poly, cell: Box, top_room: float) -> list[Text]:
    """The polygon's notes (charts.polygon_notes) right-aligned in ``cell`` under its caption,
    3.5 mm high, else 2.5 mm; none where even those do not fit (or take half the cell's width:
    a small sheet's acceleration polygon)."""
    for height in (3.5, 2.5):
        notes = polygon_notes(poly, (0.0, 0.0), height)
        if not notes:
            return []
        boxes = np.array([t.box() for t in notes])
        w, h = boxes[:, 2].max() - boxes[:, 0].min(), boxes[:, 3].max() - boxes[:, 1].min()
        if w <= 0.5 * (cell[2] - cell[0]) and h <= cell[3] - cell[1] - top_room - 2.0:
            return polygon_notes(poly, (cell[2] - 2.0 - w, cell[3] - top_room - 1.0), height)
    return []


def _dimension_rows(design: Design, rpm: float, lab: Mapping[str, str]) -> list[tuple[str, str]]:
    mm = lambda v: f"{figure_text('length', v)} mm"    # noqa: E731
    rows = [(lab["L1"], mm(design.crank)), (lab["L2"], mm(design.frame)),
            (lab["L3"], mm(design.lever))]
    if design.rod is not None:
        rows.append((lab["L4"], mm(design.rod)))
    rows += [(lab["h"], mm(design.guide_above_crank)), (lab["H"], mm(design.stroke)),
             (lab["K"], figure_text("ratio", design.time_ratio)),
             (lab["theta"], f"{figure_text('angle', math.degrees(design.theta))}°"),
             (lab["n"], f"{number_text(rpm)} r/min")]
    return rows
