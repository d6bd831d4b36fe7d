"""The Library pane's Name column stays in view when the figures are scrolled sideways
(issue 34 item 8: in a pane 600 px wide the names scrolled away with the figures, and
a row said no longer which design it was)."""
from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QSettings, Qt
from PySide6.QtWidgets import QAbstractItemView, QMessageBox

from shaperapp.library.pane import LibraryPane

from gui_helpers import shown


@pytest.fixture
def pane(qtbot, model, tmp_path, monkeypatch):
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: None)
    widget = LibraryPane(model, settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    assert widget.open_library(str(tmp_path / "lib.sqlite"))
    for name, k in (("first design", 1.4), ("second design", 1.6)):
        model.set_spec(time_ratio=k)
        assert widget.actions.save_current(name, notes="", tags=[])
    return shown(qtbot, widget, 600, 400)


def cell_seen_at(view, point: QPoint) -> tuple[int, int, str]:
    """Row, column and text of the cell a user sees at ``point`` (the view's coordinates)."""
    child = view.childAt(point)
    table = child.parentWidget()
    assert isinstance(table, QAbstractItemView), child
    index = table.indexAt(child.mapFrom(view, point))
    return index.row(), index.column(), index.data()


@pytest.mark.parametrize("where", ["middle", "end"])
def test_names_stay_when_the_figures_scroll(qtbot, pane, where):
    view = pane.view
    bar = view.horizontalScrollBar()
    assert bar.maximum() > 0                                    # 21 columns do not fit 600 px
    bar.setValue(bar.maximum() if where == "end" else bar.maximum() // 2)
    qtbot.wait(10)
    names = sorted(pane.table_model.name_at(r) for r in range(2))
    for row in range(2):
        y = view.horizontalHeader().height() + view.frameWidth() + view.rowViewportPosition(row) + 4
        seen = cell_seen_at(view, QPoint(view.frameWidth() + 8, y))
        assert seen == (row, 0, names[row]), seen
    # the other columns are reachable to the last, and come into view beside the names
    view.scrollTo(pane.table_model.index(0, pane.table_model.columnCount() - 1))
    qtbot.wait(10)
    last = pane.table_model.columnCount() - 1
    assert view.columnViewportPosition(last) + view.columnWidth(last) <= view.viewport().width() + 1


def test_clicking_the_frozen_name_header_sorts(qtbot, pane):
    view = pane.view
    header_point = QPoint(view.frameWidth() + 8, view.frameWidth() + 4)
    target = view.childAt(header_point)
    qtbot.mouseClick(target, Qt.MouseButton.LeftButton, pos=target.mapFrom(view, header_point))
    qtbot.wait(10)
    assert view.horizontalHeader().sortIndicatorSection() == 0
    order = view.horizontalHeader().sortIndicatorOrder()
    names = [pane.table_model.name_at(r) for r in range(2)]
    assert names == sorted(names, reverse=order == Qt.SortOrder.DescendingOrder)


def test_no_column_is_half_under_the_names(qtbot, pane):
    """Scrolled by the pixel, the column beside the frozen names showed only its last
    digits; every position short of the end now starts a column at the names' edge."""
    view = pane.view
    bar = view.horizontalScrollBar()
    edge = view.columnWidth(0)
    for value in range(0, bar.maximum(), 7):
        bar.setValue(value)
        if bar.value() == bar.maximum():
            break                     # the end shows the last column whole, at the right
        starts = [view.columnViewportPosition(c) for c in range(1, pane.table_model.columnCount())]
        cut = [x for x, c in zip(starts, range(1, pane.table_model.columnCount()))
               if x < edge < x + view.columnWidth(c)]
        assert cut == [], (value, bar.value(), edge, cut)


def test_small_steps_still_scroll_to_the_end(qtbot, pane):
    bar = pane.view.horizontalScrollBar()
    seen = [bar.value()]
    for _ in range(200):
        bar.setValue(bar.value() + 3)                 # an arrow key's or a wheel's small step
        seen.append(bar.value())
        if bar.value() == bar.maximum():
            break
    assert bar.value() == bar.maximum() and seen == sorted(seen)
    for _ in range(200):
        bar.setValue(bar.value() - 3)
        if bar.value() == 0:
            break
    assert bar.value() == 0
