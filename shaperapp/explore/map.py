"""The heat map of the Explore tab: one figure over two parameters.

A display component: it shows what it is given (a grid, values with NaN for
invalid designs, a marker) and reports the cell under the mouse and the cell
clicked. It knows nothing about the model. Invalid cells show the grey
background through the image (NaN is transparent).
"""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QBrush, QColor, QPen
from PySide6.QtWidgets import QGraphicsRectItem, QWidget

from shaperapp.widgets.axis_fit import axis_width

INVALID = QColor("#b8b8b8")
COLORMAP = "viridis"
TOP_MARGIN_PX = 10


class HeatMap(pg.PlotWidget):
    """A pyqtgraph plot with an ImageItem, a colour bar and a marker."""

    cellHovered = Signal(int, int)       # row (y index), column (x index); −1, −1 off the grid
    cellClicked = Signal(int, int)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent, background="w")
        self.x = np.zeros(0)
        self.y = np.zeros(0)
        item = self.getPlotItem()
        item.showGrid(False, False)
        item.setMenuEnabled(False)
        # no auto-range button ("A"): the grid sets the range, and the button's auto-range
        # framed the items instead and kept framing them after the next map
        item.hideButtons()
        # Room above the plot for half a tick label: the top tick ("3.0") was cut in half.
        item.layout.setContentsMargins(2, TOP_MARGIN_PX, 2, 2)
        self.getViewBox().setMouseEnabled(x=False, y=False)
        self.getViewBox().disableAutoRange()            # the grid sets the range
        self.backdrop = QGraphicsRectItem()
        self.backdrop.setBrush(QBrush(INVALID))
        # no outline: a pen here is 1 data unit wide (0.5 in K is 100 px), which the view's
        # clip hid on screen and an SVG export did not (grey all over the margin)
        self.backdrop.setPen(QPen(Qt.PenStyle.NoPen))
        self.backdrop.setZValue(-10)
        self.addItem(self.backdrop)
        self.image = pg.ImageItem()
        self.image.setZValue(-5)
        self.addItem(self.image)
        cmap = pg.colormap.get(COLORMAP)
        self.colorbar = pg.ColorBarItem(values=(0.0, 1.0), colorMap=cmap, interactive=False,
                                        width=14)
        self.colorbar.setImageItem(self.image, insert_in=item)
        self.colorbar.axis.setStyle(showValues=False)     # no figure computed: no values on its scale
        self.marker = pg.ScatterPlotItem(size=14, symbol="+", pen=pg.mkPen("#d62728", width=3),
                                         brush=None)
        self.addItem(self.marker)
        self.scene().sigMouseMoved.connect(self._moved)
        self.scene().sigMouseClicked.connect(self._clicked)

    def set_grid(self, x: np.ndarray, y: np.ndarray, values: np.ndarray) -> None:
        """Show ``values`` (ny, nx) on the grid x (nx,) × y (ny,); NaN cells show as invalid."""
        self.x, self.y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        rect = self._rect()
        self.backdrop.setRect(rect)
        finite = np.isfinite(values)
        low, high = (float(values[finite].min()), float(values[finite].max())) if finite.any() \
            else (0.0, 1.0)
        if high <= low:
            high = low + max(abs(low), 1.0) * 1e-9
        self.image.setImage(np.asarray(values, dtype=float).T, autoLevels=False)
        self.image.setRect(rect)
        self.colorbar.setLevels((low, high))
        self.colorbar.axis.setStyle(showValues=True)
        self.getViewBox().setRange(rect, padding=0.0)
        self._fit_colorbar()

    def show_extent(self, x: tuple[float, float], y: tuple[float, float]) -> None:
        """Before the first map: the axes span the ranges chosen, not pyqtgraph's 0 to 1,
        which read as parameter values no map had (an L1 (mm) axis from 0.2 to 0.8)."""
        if self.x.size == 0 and x[1] > x[0] and y[1] > y[0]:
            self.getViewBox().setRange(QRectF(x[0], y[0], x[1] - x[0], y[1] - y[0]), padding=0.0)

    def set_marker(self, x: float | None, y: float | None) -> None:
        self.marker.setData([] if x is None or y is None else [x], [] if y is None or x is None else [y])

    def set_labels(self, x_label: str, y_label: str, value_label: str = "") -> None:
        """The axes' titles and the colour bar's (the figure shown, with its unit)."""
        self.setLabel("bottom", x_label)
        self.setLabel("left", y_label)
        self.colorbar.axis.setLabel(value_label)
        self._fit_colorbar()

    def _fit_colorbar(self) -> None:
        """The colour bar's axis as wide as its title and its labels need: pyqtgraph allows
        0.8 of the title's height, and the Chinese title ran over the ticks."""
        axis = self.colorbar.axis
        axis.setWidth(math.ceil(axis_width(axis)))

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        if hasattr(self, "colorbar"):        # pyqtgraph resizes once while it builds the view
            self._fit_colorbar()             # another height may label other values

    def cell_center(self, row: int, column: int) -> QPointF:
        """Data coordinates of a cell's centre."""
        return QPointF(float(self.x[column]), float(self.y[row]))

    def cell_at(self, point: QPointF) -> tuple[int, int]:
        """(row, column) of the cell at data point ``point``, or (−1, −1) off the grid."""
        if self.x.size == 0 or not self._rect().contains(point):
            return -1, -1
        column = int(np.argmin(np.abs(self.x - point.x())))
        row = int(np.argmin(np.abs(self.y - point.y())))
        return row, column

    def _rect(self) -> QRectF:
        dx = (self.x[-1] - self.x[0]) / (self.x.size - 1) if self.x.size > 1 else 1.0
        dy = (self.y[-1] - self.y[0]) / (self.y.size - 1) if self.y.size > 1 else 1.0
        return QRectF(self.x[0] - dx / 2.0, self.y[0] - dy / 2.0, dx * self.x.size, dy * self.y.size)

    def _moved(self, scene_pos) -> None:
        point = self.getViewBox().mapSceneToView(scene_pos)
        self.cellHovered.emit(*self.cell_at(point))

    def _clicked(self, event) -> None:
        row, column = self.cell_at(self.getViewBox().mapSceneToView(event.scenePos()))
        if row >= 0:
            self.cellClicked.emit(row, column)
