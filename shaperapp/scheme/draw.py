"""Drawing primitives shared by the scheme's layers (mechanism, dimensions, forces).

Sizes here are in mm of the drawing, except the pens (cosmetic: screen pixels)
and the tags (screen pixels when fixed to the screen). The z values order the
layers: frame under links, links under pins, labels on top. The joint names' fonts are
here because the mechanism sets them and the labels' search shrinks them.
"""
from __future__ import annotations

import functools

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QFont, QPainterPath, QPen, QPolygonF
from PySide6.QtWidgets import (QGraphicsItem, QGraphicsPathItem, QGraphicsRectItem, QGraphicsSimpleTextItem,
                               QGraphicsView)

from shaperapp.plots.axes import HiddenAxis, NavViewBox, unlink_hidden_axes
from shaperapp.widgets.fonts import drawing_lettering
from shaperapp.widgets.style import CURSOR, FRAME, LINK, TOOL_PATH

LINK_FILL = QColor(LINK.red(), LINK.green(), LINK.blue(), 38)
BLOCK_FILL = QColor(FRAME).lighter(150)
RAM_FILL = QColor(FRAME.red(), FRAME.green(), FRAME.blue(), 30)
PATH_LIGHT = QColor(TOOL_PATH.red(), TOOL_PATH.green(), TOOL_PATH.blue(), 90)
DIM = QColor(CURSOR)
WHITE = QColor("#ffffff")
Z_FRAME, Z_GHOST, Z_RAM, Z_PATH, Z_CRANK, Z_LEVER, Z_BLOCK, Z_JOINT, Z_DIM, Z_LABEL = range(10)
Pair = tuple[tuple[float, float], tuple[float, float]]
Box = tuple[float, float, float, float]      # left, right, bottom, top in mm (y up)


def pen(colour: QColor, width: float = 1.5, style: Qt.PenStyle = Qt.PenStyle.SolidLine) -> QPen:
    """A cosmetic pen: its width stays in screen pixels at any zoom."""
    out = QPen(colour, width, style)
    out.setCosmetic(True)
    return out


def stadium(length: float, width: float) -> QPainterPath:
    """A bar with round ends from (0, 0) to (length, 0) in its local frame."""
    path = QPainterPath()
    half = width / 2.0
    path.addRoundedRect(QRectF(-half, -half, length + width, width), half, half)
    return path


def in_corner(box: Box, first: np.ndarray, second: np.ndarray, clear_first: float,
              clear_second: float) -> np.ndarray:
    """Where to centre a text of ``box``'s size in the corner at the origin between two
    lines along the unit vectors ``first`` and ``second`` (less than 180° apart): on the
    bisector, just far enough out that the text keeps ``clear_first`` from the first
    line and ``clear_second`` from the second."""
    half = np.array([abs(box[1] - box[0]), abs(box[3] - box[2])]) / 2.0
    bisector = (first + second) / np.hypot(*(first + second))
    out = 0.0
    for line, clear in ((first, clear_first), (second, clear_second)):
        normal = np.array([-line[1], line[0]])
        reach = half[0] * abs(normal[0]) + half[1] * abs(normal[1])      # the text's, across the line
        out = max(out, (reach + clear) / abs(float(bisector @ normal)))
    return bisector * out


def meets_segments(box: Box, ends: np.ndarray, margin: float) -> bool:
    """Does any segment of ``ends`` (k × 2 × 2: two points each) come within ``margin`` of
    the box (left, right and two y edges in either order)? Each segment is clipped to
    the widened box (Liang–Barsky), all at once."""
    if len(ends) == 0:
        return False
    lows = np.array([min(box[0], box[1]), min(box[2], box[3])]) - margin
    highs = np.array([max(box[0], box[1]), max(box[2], box[3])]) + margin
    start, step = ends[:, 0, :], ends[:, 1, :] - ends[:, 0, :]
    enter, leave = np.zeros(len(ends)), np.ones(len(ends))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):   # ±inf: no crossing there
        for axis in (0, 1):
            flat = step[:, axis] == 0.0
            outside = flat & ((start[:, axis] < lows[axis]) | (start[:, axis] > highs[axis]))
            t_low = (lows[axis] - start[:, axis]) / step[:, axis]
            t_high = (highs[axis] - start[:, axis]) / step[:, axis]
            enter = np.where(flat, enter, np.maximum(enter, np.minimum(t_low, t_high)))
            leave = np.where(flat, leave, np.minimum(leave, np.maximum(t_low, t_high)))
            leave[outside] = -1.0
    return bool(np.any(enter <= leave))


def rect(x0: float, y0: float, x1: float, y1: float) -> QRectF:
    return QRectF(QPointF(min(x0, x1), min(y0, y1)), QPointF(max(x0, x1), max(y0, y1)))


def body(fill: QColor, z: float, outline: QPen | None = None) -> QGraphicsPathItem:
    item = QGraphicsPathItem()
    item.setPen(outline or pen(LINK, 1.4))
    item.setBrush(QBrush(fill))
    item.setZValue(z)
    return item


def segments(pairs: list[Pair]) -> tuple[np.ndarray, np.ndarray]:
    """Point pairs → x, y arrays for a CurveItem with connect="pairs"."""
    pts = np.array([p for pair in pairs for p in pair], dtype=float).reshape(-1, 2)
    return pts[:, 0], pts[:, 1]


def arrow_head(tip: np.ndarray, direction: np.ndarray, u: float) -> QPolygonF:
    """A filled arrow head in mm with its tip at ``tip``, pointing along ``direction``."""
    d = direction / np.hypot(*direction)
    n = np.array([-d[1], d[0]])
    base = tip - d * 0.9 * u
    pts = (tip, base + n * 0.22 * u, base - n * 0.22 * u, tip)
    return QPolygonF([QPointF(float(p[0]), float(p[1])) for p in pts])


def text_box(item: pg.TextItem) -> Box:
    """Where a pyqtgraph text item (anchored, maybe rotated, fixed size on screen) covers
    the drawing now, in mm."""
    item.updateTransform()
    r = item.mapRectToParent(item.boundingRect())
    return r.left(), r.right(), r.top(), r.bottom()


def overlaps(a: Box, b: Box) -> bool:
    return a[0] < b[1] and b[0] < a[1] and a[2] < b[3] and b[2] < a[3]


def joint_font(points: int) -> QFont:
    """The joint names' font at ``points``: lettered as the drawing sheets are, in bold."""
    font = drawing_lettering(QFont())
    font.setPointSize(points)
    font.setBold(True)
    return font


JOINT_SIZES = (11, 9)        # pt: the joint names, and one standard size smaller where crowded
@functools.cache
def joint_fonts() -> dict[bool, QFont]:
    """The joint names' fonts, full size (False) and one size smaller (True). Made when
    first asked for, by a view, once the application runs: a QFont made before it (at
    import) took the system's first family, C059, a serif, so the names of a course's or a
    class's report (which import the scheme before starting Qt) were set in another face
    than those of ``shaper report``."""
    return {False: joint_font(JOINT_SIZES[0]), True: joint_font(JOINT_SIZES[1])}


class Tag(QGraphicsRectItem):
    """A short text on a light box, anchored at its position (anchor as pg.TextItem)."""

    PAD = 2.0

    def __init__(self, colour: QColor, fill: QColor, font: QFont, screen_fixed: bool) -> None:
        super().__init__()
        self.setPen(QPen(Qt.PenStyle.NoPen))
        self.setBrush(QBrush(fill))
        if screen_fixed:      # in the plot: text upright and the same size at any zoom
            self.setFlag(QGraphicsItem.GraphicsItemFlag.ItemIgnoresTransformations, True)
        self._text = QGraphicsSimpleTextItem(self)
        self._text.setBrush(QBrush(colour))
        self._text.setFont(font)
        self._shown = ""
        self._size = (0.0, 0.0)
        self._anchor = (-1.0, -1.0)

    def set_text(self, text: str) -> tuple[float, float]:
        """Show ``text``; returns the box's size in pixels."""
        if text != self._shown:
            self._text.setText(text)
            self._shown = text
            box = self._text.boundingRect()
            self._size = (box.width() + 2.0 * self.PAD, box.height() + 2.0 * self.PAD)
            self._anchor = (-1.0, -1.0)
        return self._size

    def place(self, text: str, x: float, y: float, anchor: tuple[float, float]) -> None:
        self.set_text(text)
        self.move(x, y, anchor)

    def move(self, x: float, y: float, anchor: tuple[float, float]) -> None:
        if anchor != self._anchor:
            w, h = self._size
            left, top = -anchor[0] * w, -anchor[1] * h
            self.setRect(QRectF(left, top, w, h))
            self._text.setPos(left + self.PAD, top + self.PAD)
            self._anchor = anchor
        self.setPos(x, y)

    def text(self) -> str:
        return self._shown

    def anchor(self) -> tuple[float, float]:
        return self._anchor


def canvas() -> pg.PlotWidget:
    """The plot the scheme draws on: to scale (x and y locked 1:1), no axes, no buttons and
    no pyqtgraph menu ("Export..."), navigated by its NavViewBox (drag pans, the wheel zooms
    both axes); the view box does not range itself, the scheme fits it."""
    plot = pg.PlotWidget(background="w", viewBox=NavViewBox(x_wheel=False, box_zoom=False),
                         axisItems={side: HiddenAxis(side) for side in ("left", "bottom", "top", "right")})
    plot.setAntialiasing(True)
    # one repaint of the rectangle around a frame's changes, not one per moved item
    plot.setViewportUpdateMode(QGraphicsView.ViewportUpdateMode.BoundingRectViewportUpdate)
    plot.scene().contextMenu = []
    item = plot.getPlotItem()
    for side in ("left", "bottom", "top", "right"):
        item.hideAxis(side)
    unlink_hidden_axes(item)
    item.hideButtons()
    item.setMenuEnabled(False)
    view = item.getViewBox()
    view.setAspectLocked(True, ratio=1.0)
    view.disableAutoRange()
    return plot
