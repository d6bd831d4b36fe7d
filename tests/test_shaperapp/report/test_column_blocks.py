"""``column_blocks``: a table wider than the page as blocks of columns that fit, the
identifying columns in each, every other column in exactly one, in order."""
from __future__ import annotations

from hypothesis import given, strategies as st

from shaperapp.report.blocks import Table, column_blocks, split_table

widths = st.lists(st.floats(1.0, 60.0), min_size=1, max_size=30)


@given(widths, st.integers(0, 3), st.floats(80.0, 200.0))
def test_blocks_keep_every_column_once_and_fit(ws, lead, page):
    lead = min(lead, len(ws))
    blocks = column_blocks(ws, lead, page)
    assert all(b[:lead] == list(range(lead)) for b in blocks)
    rest = [c for b in blocks for c in b[lead:]]
    assert rest == list(range(lead, len(ws)))
    for b in blocks:
        assert sum(ws[c] for c in b) <= page or len(b) <= lead + 1   # one column too wide
    if sum(ws) <= page:
        assert blocks == [list(range(len(ws)))]


def test_sixteen_speeds_split_evenly():
    blocks = column_blocks([40.0] + [20.0] * 16, 1, 176.0)
    assert [len(b) - 1 for b in blocks] == [6, 5, 5]


def test_split_table_repeats_the_row_names_and_marks_the_caption(qapp):
    table = Table(["name", "a", "b"], [["x", "1", "2"], ["y", "3", "4"]], "Cap")
    first, second = split_table(table, [[0, 1], [0, 2]])
    assert first.header == ["name", "a"] and first.rows == [["x", "1"], ["y", "3"]]
    assert second.rows == [["x", "2"], ["y", "4"]]
    assert first.caption == "Cap" and second.caption != "Cap" and "Cap" in second.caption
