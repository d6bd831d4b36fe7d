"""Where a polygon's labels go: near their point or vector, apart from each other, from
the arrowheads and, where there is room, from the lines.

A student's drawing names every point and vector; on a small pane the names of
points that lie close together (P, G₆, F_I6, N at one corner of a force polygon)
ran into one blob and sat under arrowheads. ``place`` tries positions around an
anchor, nearest first and in the preferred direction first, and takes the first
whose box is free, first of everything, then of text and arrowheads only. A box is
free only where it is read as naming its own anchor: every other named point
(``named``) lies ASSOCIATION text lines farther from it. Where the points crowd (a
force of 49 N beside one of 7000 N) the label goes farther out, and ``leader`` gives
the thin line that ties it to its point.
"""
from __future__ import annotations

import math
from collections.abc import Sequence

from PySide6.QtCore import QLineF, QPointF, QRectF, QSizeF

DIRECTIONS = 16                        # tried around an anchor
DISTANCES = (0.25, 0.6, 1.1, 1.8, 2.8)  # × text line, from the anchor to the box's near side
LEADER_DISTANCES = (1.8, 2.8, 4.0, 5.5, 7.5)   # × text line: spots tied to their point by a leader
ASSOCIATION = 0.5                     # text lines another named point must lie farther than its own
APART = 0.01                          # device units a line's extent must stay off a box to pass it by


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
                 lines: Sequence[QLineF] = (), outer: QRectF | None = None,
                 named: Sequence[QPointF] = ()) -> None:
        self.bounds = bounds
        self.outer = outer or bounds      # where a label may go when the drawing area is full
        self.line = line
        self.taken: list[QRectF] = list(obstacles)
        self.lines: list[QLineF] = []
        self._extents: list[tuple[float, float, float, float]] = []   # each line's (x0, y0, x1, y1)
        for line in lines:
            self.add_line(line)
        self.named = list(named)          # every point a label names
        self.leader: QLineF | None = None   # the last placed label's leader line, if it needs one

    def add_line(self, line: QLineF) -> None:
        """A line the labels keep off from now on (where there is room)."""
        self.lines.append(line)
        self._extents.append((min(line.x1(), line.x2()), min(line.y1(), line.y2()),
                              max(line.x1(), line.x2()), max(line.y1(), line.y2())))

    def _others(self, anchors: Sequence[QPointF]) -> list[QPointF]:
        """The named points that are not ``anchors`` (farther than 0.5 from each)."""
        return [p for p in self.named
                if all(math.hypot(p.x() - a.x(), p.y() - a.y()) > 0.5 for a in anchors)]

    def _reads_as_own(self, box: QRectF, anchors: Sequence[QPointF], others: Sequence[QPointF]) -> bool:
        """Whether ``box`` is read as naming one of ``anchors`` rather than another named
        point (``others``: :meth:`_others` of ``anchors``, found once a label, not once a box)."""
        own = min(_distance(box, a) for a in anchors)
        return all(_distance(box, p) >= own + ASSOCIATION * self.line for p in others)

    def _free(self, box: QRectF, strict: bool, bounds: QRectF) -> bool:
        if not bounds.contains(box):
            return False
        room = 0.12 * self.line          # ink may reach past a glyph's advance (the prime ′)
        grown = box.adjusted(-room, -room, room, room)
        if any(grown.intersects(other) for other in self.taken):
            return False
        return not strict or not self._meets_a_line(box)

    def _meets_a_line(self, box: QRectF) -> bool:
        """Whether any of the lines passes through ``box``: :func:`crosses` of the lines
        whose extent reaches the box (a polygon's labels tried some hundred boxes against
        every line with Qt's intersections, 3 % of a ``shaper class`` student). A line
        whose extent stays APART off the box can neither end in it nor meet its edges."""
        left, top = box.left() - APART, box.top() - APART
        right, bottom = box.right() + APART, box.bottom() + APART
        return any(crosses(box, line) for line, (x0, y0, x1, y1) in zip(self.lines, self._extents)
                   if x0 <= right and x1 >= left and y0 <= bottom and y1 >= top)

    def place(self, anchors: Sequence[QPointF], size: QSizeF, prefer: float) -> QRectF:
        """The first free box around one of ``anchors`` (nearest distance first, then
        directions from ``prefer``, radians) that is read as naming them; else one farther
        out with a leader line (``self.leader``) from the anchor; the preferred one if none
        is free."""
        angles = [prefer]
        for k in range(1, DIRECTIONS // 2 + 1):
            angles += [prefer + 2 * math.pi * k / DIRECTIONS, prefer - 2 * math.pi * k / DIRECTIONS]
        self.leader = None
        others = self._others(anchors)
        # clear of lines beside the point, then clear of lines on a leader, then over lines;
        # last, beside the point though another is as near (rather than on an arrowhead)
        passes = ((True, self.bounds, False), (True, self.bounds, True), (True, self.outer, True),
                  (False, self.bounds, False), (False, self.outer, False), (False, self.outer, True),
                  (False, self.bounds, None), (False, self.outer, None))
        for strict, bounds, tied in passes:
            for distance in (LEADER_DISTANCES if tied else DISTANCES):      # tied None: plain
                for anchor in (anchors[:1] if tied else anchors):
                    for angle in angles:
                        box = box_at(anchor, size, angle, distance * self.line)
                        if not self._free(box, strict, bounds):
                            continue
                        if tied is None or (not tied and self._reads_as_own(box, anchors, others)):
                            self.taken.append(box)
                            return box
                        tie = leader(anchor, box)
                        if tied and not any(crosses(other, tie) for other in self.taken) and not (
                                strict and any(_cross(tie, other) for other in self.lines)):
                            self.taken.append(box)
                            self.add_line(tie)
                            self.leader = tie
                            return box
        box = box_at(anchors[0], size, prefer, DISTANCES[0] * self.line)
        self.taken.append(box)
        return box


def _cross(a: QLineF, b: QLineF) -> bool:
    """Whether two segments cross."""
    return a.intersects(b)[0] == QLineF.IntersectionType.BoundedIntersection


def _distance(box: QRectF, p: QPointF) -> float:
    """From the point ``p`` to the box (0 inside)."""
    dx = max(box.left() - p.x(), 0.0, p.x() - box.right())
    dy = max(box.top() - p.y(), 0.0, p.y() - box.bottom())
    return math.hypot(dx, dy)


def leader(anchor: QPointF, box: QRectF) -> QLineF:
    """A line from ``anchor`` to the nearest point of ``box``, a little short of both."""
    near = QPointF(min(max(anchor.x(), box.left()), box.right()), min(max(anchor.y(), box.top()), box.bottom()))
    line = QLineF(anchor, near)
    length = line.length()
    if length < 1e-9:
        return line
    gap = min(2.0, length / 4.0)
    return QLineF(line.pointAt(gap / length), line.pointAt(1.0 - gap / length))
