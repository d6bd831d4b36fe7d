"""The title block does not cut a name that could be read whole (the reviewer's class: the
"Drawn" cell printed "Alexandra Konst…"). A student's name, number and class, the school,
the supervisor and the date stay on one line as large as fits down to 2.5 mm, else go on
two lines; only a text that two lines cannot hold is cut, and it ends in "…".

The cells are located here from GB/T 10609.1's layout (180 × 56 mm in the border's lower
right corner: the signature area 22 + 34 + 24 mm, the middle 22 + 28 mm, the name area
50 mm with rows of 18, 18 and 20 mm; four rows of 14 mm), not from the title block's code.
"""
from __future__ import annotations

import pytest

from core.drawing.sheet import Text, paper
from core.drawing.title_block import TITLE_ENGLISH, TitleBlock, sheet_title_block

# values whose lines at 2.5 mm are far shorter than their cells on two lines (at most 12
# Latin or 8 CJK characters a line), but longer than one line holds at 2.5 mm
FITS = {
    "en": dict(drawn="Alexandra Konstantinou", supervisor="Maximilian Schwarzer", number="202100123456",
               group="ME 2101 Excellence", school="School of Mechanical Engineering", date="2026-11-30"),
    "zh": dict(drawn="欧阳诸葛长风慕容司马上官复姓", supervisor="司马上官欧阳长风教授", number="202100123456",
               group="机械工程及自动化2101班", school="机械工程与自动化学院卓越工程师学院", date="2026年11月30日"),
}
TOO_LONG = "Bartholomew-Alexander Konstantinopoulou-Papadimitriou von Habsburg-Lothringen"


def cells(p) -> dict[str, tuple[float, float, float, float]]:
    """Each user field's cell (x0, y0, x1, y1), mm."""
    x1, y0 = p.border[2], p.border[1]
    x0, top = x1 - 180.0, y0 + 56.0
    row = lambda k: (top - 14.0 * (k + 1), top - 14.0 * k)           # noqa: E731
    sign, mid = x0 + 22.0, x0 + 80.0 + 22.0
    return {"drawn": (sign, *row(0))[:1] + (row(0)[0], sign + 34.0, row(0)[1]),
            "date": (sign + 34.0, row(0)[0], sign + 58.0, row(0)[1]),
            "supervisor": (sign, row(1)[0], sign + 34.0, row(1)[1]),
            "number": (mid, row(0)[0], mid + 28.0, row(0)[1]),
            "group": (mid, row(1)[0], mid + 28.0, row(1)[1]),
            "school": (x1 - 50.0, top - 18.0, x1, top)}


def field_lines(items, cell) -> list[Text]:
    """The texts whose centre lies in ``cell``, top line first."""
    texts = [t for t in items if isinstance(t, Text)]
    inside = [t for t in texts if cell[0] < (t.box()[0] + t.box()[2]) / 2 < cell[2]
              and cell[1] < (t.box()[1] + t.box()[3]) / 2 < cell[3]]
    return sorted(inside, key=lambda t: -t.position[1])


def drawn(block: TitleBlock, sheet: str = "A3"):
    p = paper(sheet)
    _, items = sheet_title_block(p, block, {**TITLE_ENGLISH, "title": "Motion analysis"}, "1:5")
    return p, items


@pytest.mark.parametrize("sheet", ["A3", "A1"])
@pytest.mark.parametrize("language", FITS)
def test_a_long_name_is_set_whole_on_two_lines_rather_than_cut(language, sheet):
    values = FITS[language]
    p, items = drawn(TitleBlock("Motion analysis", "s01", "1:5", "1/4", **values), sheet)
    for field, cell in cells(p).items():
        lines = field_lines(items, cell)
        assert 1 <= len(lines) <= 2, (field, [t.text for t in lines])
        for t in lines:
            box = t.box()
            assert cell[0] <= box[0] and box[2] <= cell[2] and cell[1] <= box[1] and box[3] <= cell[3], (field, t)
            assert t.height >= 2.5
        shown = "".join(t.text for t in lines)
        assert "…" not in shown and shown.replace(" ", "") == values[field].replace(" ", ""), (field, shown)
        if len(lines) == 2:                        # both lines of one height
            assert lines[0].height == lines[1].height


@pytest.mark.parametrize("field", ["drawn", "supervisor", "group", "school"])
def test_what_two_lines_cannot_hold_is_cut_with_an_ellipsis(field):
    p, items = drawn(TitleBlock("Motion analysis", "s01", "1:5", "1/4", **{field: TOO_LONG}))
    lines = field_lines(items, cells(p)[field])
    shown = "".join(t.text for t in lines)
    assert shown.endswith("…"), shown
    assert TOO_LONG.replace(" ", "").startswith(shown[:-1].replace(" ", "")), shown


# a class as schools name it: the programme and the class's number, in English and Chinese
CLASSES = ["Mechanical Engineering 2101", "Vehicle Engineering 2102", "Mechanical Eng. Class 2101",
           "机械设计制造及其自动化2101班", "机械设计制造及其自动化专业2101班", "车辆工程（卓越工程师）2102班"]


@pytest.mark.parametrize("sheet", ["A0", "A1", "A2", "A3"])
@pytest.mark.parametrize("group", CLASSES)
def test_a_class_name_is_printed_whole(group, sheet):
    """The class cell (28 × 14 mm) prints a realistic class name whole: on up to three lines
    at 2.5 mm (GB/T 14691's next height down, 1.8 mm, is for letters and digits only; its
    Chinese characters are at least 3.5 mm). "Mechanical Engineering 2101" was cut to
    "Mechanical / Engineering …" on two lines."""
    p, items = drawn(TitleBlock("Motion analysis", "s01", "1:5", "1/4", group=group), sheet)
    assert_whole(field_lines(items, cells(p)["group"]), cells(p)["group"], group)


SCHOOLS = ["School of Mechanical Engineering and Automation, Northeastern University",
           "华中科技大学机械科学与工程学院机械设计制造及其自动化系"]


@pytest.mark.parametrize("school", SCHOOLS)
def test_a_long_school_is_printed_whole_in_the_name_area(school):
    """The name area's 50 × 18 mm cell holds four lines at 2.5 mm: a university's school
    is printed whole (the English one was cut on two lines)."""
    p, items = drawn(TitleBlock("Motion analysis", "s01", "1:5", "1/4", school=school))
    assert_whole(field_lines(items, cells(p)["school"]), cells(p)["school"], school)


def assert_whole(lines, cell, value) -> None:
    """``lines`` show ``value`` whole, inside ``cell``, one height, a line pitch apart."""
    shown = "".join(t.text for t in lines)
    assert "…" not in shown and shown.replace(" ", "") == value.replace(" ", ""), shown
    for t in lines:
        box = t.box()
        assert cell[0] + 0.5 <= box[0] and box[2] <= cell[2] - 0.5, (t.text, box, cell)
        assert cell[1] <= box[1] and box[3] <= cell[3], (t.text, box, cell)
        assert t.height >= 2.5
    for upper, lower in zip(lines, lines[1:]):        # one height, a line pitch of at least 1.4 h apart
        assert upper.height == lower.height
        assert upper.position[1] - lower.position[1] >= 1.4 * upper.height - 1e-9
        assert upper.box()[1] >= lower.box()[3]


@pytest.mark.parametrize("design", ["L1 100 mm, K 1.4, H 300 mm", "L1 100 mm, K 1.46, H 312 mm, L4/L3 0.3"])
def test_a_design_named_by_its_inputs_breaks_after_a_comma(design):
    """The design cell (50 × 13 mm over the speed) breaks a name of inputs after a comma
    where that sets it as large: "L1 100 mm, K / 1.4, H 300 mm" parted K from its value."""
    p, items = drawn(TitleBlock("Motion analysis", design, "1:5", "1/4", speed="n_2 = 40 r/min"))
    x1, y0 = p.border[2], p.border[1]
    cell = (x1 - 50.0, y0 + 7.0, x1, y0 + 20.0)
    lines = field_lines(items, cell)
    assert len(lines) == 2, [t.text for t in lines]
    assert_whole(lines, cell, design)
    assert lines[0].text.endswith(","), [t.text for t in lines]
