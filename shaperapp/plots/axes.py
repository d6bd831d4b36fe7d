"""The parts of one diagram: an axis whose tick labels never overlap, a view box with
the app's navigation, and the plot item that combines them in the app's style.

Navigation (the same in every diagram): the wheel zooms x (all stacked plots are
x-linked), the wheel over the left axis zooms that plot's y, a left drag zooms to
a box, a right drag zooms freely, a double click fits everything again, a right
click opens the view's own translated menu. pyqtgraph's English menu and its
export dialog are never shown.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QColor, QFont, QFontMetricsF, QPen
from PySide6.QtWidgets import QGraphicsItem, QGraphicsTextItem
from pyqtgraph.graphicsItems.LegendItem import ItemSample

from shaperapp.widgets.axis_fit import axis_width
from shaperapp.widgets.style import TEXT

AXIS_WIDTH = 62          # fixed left-axis width so the stacked plots line up
AXIS = QColor("#424242")
GRID = QColor("#e3e3e3")
LABEL_GAP_PX = 14.0      # free space between two tick labels along an axis
TIGHT_GAP_PX = 3.0       # the least space between two labels, where the axis is too short for more
MIN_LABELS = 3           # labels an axis keeps, closer together, where it has room for them
NICE_STEPS = (1.0, 2.0, 5.0)                                      # × 10^k
DEGREE_STEPS = (1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0, 60.0, 90.0, 180.0, 360.0)


def nice_steps(span: float, steps: Sequence[float] | None) -> Iterable[float]:
    """Candidate tick spacings in increasing order, from well below ``span`` up to it."""
    if steps is not None:
        fine = 10.0 ** math.floor(math.log10(span) - 3)
        for k in range(-3, 0):          # zoomed far in: tenths, hundredths … of a degree
            for s in NICE_STEPS:
                if s * 10.0 ** k >= fine:
                    yield s * 10.0 ** k
        yield from steps
        return
    exponent = math.floor(math.log10(span)) - 4
    while True:
        for s in NICE_STEPS:
            yield s * 10.0 ** exponent
        exponent += 1


class TickAxis(pg.AxisItem):
    """An axis that picks its tick spacing from the space its labels need.

    pyqtgraph's own choice depends only on the axis length, so wide labels run
    together on a short axis ("120150180…"). Here the major spacing is the
    smallest nice step whose widest label (measured in the axis font) plus a gap
    fits between two ticks; only major ticks carry text. ``degree_steps`` limits
    the steps to divisors of a turn (15°, 30°, 45°, 90° …)."""

    def __init__(self, orientation: str, **kwargs) -> None:
        super().__init__(orientation, **kwargs)
        self._steps: Sequence[float] | None = None

    def set_degree_steps(self, on: bool) -> None:
        self._steps = DEGREE_STEPS if on else None
        self.picture = None
        self.update()

    def tickSpacing(self, minVal: float, maxVal: float, size: float):
        span = abs(maxVal - minVal)
        if not (span > 0.0 and size > 0.0 and math.isfinite(span)):
            return []
        metrics = QFontMetricsF(self.style["tickFont"] or QFont())
        horizontal = self.orientation in ("top", "bottom")
        per_px = span / size
        lo, hi = sorted((minVal, maxVal))
        # A label is drawn only where it lies wholly inside the axis: half a text height
        # in from each end (as generateDrawSpecs draws it, 0.8 of the font's height).
        inset = 0.4 * metrics.height() * per_px
        tight = None          # the coarsest step giving MIN_LABELS labels with only TIGHT_GAP_PX
        for step in nice_steps(span, self._steps):
            if horizontal:
                first = math.floor(minVal / step) * step
                labels = self.tickStrings([first, first + step, maxVal, minVal], self.scale, step)
                need = max(metrics.horizontalAdvance(s) for s in labels) + LABEL_GAP_PX
                close = need
            else:
                need = metrics.height() + 0.5 * LABEL_GAP_PX
                close = 0.8 * metrics.height() + TIGHT_GAP_PX
            count = math.floor((hi - inset) / step) - math.ceil((lo + inset) / step) + 1
            if step / per_px >= close and count >= MIN_LABELS:
                tight = step
            if step / per_px >= need:
                # A short plot keeps three labels, closer together, rather than one or two.
                if count < MIN_LABELS and tight is not None:
                    step = tight
                elif count < 2 and self._steps is None:
                    step = self._half_step(step, lo, hi, inset, per_px, close, count)
                minor = step / (3.0 if self._steps is not None and step % 3 == 0 else 2.0)
                return [(step, 0.0), (minor, 0.0)]
            if step > 2.0 * span:
                break
        return [(4.0 * span, 0.0)]      # no room for two labels: at most one


    def tickStrings(self, values, scale, spacing):  # noqa: N802 - pyqtgraph's name
        """pyqtgraph's labels, but with as many decimals as the spacing has: pyqtgraph
        counts the decimals of the spacing's power of ten, and the half step 2.5 of a short
        plot (``_half_step``) would have printed 2.5 as "2". Unchanged for 1, 2, 5 × 10^k."""
        strings = super().tickStrings(values, scale, spacing)
        step = abs(spacing * scale)
        if not (step > 0.0 and math.isfinite(step)):
            return strings
        places = next((p for p in range(13) if abs(round(step, p) - step) <= 1e-9 * step), 12)
        if places <= max(0, math.ceil(-math.log10(step))):
            return strings
        return [text if abs(v * scale) < 0.001 or abs(v * scale) >= 10000 else f"{v * scale:.{places}f}"
                for text, v in zip(strings, values)]

    @staticmethod
    def _half_step(step: float, lo: float, hi: float, inset: float, per_px: float, close: float,
                   count: int) -> float:
        """Half of ``step`` (2.5 between 2 and 5) where it gives more labels at the close
        spacing, else ``step``: a plot too short for three labels on 1, 2, 5 kept one, "0"
        alone (Compare's acceleration, ±5.6 m/s² over 69 px, at 1280 × 720 with 16 speeds)."""
        half = step / 2.0
        more = math.floor((hi - inset) / half) - math.ceil((lo + inset) / half) + 1
        return half if half / per_px >= close and more > count else step

    def needed_width(self) -> float:
        """The width this left axis needs so that its title never covers a tick label
        (``widgets.axis_fit``). With 16 speeds the torque's "−4000" ran under "(N·m)" in
        the fixed AXIS_WIDTH."""
        return axis_width(self)

    # ---- lean drawing ---------------------------------------------------------
    # pyqtgraph's tickValues and generateDrawSpecs serve every option of an axis; these
    # serve only the app's (linked, grid across the view, opaque tick pen, text on the
    # major level, linear scale) with the same output, in a third of the time: a
    # design change that moves the y ranges repaints every left axis.
    def tickValues(self, minVal: float, maxVal: float, size: float):
        if self.logMode or self.scale != 1.0:
            return super().tickValues(minVal, maxVal, size)
        lo, hi = sorted((minVal, maxVal))
        levels, seen = [], np.empty(0)
        for spacing, offset in self.tickSpacing(lo, hi, size):
            start = math.ceil((lo - offset) / spacing) * spacing + offset
            values = np.arange(int((hi - start) / spacing) + 1) * spacing + start
            if seen.size:      # drop the ticks of a coarser level (within 1 % of a step)
                values = values[np.abs(values[:, None] - seen[None, :]).min(axis=1) > spacing * 0.01]
            seen = np.concatenate([seen, values])
            levels.append((spacing, values.tolist()))
        return levels

    def generateDrawSpecs(self, p):
        if (self.linkedView() is None or self.grid is False or self.logMode or self.scale != 1.0
                or self._tickLevels is not None or self.orientation not in ("left", "bottom")
                or not isinstance(self.style["tickAlpha"], int) or self.style["maxTextLevel"] != 0
                or any(self.style["stopAxisAtTick"])):
            return super().generateDrawSpecs(p)
        if self.style["tickFont"] is not None:
            p.setFont(self.style["tickFont"])
        bounds = self.mapRectFromParent(self.geometry())
        ticks = self.linkedView().mapRectToItem(self, self.linkedView().boundingRect())
        left = self.orientation == "left"
        if left:
            span = (bounds.topRight() + QPointF(-1.0, -1.0), bounds.bottomRight() + QPointF(-1.0, 1.0))
            tick_start, tick_stop = ticks.right(), bounds.right()
        else:
            span = (bounds.topLeft() + QPointF(-1.0, 1.0), bounds.topRight() + QPointF(1.0, 1.0))
            tick_start, tick_stop = ticks.top(), bounds.top()
        device = self.deviceTransform_()
        if device is None:
            return None
        ends = [device.map(point) for point in span]
        length = math.hypot(ends[1].x() - ends[0].x(), ends[1].y() - ends[0].y())
        if length == 0:
            return None
        levels = self.tickValues(self.range[0], self.range[1], length)
        dif = self.range[1] - self.range[0]
        if dif == 0:
            scale, offset = 1.0, 0.0
        elif left:
            scale = -bounds.height() / dif
            offset = self.range[0] * scale - bounds.height()
        else:
            scale = bounds.width() / dif
            offset = self.range[0] * scale
        x_min, x_max = sorted(x * scale - offset for x in self.range)
        tick_pen = QPen(self.tickPen())
        if tick_pen.brush().style() == Qt.BrushStyle.SolidPattern:
            colour = QColor(tick_pen.color())
            colour.setAlpha(self.style["tickAlpha"])
            tick_pen.setColor(colour)
        tick_specs, positions = [], []
        for _, values in levels:
            xs = [v * scale - offset for v in values]
            positions.append([x if x_min <= x <= x_max else None for x in xs])
            for x in positions[-1]:
                if x is not None:
                    tick_specs.append((tick_pen, QPointF(tick_start, x), QPointF(tick_stop, x)) if left
                                      else (tick_pen, QPointF(x, tick_start), QPointF(x, tick_stop)))
        axis_spec = (self.pen(), span[0], span[1])
        text_specs: list = []
        if not self.style["showValues"] or not levels:
            return axis_spec, tick_specs, text_specs
        spacing, values = levels[0]
        strings = self.tickStrings(values, self.autoSIPrefixScale * self.scale, spacing)
        gap = max(0, self.style["tickLength"]) + self.style["tickTextOffset"][0 if left else 1]
        box = self.boundingRect()
        flags = (Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter if left
                 else Qt.AlignmentFlag.AlignHCenter | Qt.AlignmentFlag.AlignTop) | Qt.TextFlag.TextDontClip
        across = 0.0
        for x, text in zip(positions[0], strings):
            if x is None:
                continue
            rect = p.boundingRect(QRectF(0, 0, 100, 100), Qt.AlignmentFlag.AlignCenter, text)
            width, height = rect.width(), rect.height() * 0.8   # as pyqtgraph: a bit too large
            across = max(across, width if left else height)
            rect = (QRectF(tick_stop - gap - width, x - height / 2, width, height) if left
                    else QRectF(x - width / 2.0, tick_stop + gap, width, height))
            if box & rect == rect:
                text_specs.append((rect, flags, text))
        self._updateMaxTextSize(across)
        return axis_spec, tick_specs, text_specs


class HiddenAxis(pg.AxisItem):
    """A side no plot of the app shows (top and right; all four of the scheme's): pyqtgraph
    makes an axis for each side anyway, and each laid out its (never shown) label as HTML
    five or six times while being made and styled, about half its cost: some 7 ms of the
    window's first paint for its ten such axes (issue 43 item 5). Showing one would need
    pyqtgraph's label back: none is ever shown. (Given to a plot, pyqtgraph shows it: the
    plot hides it again.)"""

    def _updateLabel(self) -> None:  # noqa: N802 - pyqtgraph's name
        self.picture = None


class NavViewBox(pg.ViewBox):
    """A view box with the app's mouse navigation (see the module docstring); the
    scheme's keeps the wheel on both axes and drags to pan (``x_wheel``/``box_zoom`` off).

    ``sigFitRequested`` asks the owner to fit all plots; ``menu_handler`` (set by the
    owner) shows its own context menu at a screen position."""

    sigFitRequested = Signal()

    def __init__(self, x_wheel: bool = True, box_zoom: bool = True) -> None:
        super().__init__(enableMenu=False)
        self.setMouseMode(pg.ViewBox.RectMode if box_zoom else pg.ViewBox.PanMode)
        self.menu_handler: Callable[[QPointF], None] | None = None
        self.y_zoomed = False        # the user chose this plot's y range: keep it until Fit
        self._x_wheel = x_wheel

    def wheelEvent(self, ev, axis=None) -> None:
        # In a plot the wheel zooms x only; over the y axis (axis=1) it zooms y.
        if axis is None and self._x_wheel:
            axis = 0
        self.y_zoomed |= axis != 0
        super().wheelEvent(ev, axis=axis)

    def mouseDragEvent(self, ev, axis=None) -> None:
        # a box, a right-button zoom or a drag on the y axis chooses y too
        self.y_zoomed |= axis != 0 and (self.state["mouseMode"] == pg.ViewBox.RectMode
                                        or ev.button() != pg.QtCore.Qt.MouseButton.LeftButton
                                        or axis == 1)
        super().mouseDragEvent(ev, axis=axis)

    def mouseClickEvent(self, ev) -> None:
        if ev.double() and ev.button() == pg.QtCore.Qt.MouseButton.LeftButton:
            ev.accept()
            self.sigFitRequested.emit()
        elif ev.button() == pg.QtCore.Qt.MouseButton.RightButton and self.menu_handler is not None:
            ev.accept()
            self.menu_handler(ev.screenPos())

    def raiseContextMenu(self, ev) -> None:     # never pyqtgraph's own menu
        if self.menu_handler is not None:
            self.menu_handler(ev.screenPos())


def styled_plot_item(padding: float) -> pg.PlotItem:
    """A plot styled like every diagram of the app: opaque grid beneath the curves,
    fixed-width left axis, no SI prefixes, non-overlapping ticks, the app's navigation."""
    axes = {side: TickAxis(side) for side in ("left", "bottom")}
    axes.update({side: HiddenAxis(side) for side in ("top", "right")})
    item = pg.PlotItem(viewBox=NavViewBox(), axisItems=axes)
    for side in ("top", "right"):       # hidden, as pyqtgraph hides the axes it makes there
        item.hideAxis(side)
    item.showGrid(x=True, y=True)
    item.setMenuEnabled(False)
    item.hideButtons()
    item.setDefaultPadding(padding)
    for side in ("left", "bottom"):
        axis = item.getAxis(side)
        axis.enableAutoSIPrefix(False)
        axis.setPen(pg.mkPen(AXIS))
        axis.setTextPen(pg.mkPen(TEXT))
        # Grid: opaque light grey, beneath the curves (the ViewBox is at z -100); only
        # major lines across the short plots. Translucent lines draw ~15× slower.
        axis.setTickPen(pg.mkPen(GRID))
        axis.setStyle(tickAlpha=255, maxTickLevel=1 if side == "bottom" else 0, maxTextLevel=0)
        axis.setZValue(-200)
    item.getAxis("left").setWidth(AXIS_WIDTH)
    unlink_hidden_axes(item)
    return item


def unlink_hidden_axes(item: pg.PlotItem) -> None:
    """Stop the axes a plot never shows from following its view: each range change
    re-rendered their (hidden) labels as HTML, four times per plot and edit."""
    for side in ("left", "bottom", "top", "right"):
        axis = item.getAxis(side)
        if not axis.isVisible():
            axis.unlinkFromView()


def cache_static(items: Iterable[QGraphicsItem], on: bool) -> None:
    """Draw the parts of a plot that rarely change from pixmaps: the axes (grid and tick
    text from a QPicture, the slowest part of a repaint), the texts (titles, legend
    labels, band labels: Qt lays out and shapes a text item at every paint) and the
    legend samples (painted in Python). Moving the cursor or redrawing a curve then only
    blits them. Off while exporting: a scaled pixmap would blur, and vector output must
    get vectors. ``items`` and all their descendants are visited."""
    mode = QGraphicsItem.CacheMode.DeviceCoordinateCache if on else QGraphicsItem.CacheMode.NoCache
    todo = list(items)
    while todo:
        item = todo.pop()
        if isinstance(item, (pg.AxisItem, ItemSample)) or type(item) is QGraphicsTextItem:
            if item.cacheMode() != mode:
                item.setCacheMode(mode)
        todo.extend(item.childItems())
