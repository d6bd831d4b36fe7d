"""Where a polygon's labels go: near their point or vector, apart from each other, from
the arrowheads and, where there is room, from the lines.

A student's drawing names every point and vector; on a small pane the names of
points that lie close together (P, G₆, F_I6, N at one corner of a force polygon)
ran into one blob and sat under arrowheads. ``place`` tries positions around an
anchor, nearest first and in the preferred direction first, and takes the first
whose box is free, first of everything, then of text and arrowheads only.
"""
from __future__ import annotations

import math
from collections.abc import Sequence

from PySide6.QtCore import QLineF, QPointF, QRectF, QSizeF

DIRECTIONS = 16                        # tried around an anchor
DISTANCES = (0.25, 0.6, 1.1, 1.8, 2.8)  # × text line, from the anchor to the box's near side


def box_at(anchor: QPointF, size: QSizeF, angle: float, gap: float) -> QRectF:
    """The box of ``size`` whose nearest point to ``anchor`` lies ``gap`` away in the
    direction ``angle`` (radians, y down as on the device)."""
    dx, dy = math.cos(angle), math.sin(angle)
    # the box's centre is pushed out so that its near edge (not its centre) is at gap
    half_w, half_h = size.width() / 2.0, size.height() / 2.0
    reach = min(half_w / abs(dx) if abs(dx) > 1e-9 else math.inf,
                half_h / abs(dy) if abs(dy) > 1e-9 else math.inf)
    cx, cy = anchor.x() + dx * (gap + reach), anchor.y() + dy * (gap + reach)
    return QRectF(cx - half_w, cy - half_h, size.width(), size.height())


def crosses(box: QRectF, line: QLineF) -> bool:
    """Whether the segment ``line`` passes through ``box``."""
    if box.contains(line.p1()) or box.contains(line.p2()):
        return True
    corners = (box.topLeft(), box.topRight(), box.bottomRight(), box.bottomLeft())
    for i in range(4):
        edge = QLineF(corners[i], corners[(i + 1) % 4])
        kind, _ = line.intersects(edge)
        if kind == QLineF.IntersectionType.BoundedIntersection:
            return True
    return False


class LabelPlacer:
    """Places boxes one after another inside ``bounds``, each clear of those placed
    before and of the given obstacles."""

    def __init__(self, bounds: QRectF, line: float, obstacles: Sequence[QRectF] = (),
                 lines: Sequence[QLineF] = (), outer: QRectF | None = None) -> None:
        self.bounds = bounds
        self.outer = outer or bounds      # where a label may go when the drawing area is full
        self.line = line
        self.taken: list[QRectF] = list(obstacles)
        self.lines = list(lines)

    def _free(self, box: QRectF, strict: bool, bounds: QRectF) -> bool:
        if not bounds.contains(box):
            return False
        room = 0.12 * self.line          # ink may reach past a glyph's advance (the prime ′)
        grown = box.adjusted(-room, -room, room, room)
        if any(grown.intersects(other) for other in self.taken):
            return False
        return not strict or not any(crosses(box, line) for line in self.lines)

    def place(self, anchors: Sequence[QPointF], size: QSizeF, prefer: float) -> QRectF:
        """The first free box around one of ``anchors`` (nearest distance first, then
        directions from ``prefer``, radians); the preferred one if none is free."""
        angles = [prefer]
        for k in range(1, DIRECTIONS // 2 + 1):
            angles += [prefer + 2 * math.pi * k / DIRECTIONS, prefer - 2 * math.pi * k / DIRECTIONS]
        for strict, bounds in ((True, self.bounds), (False, self.bounds), (False, self.outer)):
            for distance in DISTANCES:
                for anchor in anchors:
                    for angle in angles:
                        box = box_at(anchor, size, angle, distance * self.line)
                        if self._free(box, strict, bounds):
                            self.taken.append(box)
                            return box
        box = box_at(anchors[0], size, prefer, DISTANCES[0] * self.line)
        self.taken.append(box)
        return box
