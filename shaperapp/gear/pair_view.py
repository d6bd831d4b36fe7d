"""The gear pair drawn to scale, turned to the crank angle of the animation bar.

The frame is the meshing sheet's (``core.gear.mesh``): the pinion's centre O1 left, the
gear's O2 right at a′, one scale for x and y. Both gears whole with their true involute
flanks and rack-generated fillets; per gear the reference (dash-dot), working pitch
(dashed), base, tip and root circles; the line of action N1N2 with the actual one B1B2
thick, the pitch point P. The gear z2 turns with the crank, the pinion i times as fast the
other way; a mark from each centre to a tooth shows the turning. Outlines are computed
once per pair and only turned per frame.
"""
from __future__ import annotations

import math

import numpy as np
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QPainter, QPen
from PySide6.QtWidgets import QWidget

from core.gear import GearPair
from core.gear.mesh import gear_outline, line_points, mesh_angles, placed
from shaperapp.parts.view import PartView
from shaperapp.widgets.gear_messages import describe_gear_error
from shaperapp.widgets.screen_polygon import screen_polygon
from shaperapp.widgets.style import FRAME, LINK, TEXT

from .model import GearModel

FILLS = (QColor("#cfd8dc"), QColor("#ffe0b2"))
ACTION = QColor("#1565c0")
MARGIN = 0.05
DRAWN_TOLERANCE_PX = 0.01   # how far a dropped outline point may lie from the line drawn
NAMED_LINE_PX = 150      # N1N2 at least this long on screen to name its points
# where each point's name goes (px from the point): the line of action runs up to the right
# from N1 through B2, P, B1 to N2, so names alternate sides of it
LABEL_OFFSETS = {"N1": QPointF(-24, 12), "B2": QPointF(-24, 4), "P": QPointF(8, 14),
                 "B1": QPointF(-24, 0), "N2": QPointF(6, -4)}


class GearPairView(PartView):
    """Paints the pair at the model's crank angle; ``render_pair`` paints it anywhere."""

    def __init__(self, gear_model: GearModel, parent: QWidget | None = None) -> None:
        super().__init__(gear_model, (200, 200), lambda: (gear_outline(gear_model.pair, 1),
                                                          gear_outline(gear_model.pair, 2)),
                         describe_gear_error, parent)
        self.close_up = False           # the line of action N1N2 filling the view, not both gears

    def set_close_up(self, on: bool) -> None:
        self.close_up = bool(on)
        self.update()

    outlines = PartView.shapes
    """The pinion and the gear whole about their own centres, (n, 2) mm."""

    def placed_outlines(self, crank: float) -> tuple[np.ndarray, np.ndarray]:
        """Both outlines where they stand at crank angle ``crank`` (rad), in the frame."""
        pair = self._model.pair
        turn1, turn2 = mesh_angles(pair, crank)
        one, two = self.outlines()
        return placed(one, float(turn1)), placed(two, float(turn2), (pair.centre_mm, 0.0))

    def render_pair(self, painter: QPainter, rect: QRectF) -> None:
        """The pair at the current crank angle, fitted into ``rect``, under a line that says
        the angles."""
        crank = self._model.crank_turn()
        paint_pair(painter, rect, self._model.pair, self.placed_outlines(crank), self.caption(crank),
                   self.close_up, DRAWN_TOLERANCE_PX)

    render_part = render_pair

    def caption(self, crank: float) -> str:
        """The line over the drawing: how far each gear has turned at crank angle ``crank``."""
        pair = self._model.pair
        ratio = pair.gear2.teeth / pair.gear1.teeth
        return self.tr("crank φ = %1°: gear z2 turned %1° clockwise, pinion z1 %2° counter-clockwise "
                       "(i = %3)").replace("%1", f"{math.degrees(crank) % 360.0:.1f}").replace(
            "%2", f"{math.degrees(crank * ratio) % 360.0:.1f}").replace("%3", f"{ratio:.4f}")


def pair_span(pair: GearPair, close_up: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The lower-left and upper-right corners (mm) of what :func:`paint_pair` draws: both
    gears whole, or (``close_up``) the line of action N1N2 and a module round it."""
    if close_up:
        pts = line_points(pair)
        ends = np.array([pts["N1"], pts["N2"]])
        m = pair.inputs.module_mm
        return ends.min(axis=0) - m, ends.max(axis=0) + m
    g1, g2 = pair.gear1, pair.gear2
    half = max(g1.ra, g2.ra)
    return np.array([-g1.ra, -half]), np.array([pair.centre_mm + g2.ra, half])


def paint_pair(painter: QPainter, rect: QRectF, pair: GearPair,
               outlines: tuple[np.ndarray, np.ndarray], label: str = "", close_up: bool = False,
               tolerance_px: float = 0.0) -> None:
    """Both gears (``outlines`` placed in the frame), their circles and the line of action,
    fitted into ``rect`` at one scale for x and y (``close_up``: the line of action fitted,
    the rest clipped). With ``tolerance_px`` the outlines are drawn through as few of their
    points as keep every dropped one within that distance on the device (see ``thinned``)."""
    head = QRectF()
    if label:           # wrapped, never cut, above the drawing
        head = painter.boundingRect(QRectF(rect.left() + 6, rect.top() + 4, max(rect.width() - 12, 1.0), 1e4),
                                    int(Qt.AlignmentFlag.AlignLeft | Qt.TextFlag.TextWordWrap), label)
        rect = rect.adjusted(0.0, head.height() + 4.0, 0.0, 0.0)
    lo, hi = pair_span(pair, close_up)
    span = hi - lo
    scale = min(rect.width() / (span[0] * (1 + 2 * MARGIN)), rect.height() / (span[1] * (1 + 2 * MARGIN)))
    middle = (lo + hi) / 2.0

    cx, cy = rect.center().x(), rect.center().y()

    def at(x: float, y: float) -> QPointF:
        return QPointF(cx + (x - middle[0]) * scale, cy - (y - middle[1]) * scale)

    painter.save()
    painter.setClipRect(rect)
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    centres = ((0.0, 0.0), (pair.centre_mm, 0.0))
    for k, (gear, outline) in enumerate(zip((pair.gear1, pair.gear2), outlines)):
        painter.setPen(QPen(LINK, 1.2))
        painter.setBrush(QBrush(FILLS[k]))
        drawn = thinned(outline, gear.teeth, tolerance_px / scale) if tolerance_px > 0 else outline
        painter.drawPolygon(screen_polygon(drawn, (cx, cy), middle, scale))
        painter.setBrush(Qt.BrushStyle.NoBrush)
        c = at(*centres[k])
        for radius, style, width in ((gear.r, Qt.PenStyle.DashDotLine, 1.0), (gear.rw, Qt.PenStyle.DashLine, 1.0),
                                     (gear.rb, Qt.PenStyle.SolidLine, 0.6), (gear.ra, Qt.PenStyle.SolidLine, 0.4),
                                     (gear.rf, Qt.PenStyle.SolidLine, 0.4)):
            painter.setPen(QPen(FRAME, width, style))
            painter.drawEllipse(c, radius * scale, radius * scale)
        painter.setPen(QPen(LINK, 1.5))               # a mark that turns with the gear
        tooth = outline[len(outline) // gear.teeth // 2]     # the middle of the first tooth's tip
        painter.drawLine(c, at(*tooth))
    painter.setPen(QPen(FRAME, 0.8, Qt.PenStyle.DashDotLine))
    painter.drawLine(at(lo[0], 0.0), at(hi[0], 0.0))
    pts = line_points(pair)
    painter.setPen(QPen(ACTION, 1.0))
    painter.drawLine(at(*pts["N1"]), at(*pts["N2"]))
    painter.setPen(QPen(ACTION, 3.0))
    painter.drawLine(at(*pts["B1"]), at(*pts["B2"]))
    painter.setPen(QPen(TEXT))
    painter.setBrush(QBrush(TEXT))
    room = pair.n1n2 * scale >= NAMED_LINE_PX       # else the five names run together: P alone
    for name in ("N1", "N2", "B1", "B2", "P"):
        painter.drawEllipse(at(*pts[name]), 2.5, 2.5)
        if room or name == "P":
            painter.drawText(at(*pts[name]) + LABEL_OFFSETS[name], name)
    metrics = painter.fontMetrics()
    for name, xy, gear in zip(("O1", "O2"), centres, (pair.gear1, pair.gear2)):
        painter.drawEllipse(at(*xy), 3.0, 3.0)
        box = centre_label_box(at(*xy), gear.rf * scale, gear.ra * scale,
                               metrics.horizontalAdvance(name), metrics.height())
        painter.drawText(box, int(Qt.AlignmentFlag.AlignCenter), name)
    painter.setClipping(False)
    if label:
        painter.drawText(head, int(Qt.AlignmentFlag.AlignLeft | Qt.TextFlag.TextWordWrap), label)
    painter.restore()


def centre_label_box(centre: QPointF, root_px: float, tip_px: float, width: float,
                     height: float) -> QRectF:
    """Where a centre's name goes, clear of its gear's teeth (the ring between the root and
    the tip circle): below left of the centre inside the root circle when it fits there
    (with 2 px to spare), else under the gear below its tip circle. At −22, +16 px a small
    pinion's "O1" sat on its teeth (issue 40)."""
    inside = QRectF(centre.x() - width - 4.0, centre.y() + 3.0, width, height)
    corners = (inside.topLeft(), inside.topRight(), inside.bottomLeft(), inside.bottomRight())
    if max(math.hypot(q.x() - centre.x(), q.y() - centre.y()) for q in corners) <= root_px - 2.0:
        return inside
    return QRectF(centre.x() - width / 2.0, centre.y() + tip_px + 2.0, width, height)


def thinned(outline: np.ndarray, teeth: int, tolerance: float) -> np.ndarray:
    """``outline`` (``teeth`` equal teeth, as ``gear_outline`` makes it, turned or not)
    without the points that lie within ``tolerance`` (mm) of the line through those kept
    (Douglas–Peucker on one tooth, the same points kept on every tooth).

    Why: a gear of 40 teeth has 11 160 points, a tenth of a pixel apart in the tab, and
    stroking them was 30 of a Gear edit's ~40 ms of CPU (issue 40 item 5). At 0.01 px the
    drawing keeps a fifth to a seventh of them; its antialiased edge pixels move by at
    most a few levels of 255, nothing a user can see."""
    m = len(outline) // teeth
    if m < 3 or m * teeth != len(outline):
        return outline
    tooth = outline[:m + 1] if teeth > 1 else np.vstack([outline, outline[:1]])
    keep = np.zeros(m + 1, dtype=bool)
    keep[[0, m]] = True
    spans = [(0, m)]
    while spans:
        a, b = spans.pop()
        if b - a < 2:
            continue
        chord = tooth[b] - tooth[a]
        rel = tooth[a + 1:b] - tooth[a]
        length = math.hypot(chord[0], chord[1])
        off = (np.abs(rel[:, 0] * chord[1] - rel[:, 1] * chord[0]) / length if length > 0
               else np.hypot(rel[:, 0], rel[:, 1]))
        far = int(np.argmax(off))
        if off[far] > tolerance:
            far += a + 1
            keep[far] = True
            spans += [(a, far), (far, b)]
    return outline[np.tile(keep[:m], teeth)]
