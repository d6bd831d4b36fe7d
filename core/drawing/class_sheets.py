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
from .dxf import THIN
from .mechanism import bounds, frame_items, joint_anchors, link_anchors, links_at
from .sheet import (Item, Paper, Placement, Sheet, Text, clipped, fit, frame_items as paper_frame, item_box,
                    line, marked_text, standard_scale, word_gap)
from .cells import table

A4 = Paper("A4", 210.0, 297.0, 10.0)
A4_LANDSCAPE = Paper("A4", 297.0, 210.0, 10.0)
GRAVITY = 9.81
SKETCH_DEG = 60.0           # the crank angle the sketch shows: the working stroke under way
LEADER = 9.0                # a link's number this far from the link, on a thin leader, mm
NUMBER_ROOM = 3.0           # a 3.5 mm number's box reaches 2.7 mm from its centre

TASK_WORDS = ("Course design task sheet", "Quick-return mechanism of a shaper", "Student", "Number",
              "Class", "Date", "The mechanism (sketch to scale, crank at 60°)", "Data set",
              "Quantity", "Symbol", "Value", "Unit", "Crank speed", "Frame O_2O_4", "Crank O_2A",
              "Lever O_4B", "Rod BC", "Time ratio", "Stroke", "Lever's centre of mass O_4S_4",
              "Lever weight", "Lever moment of inertia", "Ram weight", "Cutting force",
              "Height of the cutting force", "Guide line", "Follower arm", "Follower swing",
              "Allowed pressure angle", "Rise", "Outer dwell", "Return", "Pinion teeth",
              "Gear teeth", "Module", "Deliver", "Answer key", "page %1/%2", "failed checks",
              "speed", "none", "No.")


def _w(labels: Mapping[str, str], word: str) -> str:
    return labels.get(word, word)


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
    rows = [[w("Crank speed"), "n_2", " / ".join(_n(r) for r in doc["rpm"]), "r/min"]]
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
    cam = doc.get("cam")
    if cam:
        rows += [[w("Follower arm"), "l_O_9_D", _n(cam["arm_mm"]), "mm"],
                 [w("Follower swing"), "ψ_max", _n(cam["swing_deg"]), "°"],
                 [w("Allowed pressure angle"), "[α]", _n(cam["pressure_deg"]), "°"],
                 [w("Rise"), "Φ", _n(cam["rise_deg"]), "°"],
                 [w("Outer dwell"), "Φ_s", _n(cam["dwell_deg"]), "°"],
                 [w("Return"), "Φ′", _n(cam["return_deg"]), "°"]]
    gear = doc.get("gear")
    if gear:
        rows += [[w("Pinion teeth"), "z_1", _n(gear["z1"]), ""], [w("Gear teeth"), "z_2", _n(gear["z2"]), ""],
                 [w("Module"), "m", _n(gear["module_mm"]), "mm"]]
    return rows


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
    person = (f"{_w(labels, 'Student')}: {who.get('student', '')}    {_w(labels, 'Number')}: "
              f"{who.get('number', '')}    {_w(labels, 'Class')}: {who.get('group', '')}")
    items.append(Text(clipped(person, right - left - 8.0, 3.5), (left + 4.0, y), 3.5, "lm"))
    y -= 7.0
    caption = marked_text(_w(labels, "The mechanism (sketch to scale, crank at 60°)"), (left + 4.0, y), 3.5)
    items.append(caption)
    items.append(Text(f"{_w(labels, 'Date')}: {who.get('date', '')}", (right - 4.0, y), 3.5, "rb"))
    box = (left + 4.0, y - 82.0, right - 4.0, y - 4.0)
    data = Text(_w(labels, "Data set"), (left + 4.0, box[1] - 6.0), 3.5, "lm")
    # the sketch may reach a word space off the caption over it and the title under it
    items += _sketch(design, box, (box[0], data.box()[3] + word_gap(3.5), box[2],
                                   caption.box()[1] - word_gap(3.5)))
    y = box[1] - 6.0
    items.append(data)
    rows = [[_w(labels, "Quantity"), _w(labels, "Symbol"), _w(labels, "Value"), _w(labels, "Unit")]]
    rows += data_rows(doc, design, labels)
    height = min(6.0, (y - 4.0 - bottom - 12.0 - 6.0 * len(deliver)) / len(rows))
    items += table((left + 4.0, y - 4.0), (70.0, 28.0, 45.0, 24.0), rows, height, 3.5 if height >= 6 else 2.5,
                   aligns="lccc")
    y = y - 4.0 - height * len(rows) - 7.0
    items.append(Text(_w(labels, "Deliver"), (left + 4.0, y), 3.5, "lm"))
    for k, title in enumerate(deliver, start=1):
        items.append(Text(f"{k}. {title}", (left + 10.0, y - 5.5 * k), 3.5, "lm"))
    return Sheet(p, tuple(items))


def _sketch(design, box: tuple[float, float, float, float], room: tuple[float, float, float, float]
            ) -> list[Item]:
    """The linkage to a standard scale in ``box``: frame, links at SKETCH_DEG, joint names and
    the links' numbers, all of it inside ``room`` (``box`` and the paper up to the texts
    round it: a number led up from the ram ran into the caption over the sketch), moved into
    it; where it does not fit, the numbers kept inside it, then the next smaller scale."""
    b = bounds(design)
    scale = max(standard_scale(b[2] - b[0], box[2] - box[0] - 16.0),
                standard_scale(b[3] - b[1], box[3] - box[1] - 16.0))
    while True:
        for within in (None, room):
            where = fit(b, box, scale)
            items = _sketch_items(design, where, within)
            extent = np.array([item_box(it) for it in items])
            (x0, y0), (x1, y1) = extent[:, :2].min(axis=0), extent[:, 2:].max(axis=0)
            fits = x1 - x0 <= room[2] - room[0] and y1 - y0 <= room[3] - room[1]
            if fits:
                break
        if fits or scale >= 1e6:
            break
        scale = standard_scale(scale * (1.0 + 1e-9), 1.0)         # the next of the series
    dx = max(room[0] - x0, 0.0) - max(x1 - room[2], 0.0)
    dy = max(room[1] - y0, 0.0) - max(y1 - room[3], 0.0)
    if dx or dy:
        where = Placement(scale, (where.origin[0] + dx, where.origin[1] + dy), where.anchor)
        items = _sketch_items(design, where, within)
    return items + [Text(f"1:{scale:g}", (box[2], box[1] + 2.0), 3.5, "rb")]


def _sketch_items(design, where: Placement, box: tuple[float, float, float, float] | None) -> list[Item]:
    """The sketch's frame, links, joint names and the links' numbers on their leaders; with
    ``box``, the numbers' centres NUMBER_ROOM inside it where there is a spot."""
    items: list[Item] = frame_items(design, where) + links_at(design, SKETCH_DEG, where)
    names = []
    for text, spans, point, way in joint_anchors(design, SKETCH_DEG, where, 3.5):
        at = point + way * 6.0
        names.append(at)
        items.append(Text(text, (float(at[0]), float(at[1])), 3.5, "cm", subscripts=spans))
    inner = None if box is None else (box[0] + NUMBER_ROOM, box[1] + NUMBER_ROOM, box[2] - NUMBER_ROOM,
                                      box[3] - NUMBER_ROOM)
    for number, point, offset in link_anchors(design, SKETCH_DEG, where, LEADER, names, inner):
        at, way = point + offset, offset / float(np.hypot(*offset))
        items.append(line([point + way * 0.8, at - way * 2.8], THIN))
        items.append(Text(number, (float(at[0]), float(at[1])), 3.5, "cm"))
    return items


def answer_pages(tables: Sequence[tuple[Sequence[Sequence[str]], Sequence[float], Sequence[Sequence[str]]]],
                 title: str, labels: Mapping[str, str], plain: Sequence[int] = ()) -> list[Sheet]:
    """The answer key as A4-landscape pages: each of ``tables`` (its header rows in the index
    notation, widths in mm, rows of texts; all with as many rows) stacked on every page,
    the same rows of each, as many as fit; each page titled and numbered. ``plain``: the
    columns of a user's words (a student's name), taken as they are."""
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
            scale = min(1.0, (right - left - 4.0) / sum(widths))
            chunk = [*map(list, header), *rows[at:at + per_page]]
            items += table((left + 2.0, y), [w * scale for w in widths], chunk, row_h, 2.5, plain=plain,
                           header_rows=len(header))
            y -= row_h * len(chunk) + gap
        pages.append(Sheet(p, tuple(items)))
    return pages
