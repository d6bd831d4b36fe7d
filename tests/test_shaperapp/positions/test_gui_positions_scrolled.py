"""The Positions tab scrolled sideways on a laptop (issue 34 item 8): the table moved by
the pixel and its crank-angle column scrolled away with the values, so a row said only
its number. Now φ stays frozen beside the row titles and the values move by whole
columns, as in the Results pane and the library."""
from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QRect, Qt
from PySide6.QtWidgets import QAbstractItemView

from shaperapp.positions.view import PositionsView
from shaperapp.widgets import i18n

from gui_helpers import shown


@pytest.fixture(params=["en", "zh_CN"])
def view(request, qtbot, model):
    """The tab's table as wide as at 1280 × 720 (530 px), in both languages."""
    i18n.set_language(request.param)
    try:
        widget = shown(qtbot, PositionsView(model), 530, 430)
        qtbot.wait(20)
        yield widget
    finally:
        i18n.set_language("en")


def seen_at(view, point: QPoint) -> tuple[int, int]:
    """Row and column of the cell a user sees at ``point`` of the table's coordinates."""
    table = view.view
    child = table.childAt(point)
    owner = child.parentWidget()
    assert isinstance(owner, QAbstractItemView), child
    index = owner.indexAt(child.mapFrom(table, point))
    return index.row(), index.column()


def test_angle_column_stays_and_values_move_by_whole_columns(qtbot, view):
    table = view.view
    bar = table.horizontalScrollBar()
    assert bar.maximum() > 0                               # 27 columns do not fit 530 px
    left = table.verticalHeader().width() + table.frameWidth()
    edge = table.columnWidth(0)                            # the frozen φ column's right edge
    seen_values = set()
    value = -1
    while value != bar.value() or value < 0:
        value = bar.value()
        for row in (0, table.model().rowCount() - 1):
            y = table.horizontalHeader().height() + table.frameWidth() + table.rowViewportPosition(row) + 4
            assert seen_at(view, QPoint(left + 8, y)) == (row, 0), value       # φ, at every position
        columns = table.model().columnCount()
        starts = {c: table.columnViewportPosition(c) for c in range(1, columns)}
        cut = [c for c, x in starts.items() if x < edge < x + table.columnWidth(c)]
        assert cut == [], (value, cut)                     # none half under φ
        assert edge in starts.values(), value              # a column starts at φ's edge
        seen_values.add(value)
        bar.triggerAction(bar.SliderAction.SliderSingleStepAdd)
        qtbot.wait(1)
    last = table.model().columnCount() - 1
    assert table.columnViewportPosition(last) + table.columnWidth(last) <= table.viewport().width()
    assert len(seen_values) >= 5


def test_frozen_rows_line_up_with_the_table(view):
    table, frozen = view.view, view.view.frozen
    assert frozen.horizontalHeader().height() == table.horizontalHeader().height()
    for row in range(table.model().rowCount()):
        assert frozen.rowViewportPosition(row) == table.rowViewportPosition(row), row
        assert frozen.rowHeight(row) == table.rowHeight(row), row
    port = QRect(QPoint(0, 0), table.size())
    assert port.contains(frozen.geometry())


def test_headers_write_the_notation_in_characters(view):
    """A header is plain text: the course notation of its title (v_A3A4, a^k, typeset in
    the report) is written as characters there (vA3A4, aᵏ), never with its marks, and the
    header's font draws every character of it."""
    from PySide6.QtGui import QFontMetrics
    model = view.table_model
    titles = [model.headerData(c, Qt.Orientation.Horizontal) for c in range(model.columnCount())]
    columns = [model.headerData(c, Qt.Orientation.Horizontal, Qt.ItemDataRole.ToolTipRole)
               for c in range(model.columnCount())]
    assert not [t for t in titles if "^" in t or "_" in t], titles
    slide, coriolis = titles[columns.index("slide_v_m_s")], titles[columns.index("coriolis_m_s2")]
    assert "vA3A4 (m/s)" in slide and "aᵏ (m/s²)" in coriolis
    metrics = QFontMetrics(view.view.horizontalHeader().font())
    assert all(metrics.inFontUcs4(ord(ch)) for ch in "vA3A4aᵏ")
