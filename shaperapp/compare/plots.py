"""The comparison's overlay curves: ram x, v, a and crank torque of 2 to 6 designs.

One component for the Compare tab and the design report, so both draw a
comparison the same way. Each design keeps one colour and one line style in all
four plots (Okabe–Ito colours, six dash patterns), so curves stay apart in
grey-scale prints too. It draws a :class:`core.space.compare.Comparison` and nothing else.
"""
from __future__ import annotations

import html

import pyqtgraph as pg
from PySide6.QtCore import QEvent, QRectF, QSizeF, Qt
from PySide6.QtGui import QColor, QPainter
from PySide6.QtWidgets import QWidget

from core.space.compare import Comparison

from shaperapp.plots.axes import cache_static, styled_plot_item
from shaperapp.widgets.image_export import painting_bytes, render_scene
from shaperapp.widgets.legend_wrap import wrap_legend

# Okabe–Ito colours (distinguishable with colour-blindness) and six line styles
COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9")
STYLES = (Qt.PenStyle.SolidLine, Qt.PenStyle.DashLine, Qt.PenStyle.DotLine, Qt.PenStyle.DashDotLine,
          Qt.PenStyle.DashDotDotLine, Qt.PenStyle.CustomDashLine)
CURVES = ("ram_x_mm", "ram_v_m_s", "ram_a_m_s2", "crank_torque_N_m")
WHITE = QColor("white")
LEGEND_ROW_PX = 26     # one row of legend entries
MAX_COLUMNS = 3        # designs a legend row holds at most, however wide the pane


def design_pen(index: int) -> pg.QtGui.QPen:
    """The pen of the ``index``-th design: its own colour and its own line style."""
    pen = pg.mkPen(COLOURS[index % len(COLOURS)], width=2)
    pen.setStyle(STYLES[index % len(STYLES)])
    if pen.style() == Qt.PenStyle.CustomDashLine:
        pen.setDashPattern([8, 3, 1, 3, 1, 3])
    pen.setCosmetic(True)
    return pen


class ComparePlots(pg.GraphicsLayoutWidget):
    """Four x-linked plots over the crank angle in a 2 × 2 grid, one curve per design, under
    a legend row of their own.

    A grid, not a column: on a laptop screen the Compare tab has about 300 px for its
    plots, and four plots stacked got 45 px each, too short for their axis titles (which
    ran into each other) or more than one tick. The legend sits above the plots, so it
    never covers a curve, in as many columns (at most three) as the pane's width holds:
    three long snapshot names on one row ran past the pane and cut the right plots.
    """

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setBackground("w")
        self._legend = pg.LegendItem(colCount=MAX_COLUMNS)
        self._columns = MAX_COLUMNS
        self._legend.setLabelTextColor("k")
        self.addItem(self._legend, row=0, col=0, colspan=2)
        self.ci.layout.setRowMaximumHeight(0, LEGEND_ROW_PX)
        self.ci.setContentsMargins(2, 2, 2, 2)
        self._items: dict[str, pg.PlotItem] = {}
        for k, key in enumerate(CURVES):
            item = styled_plot_item(0.05)
            self.addItem(item, row=1 + k // 2, col=k % 2)
            self._items[key] = item
            if k:
                item.setXLink(self._items[CURVES[0]])
        self._retranslate()
        self._show_empty(True)

    def item(self, key: str) -> pg.PlotItem:
        """The plot of ``key`` (one of ``CURVES``)."""
        return self._items[key]

    def show_comparison(self, result: Comparison | None) -> None:
        """Draw ``result``'s curves (a design without loads has no torque curve); None clears."""
        for item in self._items.values():
            for curve in list(item.listDataItems()):
                item.removeItem(curve)
        self._legend.clear()
        self._show_empty(result is None)
        if result is None:
            return
        for k, label in enumerate(result.labels):
            pen = design_pen(k)
            series = (result.ram_x_mm[k], result.ram_v_m_s[k], result.ram_a_m_s2[k],
                      result.crank_torque_N_m[k])
            for key, y in zip(CURVES, series):
                if y is not None:
                    curve = self._items[key].plot(result.crank_deg, y, pen=pen)
                    if key == CURVES[0]:
                        self._legend.addItem(curve, html.escape(label))   # rich text
        for item in self._items.values():
            item.enableAutoRange()
        self._columns = 0                     # new entries: lay them out again
        self._fit_legend()

    def _show_empty(self, empty: bool) -> None:
        """With no design to show, the plots span the cycle (0 to 360°) and their value
        axes show no numbers: pyqtgraph's 0 to 1 read as values no design had."""
        for item in self._items.values():
            item.getAxis("left").setStyle(showValues=not empty)
        if empty:
            self._items[CURVES[0]].setXRange(0.0, 360.0, padding=0.0)

    def legend_columns(self) -> int:
        """The columns the legend's entries take now."""
        return self._columns

    def _fit_legend(self) -> None:
        """The legend in the most columns (at most MAX_COLUMNS) the view's width holds,
        its row as tall as its rows of entries, which must not run into the plots."""
        left, _, right, _ = self.ci.getContentsMargins()
        room = self.viewport().width() - left - right - 4
        self._columns = wrap_legend(self._legend, room, self._columns, MAX_COLUMNS)
        rows = max(1, -(-len(self._legend.items) // max(self._columns, 1)))
        self.ci.layout.setRowMaximumHeight(0, LEGEND_ROW_PX * rows)
        self.ci.layout.setRowMinimumHeight(0, LEGEND_ROW_PX * rows)
        self._legend.layout.activate()        # laid out now: an export may follow at once
        self.ci.layout.activate()

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        # pyqtgraph resizes before __init__ ends, and after close() has cleared the scene
        legend = getattr(self, "_legend", None)
        if legend is not None and not self.closed and legend.items:
            self._fit_legend()

    def render_plots(self, painter: QPainter, target: QRectF) -> None:
        """Paint the plots into ``target`` of any painter, as vectors."""
        items = list(self._items.values())
        render_scene(self.scene(), self.ci.sceneBoundingRect(), painter, target, WHITE,
                     lambda exporting: cache_static(items, not exporting))

    def svg(self, title: str) -> bytes:
        """The plots at their current size as an SVG document."""
        return painting_bytes("svg", QSizeF(self.size()), self.render_plots, title, WHITE)

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        titles = (self.tr("Ram x (mm)"), self.tr("Ram v (m/s)"), self.tr("Ram a (m/s²)"),
                  self.tr("Torque (N·m)"))
        for key, title in zip(CURVES, titles):
            self._items[key].setLabel("left", title)
        for key in CURVES[2:]:                        # the bottom row names the shared x axis
            self._items[key].setLabel("bottom", self.tr("Crank angle (°)"))
        if self._legend.items:
            self._fit_legend()
