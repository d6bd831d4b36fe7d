"""The graphics items a plot draws with: curves, cursor lines and dots, shaded bands.

Each is drawn and bounded in C++ (a Qt path, line, rectangle or ellipse item)
instead of pyqtgraph's items that paint and bound themselves in Python, which
cost a visible share of every edit and animation frame. And each puts into an
export only what the screen's clip shows (see below). The scheme draws its links
with :class:`CurveItem` too; :mod:`.curves` arranges these items per plot.
"""
from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QPainter, QPainterPath, QPen
from PySide6.QtWidgets import (QGraphicsEllipseItem, QGraphicsItem, QGraphicsLineItem, QGraphicsPathItem,
                               QGraphicsRectItem)

from .clip import clipped_path, view_of

DOT_RADIUS = 3.5         # px, the dot marking each curve's value at the cursor


# ---- export: what a painter gets is what the screen's clip shows ---------------------------
# On screen the ViewBox clips its children to the plot area. An SVG (QSvgGenerator) has no
# clip, and QSvgRenderer, which replays it into the PDF report, ignores clip paths, so every
# item here puts only what lies in its view into an export (``setExportMode``, called by
# ``image_export.render_scene`` for every item that has it). The cursor and its dots are
# an animation's, not the figure's: an export leaves them out unless ``opts["cursor"]``.
class CursorDot(QGraphicsEllipseItem):
    """The cursor's dot on a curve: in an export only when asked, and inside its view."""

    def __init__(self) -> None:
        super().__init__(QRectF(-DOT_RADIUS, -DOT_RADIUS, 2 * DOT_RADIUS, 2 * DOT_RADIUS))
        self.setFlag(QGraphicsItem.GraphicsItemFlag.ItemIgnoresTransformations, True)
        self.setPen(QPen(QColor("#ffffff"), 1.0))

    def setExportMode(self, export: bool, opts: dict | None = None) -> None:  # noqa: N802
        if export:
            view = view_of(self)
            self._shown = self.isVisible()
            inside = view is not None and view.viewRect().contains(self.pos())
            self.setVisible(self._shown and inside and bool((opts or {}).get("cursor")))
        elif hasattr(self, "_shown"):
            self.setVisible(self._shown)
            del self._shown


def _full_height(view: pg.ViewBox) -> tuple[float, float]:
    """The view's y range and as much again above and below, so a pan never shows the
    ends of an item spanning it before the range signal has moved them."""
    y0, y1 = view.viewRange()[1]
    extra = max(y1 - y0, 1e-12)
    return y0 - extra, y1 + extra


class CursorLine(QGraphicsLineItem):
    """A vertical cursor across the plot's whole y range, moved by setPos only.

    Drawn and bounded in C++: pyqtgraph's InfiniteLine recomputes its bounding
    rectangle in Python at every move and paint, a visible share of an animation
    frame with several plots. The line follows the view's y range."""

    def __init__(self, view: pg.ViewBox) -> None:
        super().__init__()
        self._view = view
        view.sigYRangeChanged.connect(self.span)
        self.span()

    def span(self, *_: object) -> None:
        y0, y1 = _full_height(self._view)
        self.setLine(0.0, y0, 0.0, y1)

    def set_colour(self, rgba: int) -> None:
        line_pen = QPen(QColor.fromRgba(rgba), 1.0, Qt.PenStyle.DashLine)
        line_pen.setCosmetic(True)
        self.setPen(line_pen)

    def value(self) -> float:
        return self.x()

    def setExportMode(self, export: bool, opts: dict | None = None) -> None:  # noqa: N802
        """In an export: left out unless ``opts["cursor"]``, else across the view only."""
        if export:
            self._shown = self.isVisible()
            (x0, x1), (y0, y1) = self._view.viewRange()
            inside = x0 <= self.x() <= x1
            self.setVisible(self._shown and inside and bool((opts or {}).get("cursor")))
            self.setLine(0.0, y0, 0.0, y1)
        else:
            self.span()
            if hasattr(self, "_shown"):
                self.setVisible(self._shown)
                del self._shown

    def setValue(self, x: float) -> None:  # noqa: N802 - as InfiniteLine
        self.setPos(x, 0.0)


class BandRect(QGraphicsRectItem):
    """A shaded x span across the plot's whole y range (see :class:`CursorLine`): a C++
    rectangle instead of pyqtgraph's LinearRegionItem with its two Python edge lines."""

    def __init__(self, view: pg.ViewBox) -> None:
        super().__init__()
        self._view = view
        self._span = (0.0, 1.0)
        self.setPen(QPen(Qt.PenStyle.NoPen))
        view.sigYRangeChanged.connect(self._place)

    def set_span(self, start: float, end: float) -> None:
        self._span = (float(start), float(end))
        self._place()

    def span(self) -> tuple[float, float]:
        return self._span

    def _place(self, *_: object) -> None:
        y0, y1 = _full_height(self._view)
        x0, x1 = self._span
        self.setRect(QRectF(x0, y0, x1 - x0, y1 - y0).normalized())

    def setExportMode(self, export: bool, opts: dict | None = None) -> None:  # noqa: N802
        """In an export: the part of the span in the view, from its bottom to its top."""
        if not export:
            self._place()
            return
        view = self._view.viewRect()
        x0, x1 = self._span
        self.setRect(QRectF(x0, view.top(), x1 - x0, view.height()).normalized().intersected(view))


class CurveItem(QGraphicsPathItem):
    """A polyline through (x, y), broken at non-finite points, drawn and bounded in C++.

    pyqtgraph's PlotCurveItem paints and bounds itself in Python (pixel sizes, pen
    checks, the path built lazily in the paint): about 0.2 ms per curve and edit, with
    some twenty curves on a tab. Here the path is built once per ``set_data`` and Qt
    does the rest. The shape, used for the bounding rectangle and mouse hit tests, is
    the data's bounding box (stroking a long path for every hover would cost more)."""

    def __init__(self, pen: QPen | None = None, connect: str = "finite") -> None:
        super().__init__()
        if pen is not None:
            self.setPen(pen)
        self._connect = connect          # "finite", or "pairs": a segment per two points
        self.setAcceptedMouseButtons(Qt.MouseButton.NoButton)     # clicks go to the plot
        self._box = QPainterPath()
        self._antialias = bool(pg.getConfigOption("antialias"))
        self.x = self.y = np.empty(0)

    @property
    def connect(self) -> str:
        """"finite" (a polyline broken at non-finite points) or "pairs" (a segment per two points)."""
        return self._connect

    def set_data(self, x: np.ndarray, y: np.ndarray) -> None:
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        self.x, self.y = x, y
        finite = np.isfinite(x) & np.isfinite(y)
        box, path = QPainterPath(), QPainterPath()
        connect = "all" if self._connect == "finite" else self._connect     # within a finite run
        if finite.all() and x.size:
            box.addRect(QRectF(QPointF(x.min(), y.min()), QPointF(x.max(), y.max())))
            path = pg.arrayToQPath(x, y, connect=connect, finiteCheck=False)
        elif finite.any():
            box.addRect(QRectF(QPointF(x[finite].min(), y[finite].min()),
                               QPointF(x[finite].max(), y[finite].max())))
            # one polyline per finite run: pyqtgraph's general path for data with gaps
            # is five times slower than its polygon for a run
            edges = np.flatnonzero(np.diff(np.concatenate(([0], finite.view(np.int8), [0]))))
            for start, stop in zip(edges[::2], edges[1::2]):
                path.addPath(pg.arrayToQPath(x[start:stop], y[start:stop], connect=connect,
                                             finiteCheck=False))
        self._box = box     # before setPath: setting the path asks for the shape
        self.setPath(path)

    def shape(self) -> QPainterPath:
        return self._box

    def setExportMode(self, export: bool, opts: dict | None = None) -> None:  # noqa: N802
        """In an export: only the parts of the line inside the view (see ``clip_polyline``)."""
        if not export:
            if getattr(self, "_whole", None) is not None:
                self.setPath(self._whole)
                self._whole = None
            return
        view = view_of(self)
        if view is None or not self.x.size:
            return
        path = clipped_path(self.x, self.y, self._connect, view.viewRect())
        if path is not None:
            self._whole = self.path()
            self.setPath(path)

    def paint(self, painter: QPainter, option, widget=None) -> None:
        # pyqtgraph's antialias option, as its own curves: the views leave it off for the
        # axes and the text
        painter.setRenderHint(QPainter.RenderHint.Antialiasing, self._antialias)
        super().paint(painter, option, widget)
