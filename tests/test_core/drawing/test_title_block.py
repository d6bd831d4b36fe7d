"""The title block after GB/T 10609.1 (issue 32, item 6): 180 × 56 mm in the border's lower
right corner, in its three zones of ruled cells, with the course design's fields (the
report cover's: name, number, class, school, supervisor, date) each in a cell of its own."""
from __future__ import annotations

import numpy as np
import pytest

from core.drawing.dxf import OUTLINE, THIN, TITLE
from core.drawing.motion import motion_sheet
from core.drawing.checks import overlapping_texts
from core.drawing.sheet import PAPERS, Polyline, Text, item_box, paper
from core.drawing.title_block import TITLE_ENGLISH, TitleBlock, sheet_title_block
from core.linkage.geometry import synthesize

FIELDS = dict(drawn="Zhang San", number="2021001", group="ME 2101", school="SME",
              supervisor="Li Si", date="2026-11-27")
BLOCK = TitleBlock("Motion analysis", "bracket", "", "1/3", **FIELDS)


def drawn(name: str = "A1", block: TitleBlock = BLOCK):
    p = paper(name)
    box, items = sheet_title_block(p, block, {**TITLE_ENGLISH, "title": "Motion analysis"}, "1:5")
    return p, box, items


@pytest.mark.parametrize("name", sorted(PAPERS))
def test_180_by_56_in_the_lower_right_corner_of_the_border(name):
    p, box, items = drawn(name)
    x0, y0, x1, y1 = box
    assert (x1 - x0, y1 - y0) == pytest.approx((180.0, 56.0))
    assert (x1, y0) == pytest.approx((p.border[2], p.border[1]))
    bounds = np.array([item_box(it) for it in items])
    assert bounds[:, 0].min() >= x0 - 1e-9 and bounds[:, 2].max() <= x1 + 1e-9
    assert bounds[:, 1].min() >= y0 - 1e-9 and bounds[:, 3].max() <= y1 + 1e-9


def vertical_lines(items, layer):
    return sorted({round(float(it.points[0, 0]), 6) for it in items if isinstance(it, Polyline)
                   and it.layer == layer and len(it.points) == 2 and it.points[0, 0] == it.points[1, 0]})


def test_three_zones_of_ruled_cells():
    """Thick zone borders at 80 and 130 mm from the left edge (signature area, other area,
    name area), thin cell rules between; four rows of 14 mm left and in the middle, the
    name area 18 + 18 + 20 mm."""
    _, (x0, y0, x1, y1), items = drawn()
    assert [x - x0 for x in vertical_lines(items, OUTLINE)] == pytest.approx([80.0, 130.0])
    assert [x - x0 for x in vertical_lines(items, THIN)] == pytest.approx([22.0, 56.0, 102.0])
    rules = [it for it in items if isinstance(it, Polyline) and it.layer == THIN
             and it.points[0, 1] == it.points[1, 1]]
    left = sorted(float(r.points[0, 1]) - y0 for r in rules if r.points[0, 0] == x0)
    right = sorted(float(r.points[0, 1]) - y0 for r in rules if r.points[0, 0] == x0 + 130.0)
    assert left == pytest.approx([14.0, 28.0, 42.0]) and right == pytest.approx([20.0, 38.0])


def cell_of(items, text: str):
    """The title block text ``text`` (on the TITLE layer)."""
    found = [t for t in items if isinstance(t, Text) and t.text == text]
    assert len(found) == 1, text
    assert found[0].layer == TITLE
    return found[0]


def test_every_course_design_field_in_its_own_cell():
    """Each value sits in the cell beside its label (same row, the next column), the school,
    the sheet's name and the design in the name area."""
    _, (x0, y0, x1, y1), items = drawn()
    row = lambda t: int((y1 - t.position[1]) // 14.0)                     # noqa: E731
    column = lambda t: t.position[0] - x0                                # noqa: E731
    pairs = [("Drawn", "Zhang San"), ("Supervisor", "Li Si"), ("Number", "2021001"),
             ("Class", "ME 2101"), ("Scale", "1:5"), ("Sheet", "1/3")]
    for label, value in pairs:
        lab, val = cell_of(items, label), cell_of(items, value)
        assert row(lab) == row(val), label
        assert column(val) > column(lab) and (column(lab) < 80.0) == (column(val) < 80.0), label
    date = cell_of(items, "2026-11-27")
    assert row(date) == row(cell_of(items, "Zhang San")) and 56.0 < column(date) < 80.0
    named = [t for t in items if isinstance(t, Text) and column(t) > 130.0]
    assert " ".join(t.text for t in named) == "SME Motion analysis bracket"   # top to bottom
    heights = [t.height for t in items if isinstance(t, Text)]
    title = [t for t in named if t.text in ("Motion", "analysis")]           # on two lines, 5 mm
    assert len(title) == 2 and all(t.height == max(heights) == 5.0 for t in title)
    assert [(a.text, b.text) for a, b in overlapping_texts(type("S", (), {"items": items})())] == []


def test_a_long_design_name_on_two_lines_not_cut():
    name = "L1 100 mm, K 1.46, H 312 mm, L4/L3 0.3"
    _, (x0, y0, x1, y1), items = drawn(block=TitleBlock("Motion analysis", name, "", "1/3"))
    texts = [t.text for t in items if isinstance(t, Text)]
    assert not any("…" in t for t in texts)
    assert any(f"{a} {b}" == name for a, b in zip(texts, texts[1:]))


def test_the_sheets_keep_clear_of_the_taller_block_on_a3():
    """The motion sheet's curves and table on A3 stay out of the 56 mm block (the checks of
    sheet_checks for every sheet and paper are in the sheets' own tests)."""
    sheet = motion_sheet(synthesize(100.0, 1.46, 312.0, rod_ratio=0.3), 40.0, paper("A3"),
                         block=BLOCK)
    block_area = sheet.areas["title"][0]
    for name, (area, _) in sheet.areas.items():
        if name != "title":
            assert not (area[0] < block_area[2] and block_area[0] < area[2]
                        and area[1] < block_area[3] and block_area[1] < area[3]), name
