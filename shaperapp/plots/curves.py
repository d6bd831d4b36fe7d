"""What one plot of a stack holds: its curves, shaded bands, cursor lines and dots.

``PlotSlots`` keeps one pair of curve items (solid, dashed) and one cursor dot per
curve, reused from one result to the next; only counts that change add or drop
items (made in C++, see items.py). Everything here is per plot; the stack (stack.py)
coordinates them.
"""
from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtGui import QBrush, QColor

from shaperapp.widgets.style import CURSOR, TEXT

from .items import BandRect, CursorDot, CursorLine, CurveItem

# One pixel: Qt's raster engine draws thin cosmetic lines on a fast path; at 1.8 px an
# edit of the six kinematics plots took ~1.7× and a cursor frame ~2× as long (measured).
CURVE_WIDTH = 1.0
LEGEND_WIDTH = 2.0       # the legend's samples, thicker so that colours are easy to tell
Z_BAND, Z_CURSOR, Z_DOT = -10, 10, 20
ZERO_SHARE = 1e-12       # a read-out value this small against its curve's largest is 0


@dataclass(frozen=True, eq=False)
class Curve:
    """One drawn line. Curves with the same ``label`` are one legend entry and are
    shown or hidden together (a speed in every plot, with its mean line)."""

    x: np.ndarray
    y: np.ndarray
    label: str
    colour: QColor
    style: Qt.PenStyle = Qt.PenStyle.SolidLine
    width: float = CURVE_WIDTH
    dashed: np.ndarray | None = None   # bool per point: drawn dashed (the return stroke)
    legend: bool = True                # may give its label's legend sample
    readout: bool = True               # listed in the read-out and dotted at the cursor
    role: str = ""                     # "" for the plot's own curves; e.g. "mean"
    short: str = ""                    # the legend's text, when shorter than the label


@dataclass(frozen=True)
class Band:
    """A shaded x span in every plot, optionally labelled in the first plot."""

    start: float
    end: float
    brush: QColor
    label: str = ""
    colour: QColor | None = None       # of the label; None: the plots' text colour


def finite_range(arrays: Iterable[np.ndarray]) -> tuple[float, float]:
    """(min, max) of the finite values, widened when flat; (-1, 1) when there are none."""
    values = [a[np.isfinite(a)] for a in arrays]
    values = [v for v in values if v.size]
    if not values:
        return -1.0, 1.0
    lo = float(min(v.min() for v in values))
    hi = float(max(v.max() for v in values))
    if hi - lo <= 1e-12 * max(abs(lo), abs(hi), 1.0):
        half = 0.5 * max(abs(lo), 1.0)
        return lo - half, hi + half
    return lo, hi


class PlotSlots:
    """Items of one plot, created once per curve and reused (see the module docstring)."""

    def __init__(self, item: pg.PlotItem, series) -> None:
        self.item = item
        self.series = series
        self.curves: list[Curve] = []
        self._items: list[tuple[CurveItem, CurveItem, CursorDot]] = []
        self._styles: list[tuple] = []
        self._hidden: set[str] = set()
        self._cursors: list[tuple[CursorLine, int]] = []
        self._regions: list[BandRect] = []
        self._texts: list[pg.TextItem | None] = []     # made when first labelled
        self._bands: list[Band] = []
        self._labelled = False

    # ---- curves ---------------------------------------------------------
    def draw(self, curves: list[Curve], hidden: set[str]) -> None:
        while len(self._items) > len(curves):
            for thing in self._items.pop():
                self.item.removeItem(thing)
            self._styles.pop()
        while len(self._items) < len(curves):
            pair = (CurveItem(), CurveItem(), CursorDot())
            pair[2].setZValue(Z_DOT)
            self.item.addItem(pair[0], ignoreBounds=True)     # the stack fits y itself
            self.item.addItem(pair[1], ignoreBounds=True)
            self.item.addItem(pair[2], ignoreBounds=True)
            self._items.append(pair)
            self._styles.append(None)
        for i, (curve, (solid, dashed, dot)) in enumerate(zip(curves, self._items)):
            style = (curve.colour.rgba(), curve.style, curve.width)
            if self._styles[i] != style:       # pens only when they change: setPen repaints
                solid.setPen(pg.mkPen(curve.colour, width=curve.width, style=curve.style))
                dashed.setPen(pg.mkPen(curve.colour, width=curve.width,
                                       style=Qt.PenStyle.DashLine))
                dot.setBrush(QBrush(curve.colour))
                self._styles[i] = style
            if curve.dashed is None:
                solid.set_data(curve.x, curve.y)
                if dashed.x.size:
                    dashed.set_data(np.empty(0), np.empty(0))
            else:   # the dashed part widened by a point each side, so the two join
                back = np.asarray(curve.dashed, dtype=bool)
                wide = back.copy()
                wide[1:] |= back[:-1]
                wide[:-1] |= back[1:]
                solid.set_data(curve.x, np.where(back, np.nan, curve.y))
                dashed.set_data(curve.x, np.where(wide, curve.y, np.nan))
        self.curves = list(curves)
        self.apply_hidden(hidden)

    def apply_hidden(self, hidden: set[str]) -> None:
        self._hidden = set(hidden)
        for curve, (solid, dashed, dot) in zip(self.curves, self._items):
            shown = curve.label not in hidden
            solid.setVisible(shown)
            dashed.setVisible(shown and curve.dashed is not None)
            if not shown:
                dot.setVisible(False)

    def shown_curves(self, role: str | None = "") -> list[Curve]:
        return [c for c in self.curves if c.label not in self._hidden
                and (role is None or c.role == role)]

    def data(self, role: str = "") -> list[tuple[np.ndarray, np.ndarray]]:
        """(x, y) of every curve of ``role`` as drawn, shown or not."""
        return [(c.x, c.y) for c in self.curves if c.role == role]

    def visible_values(self, x0: float, x1: float) -> list[np.ndarray]:
        return [c.y[(c.x >= x0) & (c.x <= x1)] for c in self.shown_curves(None)]

    def values_at(self, where: float | dict[str, float]) -> list[tuple[Curve, float | None]]:
        """Each shown read-out curve's value at the grid point nearest x (one x for all, or
        one per label); None outside the curve's x range."""
        out = []
        for curve in self.shown_curves(None):
            if not curve.readout:
                continue
            x = where if isinstance(where, float) else where.get(curve.label)
            if x is None or not curve.x.size or x < curve.x[0] or x > curve.x[-1]:
                out.append((curve, None))
            else:
                value = float(curve.y[int(np.argmin(np.abs(curve.x - x)))])
                # core's exact zeros (limit positions) come out as ±1e-16 of the curve's size
                scale = float(np.nanmax(np.abs(curve.y), initial=0.0))
                out.append((curve, 0.0 if abs(value) <= ZERO_SHARE * scale else value))
        return out

    # ---- cursor -----------------------------------------------------------
    def move_cursor(self, where: float | dict[str, float]) -> None:
        """Cursor lines at ``where`` (one, or one per label in that label's colour) and a
        dot on every shown curve at its cursor."""
        if isinstance(where, float):
            lines = [(where, CURSOR.rgba())]
        else:
            colours = {c.label: c.colour.rgba() for c in reversed(self.curves) if c.legend}
            lines = [(x, colours.get(label, CURSOR.rgba())) for label, x in where.items()
                     if label not in self._hidden]
        while len(self._cursors) < len(lines):
            line = CursorLine(self.item.vb)
            line.setZValue(Z_CURSOR)
            self.item.addItem(line, ignoreBounds=True)
            self._cursors.append((line, 0))
        for i, (line, rgba) in enumerate(self._cursors):
            if i >= len(lines):
                line.setVisible(False)
                continue
            x, wanted = lines[i]
            if rgba != wanted:
                line.set_colour(wanted)
                self._cursors[i] = (line, wanted)
            line.setValue(x)
            line.setVisible(True)
        for curve, (_, _, dot) in zip(self.curves, self._items):
            x = where if isinstance(where, float) else where.get(curve.label)
            if (not curve.readout or curve.label in self._hidden or x is None
                    or not curve.x.size or x < curve.x[0] or x > curve.x[-1]):
                dot.setVisible(False)
                continue
            y = float(np.interp(x, curve.x, curve.y))
            dot.setVisible(math.isfinite(y))
            dot.setPos(x, y)

    def cursor_positions(self) -> list[float]:
        return [float(line.value()) for line, _ in self._cursors if line.isVisible()]

    def dots(self) -> list[tuple[str, float, float]]:
        """(label, x, y) of the dots shown at the cursor."""
        return [(c.label, dot.x(), dot.y()) for c, (_, _, dot) in zip(self.curves, self._items)
                if dot.isVisible()]

    # ---- bands --------------------------------------------------------------
    def set_bands(self, bands: list[Band], labelled: bool) -> bool:
        """Shaded spans (and their labels); True when new items were made for them. A
        band's text item is made the first time it shows a label: of a stack's bands only
        the first plot's are labelled, and the Kinematics tab made nine text items before
        the window's first paint to show two (issue 43 item 5)."""
        added = len(self._regions) < len(bands)
        while len(self._regions) < len(bands):
            region = BandRect(self.item.vb)
            region.setZValue(Z_BAND)
            self.item.addItem(region, ignoreBounds=True)
            self._regions.append(region)
            self._texts.append(None)
        for i, region in enumerate(self._regions):
            shown = i < len(bands)
            region.setVisible(shown)
            text = self._texts[i]
            wanted = shown and labelled and bool(bands[i].label)
            if text is None and wanted:
                text = self._texts[i] = pg.TextItem(anchor=(0.5, 0.0))
                self.item.addItem(text, ignoreBounds=True)
                added = True
            if text is not None:
                text.setVisible(wanted)
            if shown:
                band = bands[i]
                if region.brush().color() != band.brush:
                    region.setBrush(QBrush(band.brush))
                region.set_span(band.start, band.end)
                if text is not None and (text.toPlainText() != band.label
                                         or text.color != (band.colour or TEXT)):
                    text.setText(band.label, color=band.colour or TEXT)
        self._bands, self._labelled = list(bands), labelled
        return added

    def bands(self) -> list[tuple[float, float]]:
        return [r.span() for r in self._regions if r.isVisible()]

    def place_band_labels(self) -> None:
        """Each label at the top of its band, or at the bottom where the curves fill the
        upper half of the band (a torque usually peaks while cutting)."""
        if not self._labelled:
            return
        (_, _), (y_low, y_top) = self.item.vb.viewRange()
        for band, text in zip(self._bands, self._texts):
            if not band.label or text is None:
                continue
            inside = [c.y[(c.x >= band.start) & (c.x <= band.end)] for c in self.shown_curves()]
            lowest, _ = finite_range(inside) if any(v.size for v in inside) else (y_low, y_top)
            bottom = lowest > (y_low + y_top) / 2.0
            text.setAnchor((0.5, 1.0) if bottom else (0.5, 0.0))
            text.setPos((band.start + band.end) / 2.0, y_low if bottom else y_top)

    def band_labels(self) -> list[str]:
        return [t.textItem.toPlainText() for t in self._texts if t is not None and t.isVisible()]
