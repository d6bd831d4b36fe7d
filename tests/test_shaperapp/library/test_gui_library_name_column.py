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
