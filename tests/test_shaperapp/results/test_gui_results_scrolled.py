"""The Results pane scrolled as a user scrolls it on a laptop, with 16 speeds (issue 34
item 8): scrolled sideways by the pixel, the column beside the frozen row titles was cut
(253.0615 read 53.0615), and scrolled down, a table taller than the pane lost the speeds
over its columns."""
from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QRect
from PySide6.QtWidgets import QScrollArea

from shaperapp.results.panel import MetricsPanel
from shaperapp.widgets.result_table import CELL_PADDING

from gui_helpers import shown

SIXTEEN = [20.0 + 5.0 * i for i in range(16)]


@pytest.fixture
def pane(qtbot, model):
    """The pane in a scroll area as the dock holds it: 360 × 200 px (1280 × 720)."""
    model.set_rpms(SIXTEEN)
    area = QScrollArea()
    area.setWidgetResizable(True)
    panel = MetricsPanel(model)
    area.setWidget(panel)
    shown(qtbot, area, 360, 200)
    qtbot.wait(20)
    return area, panel


@pytest.mark.parametrize("table_index", [2, 3])
def test_every_column_in_view_is_whole_at_every_scroll_position(qtbot, pane, table_index):
    area, panel = pane
    table = panel.tables()[table_index]
    area.ensureWidgetVisible(table)
    bar = table.horizontalScrollBar()
    assert bar.maximum() > 0                                   # 16 speeds scroll
    port = table.viewport().width()
    for value in range(bar.minimum(), bar.maximum() + 1):
        bar.setValue(value)
        qtbot.wait(1)
        cut = []
        for col in range(table.columnCount()):
            x, w = table.columnViewportPosition(col), table.columnWidth(col)
            seen = min(x + w, port) - max(x, 0)
            # cut, unless all that shows is a sliver of the blank beside its text
            if 0 < seen < w and seen >= CELL_PADDING // 2:
                cut.append((col, x, w))
        assert cut == [], (value, port, cut)


def test_speed_titles_stay_over_the_rows_seen(qtbot, pane):
    area, panel = pane
    table = panel.tables()[2]
    header = table.horizontalHeader()
    port = area.viewport()
    top = table.mapTo(panel, QPoint(0, 0)).y()
    for scrolled in (top + 30, top + 80):         # the table's top above the pane's view
        area.verticalScrollBar().setValue(scrolled)
        qtbot.wait(10)
        seen = QRect(header.mapTo(port, QPoint(0, 0)), header.size())
        assert port.rect().contains(seen), (scrolled, seen, port.rect())
        assert header.isVisible()
        rows_seen = QRect(table.viewport().mapTo(port, QPoint(0, 0)), table.viewport().size()) & port.rect()
        assert not rows_seen.isEmpty()
    assert table.horizontalHeaderItem(0).text() == "20 r/min"
