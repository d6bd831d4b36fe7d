"""The class's two hand-outs as sheets (issue 41): the task sheet (设计任务书) of one student
on A4, and the answer key's pages on A4 landscape, painted into PDF by ``shaperapp.course``.

A task sheet holds the mechanism's sketch (the student's own linkage, to scale, as the
motion sheet draws it), the student's data set as a table in the task book's symbols and
the files to deliver. ``labels`` maps the English words (:data:`TASK_WORDS`) to the
language's; core cannot translate.
"""
from __future__ import annotations

from typing import Any, Mapping, Sequence

import numpy as np

from core.base.figure_text import figure_text
from core.cam.defaults import BOSS_MM, CLEARANCE_MM, HUB_MM, RETURN_PRESSURE_DEG
from .dxf import THIN
from .labels import Room, free_spots, spot_boxes
from .segments import strokes_meet_boxes
from .mechanism import PIN_RADIUS, bounds, frame_items, joint_anchors, link_anchors, links_at
from .forces import JOINT_RINGS
from .motion import JOINT_GAP
from .sheet import (TEXT_HEIGHTS, Item, Paper, Sheet, Text, clipped, fit, frame_items as paper_frame, line,
                    marked, marked_text, standard_scale, text_width)
from .cells import fitting_height, table

A4 = Paper("A4", 210.0, 297.0, 10.0)
A4_LANDSCAPE = Paper("A4", 297.0, 210.0, 10.0)
GRAVITY = 9.81
SKETCH_DEG = 60.0           # the crank angle the sketch shows: the working stroke under way
LEADER = 9.0                # a link's number this far from the link, on a thin leader, mm
SKETCH_MM, LEAST_SKETCH_MM = 78.0, 40.0    # the sketch's height, and the least it gives up to the data
LEAST_ROW_MM = 4.6          # a data row holds its 2.5 mm text and an index below it clear of the rules

TASK_WORDS = ("Course design task sheet", "Quick-return mechanism of a shaper", "Student", "Number",
              "Class", "Date", "The mechanism (sketch to scale, crank at 60°)", "Data set",
              "Quantity", "Symbol", "Value", "Unit", "Crank speed", "Frame O_2O_4", "Crank O_2A",
              "Lever O_4B", "Rod BC", "Time ratio", "Stroke", "Lever's centre of mass O_4S_4",
              "Lever weight", "Lever moment of inertia", "Ram weight", "Cutting force",
              "Height of the cutting force", "Guide line", "Follower arm", "Follower swing",
              "Allowed pressure angle", "Rise", "Outer dwell", "Return", "Pinion teeth",
              "Gear teeth", "Module", "Deliver", "Answer key", "page %1/%2", "failed checks",
              "speed", "none", "No.", ", ", "cam pressure angle", "undercut 1", "undercut 2", "tip 1", "tip 2",
              "contact ratio", "interference 1", "interference 2", "Coefficient of speed fluctuation",
              "Idle margin at each end of the stroke", "Rod mass", "Block mass", "Crank mass", "Gravity",
              "not counted", "Other rotating parts", "Rise law", "Return law", "parabolic", "cosine",
              "sine (cycloidal)", "3-4-5 polynomial", "Allowed pressure angle, return", "Roller radius",
              "Base radius", "Centre distance of the cam", "Hub radius", "Pivot boss radius", "Least clearance",
              "Shift factors", "Centre distance", "Pressure angle", "Addendum", "Clearance", "Least tip thickness",
              "Least contact ratio", "Rod side: C ahead of B while cutting", "leading")

CHECK_WORDS = {"cam_pressure_angle": "cam pressure angle", "undercut1": "undercut 1", "undercut2": "undercut 2",
               "tip1": "tip 1", "tip2": "tip 2", "contact": "contact ratio", "interference1": "interference 1",
               "interference2": "interference 2"}
"""The answer key's words for the checks ``core.cli.answers.failed_checks`` names (the
cam's allowance, ``core.gear.checks.CHECKS``): a teacher reads these, in the key's
language; the CSV and JSON keep the names."""


def _w(labels: Mapping[str, str], word: str) -> str:
    return labels.get(word, word)


def failed_text(names: Sequence[str], labels: Mapping[str, str]) -> str:
    """The failed checks ``names`` as the answer key writes them: each in words of the
    language, joined by the language's list separator; 'none' for none."""
    if not names:
        return _w(labels, "none")
    return _w(labels, ", ").join(_w(labels, CHECK_WORDS.get(name, name)) for name in names)


def _n(value: float | None) -> str:
    """A given value as the design file holds it (as typed: 1.46, 0.12345, 700), never
    rounded; a figure the tool derives is written by ``core.base.figure_text``."""
    if value is None:
        return "—"
    return f"{value:.10g}"


def _weight(forces: Mapping[str, Any], link: str) -> str:
    """A link's weight as the design file holds it: the weight as typed (G4 = 200 N, the
    task book's way), else the mass times g."""
    weight = forces.get(f"{link}_weight_N")
    if weight is not None:
        return _n(weight)
    return f"{forces.get(f'{link}_mass_kg', 0.0) * GRAVITY:.4g}"     # 20.387 kg: G4 = 200 N, the book's


def data_rows(doc: Mapping[str, Any], design, labels: Mapping[str, str]) -> list[list[str]]:
    """The student's data set: (quantity, symbol in the task book's notation, value, unit)."""
    spec, forces = doc["spec"], doc.get("forces") or {}
    w = lambda word: _w(labels, word)      # noqa: E731
    rows = _listed([w("Crank speed"), "n_2", "", "r/min"], [_n(r) for r in doc["rpm"]], " / ")
    if spec["mode"] == "dimensions":
        rows += [[w("Frame O_2O_4"), "l_O_2_O_4", _n(spec["frame"]), "mm"],
                 [w("Crank O_2A"), "l_O_2_A", _n(spec["crank"]), "mm"],
                 [w("Lever O_4B"), "l_O_4_B", _n(spec["lever"]), "mm"]]
    else:
        rows += [[w("Crank O_2A"), "l_O_2_A", _n(spec["crank"]), "mm"],
                 [w("Time ratio"), "K", _n(spec["time_ratio"]), ""],
                 [w("Stroke"), "H", _n(spec["stroke"]), "mm"]]
    if design.rod is not None:
        rod = f"{_n(spec['rod_ratio'])} l_O_4_B" if spec["rod_input"] == "ratio" else _n(spec["rod_length"])
        rows.append([w("Rod BC"), "l_BC", rod, "mm"])
        if spec.get("rod_side") == "leading":      # the answer key's motion follows it; trailing is the book's
            rows.append([w("Rod side: C ahead of B while cutting"), "", w("leading"), ""])
    rows.append([w("Guide line"), "h", figure_text("length", design.guide_above_crank), "mm"])
    if forces:
        cg = forces.get("lever_cg_mm")
        rows += [[w("Lever's centre of mass O_4S_4"), "l_O_4_S_4",
                  _n(cg) if cg is not None else "0.5 l_O_4_B", "mm"],
                 [w("Lever weight"), "G_4", _weight(forces, "lever"), "N"],
                 [w("Lever moment of inertia"), "J_S_4", _n(forces["lever_inertia_kg_m2"]), "kg·m²"],
                 [w("Ram weight"), "G_6", _weight(forces, "ram"), "N"],
                 [w("Cutting force"), "P", _n(forces["cut_force_N"]), "N"],
                 [w("Height of the cutting force"), "y_P", _n(forces["cut_height_mm"]), "mm"]]
        rows += _flywheel_rows(forces, w)
    cam = doc.get("cam")
    if cam:
        rows += [[w("Follower arm"), "l_O_9_D", _n(cam["arm_mm"]), "mm"],
                 [w("Follower swing"), "ψ_max", _n(cam["swing_deg"]), "°"],
                 [w("Allowed pressure angle"), "[α]", _n(cam["pressure_deg"]), "°"],
                 [w("Rise"), "Φ", _n(cam["rise_deg"]), "°"],
                 [w("Outer dwell"), "Φ_s", _n(cam["dwell_deg"]), "°"],
                 [w("Return"), "Φ′", _n(cam["return_deg"]), "°"],
                 [w("Rise law"), "", w(LAW_WORDS.get(cam["rise_law"], cam["rise_law"])), ""],
                 [w("Return law"), "", w(LAW_WORDS.get(cam["return_law"], cam["return_law"])), ""]]
        rows += _given_rows(cam, _CAM_GIVEN, w)
    gear = doc.get("gear")
    if gear:
        rows += [[w("Pinion teeth"), "z_1", _n(gear["z1"]), ""], [w("Gear teeth"), "z_2", _n(gear["z2"]), ""],
                 [w("Module"), "m", _n(gear["module_mm"]), "mm"]]
        if gear.get("x1") is not None and gear.get("x2") is not None:
            rows.append([w("Shift factors"), "x_1, x_2", f"{_n(gear['x1'])}, {_n(gear['x2'])}", ""])
        rows += _given_rows(gear, _GEAR_GIVEN, w)
    return rows


# inputs a task sheet lists only where the design file sets them (a default or blank is the
# task book's, stated by the program): (key, word, symbol, unit, the value that needs no row)
_FORCES_GIVEN = (("rod_mass_kg", "Rod mass", "m_5", "kg", 0.0), ("block_mass_kg", "Block mass", "m_3", "kg", 0.0),
                 ("crank_mass_kg", "Crank mass", "m_2", "kg", 0.0))
_CAM_GIVEN = (("return_pressure_deg", "Allowed pressure angle, return", "[α]′", "°", RETURN_PRESSURE_DEG),
              ("roller_mm", "Roller radius", "r_r", "mm", None), ("base_mm", "Base radius", "r_0", "mm", None),
              ("distance_mm", "Centre distance of the cam", "a", "mm", None),
              ("hub_mm", "Hub radius", "", "mm", HUB_MM), ("boss_mm", "Pivot boss radius", "", "mm", BOSS_MM),
              ("clearance_mm", "Least clearance", "", "mm", CLEARANCE_MM))
_GEAR_GIVEN = (("centre_mm", "Centre distance", "a′", "mm", None),
               ("pressure_angle_deg", "Pressure angle", "α", "°", 20.0), ("addendum", "Addendum", "h_a*", "", 1.0),
               ("clearance", "Clearance", "c*", "", 0.25), ("tip_limit", "Least tip thickness", "s_a/m", "", 0.25),
               ("contact_limit", "Least contact ratio", "ε", "", 1.2))

LAW_WORDS = {"parabolic": "parabolic", "cosine": "cosine", "sine": "sine (cycloidal)", "poly345": "3-4-5 polynomial"}
"""The cam's laws as the task sheet names them (``core.cam.defaults.LAWS``)."""


def _given_rows(part: Mapping[str, Any], given, w) -> list[list[str]]:
    """A row for each input of ``given`` the file sets to other than what needs no row."""
    rows = []
    for key, word, symbol, unit, usual in given:
        value = part.get(key)
        if value is not None and value != usual:
            rows.append([w(word), symbol, _n(value), unit])
    return rows


def _flywheel_rows(forces: Mapping[str, Any], w) -> list[list[str]]:
    """What else the answer key's torque and flywheel figures depend on: δ, the idle margin
    (the task book states both: a task sheet without them leaves J_F and M_m unknowable, and
    a teacher's ``delta`` or ``idle`` column went unseen), and the rest where it is set: the
    other links' masses, gravity off, the other rotating parts (J_F − J_c)."""
    delta = forces.get("delta", 1.0 / 30.0)
    inverse, typed = 1.0 / delta, _n(delta)      # 1/30, the default, was typed as a fraction
    whole = len(typed) > 8 and abs(inverse - round(inverse)) < 1e-9 * inverse
    rows = [[w("Coefficient of speed fluctuation"), "[δ]", f"1/{round(inverse)}" if whole else typed, ""],
            [w("Idle margin at each end of the stroke"), "", f"{_n(forces.get('idle_fraction', 0.05))} H", ""]]
    rows += _given_rows(forces, _FORCES_GIVEN, w)
    if forces.get("gravity") is False:
        rows.append([w("Gravity"), "g", w("not counted"), ""])
    rotors = forces.get("rotors") or []
    if rotors:
        rows += _listed([w("Other rotating parts"), "J, ω/ω_2", "", "kg·m², —"],
                        [f"{_n(r['J_kg_m2'])}, {_n(r['speed_ratio'])}" for r in rotors], "; ")
    return rows


COLUMNS_MM = (70.0, 28.0, 45.0, 24.0)
"""The data set's columns: quantity, symbol, value, unit."""


def _listed(row: list[str], values: Sequence[str], separator: str) -> list[list[str]]:
    """``row`` with ``values`` in its value cell, as many rows as they need to print whole
    at the table's smallest text (2.5 mm), the later ones with the value alone: the speeds
    of a student given many were cut ('20 / 25 / 30 / 35 / 40 / …' of 16), so the task
    sheet no longer said which speeds to compute."""
    room = COLUMNS_MM[2] - 3.0
    lines: list[str] = []
    for value in values:
        joined = f"{lines[-1]}{separator}{value}" if lines else value
        if lines and text_width(joined, 2.5) <= room:
            lines[-1] = joined
        else:
            lines.append(value)
    first = [*row[:2], lines[0] if lines else "", *row[3:]]
    return [first] + [["", "", line, ""] for line in lines[1:]]


def task_sheet(doc: Mapping[str, Any], who: Mapping[str, str], deliver: Sequence[str],
               labels: Mapping[str, str]) -> Sheet:
    """One student's task sheet: ``doc`` the design file's document, ``who`` the student,
    number, group and date, ``deliver`` the files' titles in order."""
    from core.linkage.spec import Spec
    design = Spec.from_dict(doc["spec"]).design()
    p = A4
    left, bottom, right, top = p.border
    items: list[Item] = list(paper_frame(p))
    y = top - 12.0
    items.append(Text(_w(labels, "Course design task sheet"), ((left + right) / 2, y), 7.0, "cm"))
    y -= 9.0
    items.append(Text(_w(labels, "Quick-return mechanism of a shaper"), ((left + right) / 2, y), 5.0, "cm"))
    y -= 10.0
    person, size = _person(who, labels, right - left - 8.0)
    items.append(Text(person, (left + 4.0, y), size, "lm"))
    y -= 7.0
    items.append(marked_text(_w(labels, "The mechanism (sketch to scale, crank at 60°)"), (left + 4.0, y), 3.5))
    items.append(Text(f"{_w(labels, 'Date')}: {who.get('date', '')}", (right - 4.0, y), 3.5, "rb"))
    rows = [[_w(labels, "Quantity"), _w(labels, "Symbol"), _w(labels, "Value"), _w(labels, "Unit")]]
    rows += data_rows(doc, design, labels)
    below = bottom + 12.0 + 6.0 * len(deliver) + 10.0         # the list to deliver, the table's title
    sketch = min(SKETCH_MM, max(LEAST_SKETCH_MM, y - 4.0 - below - LEAST_ROW_MM * len(rows)))
    box = (left + 4.0, y - 4.0 - sketch, right - 4.0, y - 4.0)
    items += _sketch(design, box)
    y = box[1] - 6.0
    items.append(Text(_w(labels, "Data set"), (left + 4.0, y), 3.5, "lm"))
    height = min(6.0, (y - 4.0 - bottom - 12.0 - 6.0 * len(deliver)) / len(rows))
    items += table((left + 4.0, y - 4.0), COLUMNS_MM, rows, height, 3.5 if height >= 6 else 2.5,
                   aligns="lccc")
    y = y - 4.0 - height * len(rows) - 7.0
    items.append(Text(_w(labels, "Deliver"), (left + 4.0, y), 3.5, "lm"))
    for k, title in enumerate(deliver, start=1):
        items.append(Text(f"{k}. {title}", (left + 10.0, y - 5.5 * k), 3.5, "lm"))
    return Sheet(p, tuple(items))


def _person(who: Mapping[str, str], labels: Mapping[str, str], room: float) -> tuple[str, float]:
    """The student's line and its height: 3.5 mm, else 2.5 mm, else the name cut with "…"
    so that the number and the class still print whole (a name of 17 CJK characters cut
    them off the line's end, 'Number: 20230…', so the sheet no longer said whose it was);
    a class too long for what is left is cut last."""
    name, number, group = who.get("student", ""), who.get("number", ""), who.get("group", "")
    head = f"{_w(labels, 'Student')}: "
    tail = f"    {_w(labels, 'Number')}: {number}    {_w(labels, 'Class')}: {group}"
    size = fitting_height(head + name + tail, room, 3.5)
    least = text_width("MMMMMMMM…", size)          # a name keeps at least its first few letters
    name = clipped(name, max(room - text_width(head + tail, size), least), size)
    return clipped(head + name + tail, room, size), size


def _sketch(design, box: tuple[float, float, float, float]) -> list[Item]:
    """The linkage to a standard scale in ``box``: frame, links at SKETCH_DEG, joint names."""
    b = bounds(design)
    scale = max(standard_scale(b[2] - b[0], box[2] - box[0] - 16.0),
                standard_scale(b[3] - b[1], box[3] - box[1] - 16.0))
    where = fit(b, box, scale)
    items: list[Item] = frame_items(design, where) + links_at(design, SKETCH_DEG, where)
    room = Room(items, within=box)      # the names as every sheet places them: off every line and circle
    anchors = joint_anchors(design, SKETCH_DEG, where, 3.5)
    room.name([p for _, _, p, _ in anchors])
    names = []
    for text, spans, point, way in anchors:
        placed = room.place(text, tuple(point), 3.5, tuple(way), gap=JOINT_GAP, rings=JOINT_RINGS,
                            subscripts=spans, leader_gap=PIN_RADIUS + 0.3)
        items += placed
        names += [np.mean(np.reshape(placed[0].box(), (2, 2)), axis=0)] if placed else []

    def leader(start: np.ndarray, at: np.ndarray) -> np.ndarray:
        way = (at - start) / float(np.hypot(*(at - start)))
        return np.concatenate([start + way * 0.8, at - way * 2.8])

    def free(start: np.ndarray, at: np.ndarray, number: str) -> bool:
        taken = np.asarray(room.taken, dtype=float).reshape(-1, 4)
        spot = spot_boxes([Text(number, (float(at[0]), float(at[1])), 3.5, "cm")])
        return bool(free_spots(spot, taken, room.segments, room.within)[0]
                    and not strokes_meet_boxes(leader(start, at)[None, :], taken)[0])
    for number, point, offset in link_anchors(design, SKETCH_DEG, where, LEADER, names, free):
        if free(point, point + offset, number):
            placed = [line(np.reshape(leader(point, point + offset), (2, 2)), THIN),
                      Text(number, (float(point[0] + offset[0]), float(point[1] + offset[1])), 3.5, "cm")]
        else:       # no spot at a leader's length is free: the labels' search (beside it, else led)
            placed = room.place(number, tuple(point), 3.5, tuple(offset), gap=1.0, leader_gap=0.8)
        room.draw(placed)
        items += placed
    items.append(Text(f"1:{scale:g}", (box[2], box[1] + 2.0), 3.5, "rb"))
    return items


def answer_pages(tables: Sequence[tuple[Sequence[Sequence[str]], Sequence[float], Sequence[Sequence[str]]]],
                 title: str, labels: Mapping[str, str], plain: Sequence[int] = ()) -> list[Sheet]:
    """The answer key as A4-landscape pages: each of ``tables`` (its header rows in the index
    notation, widths in mm, rows of texts; all with as many rows) stacked on every page,
    the same rows of each, as many as fit; each page titled and numbered. ``plain``: the
    columns of a user's words (a student's name), taken as they are. A row whose first
    cell is empty continues the row above (a student's next speed); where one starts a
    page it repeats that row's first cell and ``plain`` cells, so that the page says whose
    figures they are (a student of 16 speeds ran over three pages, the last two with
    figures under no name)."""
    p = A4_LANDSCAPE
    left, bottom, right, top = p.border
    row_h, gap = 6.0, 6.0
    room = top - bottom - 16.0 - sum(len(head) * row_h + gap for head, _, _ in tables)
    per_page = max(1, int(room / (row_h * len(tables))))
    count = len(tables[0][2])
    starts = range(0, max(count, 1), per_page)
    pages = []
    for k, at in enumerate(starts, start=1):
        items: list[Item] = list(paper_frame(p))
        items.append(Text(title, (left + 2.0, top - 7.0), 5.0, "lm"))
        page = _w(labels, "page %1/%2").replace("%1", str(k)).replace("%2", str(len(starts)))
        items.append(Text(page, (right - 2.0, top - 7.0), 3.5, "rm"))
        y = top - 14.0
        for header, widths, rows in tables:
            widths = fitted_widths(header, widths, rows, plain, right - left - 4.0)
            scale = min(1.0, (right - left - 4.0) / sum(widths))
            chunk = [*map(list, header), *_carried(rows, at, (0, *plain)), *rows[at + 1:at + per_page]]
            items += table((left + 2.0, y), [w * scale for w in widths], chunk, row_h, 2.5, plain=plain,
                           header_rows=len(header))
            y -= row_h * len(chunk) + gap
        pages.append(Sheet(p, tuple(items)))
    return pages


def _carried(rows: Sequence[Sequence[str]], at: int, who: Sequence[int]) -> list[list[str]]:
    """Row ``at`` (none past the end), with the ``who`` cells of the row it continues."""
    if at >= len(rows):
        return []
    row = list(rows[at])
    owner = next((r for r in reversed(rows[:at]) if r[0]), None) if not row[0] else None
    for column in who if owner is not None else ():
        row[column] = owner[column]
    return [row]


PLAIN_MOST = 60.0
"""The widest a column of a user's words (a name, a number) grows, mm, some 30 characters at
2.5 mm (the first table's room lets a name of 20 through whole beside a 12-digit number).
Longer, it is cut with "…" rather than squeeze the figures' columns."""


def fitted_widths(header: Sequence[Sequence[str]], widths: Sequence[float], rows: Sequence[Sequence[str]],
                  plain: Sequence[int], room: float) -> list[float]:
    """The answer key's column widths: each its given width (``widths``), or wider where its
    widest text (a 12-digit student number, a name, the failed checks' words) needs it at the
    key's 2.5 mm with the 1 mm a cell keeps each side, a column of a user's words at most
    PLAIN_MOST (or its given width). Where they exceed ``room``, the figures' columns give up
    their spare width first, then the widest columns of a user's words down to their given
    width. Why: fixed widths cut 10-digit numbers in their 20 mm column to '20210012…', and
    two students read alike."""
    need = []
    for c in range(len(widths)):
        texts = [marked(h[c])[0] for h in header] + [row[c] for row in rows]
        need.append(max((text_width(t, TEXT_HEIGHTS[0]) for t in texts if t), default=0.0) + 2.2)
    out = [max(widths[c], min(n, max(PLAIN_MOST, widths[c])) if c in plain else n) for c, n in enumerate(need)]
    excess = sum(out) - room
    spare = [0.0 if c in plain else max(out[c] - need[c], 0.0) for c in range(len(out))]
    if excess > 0.0 and sum(spare) > 0.0:
        share = min(1.0, excess / sum(spare))
        out = [w - share * s for w, s in zip(out, spare)]
        excess -= share * sum(spare)
    for c in sorted(plain, key=lambda k: -out[k]):
        cut = min(max(excess, 0.0), max(out[c] - widths[c], 0.0))
        out[c] -= cut
        excess -= cut
    return out
