"""θ on the report's scheme figure: the lever's two limit positions dashed, the arc of θ
between them at O4, and its label, placed by the scheme's own label search.

The scheme is exported as SVG and replayed; θ is drawn over it by the report. Its label
takes the first candidate spot that :class:`shaperapp.scheme.place.Obstacles` finds clear,
as the scheme's labels do: clear of the scheme's lines (its picture's ink, read back), of
the dashed limit positions and the arc drawn here, and :func:`core.base.lettering.label_gap`
(1.5 heights beside, 0.5 over or under) off every text of the scheme (its read-back boxes).
Clear of ink alone, 方案 I's θ stood a third of a line under "L3 = 540.0" and read as its
second line. All of it in the shot's own px (its SVG's units), y down.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFontInfo, QFontMetricsF, QImage, QPainter, QPen
from PySide6.QtSvg import QSvgRenderer

from core.base.figure_text import dimension_text
from core.base.lettering import label_gap
from shaperapp.scheme.place import Obstacles
from shaperapp.scheme.raster import Raster

INK_LEVEL = 235         # a pixel of the scheme darker than this in any channel is drawn on
LINE_CLEAR = 0.2        # θ's text keeps this many of its heights off any line
ARC_SEGMENTS = 24       # the arc as segments, for the search

PxBox = tuple[float, float, float, float]
"""A box in a shot's px: (left, right, top, bottom), y down."""


@dataclass(frozen=True)
class SchemeShot:
    """A scheme exported as SVG, with where O4 and the lever tip's limit positions lie in
    it (px) and how many design mm one of its px is."""

    svg: bytes
    o4: QPointF
    tips: tuple[QPointF, QPointF]
    mm_per_px: float
    text_px: float = 12.0
    """The pixel size of the scheme's own text (its dimensions): θ is written at it."""
    texts: tuple[tuple[PxBox, bool], ...] = ()
    """The scheme's texts as drawn in it: each one's box and whether it is turned (read upwards)."""


def theta_spots(ends: list[QPointF], o4: QPointF, radius: float, width: float,
                height: float) -> list[QRectF]:
    """Where θ's label may go, best first (y down): right of the swing level with the arc's
    end, then the nearest spots farther right, higher or lower (past the L3 dimension line
    and its label beside the lever's right limit), then the same left of the arc's other
    end, then above the arc inside the swing."""
    right, left = max(ends, key=QPointF.x), min(ends, key=QPointF.x)
    gap = height / 3.0
    shifts = sorted(((0.5 * i * height, j * height) for i in range(24) for j in (0, 1, -1, 2, -2, 3)),
                    key=lambda d: math.hypot(*d))          # nearest first
    out = [QRectF(right.x() + gap + dx, right.y() - height / 2 + dy, width, height) for dx, dy in shifts]
    out += [QRectF(left.x() - gap - width - dx, left.y() - height / 2 + dy, width, height) for dx, dy in shifts]
    out += [QRectF(o4.x() - width / 2, o4.y() - radius - (1.5 + i * 0.5) * height, width, height)
            for i in range(8)]
    return out


def ink(renderer: QSvgRenderer) -> np.ndarray:
    """Where the scheme drew (a line, a text): its picture at its own size, (rows, columns) bools."""
    box = renderer.viewBoxF()
    image = QImage(max(int(math.ceil(box.width())), 1), max(int(math.ceil(box.height())), 1),
                   QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    p = QPainter(image)
    renderer.render(p, QRectF(0, 0, image.width(), image.height()))
    p.end()
    pixels = np.frombuffer(image.constBits(), dtype=np.uint8)
    return (pixels.reshape(image.height(), image.bytesPerLine() // 4, 4)[:, :image.width(), :3].min(axis=2)
            < INK_LEVEL)


def theta_spot(spots: list[QRectF], drawn: np.ndarray, texts: tuple[tuple[PxBox, bool], ...],
               lines: np.ndarray, height: float) -> QRectF:
    """The first of ``spots`` clear of the ink ``drawn`` and of ``lines`` (k × 2 × 2) by
    LINE_CLEAR and of ``texts`` by the labels' gap, all in a shot's px, for a text
    ``height`` px high; where none is, the one the fewest come near (the scheme's
    ``Obstacles.best``)."""
    clear = LINE_CLEAR * height
    turned = np.array([box for box, up in texts if up], dtype=float).reshape(-1, 4)
    obstacles = Obstacles(lines, clear, turned, (0.0, float(drawn.shape[1]), 0.0, float(drawn.shape[0])),
                          Raster.of_cells(drawn, clear), label_gap(height))
    for box, up in texts:
        if not up:
            obstacles.add(box)
    boxes = np.array([(r.left(), r.right(), r.top(), r.bottom()) for r in spots], dtype=float)
    return spots[obstacles.best(boxes)]


def mark_theta(painter: QPainter, origin: QPointF, k: float, shot: SchemeShot, theta_deg: float,
               renderer: QSvgRenderer) -> None:
    """Dashed lever limit positions O4–B', O4–B'' and the arc of θ between them at O4, the
    label in the painter's font; the shot drawn from ``origin`` at ``k`` device units per px."""
    o4 = shot.o4
    radius = 0.3 * math.dist((o4.x(), o4.y()), (shot.tips[0].x(), shot.tips[0].y()))
    angles = [math.degrees(math.atan2(o4.y() - t.y(), t.x() - o4.x())) for t in shot.tips]
    metrics = QFontMetricsF(painter.font(), painter.device())
    label = f"θ = {dimension_text(theta_deg)}°"      # as the sheets' θ
    painter.save()
    pen = QPen(QColor("#37474f"), max(0.6 * metrics.height() / 10, 1.0), Qt.PenStyle.DashLine)
    painter.setPen(pen)
    device = lambda p: origin + p * k              # noqa: E731
    for tip in shot.tips:
        painter.drawLine(device(o4), device(tip))
    painter.setPen(QPen(QColor("#37474f"), pen.widthF()))
    r = radius * k
    painter.drawArc(QRectF(device(o4).x() - r, device(o4).y() - r, 2 * r, 2 * r),
                    round(angles[1] * 16), round((angles[0] - angles[1]) * 16))
    turns = np.radians(np.linspace(angles[1], angles[0], ARC_SEGMENTS + 1))
    arc = np.column_stack([o4.x() + radius * np.cos(turns), o4.y() - radius * np.sin(turns)])
    lines = np.concatenate([[[[o4.x(), o4.y()], [t.x(), t.y()]] for t in shot.tips],
                            np.stack([arc[:-1], arc[1:]], axis=1)])
    ends = [QPointF(*arc[-1]), QPointF(*arc[0])]
    height = QFontInfo(painter.font()).pixelSize() / k
    spots = theta_spots(ends, o4, radius, metrics.horizontalAdvance(label) / k, metrics.height() / k)
    box = theta_spot(spots, ink(renderer), shot.texts, lines, height)
    box = QRectF(device(box.topLeft()), device(box.bottomRight()))
    painter.fillRect(box, QColor("white"))
    painter.setPen(QColor("#1b262c"))
    painter.drawText(box, Qt.AlignmentFlag.AlignCenter, label)
    painter.restore()
