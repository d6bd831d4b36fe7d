"""A shown axis (plots.axes.TickAxis) lays its title out as HTML only when the title's text
changes: pyqtgraph set it again whenever it was shown or its range changed, the same text
(docs/performance.md, "The report's build (issue 43 item 4), 30 November"). On 18a5ced
each of these laid it out again."""
from __future__ import annotations

import pyqtgraph as pg

from shaperapp.plots.axes import TickAxis


def spied_axis() -> tuple[pg.AxisItem, list[str], pg.PlotItem]:
    """The left axis of an app plot, titled, the texts its label is given from now on, and
    the plot (kept alive by the caller: it owns the axis)."""
    axis = TickAxis("left")           # pyqtgraph's default SI prefixes on, as a plot first makes it
    plot = pg.PlotItem(axisItems={"left": axis})
    axis.setLabel("Ram x", units="mm")
    given: list[str] = []
    set_html = axis.label.setHtml
    axis.label.setHtml = lambda text: given.append(text) or set_html(text)
    return axis, given, plot


def test_a_range_change_leaves_the_title_as_it_is(qapp):
    axis, given, _plot = spied_axis()
    before = axis.label.toHtml()
    for low, high in ((0.0, 10.0), (-5.0, 250.0), (0.0, 20.0)):
        axis.setRange(low, high)          # no SI prefix in these: "mm" stays
    axis.showLabel(True)
    axis.enableAutoSIPrefix(False)
    assert given == []
    assert axis.label.toHtml() == before


def test_a_new_title_or_colour_is_laid_out(qapp):
    axis, given, _plot = spied_axis()
    axis.setLabel("Ram v", units="m/s")
    axis.setTextPen(pg.mkPen("#ff0000"))
    assert len(given) == 2
    assert "Ram v" in given[0] and "m/s" in given[0]
    assert "#ff0000" in given[1]
    assert "Ram v" in axis.label.toPlainText()
