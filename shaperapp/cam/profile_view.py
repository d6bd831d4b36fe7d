"""The cam drawn to scale, turned to the crank's angle, with its follower and roller.

The drawing is in the fixed frame (the cam centre O at the origin, the follower pivot A
on +x at the centre distance): the cam's profile, pitch curve and base circle turned
clockwise by the cam angle δ, and the arm and roller at the follower's angle ψ(δ). One
scale for x and y, so the cam keeps its shape whatever the widget's proportions.
"""
from __future__ import annotations

import math

import numpy as np
from PySide6.QtCore import QPointF, QRectF, QSizeF, Qt
from PySide6.QtGui import QBrush, QColor, QPainter, QPen, QPolygonF
from PySide6.QtWidgets import QWidget

from core.cam import Cam
from core.cam.follower import pitch, profile
from shaperapp.parts.view import PartView
from shaperapp.widgets.image_export import export_painting
from shaperapp.widgets.messages import describe
from shaperapp.widgets.screen_polygon import screen_polygon
from shaperapp.widgets.style import FRAME, LINK, TEXT

from .model import CamModel

POINTS = 720
CAM_FILL = QColor("#cfd8dc")
PITCH = QColor("#1565c0")
MARGIN = 0.08


def _turn(points: np.ndarray, angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.stack([c * points[0] - s * points[1], s * points[0] + c * points[1]])


class CamProfileView(PartView):
    """Paints the cam at the model's crank angle; ``render`` paints it anywhere."""

    def __init__(self, cam_model: CamModel, parent: QWidget | None = None) -> None:
        super().__init__(cam_model, (240, 200), lambda: cam_curves(cam_model.cam), describe, parent)

    curves = PartView.shapes
    """The pitch curve and the profile in the cam's frame (2, POINTS) mm."""

    def render_cam(self, painter: QPainter, rect: QRectF) -> None:
        """The cam, follower and roller at the current crank angle, fitted into ``rect``."""
        delta = self._model.current_cam_angle()
        psi = float(self._model.cam.program.motion(np.array([delta])).psi[0])
        label = self.tr("cam angle δ = %1°, follower ψ = %2°").replace(
            "%1", f"{math.degrees(delta) % 360.0:.1f}").replace("%2", f"{math.degrees(psi):.2f}")
        paint_cam(painter, rect, self._model.cam, delta, label, self.curves())

    render_part = render_cam

    def export_image(self, path: str) -> None:
        """PNG or SVG of the cam at the current angle (atomic, see image_export)."""
        export_painting(path, QSizeF(800, 600), self.render_cam, self.tr("Feed cam"), QColor("white"))


def cam_curves(cam: Cam) -> tuple[np.ndarray, np.ndarray]:
    """The pitch curve and the profile in the cam's frame (2, POINTS) mm."""
    p = pitch(cam.follower, cam.program, np.linspace(0.0, 2.0 * math.pi, POINTS, endpoint=False))
    return p.point, profile(p, cam.roller_mm)


def _roller_centre(cam: Cam, delta: float) -> np.ndarray:
    f = cam.follower
    beta = math.radians(f.initial_deg) + float(cam.program.motion(np.array([delta])).psi[0])
    return np.array([f.distance_mm - f.arm_mm * math.cos(beta), f.side * f.arm_mm * math.sin(beta)])


def _extent(cam: Cam, roller: np.ndarray, reach: float) -> tuple[np.ndarray, np.ndarray]:
    lo = np.array([min(-reach, roller[0] - cam.roller_mm), min(-reach, roller[1] - cam.roller_mm)])
    hi = np.array([max(reach, cam.follower.distance_mm), max(reach, roller[1] + cam.roller_mm)])
    return lo, hi


def cam_span(cam: Cam, delta: float, curves: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """Width and height (mm of the design) that :func:`paint_cam` draws, margins included:
    what a caller needs to choose a round drawing scale."""
    pitch_pts = curves[0] if curves is not None else cam_curves(cam)[0]
    lo, hi = _extent(cam, _roller_centre(cam, delta), float(np.hypot(*pitch_pts).max()) + cam.roller_mm)
    return (hi - lo) * (1 + 2 * MARGIN)


def paint_cam(painter: QPainter, rect: QRectF, cam: Cam, delta: float, label: str = "",
              curves: tuple[np.ndarray, np.ndarray] | None = None, scale: float | None = None) -> None:
    """The cam turned to cam angle ``delta`` (rad) with its follower and roller, to scale:
    fitted into ``rect``, or at ``scale`` (device units per mm of the design) centred in
    it (the Cam tab, its image export and the report)."""
    f = cam.follower
    head = QRectF()
    if label:           # wrapped, never cut (the Chinese line lost its ψ at 1280 × 720), above the cam
        head = painter.boundingRect(QRectF(rect.left() + 6, rect.top() + 4, max(rect.width() - 12, 1.0), 1e4),
                                    int(Qt.AlignmentFlag.AlignLeft | Qt.TextFlag.TextWordWrap), label)
        rect = rect.adjusted(0.0, head.height() + 4.0, 0.0, 0.0)
    pitch_pts, profile_pts = (_turn(c, -delta) for c in (curves or cam_curves(cam)))
    a = f.distance_mm
    roller = _roller_centre(cam, delta)
    reach = float(np.hypot(*pitch_pts).max()) + cam.roller_mm
    lo, hi = _extent(cam, roller, reach)
    span = hi - lo
    if scale is None:
        scale = min(rect.width() / (span[0] * (1 + 2 * MARGIN)), rect.height() / (span[1] * (1 + 2 * MARGIN)))
    centre = (lo + hi) / 2.0

    def at(x: float, y: float) -> QPointF:
        return QPointF(rect.center().x() + (x - centre[0]) * scale,
                       rect.center().y() - (y - centre[1]) * scale)

    def polygon(points: np.ndarray) -> QPolygonF:          # (2, n) mm
        return screen_polygon(points.T, (rect.center().x(), rect.center().y()), centre, scale)

    painter.save()
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    painter.setPen(QPen(LINK, 2.0))
    painter.setBrush(QBrush(CAM_FILL))
    painter.drawPolygon(polygon(profile_pts))
    painter.setPen(QPen(PITCH, 1.0, Qt.PenStyle.DashLine))
    painter.setBrush(Qt.BrushStyle.NoBrush)
    painter.drawPolygon(polygon(pitch_pts))
    painter.setPen(QPen(FRAME, 1.0, Qt.PenStyle.DashDotLine))
    r0 = cam.base_radius_mm * scale
    painter.drawEllipse(at(0.0, 0.0), r0, r0)
    painter.drawLine(at(-reach, 0.0), at(a * 1.05, 0.0))
    painter.drawLine(at(0.0, -reach), at(0.0, reach))
    # a mark on the cam that turns with it: its angle-zero ray
    painter.setPen(QPen(LINK, 1.0))
    tip = _turn(np.array([[cam.base_radius_mm * 0.5], [0.0]]), -delta)[:, 0]
    painter.drawLine(at(0.0, 0.0), at(*tip))
    painter.setPen(QPen(LINK, 3.0))
    painter.drawLine(at(a, 0.0), at(*roller))
    painter.setPen(QPen(LINK, 1.5))
    painter.setBrush(QBrush(Qt.GlobalColor.white))
    rr = cam.roller_mm * scale
    painter.drawEllipse(at(*roller), rr, rr)
    for x, y in ((0.0, 0.0), (a, 0.0)):
        painter.drawEllipse(at(x, y), 4.0, 4.0)
    painter.setPen(QPen(TEXT))
    painter.drawText(at(0.0, 0.0) + QPointF(6, 14), "O")
    painter.drawText(at(a, 0.0) + QPointF(6, 14), "A")
    if label:
        painter.drawText(head, int(Qt.AlignmentFlag.AlignLeft | Qt.TextFlag.TextWordWrap), label)
    painter.restore()
