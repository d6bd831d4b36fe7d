"""The Gear tab's result tables whole on a laptop screen: at 1280 × 720 their scroll area
was 13 px narrower than the tables' least width (row titles and one column) and cut their
right edge, so the pinion's 13 teeth read "1" and x = 0.239644 read 0.23964. Now the area
is at least that wide and the tables scroll their columns whole.

The window is the size it takes on those screens (the layout probe's frame, as in
tests/test_shaperapp/plots/test_gui_stack_on_screen.py)."""
from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QRect

from gui_helpers import main_window

WINDOWS = {"1280x720": (1268, 672), "1366x768": (1354, 720)}


@pytest.fixture(scope="module", params=list(WINDOWS))
def window(request, qapp, tmp_path_factory):
    with main_window(tmp_path_factory.mktemp("gear")) as win:
        win.resize(*WINDOWS[request.param])
        yield win


@pytest.mark.parametrize("lang", ["en", "zh_CN"])
def test_every_shown_cell_of_the_gear_tables_is_whole(qtbot, window, lang):
    qtbot.waitExposed(window)
    window.set_language(lang)
    window.tabs.setCurrentWidget(window._pages["gear"])
    tab = window._pages["gear"].view()
    qtbot.waitUntil(lambda: tab.isVisible(), timeout=10_000)
    qtbot.wait(50)
    area = tab.results.parentWidget().parentWidget()           # the tables' scroll area
    shown = QRect(area.viewport().mapTo(window, QPoint(0, 0)), area.viewport().size())
    assert window.rect().contains(shown)
    for table in (tab.results.gears, tab.results.pair):
        port = table.viewport()
        for col in range(table.columnCount()):
            left = table.columnViewportPosition(col)
            if left < 0 or left >= port.width():
                continue                                         # scrolled away, not cut
            cell = QRect(port.mapTo(window, QPoint(left, 0)),
                         port.mapTo(window, QPoint(left + table.columnWidth(col) - 1, 0)))
            assert shown.left() <= cell.left() and cell.right() <= shown.right(), (table, col, cell, shown)
            assert left + table.columnWidth(col) <= port.width(), (col, "cut by the table's own edge")


@pytest.mark.parametrize("lang", ["en", "zh_CN"])
def test_both_gears_columns_are_in_view_and_the_shift_fields_readable(qtbot, window, lang):
    """Issue 40: at 1280 × 720 in English "Gear 2" sat behind the table's own scroll bar,
    below the fold (only "Pinion 1" in view), and x1 = 0.2396444401… was cut in its field.
    Now the form leaves both columns room, and the fields show 7 significant digits."""
    qtbot.waitExposed(window)
    window.set_language(lang)
    window.tabs.setCurrentWidget(window._pages["gear"])
    tab = window._pages["gear"].view()
    qtbot.waitUntil(lambda: tab.isVisible(), timeout=10_000)
    tab.gear_model.set_fields(z1=10.0)                  # x1, x2 of a′ = 162: long numbers
    qtbot.wait(50)
    table = tab.results.gears
    for col in range(table.columnCount()):
        left = table.columnViewportPosition(col)
        assert 0 <= left and left + table.columnWidth(col) <= table.viewport().width(), (col, left)
    assert table.horizontalScrollBar().maximum() == 0
    for name in ("x1", "x2", "centre"):
        edit = tab.form.fields[name].edit
        assert edit.fontMetrics().horizontalAdvance(edit.text()) <= edit.contentsRect().width() - 4, \
            (name, edit.text())
