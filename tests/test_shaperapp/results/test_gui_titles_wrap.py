"""A results table's long row titles, wrapped on two lines, stay wrapped when the table
becomes a scroll bar's width narrower.

Why: in the Results pane the tables' width followed their wrapping by 14 px (325 px
wrapped, 311 px not; the cause of the 14 px is not found, and it is not the pane's own
scroll bar), so the titles wrapped, unwrapped and wrapped again every turn of the event
loop: 61 450 fits and then a segmentation fault in test_gui_open_hostile.py under load
(1 December).
"""
from PySide6.QtWidgets import QStyle, QWidget

from shaperapp.widgets.result_table import TITLES_SHARE, ResultTable

TITLES = ["largest velocity of the ram while it cuts", "largest velocity of the ram on its return",
          "largest acceleration of the ram over the cycle"]


def wrapped(table: ResultTable) -> bool:
    return any("\n" in table.verticalHeaderItem(r).text() for r in range(table.rowCount()))


def test_wrapped_titles_stay_wrapped_a_scroll_bars_width_narrower(qtbot):
    """The rule itself, at its edge: columns that leave the titles exactly their share
    wrap them; a scroll bar's width narrower (the pane's bar came) they stay wrapped, so
    the bar does not go again (before: unwrapped, and the loop the module docstring tells)."""
    holder = QWidget()                  # a child is resized at once (a window, by its system)
    qtbot.addWidget(holder)
    holder.resize(1400, 600)
    table = ResultTable(holder)
    table.set_content(TITLES, ["60 r/min", "90 r/min"], [["0.7487 m/s", "1.1230 m/s"]] * 3)
    holder.show()
    qtbot.waitExposed(holder)
    table.resize(400, table.height())
    total = table.width() - 2 * table.frameWidth()
    columns = [total - round(TITLES_SHARE * total)]          # the titles' free width: their share
    table._wrap_titles(columns)
    assert wrapped(table)
    bar = table.style().pixelMetric(QStyle.PixelMetric.PM_ScrollBarExtent)
    table.resize(400 - bar, table.height())
    table._wrap_titles(columns)
    assert wrapped(table)               # before: unwrapped
    table.resize(400 - 3 * bar, table.height())
    table._wrap_titles(columns)
    assert not wrapped(table)           # well below the share: the columns scroll instead
