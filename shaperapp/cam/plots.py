"""The follower's motion and the pressure angle over one turn of the cam.

Three plots against the cam angle δ: the follower's angle ψ; its angular velocity ω and
acceleration α at each crank speed of the design (the cam turns with the crank); and the
pressure angle with the allowances of the rise and the return drawn over their phases.
A cursor follows the animation.
"""
from __future__ import annotations

import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QRectF
from PySide6.QtGui import QColor, QPainter
from PySide6.QtWidgets import QGridLayout, QWidget

from core.cam.follower import pitch, pressure_angle
from shaperapp.widgets.image_export import render_scene
from shaperapp.widgets.style import CURSOR, speed_colour

from .model import CamModel

SAMPLES = 721
ALLOWANCE = "#c62828"


class CamPlots(QWidget):
    """ψ, ω and α, and the pressure angle, with a cursor at the current cam angle."""

    def __init__(self, cam_model: CamModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = cam_model
        self.angle_plot = pg.PlotWidget()
        self.speed_plot = pg.PlotWidget()
        self.accel_plot = pg.PlotWidget()
        self.pressure_plot = pg.PlotWidget()
        self.plots = (self.angle_plot, self.speed_plot, self.accel_plot, self.pressure_plot)
        layout = QGridLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(2)
        self.cursors = []
        for i, plot in enumerate(self.plots):
            plot.setMenuEnabled(False)
            plot.showGrid(x=True, y=True, alpha=0.25)
            plot.setXRange(0.0, 360.0, padding=0.0)
            cursor = pg.InfiniteLine(angle=90, pen=pg.mkPen(CURSOR, width=1))
            plot.addItem(cursor)
            self.cursors.append(cursor)
            plot.setLabel("bottom", "δ (°)")
            layout.addWidget(plot, i // 2, i % 2)
        for plot in self.plots[1:]:
            plot.setXLink(self.angle_plot)
        self.curves: dict[str, object] = {}
        self._stale = False
        cam_model.camChanged.connect(self.redraw)
        cam_model.design_model.angleChanged.connect(self.move_cursor)
        cam_model.design_model.resultsChanged.connect(self.redraw)
        self.retranslate()
        self.redraw()

    def retranslate(self) -> None:
        labels = ((self.tr("follower ψ"), "°"), (self.tr("follower ω"), "rad/s"),
                  (self.tr("follower α"), "rad/s²"), (self.tr("pressure angle"), "°"))
        for plot, (text, unit) in zip(self.plots, labels):
            plot.setLabel("left", f"{text} ({unit})")

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

    def redraw(self) -> None:
        """Draw the series; a hidden view only marks itself stale (redrawn when shown)."""
        if not self.isVisible():
            self._stale = True
            return
        self._stale = False
        d = self.data()
        cam = self._model.cam
        for plot in self.plots:
            for item in list(plot.listDataItems()):
                plot.removeItem(item)
        x = d["cam_deg"]
        self.curves["psi"] = self.angle_plot.plot(x, d["psi_deg"], pen=pg.mkPen(speed_colour(0), width=2))
        for i, rpm in enumerate(self._model.design_model.rpms):
            pen = pg.mkPen(speed_colour(i), width=2)
            self.speed_plot.plot(x, d["omega"][i], pen=pen, name=f"{rpm:g} r/min")
            self.accel_plot.plot(x, d["alpha"][i], pen=pen, name=f"{rpm:g} r/min")
        self.curves["pressure"] = self.pressure_plot.plot(x, d["pressure_deg"], pen=pg.mkPen(speed_colour(0), width=2))
        prog = cam.program
        rise_end = prog.rise_deg
        back = (prog.rise_deg + prog.dwell_deg, prog.feed_deg)
        dash = pg.mkPen(ALLOWANCE, width=1.5, style=pg.QtCore.Qt.PenStyle.DashLine)
        self.pressure_plot.plot([0.0, rise_end], [cam.inputs.pressure_deg] * 2, pen=dash)
        self.pressure_plot.plot(list(back), [cam.inputs.return_pressure_deg] * 2, pen=dash)
        self.pressure_plot.setYRange(0.0, max(90.0, float(d["pressure_deg"].max())), padding=0.02)
        self.move_cursor()

    def render(self, painter: QPainter, target: QRectF, cursor: bool = False) -> None:
        """Paint the four plots as laid out into ``target`` of any painter (the report):
        vectors, without the cursor unless ``cursor``."""
        if self._stale:
            self.redraw()
        sx, sy = target.width() / max(self.width(), 1), target.height() / max(self.height(), 1)
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
