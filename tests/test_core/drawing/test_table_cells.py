"""Each text of a ruled table stands in its own cell. The answer key of `shaper class` printed
its first column, the row numbers and their heading 序号 / "No.", centred on the whole table
(over L4's values, "1135.000", and over M_m's and x2's): `table` gave the first column's
cell the table's full width whenever no text spanned (5058cdb)."""
from __future__ import annotations

import numpy as np
import pytest

from core.drawing.cells import table
from core.drawing.class_sheets import answer_pages
from core.drawing.sheet import Text


def columns_of(texts: list[Text], edges: np.ndarray) -> list[tuple[str, int, int]]:
    """(text, the column its box starts in, the column it ends in) of each text."""
    out = []
    for t in texts:
        x0, _, x1, _ = t.box()
        out.append((t.text, int(np.searchsorted(edges, x0, side="right")) - 1,
                    int(np.searchsorted(edges, x1, side="left")) - 1))
    return out


@pytest.mark.parametrize("spans", [False, True])
@pytest.mark.parametrize("aligns", [None, "lcc"])
def test_every_text_stands_in_its_own_column(spans, aligns):
    widths = (9.0, 24.0, 20.0)
    rows = [("No.", "Student", "Number"), ("1", "Zhang", "2021001"), ("12", "Li", "2021002")]
    items = table((10.0, 100.0), widths, rows, 6.0, 2.5, aligns=aligns, spans=spans)
    edges = 10.0 + np.concatenate([[0.0], np.cumsum(widths)])
    texts = [t for t in items if isinstance(t, Text)]
    expected = {text: c for row in rows for c, text in enumerate(row)}
    assert [(text, expected[text], expected[text]) for text, _, _ in columns_of(texts, edges)] \
        == columns_of(texts, edges)


def test_a_spanning_text_still_fills_the_empty_cells_after_it():
    items = table((0.0, 50.0), (30.0, 20.0, 20.0), [("a′", "162.0000 (159.0000) mm", "")], 8.0, 3.5,
                  aligns="lcc", spans=True)
    (value,) = [t for t in items if isinstance(t, Text) and t.text.startswith("162")]
    assert value.box()[0] < 50.0 < value.box()[2]          # centred on both gears' columns


def test_the_answer_keys_row_numbers_stand_in_the_first_column():
    header = (("No.", "Student", "θ"), ("", "", "°"))
    rows = [[str(k), f"student {k}", "33.653"] for k in range(1, 4)]
    (page,) = answer_pages([(header, [9.0, 24.0, 16.0], rows)], "Answer key", {"page %1/%2": "page %1/%2"},
                           plain=(1,))
    numbers = [t for t in page.items if isinstance(t, Text) and t.text in ("No.", "1", "2", "3")]
    name = next(t for t in page.items if isinstance(t, Text) and t.text == "student 1")
    assert len(numbers) == 4
    assert all(t.box()[2] < name.box()[0] for t in numbers)      # left of the names' column


def test_a_left_aligned_first_column_fits_its_text_to_its_own_width():
    """The sheets' tables align their first column left: there the text started in place,
    but was fitted to the whole table's width, so a long label was neither set smaller nor
    cut and ran on under the values."""
    items = table((0.0, 50.0), (30.0, 40.0), [("Energy fluctuation ΔW_max", "1102 J")], 8.0, 5.0, aligns="lc")
    label = next(t for t in items if isinstance(t, Text) and t.text != "1102 J")
    assert label.box()[2] <= 30.0


def test_a_student_whose_speeds_run_onto_the_next_page_is_named_on_it():
    """A student's speeds after the first are rows with no number nor name; a student of 16
    speeds ran onto the next pages of the answer key, which showed figures under no name.
    The first row of a page that continues a student repeats the number and the name."""
    header = (("No.", "Student", "Number", "n"), ("", "", "", "r/min"))
    rows = [["1", "Zhang", "2021001", "60"]] + [["2", "Li", "2021002", "20"]] + \
        [["", "", "", str(10 + k)] for k in range(80)] + [["3", "Wang", "2021003", "60"]]
    pages = answer_pages([(header, [9.0, 24.0, 20.0, 12.0], rows)], "Answer key", {"page %1/%2": "page %1/%2"},
                         plain=(1, 2))
    assert len(pages) >= 3
    for page in pages:
        texts = [t for t in page.items if isinstance(t, Text)]
        speeds = [t for t in texts if t.text.isdigit() and len(t.text) == 2]
        top = max(speeds, key=lambda t: t.box()[1])               # the page's first row of figures
        row = {t.text for t in texts if abs(sum(t.box()[1::2]) - sum(top.box()[1::2])) < 1e-6}
        assert any(who <= row for who in ({"1", "Zhang", "2021001"}, {"2", "Li", "2021002"},
                                          {"3", "Wang", "2021003"})), row
