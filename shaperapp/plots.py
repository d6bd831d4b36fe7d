"""Motion diagrams: ram and lever motion over one crank revolution.

Stacked pyqtgraph plots with linked x axes, one curve per crank speed. All
numbers come from ``model.motion`` and ``model.metrics``; this module only
chooses what to draw. Plot items are created once and fed with ``setData``
so that a design change redraws in a few milliseconds, and the animation
angle only moves the cursor lines.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pyqtgraph as pg
from pyqtgraph.GraphicsScene.mouseEvents import MouseClickEvent
from PySide6.QtCore import QEvent, QPointF, QRectF, Qt
from PySide6.QtGui import QAction, QColor, QImage, QImageWriter, QPainter, QPicture
from PySide6.QtSvg import QSvgGenerator
from PySide6.QtWidgets import (QComboBox, QGraphicsItem, QHBoxLayout, QLabel, QMenu,
                               QSizePolicy, QToolButton, QVBoxLayout, QWidget)

from core.kinematics import Motion

from .model import DesignModel
from .style import CURSOR, RETURN_FILL, WORK_FILL, speed_colour

PLOT_NAMES = ("ram_x", "ram_v", "ram_a", "lever_angle", "lever_omega", "lever_alpha")
LEVER_PLOTS = PLOT_NAMES[3:]
UNITS = {"ram_x": "mm", "ram_v": "m/s", "ram_a": "m/s²", "lever_angle": "°",
         "lever_omega": "rad/s", "lever_alpha": "rad/s²"}
ANGLE, TIME = "angle", "time"
AXIS_WIDTH = 62          # fixed left-axis width so the stacked plots line up
EXPORT_WIDTH = 1600      # minimum width of an exported raster image, px
TOLERANCE_DEG = 1e-6     # a limit within this of a grid angle counts as on it
TEXT = QColor("#212121")
AXIS = QColor("#424242")
GRID = QColor("#e3e3e3")
SHARED = QColor("#37474f")   # curves that are the same at every speed (positions vs. angle)
CURVE_WIDTH = 1.8
LEGEND_HEIGHT = 24


def _y_data(motion: Motion, name: str) -> np.ndarray:
    """The (speeds, angles) array drawn in plot ``name``; the lever angle in degrees."""
    m = motion.rpm.size
    if name == "ram_x":
        return np.broadcast_to(motion.ram_x, (m, motion.ram_x.size))
    if name == "lever_angle":
        return np.broadcast_to(np.degrees(motion.lever_angle), (m, motion.lever_angle.size))
    return getattr(motion, name)



def styled_plot_item(padding: float) -> pg.PlotItem:
    """A plot styled like every diagram of the app: opaque grid beneath the curves,
    fixed-width left axis, no SI prefixes, pan along x only."""
    item = pg.PlotItem()
    item.showGrid(x=True, y=True)
    item.setMenuEnabled(False)
    item.hideButtons()
    item.setDefaultPadding(padding)
    item.vb.setMouseEnabled(x=True, y=False)
    for side in ("left", "bottom"):
        axis = item.getAxis(side)
        axis.enableAutoSIPrefix(False)
        axis.setPen(pg.mkPen(AXIS))
        axis.setTextPen(pg.mkPen(TEXT))
        # Grid: opaque light grey, beneath the curves (the ViewBox is at z -100); only
        # major lines across the short plots. Translucent lines draw ~15× slower.
        axis.setTickPen(pg.mkPen(GRID))
        axis.setStyle(tickAlpha=255, maxTickLevel=1 if side == "bottom" else 0)
        axis.setZValue(-200)
    item.getAxis("left").setWidth(AXIS_WIDTH)
    return item


def add_cursor(item: pg.PlotItem) -> pg.InfiniteLine:
    """The dashed vertical line that follows the animation's crank angle."""
    cursor = pg.InfiniteLine(angle=90, movable=False,
                             pen=pg.mkPen(CURSOR, width=1.0, style=Qt.PenStyle.DashLine))
    cursor.setZValue(10)
    item.addItem(cursor, ignoreBounds=True)
    return cursor


def plot_under(items: dict[str, pg.PlotItem], scene_pos: QPointF) -> tuple[str, float] | None:
    """Name of the plot under ``scene_pos`` and the x there, in view units."""
    for name, item in items.items():
        if item.vb.sceneBoundingRect().contains(scene_pos):
            return name, float(item.vb.mapSceneToView(scene_pos).x())
    return None


def cache_axes(items, on: bool) -> None:
    """Axes draw grid and text from a QPicture, the slowest part of a repaint: cache
    them as pixmaps, so moving the cursor or redrawing a curve only blits them."""
    mode = QGraphicsItem.CacheMode.DeviceCoordinateCache if on else QGraphicsItem.CacheMode.NoCache
    for item in items:
        for side in ("left", "bottom"):
            item.getAxis(side).setCacheMode(mode)


def export_layout(view: pg.GraphicsLayoutWidget, path: str, title: str,
                set_axis_cache) -> None:
    """Write ``view`` to ``path``: SVG through Qt's QSvgGenerator, else a raster image
    at least EXPORT_WIDTH px wide. ``set_axis_cache(on)`` switches axis pixmap caching,
    which would blur a scaled raster.

    pyqtgraph 0.14's SVGExporter fails on the closed paths ("… Z") Qt 6.11+ writes
    for every ViewBox (pyqtgraph issue #3495), hence Qt's own SVG painter. The raster
    is scaled through the device pixel ratio, not a painter transform, so the legend
    (drawn ignoring transformations) grows with everything else. Axes replay QPictures
    recorded at the screen's DPI, so the SVG resolution must match it."""
    target = Path(path)
    suffix = target.suffix.lower().lstrip(".")
    raster = {bytes(f).decode() for f in QImageWriter.supportedImageFormats()}
    if suffix != "svg" and suffix not in raster:
        raise ValueError(f"unsupported image type: {target.suffix!r}")
    source = view.ci.sceneBoundingRect()
    page = QRectF(0.0, 0.0, source.width(), source.height())
    if suffix == "svg":
        device = QSvgGenerator()
        device.setFileName(str(target))
        device.setSize(page.size().toSize())
        device.setViewBox(page)
        device.setTitle(title)
        device.setResolution(QPicture().logicalDpiX())   # axes replay DPI-bound QPictures
    else:
        scale = max(1.0, EXPORT_WIDTH / page.width())
        device = QImage(math.ceil(page.width() * scale), math.ceil(page.height() * scale),
                        QImage.Format.Format_ARGB32)
        device.setDevicePixelRatio(scale)
    painter = QPainter(device)
    set_axis_cache(False)
    try:
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.setRenderHint(QPainter.RenderHint.TextAntialiasing)
        painter.fillRect(page, view.backgroundBrush())
        view.scene().render(painter, page, source)
    finally:
        painter.end()
        set_axis_cache(True)
    if suffix != "svg" and not device.save(str(target)):
        raise OSError(f"could not write {target}")
    if not target.exists():
        raise OSError(f"could not write {target}")



@dataclass
class _Plot:
    """One stacked plot and the items that live in it."""

    item: pg.PlotItem
    cursor: pg.InfiniteLine
    regions: tuple[pg.LinearRegionItem, ...]     # working, return, return before the start
    curves: list[tuple[pg.PlotCurveItem, pg.PlotCurveItem]] = field(default_factory=list)


class PlotsWidget(QWidget):
    """Ram displacement, velocity, acceleration and optional lever plots of one cycle."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._mode = ANGLE
        self._visible = {name: name not in LEVER_PLOTS for name in PLOT_NAMES}
        self._hidden_speeds: set[int] = set()
        self._styled: tuple[str, int] | None = None

        self._x_label = QLabel()
        self._x_combo = QComboBox()
        self._x_combo.addItems(["", ""])
        self._lever_button = QToolButton()
        self._lever_button.setPopupMode(QToolButton.ToolButtonPopupMode.InstantPopup)
        self._lever_menu = QMenu(self)
        self._lever_actions: dict[str, QAction] = {}
        for name in LEVER_PLOTS:
            action = QAction(self)
            action.setCheckable(True)
            action.toggled.connect(lambda on, n=name: self.set_plot_visible(n, on))
            self._lever_menu.addAction(action)
            self._lever_actions[name] = action
        self._lever_button.setMenu(self._lever_menu)
        self._readout = QLabel()
        self._readout.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self._readout.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self._readout.setContentsMargins(6, 2, 6, 2)

        bar = QHBoxLayout()
        bar.setContentsMargins(4, 2, 4, 2)
        bar.addWidget(self._x_label)
        bar.addWidget(self._x_combo)
        bar.addSpacing(12)
        bar.addWidget(self._lever_button)
        bar.addStretch(1)

        self._view = pg.GraphicsLayoutWidget()
        self._view.setBackground("w")
        self._view.ci.setSpacing(4)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(0)
        layout.addLayout(bar)
        layout.addWidget(self._view, 1)
        layout.addWidget(self._readout)

        self._plots = {name: self._make_plot() for name in PLOT_NAMES}
        top = self._plots["ram_x"].item
        for plot in self._plots.values():
            if plot.item is not top:
                plot.item.setXLink(top)
        # The legend is a row of its own above the plots, so it never hides a curve.
        self._legend = pg.LegendItem(labelTextColor=TEXT, frame=False, horSpacing=4)
        self._legend.setMaximumHeight(LEGEND_HEIGHT)
        self._view.ci.addItem(self._legend, row=0, col=0)
        self._view.ci.layout.setAlignment(self._legend, Qt.AlignmentFlag.AlignRight)
        self._legend.sigSampleClicked.connect(self._on_legend_clicked)
        grey = pg.mkPen(QColor("#616161"), width=1.6)
        self._key_work = pg.PlotCurveItem(pen=grey)
        self._key_return = pg.PlotCurveItem(pen=pg.mkPen(QColor("#616161"), width=1.6,
                                                         style=Qt.PenStyle.DashLine))
        self._stroke_text = (pg.TextItem(color=QColor(46, 110, 50), anchor=(0.5, 0)),
                             pg.TextItem(color=QColor(170, 40, 40), anchor=(0.5, 0)))
        for text in self._stroke_text:
            top.addItem(text, ignoreBounds=True)
        top.vb.sigRangeChanged.connect(self._place_stroke_text)

        self._cache_axes(True)
        self._relayout()
        self._x_combo.currentIndexChanged.connect(
            lambda i: self.set_x_mode(TIME if i == 1 else ANGLE))
        scene = self._view.scene()
        scene.sigMouseClicked.connect(self._on_click)
        self._mouse_proxy = pg.SignalProxy(scene.sigMouseMoved, rateLimit=60,
                                           slot=self._on_mouse_moved)
        model.resultsChanged.connect(self._on_results)
        model.angleChanged.connect(self._on_angle)
        self._retranslate()
        self._on_results()

    # ---- public API ----------------------------------------------------
    def x_mode(self) -> str:
        """``"angle"`` (crank angle, °) or ``"time"`` (s)."""
        return self._mode

    def set_x_mode(self, mode: str) -> None:
        """Plot against crank angle or time; each speed then uses its own time array."""
        if mode not in (ANGLE, TIME):
            raise ValueError(f"x mode must be {ANGLE!r} or {TIME!r}")
        self._x_combo.setCurrentIndex(1 if mode == TIME else 0)
        if mode == self._mode:
            return
        self._mode = mode
        self._retranslate()
        self._on_results()

    def plot_visible(self, name: str) -> bool:
        return self._visible[name]

    def set_plot_visible(self, name: str, visible: bool) -> None:
        """Show or hide one of the lever plots (the ram plots are always shown)."""
        if name not in LEVER_PLOTS:
            raise ValueError(f"only lever plots can be hidden, not {name!r}")
        action = self._lever_actions[name]
        if action.isChecked() != visible:
            action.setChecked(visible)   # re-enters through toggled
            return
        if self._visible[name] != visible:
            self._visible[name] = visible
            self._relayout()

    def curve_data(self, plot_name: str) -> list[tuple[np.ndarray, np.ndarray]]:
        """(x, y) currently drawn for each speed in ``plot_name``, read back from the items."""
        out = []
        for work, back in self._plots[plot_name].curves:
            x, y = work.getData()
            if x is None:
                continue
            if self._mode == TIME:      # working part in one item, return part in the other
                y = np.where(np.isfinite(y), y, back.getData()[1])
            out.append((np.asarray(x), np.asarray(y)))
        return out

    def cursor_value(self) -> float:
        """x of the cursor line: crank angle in ° or time in s."""
        return float(self._plots["ram_x"].cursor.value())

    def readout_text(self) -> str:
        """The mouse read-out (rich text)."""
        return self._readout.text()

    def plot_item(self, plot_name: str) -> pg.PlotItem:
        """The pyqtgraph plot of ``plot_name`` (in the scene only while shown)."""
        return self._plots[plot_name].item

    def legend_names(self) -> list[str]:
        """Legend entries in order: the speeds, then in time mode the stroke key."""
        return [label.text for _, label in self._legend.items]

    def work_span(self) -> tuple[float, float] | None:
        """Shaded working stroke (°) in angle mode; None in time mode (no shading)."""
        region = self._plots["ram_x"].regions[0]
        return tuple(float(v) for v in region.getRegion()) if region.isVisible() else None

    def export_image(self, path: str) -> None:
        """Write the shown plots to ``path``: SVG for ``.svg``, else a raster image (PNG …)
        at least EXPORT_WIDTH px wide."""
        export_layout(self._view, path, self.tr("Shaper motion diagrams"), self._cache_axes)

    # ---- construction --------------------------------------------------
    def _make_plot(self) -> _Plot:
        item = styled_plot_item(0.1)   # the same padding at any plot height: fitted before layout too
        item.vb.setAutoVisible(y=True)
        regions = tuple(pg.LinearRegionItem((0, 1), movable=False, brush=fill, pen=pg.mkPen(None))
                        for fill in (WORK_FILL, RETURN_FILL, RETURN_FILL))
        for region in regions:
            region.setZValue(-10)
            item.addItem(region, ignoreBounds=True)
        return _Plot(item, add_cursor(item), regions)

    def _cache_axes(self, on: bool) -> None:
        cache_axes([plot.item for plot in self._plots.values()], on)

    def _relayout(self) -> None:
        """Put the shown plots in the layout; only the lowest one carries x tick values."""
        ci = self._view.ci
        for plot in self._plots.values():
            if plot.item in ci.items:
                ci.removeItem(plot.item)
        for row, plot in enumerate((p for n, p in self._plots.items() if self._visible[n]), 1):
            ci.addItem(plot.item, row=row, col=0)
        self._show_x_axis()
        self._fit_y()

    def _show_x_axis(self) -> None:
        """Tick values and the x label only under the lowest shown plot; grids stay on all."""
        last = [n for n in PLOT_NAMES if self._visible[n]][-1]
        for name, plot in self._plots.items():
            bottom = plot.item.getAxis("bottom")
            bottom.setStyle(showValues=name == last)
            bottom.showLabel(name == last)

    # ---- text ----------------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self._x_label.setText(self.tr("X axis:"))
        self._x_combo.setItemText(0, self.tr("Crank angle (°)"))
        self._x_combo.setItemText(1, self.tr("Time (s)"))
        # one literal per tr() call, so that lupdate sees the whole text
        self._x_combo.setToolTip(self.tr(
            "Plot against the crank angle (0–360°) or against time (each speed's own cycle)"))
        self._lever_button.setText(self.tr("Lever plots"))
        self._lever_button.setToolTip(self.tr(
            "Show the slotted lever's angle, angular velocity or angular acceleration"))
        names, axis_titles = self._plot_names(), self._axis_titles()
        for name, action in self._lever_actions.items():
            action.setText(names[name])
        self._readout.setToolTip(self.tr(
            "Values under the mouse; click a plot to move the mechanism to that crank position"))
        x_text = self.tr("Crank angle φ (°)") if self._mode == ANGLE else self.tr("Time t (s)")
        for name, plot in self._plots.items():
            plot.item.setLabel("left", f"{axis_titles[name]}<br>({UNITS[name]})",
                               color=TEXT.name(), **{"font-size": "9pt"})
            plot.item.setLabel("bottom", x_text, color=TEXT.name(), **{"font-size": "9pt"})
        self._show_x_axis()
        self._stroke_text[0].setText(self.tr("working stroke"))
        self._stroke_text[1].setText(self.tr("return stroke"))
        hint = self.tr("Point at a plot to read values; click to set the crank angle")
        self._readout.setText(hint)
        self._rebuild_legend()

    def _plot_names(self) -> dict[str, str]:
        """Full names, for the menu and the read-out."""
        return {"ram_x": self.tr("Ram displacement"), "ram_v": self.tr("Ram velocity"),
                "ram_a": self.tr("Ram acceleration"), "lever_angle": self.tr("Lever angle"),
                "lever_omega": self.tr("Lever angular velocity"),
                "lever_alpha": self.tr("Lever angular acceleration")}

    def _axis_titles(self) -> dict[str, str]:
        """Short enough to stand beside a plot about 100 px tall."""
        return {"ram_x": self.tr("Ram displacement"), "ram_v": self.tr("Ram velocity"),
                "ram_a": self.tr("Ram acceleration"), "lever_angle": self.tr("Lever angle ψ"),
                "lever_omega": self.tr("Lever ω"), "lever_alpha": self.tr("Lever α")}

    def _speed_name(self, rpm: float) -> str:
        return self.tr("{0} r/min").format(f"{rpm:g}")

    def _rebuild_legend(self) -> None:
        """One entry per speed; in time mode also the solid/dashed stroke key."""
        entries = [(work, self._speed_name(float(rpm)))
                   for (work, _), rpm in zip(self._plots["ram_v"].curves, self._model.motion.rpm)]
        if self._mode == TIME:
            entries += [(self._key_work, self.tr("working stroke")),
                        (self._key_return, self.tr("return stroke"))]
        self._legend.clear()
        self._legend.setColumnCount(max(len(entries), 1))   # one row
        for item, name in entries:
            self._legend.addItem(item, name)
        self._legend.setMaximumWidth(self._legend.layout.preferredWidth() + 12)

    def _on_legend_clicked(self, item: pg.PlotCurveItem) -> None:
        """A click on a speed in the legend shows or hides that speed in every plot."""
        for i, (work, _) in enumerate(self._plots["ram_v"].curves):
            if work is item:
                self._hidden_speeds ^= {i}
                self._apply_speed_visibility()
                return
        item.setVisible(True)   # the stroke key is not a curve: keep it drawn

    # ---- model → plots -------------------------------------------------
    def _on_results(self) -> None:
        """Redraw every curve from the new motion; items are reused, not rebuilt."""
        motion, metrics = self._model.motion, self._model.metrics
        count = motion.rpm.size
        degrees = np.degrees(motion.crank_angle)
        angle = self._mode == ANGLE
        resized = count != len(self._plots["ram_v"].curves)
        if angle:
            xs, x_max = [degrees] * count, 360.0
        else:
            in_work, back = self._stroke_masks(degrees)
            xs, x_max = list(motion.time), float(motion.time[:, -1].max())
        start, end = metrics.work_start_deg, metrics.work_end_deg
        first = max(start, 0.0)   # regions kept inside 0…360°: an SVG export does not clip
        spans = ((first, end), (end, 360.0), (0.0, first))
        for name, plot in self._plots.items():
            self._fit_curves(plot, count)
            y = _y_data(motion, name)
            if angle:      # one curve per speed; the shading shows the strokes
                for x, row, (work, _) in zip(xs, y, plot.curves):
                    work.setData(x, row)
            else:          # working part solid, return part dashed
                y_work, y_back = np.where(in_work, y, np.nan), np.where(back, y, np.nan)
                for x, row_work, row_back, (work, ret) in zip(xs, y_work, y_back, plot.curves):
                    work.setData(x, row_work)
                    ret.setData(x, row_back)
            for region, span in zip(plot.regions, spans):
                region.setRegion(span)
        if resized or self._styled != (self._mode, count):
            self._style_curves()
        if resized:
            self._rebuild_legend()
        self._plots["ram_x"].item.setXRange(0.0, x_max, padding=0.0)
        self._fit_y()
        self._place_stroke_text()
        self._on_angle(self._model.angle_index)

    def _fit_y(self) -> None:
        """Fit y of the shown plots to their curves now, then hold it.

        Left on, auto-range would repaint a whole plot whenever the cursor moves; left
        to paint time, it costs a second repaint. A hidden plot is out of the scene and
        has no bounds: it is fitted when shown."""
        for name, plot in self._plots.items():
            if self._visible[name]:
                vb = plot.item.vb
                vb.enableAutoRange(axis=pg.ViewBox.YAxis)
                vb.updateAutoRange()
                vb.disableAutoRange()
                vb.updateMatrix()

    def _stroke_masks(self, degrees: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Grid points on the working stroke, and on the return stroke widened by one
        point each side so the dashed part joins the solid one."""
        metrics = self._model.metrics
        offset = (degrees - metrics.work_start_deg + TOLERANCE_DEG) % 360.0
        in_work = offset <= metrics.work_angle_deg + 2 * TOLERANCE_DEG
        back = ~in_work
        back[1:] |= ~in_work[:-1]
        back[:-1] |= ~in_work[1:]
        return in_work, back

    def _fit_curves(self, plot: _Plot, count: int) -> None:
        """Add or drop curve pairs so there is one per speed."""
        while len(plot.curves) > count:
            for curve in plot.curves.pop():
                plot.item.removeItem(curve)
        while len(plot.curves) < count:
            # PlotCurveItem, not PlotDataItem: no per-call dataset processing
            pair = (pg.PlotCurveItem(connect="finite"), pg.PlotCurveItem(connect="finite"))
            for curve in pair:
                plot.item.addItem(curve)
            plot.curves.append(pair)
        self._hidden_speeds &= set(range(count))

    def _style_curves(self) -> None:
        """Pens, ticks and stroke marks for the x mode; done only when it or the count changes.

        Return strokes are dashed in time mode, where no shading shows them. Against the
        crank angle, positions do not depend on speed: drawn in one neutral colour."""
        angle = self._mode == ANGLE
        for name, plot in self._plots.items():
            shared = angle and name in ("ram_x", "lever_angle")
            for i, (work, ret) in enumerate(plot.curves):
                colour = SHARED if shared else speed_colour(i)
                work.setPen(pg.mkPen(colour, width=CURVE_WIDTH))
                ret.setPen(pg.mkPen(colour, width=CURVE_WIDTH, style=Qt.PenStyle.DashLine))
            for region in plot.regions:
                region.setVisible(angle)
            plot.item.getAxis("bottom").setTickSpacing(
                levels=[(30.0, 0.0)] if angle else None)
        for text in self._stroke_text:
            text.setVisible(angle)
        self._apply_speed_visibility()
        self._styled = (self._mode, len(self._plots["ram_v"].curves))

    def _apply_speed_visibility(self) -> None:
        """Speeds switched off in the legend stay off; return items only exist in time mode."""
        for plot in self._plots.values():
            for i, (work, ret) in enumerate(plot.curves):
                shown = i not in self._hidden_speeds
                work.setVisible(shown)
                ret.setVisible(shown and self._mode == TIME)

    def _on_angle(self, index: int) -> None:
        """Only the cursor lines move with the animation."""
        motion = self._model.motion
        if self._mode == ANGLE:
            x = math.degrees(float(motion.crank_angle[index]))
        else:
            x = float(motion.time[0, index])
        for plot in self._plots.values():
            plot.cursor.setValue(x)

    def _place_stroke_text(self, *_: object) -> None:
        if self._mode != ANGLE:
            return
        metrics = self._model.metrics
        (_, _), (_, y_top) = self._plots["ram_x"].item.vb.viewRange()
        start, end = metrics.work_start_deg, metrics.work_end_deg
        self._stroke_text[0].setPos((start + end) / 2.0, y_top)
        self._stroke_text[1].setPos((end + start + 360.0) / 2.0, y_top)

    # ---- mouse ---------------------------------------------------------
    def _plot_at(self, scene_pos: QPointF) -> tuple[str, float] | None:
        return plot_under({n: p.item for n, p in self._plots.items() if self._visible[n]}, scene_pos)

    def _on_click(self, event: MouseClickEvent) -> None:
        """A left click in a plot moves the animation to that crank angle."""
        if event.button() != Qt.MouseButton.LeftButton or event.isAccepted():
            return
        hit = self._plot_at(event.scenePos())
        if hit is None:
            return
        x = hit[1]
        if self._mode == TIME:
            x = math.degrees(x * float(self._model.motion.omega[0]))
        self._model.set_angle_deg(x)

    def _on_mouse_moved(self, args: tuple) -> None:
        hit = self._plot_at(args[0])
        if hit is not None:
            self._readout.setText(self._readout_for(*hit))

    def _readout_for(self, name: str, x: float) -> str:
        """x and each speed's curve value at the nearest grid point."""
        unit = UNITS[name]
        if self._mode == ANGLE:
            where = self.tr("φ = {0}°").format(f"{x:.1f}")
        else:
            where = self.tr("t = {0} s").format(f"{x:.4g}")
        parts = [f"<b>{self._plot_names()[name]}</b>", where]
        motion = self._model.motion
        for i, (xs, ys) in enumerate(self.curve_data(name)):
            if x < xs[0] or x > xs[-1]:
                value = "—"
            else:
                value = f"{ys[int(np.argmin(np.abs(xs - x)))]:.4g} {unit}"
            colour = speed_colour(i).name()
            parts.append(f"<span style='color:{colour}'>{self._speed_name(float(motion.rpm[i]))}:"
                         f"</span> {value}")
        return "&nbsp;&nbsp; ".join(parts)
