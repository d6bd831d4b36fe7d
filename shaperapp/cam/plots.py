"""The follower's motion and the pressure angle over one turn of the cam.

Three plots against the cam angle δ: the follower's angle ψ; its angular velocity ω and
acceleration α at each crank speed of the design (the cam turns with the crank); and the
pressure angle with the allowances of the rise and the return drawn over their phases.
A cursor follows the animation. The axes are the stacked plots' (``plots.axes.TickAxis``):
their tick spacing comes from the widest label, so "100200300" no longer runs together in a
narrow Chinese pane, and each left axis is as wide as its two-line title and labels need.
"""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QRectF, QTimer
from PySide6.QtGui import QColor, QPainter
from PySide6.QtWidgets import QGridLayout, QWidget

from core.cam.follower import pitch, pressure_angle
from shaperapp.plots.axes import TickAxis
from shaperapp.widgets.image_export import render_scene
from shaperapp.widgets.scroll import vertical_scroll
from shaperapp.widgets.style import CURSOR, speed_colour

from .model import CamModel

SAMPLES = 721
# One plot's least size: δ labelled every 90° beside the y labels and the two-line title,
# and three y labels. Narrower (the Chinese pane at 1280 × 720 gave each 60 px of δ and
# its labels ran together), the plots stand in one column that scrolls.
MIN_PLOT_WIDTH = 230
MIN_PLOT_HEIGHT = 130
ALLOWANCE = "#c62828"


def _plot() -> pg.PlotWidget:
    """A plot with the app's tick axes: degrees at divisors of a turn along δ."""
    axes = {side: TickAxis(side) for side in ("left", "bottom")}
    axes["bottom"].set_degree_steps(True)
    for axis in axes.values():
        axis.enableAutoSIPrefix(False)
    return pg.PlotWidget(axisItems=axes)


class CamPlots(QWidget):
    """ψ, ω and α, and the pressure angle, with a cursor at the current cam angle."""

    def __init__(self, cam_model: CamModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = cam_model
        self.angle_plot, self.speed_plot, self.accel_plot, self.pressure_plot = (_plot() for _ in range(4))
        self.plots = (self.angle_plot, self.speed_plot, self.accel_plot, self.pressure_plot)
        self._inner = QWidget()
        self._grid = QGridLayout(self._inner)
        self._grid.setContentsMargins(0, 0, 0, 0)
        self._grid.setSpacing(2)
        self._columns = 0
        self._scroll = vertical_scroll(self._inner, self)
        self.cursors = []
        for i, plot in enumerate(self.plots):
            plot.setMenuEnabled(False)
            plot.showGrid(x=True, y=True, alpha=0.25)
            plot.setXRange(0.0, 360.0, padding=0.0)
            cursor = pg.InfiniteLine(angle=90, pen=pg.mkPen(CURSOR, width=1))
            plot.addItem(cursor)
            self.cursors.append(cursor)
            plot.setLabel("bottom", "δ (°)")
        self._arrange(2)
        for plot in self.plots[1:]:
            plot.setXLink(self.angle_plot)
        # pyqtgraph fits y when it next paints: the axes' widths follow the ranges shown
        self._fit_timer = QTimer(self)
        self._fit_timer.setSingleShot(True)
        self._fit_timer.timeout.connect(self.fit_axes)
        for plot in self.plots:
            plot.getPlotItem().vb.sigYRangeChanged.connect(self._fit_timer.start)
        self.curves: dict[str, object] = {}
        self._curve_rpms: tuple[float, ...] | None = None       # the speeds the curve items are for
        self._speed_curves: dict[str, list] = {"omega": [], "alpha": []}
        self._items: list[tuple[pg.PlotWidget, pg.PlotCurveItem]] = []
        self._stale = False
        cam_model.camChanged.connect(self.redraw)
        cam_model.errorChanged.connect(self.redraw)     # own_value may have changed
        cam_model.design_model.angleChanged.connect(self.move_cursor)
        cam_model.design_model.resultsChanged.connect(self.redraw)
        self.retranslate()
        self.redraw()

    def retranslate(self) -> None:
        labels = ((self.tr("follower ψ"), "°"), (self.tr("follower ω"), "rad/s"),
                  (self.tr("follower α"), "rad/s²"), (self.tr("pressure angle"), "°"))
        for plot, (text, unit) in zip(self.plots, labels):
            plot.setLabel("left", f"{text}<br>({unit})")
        self.fit_axes()

    def fit_axes(self) -> None:
        """One left-axis width (the δ axes line up), as wide as every title and widest
        tick label need."""
        axes = [plot.getAxis("left") for plot in self.plots]
        width = max(math.ceil(axis.needed_width()) for axis in axes)
        for axis in axes:
            if axis.fixedWidth != width:
                axis.setWidth(width)

    def _arrange(self, columns: int) -> None:
        """The plots in two columns, or in one that scrolls."""
        if columns != self._columns:
            self._columns = columns
            for i, plot in enumerate(self.plots):
                self._grid.addWidget(plot, i // columns, i % columns)
            self._inner.setMinimumHeight(MIN_PLOT_HEIGHT * (len(self.plots) // columns))

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        self._arrange(2 if event.size().width() >= 2 * MIN_PLOT_WIDTH else 1)
        self.fit_axes()

    def data(self) -> dict[str, np.ndarray]:
        """The plotted series: cam angle (°), ψ (°), ω and α per speed, pressure angle (°)."""
        cam = self._model.cam
        delta = np.linspace(0.0, 2.0 * math.pi, SAMPLES)
        p = pitch(cam.follower, cam.program, delta)
        omega = np.array(self._model.design_model.rpms) * (2.0 * math.pi / 60.0)
        return {"cam_deg": np.degrees(delta), "psi_deg": np.degrees(p.motion.psi),
                "omega": p.motion.psi1[None, :] * omega[:, None],
                "alpha": p.motion.psi2[None, :] * (omega ** 2)[:, None],
                "pressure_deg": np.degrees(pressure_angle(cam.follower, p))}

    def showEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().showEvent(event)
        if self._stale:
            self.redraw()
        else:                   # drawn while hidden (catch_up): the cursor did not follow
            self.move_cursor()

    def redraw(self) -> None:
        """Draw the series; a hidden view only marks itself stale (redrawn when shown)."""
        if not self.isVisible():
            self._stale = True
            return
        self._draw()

    def catch_up(self) -> None:
        """Draw now, while hidden, what the first show would (the Cam tab's ``catch_up``):
        making 36 curve items for 16 speeds and filling them was most of its first visit."""
        if self._stale:
            self._draw()

    def _draw(self) -> None:
        self._stale = False
        own = self._model.own_value
        self._inner.setVisible(own)         # an earlier design's cam: none of its curves or axes
        if not own:
            for _plot, item in self._items:
                item.setData([], [])
            return
        d = self.data()
        cam = self._model.cam
        x = d["cam_deg"]
        self._make_curves(tuple(self._model.design_model.rpms))
        self.curves["psi"].setData(x, d["psi_deg"])
        for i, (omega, alpha) in enumerate(zip(self._speed_curves["omega"], self._speed_curves["alpha"])):
            omega.setData(x, d["omega"][i])
            alpha.setData(x, d["alpha"][i])
        self.curves["pressure"].setData(x, d["pressure_deg"])
        prog = cam.program
        back = (prog.rise_deg + prog.dwell_deg, prog.feed_deg)
        self.curves["rise_allowed"].setData([0.0, prog.rise_deg], [cam.inputs.pressure_deg] * 2)
        self.curves["return_allowed"].setData(list(back), [cam.inputs.return_pressure_deg] * 2)
        self.pressure_plot.setYRange(0.0, max(90.0, float(d["pressure_deg"].max())), padding=0.02)
        for plot in self.plots:                         # ranges now, for the axes' widths
            box = plot.getPlotItem().vb
            box.updateAutoRange()
            box.updateMatrix()
        self.fit_axes()
        self._fit_timer.stop()      # the ranges' signals asked for the fit just made
        self.move_cursor()

    def _make_curves(self, rpms: tuple[float, ...]) -> None:
        """The curve items, made once per set of speeds and given new data on every
        redraw: making 36 items for 16 speeds took most of an edit's time (issue 40).

        Plain curve items, not ``plot()``'s data items: a data item draws through a curve
        item of its own, with the same pen, so the pixels are the same, and its own layer
        (display data sets, data rectangle, three scene items) was a third of a redraw.
        Of the speeds' curves only the slowest's and the fastest's count towards the fit
        of y (``ignoreBounds`` the rest): each is ψ′ or ψ″ times a factor (ω, ω²), and a
        sample times a factor between two others lies between those two products (their
        rounding too is monotonic), so the fit is the same with the 16 and it is done over
        2 (the fit of the 16 was another third of a redraw)."""
        if rpms == self._curve_rpms:
            return
        self._curve_rpms = rpms
        for plot, item in self._items:
            plot.removeItem(item)
        self._items = []
        omega = np.array(rpms)
        first = pg.mkPen(speed_colour(0), width=2)
        self.curves["psi"] = self._curve(self.angle_plot, first)
        self._speed_curves = {"omega": [], "alpha": []}
        for name, plot, factor in (("omega", self.speed_plot, omega), ("alpha", self.accel_plot, omega ** 2)):
            fitted = {int(np.argmin(factor)), int(np.argmax(factor))}
            self._speed_curves[name] = [self._curve(plot, pg.mkPen(speed_colour(i), width=2), i not in fitted)
                                        for i in range(len(rpms))]
        self.curves["pressure"] = self._curve(self.pressure_plot, first)
        dash = pg.mkPen(ALLOWANCE, width=1.5, style=pg.QtCore.Qt.PenStyle.DashLine)
        self.curves["rise_allowed"] = self._curve(self.pressure_plot, dash)
        self.curves["return_allowed"] = self._curve(self.pressure_plot, dash)

    def _curve(self, plot: pg.PlotWidget, pen, unfitted: bool = False) -> pg.PlotCurveItem:
        item = pg.PlotCurveItem(pen=pen)
        plot.addItem(item, ignoreBounds=unfitted)
        self._items.append((plot, item))
        return item

    def render(self, painter: QPainter, target: QRectF, cursor: bool = False) -> None:
        """Paint the four plots as laid out into ``target`` of any painter (the report):
        vectors, without the cursor unless ``cursor``."""
        if self._stale:
            self.redraw()
        sx, sy = target.width() / max(self._inner.width(), 1), target.height() / max(self._inner.height(), 1)
        for line in self.cursors:
            line.setVisible(cursor)
        try:
            self._render_plots(painter, target, sx, sy)
        finally:
            for line in self.cursors:
                line.setVisible(True)

    def _render_plots(self, painter: QPainter, target: QRectF, sx: float, sy: float) -> None:
        for plot in self.plots:
            g = plot.geometry()
            render_scene(plot.scene(), plot.sceneRect(), painter,
                         QRectF(target.left() + g.x() * sx, target.top() + g.y() * sy,
                                g.width() * sx, g.height() * sy), QColor("white"))

    def move_cursor(self, *_args) -> None:
        if not self.isVisible():
            return              # redraw() places it when shown
        deg = math.degrees(self._model.current_cam_angle()) % 360.0
        for cursor in self.cursors:
            cursor.setValue(deg)
