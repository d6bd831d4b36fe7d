"""The task sheet's sketch (issue 41, gap 3): every link carries the task book's number
(crank 2, block 3, lever 4, rod 5, ram 6) on a leader that starts on that link, the number
clear of every link, so a student reads the sketch in the book's numbering."""
from __future__ import annotations

import numpy as np
import pytest

from core.drawing.class_sheets import LEADER, SKETCH_DEG, task_sheet
from core.drawing.mechanism import BLOCK, joints, link_anchors
from core.drawing.sheet import Text
from core.linkage.spec import Spec


def _doc(rod_ratio):
    spec = {"mode": "dimensions", "crank": 90.0, "frame": 350.0, "lever": 580.0}
    doc = Spec.from_dict({**Spec.from_dict(spec).to_dict(), **({"rod_ratio": rod_ratio, "rod_input": "ratio",
                                                               "variant": "rod"} if rod_ratio else {})})
    return {"spec": doc.to_dict(), "rpm": [64.0]}, doc.design()


def _segment_distance(p, a, b):
    d = b - a
    t = min(max(float(np.dot(p - a, d) / np.dot(d, d)), 0.0), 1.0)
    return float(np.hypot(*(p - a - t * d)))


@pytest.mark.parametrize("rod_ratio, numbers", [(0.3, {"2", "3", "4", "5", "6"}), (None, {"2", "3", "4", "5", "6"})])
def test_every_link_is_numbered_as_the_task_book_numbers_it(rod_ratio, numbers):
    doc, design = _doc(rod_ratio)
    where = lambda p: np.asarray(p, dtype=float) / 10.0      # noqa: E731  (1:10)
    found = link_anchors(design, SKETCH_DEG, where, LEADER)
    assert {n for n, _, _ in found} == numbers
    j = {k: where(v) for k, v in joints(design, SKETCH_DEG).items()}
    links = {"2": [(j["O2"], j["A"])], "4": [(j["O4"], j["B"])], "3": [(j["O4"], j["B"])]}
    if rod_ratio:
        links["5"] = [(j["B"], j["C"])]
    for number, point, offset in found:
        assert LEADER - 1e-9 <= float(np.hypot(*offset)) <= 1.6 * LEADER + 1e-9
        if number in links:       # the leader starts on its own link (the block: on the lever it slides on)
            assert min(_segment_distance(point, a, b) for a, b in links[number]) < 1e-9, number
        elif number == "5":       # the block at B in the ram's vertical slot (task book 5): inside it
            assert np.all(np.abs(point - j["B"]) <= np.array(BLOCK[::-1]) / 2.0), point - j["B"]
        spot = point + offset
        for a, b in [(j["O2"], j["A"]), (j["O4"], j["B"])]:
            assert _segment_distance(spot, a, b) > 2.0, number        # the number is off the links
    sheet = task_sheet(doc, {"student": "x"}, [], {})
    assert numbers <= {item.text for item in sheet.items if isinstance(item, Text)}


def test_the_data_set_shows_given_values_as_typed_and_derived_ones_in_figure_text():
    """A typed K = 1.4599 and L1 = 100.25 are not rounded to 4 digits (1.46, 100.3); the
    guide height h, which the tool derives, reads as the answer key and the CLI write it."""
    from core.drawing.class_sheets import data_rows
    from core.base.figure_text import figure_text
    spec = Spec.from_dict({"mode": "synthesis", "crank": 100.25, "time_ratio": 1.4599, "stroke": 312.5})
    doc = {"spec": spec.to_dict(), "rpm": [60.0, 72.5]}
    rows = {row[1]: row[2] for row in data_rows(doc, spec.design(), {})}
    assert rows["K"] == "1.4599" and rows["l_O_2_A"] == "100.25" and rows["H"] == "312.5"
    assert rows["n_2"] == "60 / 72.5"
    assert rows["h"] == figure_text("length", spec.design().guide_above_crank)


@pytest.mark.parametrize("dims, rod_ratio", [((110.0, 380.0, 540.0), 0.25), ((90.0, 350.0, 580.0), 0.3),
                                             ((110.0, 430.0, 810.0), 0.36), ((100.0, 386.37, 579.56), None),
                                             ((100.0, 386.37, 579.56), 0.3)],
                         ids=["方案 I", "方案 II", "方案 III", "default block", "default rod"])
def test_no_name_or_number_of_the_sketch_is_crossed_or_overlaps(dims, rod_ratio):
    """The joints' names stood at a fixed 6 mm off their pins and the link numbers were
    placed clear of the links alone: on 方案 II and III the ground hatching ran through O2 and
    O4, on 方案 I and III the crank's circle through '2', on the default design the block's
    number's leader through 'A', and in English the rod's '5' sat on the caption over the
    sketch. Every text must be clear of every line, circle and other text (the sheets'
    check, tests/sheet_checks.py), and every name and number still there."""
    from core.drawing.checks import overlapping_texts
    from sheet_checks import crossed_texts
    crank, frame, lever = dims
    spec = {"mode": "dimensions", "crank": crank, "frame": frame, "lever": lever, "guide_rule": "sagitta"}
    if rod_ratio:
        spec.update(rod_ratio=rod_ratio, rod_input="ratio", variant="rod")
    doc = Spec.from_dict({**Spec.from_dict(spec).to_dict(), **spec})
    sheet = task_sheet({"spec": doc.to_dict(), "rpm": [60.0]},
                       {"student": "x", "number": "1", "group": "g", "date": "2026-01-01"}, ["a"], {})
    assert [(t.text, type(it).__name__) for t, it in crossed_texts(sheet)] == []
    assert [(a.text, b.text) for a, b in overlapping_texts(sheet)] == []
    texts = {item.text for item in sheet.items if isinstance(item, Text)}
    assert {"O2", "O4", "A", "B", "2", "3", "4", "5", "6"} | ({"C"} if rod_ratio else set()) <= texts


def test_the_students_line_shows_the_whole_name_and_number():
    """A long name pushed the student's number off the task sheet's line at 3.5 mm
    ('Number: 202100…'): the line goes one standard height smaller (2.5 mm) before it is cut."""
    doc, _ = _doc(0.3)
    who = {"student": "Alexandra Konstantinopoulou-Smith", "number": "202100123456", "group": "ME2101",
           "date": "2026-01-01"}
    sheet = task_sheet(doc, who, [], {})
    line = next(t for t in sheet.items if isinstance(t, Text) and t.text.startswith("Student: "))
    assert "…" not in line.text and all(v in line.text for v in (who["student"], who["number"], who["group"]))
    left, _, right, _ = sheet.paper.border
    assert left <= line.box()[0] and line.box()[2] <= right


@pytest.mark.parametrize("name", ["名" * 17, "名" * 200, "Alexandra Konstantinopoulou-Smith of Mechanical Eng"])
def test_a_name_too_long_for_the_line_is_cut_and_the_number_and_class_stay(name):
    """A name too long for the student's line even at 2.5 mm was cut with the line's end,
    the number and the class with it ('名名…名…' and no number: 17 CJK characters did it),
    so the sheet no longer said whose it was; now the name is cut and the rest prints whole,
    within the border."""
    doc, _ = _doc(0.3)
    who = {"student": name, "number": "2023010101", "group": "Mechanical Engineering 2301", "date": "2026-01-01"}
    sheet = task_sheet(doc, who, [], {})
    line = next(t for t in sheet.items if isinstance(t, Text) and t.text.startswith("Student: "))
    assert line.text.endswith("Number: 2023010101    Class: Mechanical Engineering 2301")
    shown = line.text[len("Student: "):line.text.index("    Number: ")]
    assert shown == name or (shown.endswith("…") and name.startswith(shown[:-1]) and len(shown) > 8)
    left, _, right, _ = sheet.paper.border
    assert left <= line.box()[0] and line.box()[2] <= right


def test_every_speed_and_rotating_part_prints_whole():
    """A student given 16 speeds read '20 / 25 / 30 / 35 / 40 / …' on the task sheet, the
    other eleven speeds to compute cut away (and so many rotating parts): the list takes
    as many rows of the data set as it needs, each within its cell, none cut."""
    value_mm = 45.0                      # the data set's value column
    doc, _ = _doc(0.3)
    speeds = [20.0 + 5.0 * k for k in range(15)] + [999.99]
    from core.files.design_file import masses_to_dict
    from core.forces.masses import MassProperties
    forces = masses_to_dict(MassProperties(rotors=tuple((0.5 + k, 1.0 + k) for k in range(20))))
    doc = {**doc, "rpm": speeds, "forces": forces}
    sheet = task_sheet(doc, {"student": "x"}, ["Motion"], {})
    texts = [t for t in sheet.items if isinstance(t, Text)]
    assert not [t.text for t in texts if "…" in t.text]
    listed = " / ".join(t.text for t in texts if " / " in t.text or t.text in ("95", "999.99"))
    assert [float(v) for v in listed.split(" / ")] == speeds
    parts = "; ".join(t.text for t in texts if t.text.count(",") and t.text[0].isdigit())
    assert parts == "; ".join(f"{0.5 + k:g}, {1 + k:g}" for k in range(20))
    value = next(t for t in texts if t.text.startswith("20 / 25"))
    centre = (value.box()[0] + value.box()[2]) / 2
    assert all(t.box()[2] - t.box()[0] <= value_mm - 2.0 for t in texts if abs(
        (t.box()[0] + t.box()[2]) / 2 - centre) < 1e-6)


@pytest.mark.parametrize("side", ["trailing", "leading"])
def test_a_leading_rod_is_said_on_the_task_sheet(side):
    """The rod's side sets the motion the answer key gives (v, a, M, J_F), and the data set
    did not say it: a leading rod's student read the book's trailing layout's data. The
    sheet says a leading rod; the book's trailing one goes without saying."""
    doc, _ = _doc(0.3)
    doc = {**doc, "spec": {**doc["spec"], "rod_side": side}}
    texts = [t.text for t in task_sheet(doc, {"student": "x"}, [], {}).items if isinstance(t, Text)]
    assert ("Rod side: C ahead of B while cutting" in texts) == (side == "leading")
    assert ("leading" in texts) == (side == "leading")


# 方案 I–III of the task book (l_O2A, l_O2O4, l_O4B, l_BC/l_O4B) and a block design
TASK_BOOK = [(110.0, 380.0, 540.0, 0.25), (90.0, 350.0, 580.0, 0.3), (110.0, 430.0, 810.0, 0.36),
             (90.0, 350.0, 580.0, None)]


@pytest.mark.parametrize("crank, frame, lever, rod_ratio", TASK_BOOK)
def test_the_sketch_keeps_off_the_caption_over_it(crank, frame, lever, rod_ratio):
    """The rod's number 5 (the ram's 6 on a block design) was led up from its link into the
    caption "The mechanism (sketch to scale, …)" over the sketch (方案 II and III and the
    block design; 方案 I's numbers found room): no two texts of the sheet overlap or stand nearer than a word space
    (tests/sheet_checks), every text of the sketch lies under the caption."""
    from core.drawing.checks import overlapping_texts
    from sheet_checks import crowded_texts
    spec = {"mode": "dimensions", "crank": crank, "frame": frame, "lever": lever}
    if rod_ratio:
        spec = {**Spec.from_dict(spec).to_dict(), "rod_ratio": rod_ratio, "rod_input": "ratio", "variant": "rod"}
    doc = {"spec": Spec.from_dict(spec).to_dict(), "rpm": [64.0]}
    sheet = task_sheet(doc, {"student": "x"}, ["Motion"], {})
    assert overlapping_texts(sheet) == [] and crowded_texts(sheet) == []
    texts = [t for t in sheet.items if isinstance(t, Text)]
    caption = next(t for t in texts if t.text.startswith("The mechanism"))
    numbers = [t for t in texts if t.text in {"2", "3", "4", "5", "6"}]
    assert len(numbers) == 5           # the block variant's block at B is 5, as the rod is
    assert all(t.box()[3] < caption.box()[1] for t in numbers)
