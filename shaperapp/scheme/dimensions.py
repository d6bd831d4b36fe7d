"""The scheme's dimension layer: L1, L2, h, L3 and the measured stroke H.

Dimensions are placed where no moving part ever goes, so that a label never sits
on a link at any crank angle: L2 and h as a vertical chain left of everything,
L3 beside the lever's rightmost limit position, H under the tool path, and L1 as
the crank radius to the point where the lever's limit position touches the
crank circle (on the side the crank is drawn at when the dimensions are placed), its label led out beyond the lever's swing (the lever only ever
moves inside the wedge between its limit positions, which the crank circle
touches there).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QObject
from PySide6.QtGui import QColor, QPainterPath, QPen, Qt

from core.base.figure_text import dimension_text
from shaperapp.design.model import DesignModel
from shaperapp.plots.items import CurveItem

from .draw import DIM, Pair, Z_DIM, arrow_head, body, pen, segments, text_box
from .mechanism import Geometry
from .outlines import outline
from .place import RINGS, along, around, leader

L1_LEAD = 4.5            # the L1 label this many u beyond the crank circle, outside the lever
NAMES = ("L2", "h", "L3", "L1", "H")     # the dimensions in drawing order
CHAIN_GAP_LINES = 0.6
"""The L2 and h labels keep this many of their line heights apart: end to end on one
line with less between them (0.07 line at K = 1.6 in the report) they read as one text."""


@dataclass(frozen=True)
class Dimension:
    """One dimension: line segments, arrow tips (pos, outward direction) and its text."""

    segments: list[Pair]
    arrows: list[Pair]
    text: str
    text_pos: tuple[float, float]
    anchor: tuple[float, float]
    angle: float = 0.0


def text_anchor(normal: np.ndarray) -> tuple[float, float]:
    """Text anchor that puts a label on the ``normal`` side of its point (y up)."""
    return (0.5 - 0.5 * float(normal[0]), 0.5 + 0.5 * float(normal[1]))


def linear_dim(p: np.ndarray, q: np.ndarray, normal: np.ndarray, offset: float,
               u: float, text: str, vertical_text: bool = False) -> Dimension:
    """Dimension p–q with its line ``offset`` along the unit ``normal`` (0: no extension lines)."""
    a, b = p + normal * offset, q + normal * offset
    lines = [(tuple(a), tuple(b))]
    if offset > 0:
        lines += [(tuple(p + normal * 0.5 * u), tuple(a + normal * 0.6 * u)),
                  (tuple(q + normal * 0.5 * u), tuple(b + normal * 0.6 * u))]
    arrows = [(tuple(a), tuple(a - b)), (tuple(b), tuple(b - a))]
    mid = tuple((a + b) / 2.0 + normal * 0.3 * u)
    if vertical_text:
        return Dimension(lines, arrows, text, mid, (0.5, 1.0), 90.0)
    return Dimension(lines, arrows, text, mid, text_anchor(normal))


def crank_dim(o2: np.ndarray, crank: float, theta: float, u: float, text: str,
              side: float = -1.0) -> Dimension:
    """L1 as the radius to the tangent point of the lever's limit position on ``side``
    (-1 left, +1 right), with a leader out of the lever's swing to the label."""
    normal = np.array([side * math.cos(theta / 2.0), -math.sin(theta / 2.0)])   # away from the wedge
    touch = o2 + normal * crank
    label = touch + normal * L1_LEAD * u
    return Dimension([(tuple(o2), tuple(touch)), (tuple(touch), tuple(label))],
                     [(tuple(touch), tuple(normal))], text, tuple(label), text_anchor(normal))


class DimensionLayer(QObject):
    """Dimension lines, arrow heads and texts, placed per design; can be hidden."""

    def __init__(self, add: Callable[[object], None], parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._lines = CurveItem(pen(DIM, 1.0), connect="pairs")
        self._lines.setZValue(Z_DIM)
        add(self._lines)
        self._heads = body(DIM, Z_DIM, QPen(Qt.PenStyle.NoPen))
        add(self._heads)
        self._texts = [pg.TextItem(color=DIM, fill=QColor(255, 255, 255, 200)) for _ in range(5)]
        for item in self._texts:
            item.setZValue(Z_DIM)
            add(item)
        self._visible = True
        self._chain: tuple[float, tuple] | None = None   # (y of O2, mid text positions of L2, h)
        self._chain_top = 0.0                             # y of the chain's top end (the guide)
        self._spots: dict[str, tuple] = {}               # where L1, L3, H may go (candidates)
        self._segments: list[Pair] = []
        self._leader_index = 0
        self._u = 1.0
        self.crank_side = -1.0
        """L1 is drawn along the crank at the limit position on this side (-1 left, +1
        right): the view sets it from the crank as drawn when it places the dimensions, so
        that at the end limit L1 names the crank drawn, not the other position's lever."""

    def update(self, model: DesignModel, g: Geometry) -> None:
        """Place the dimensions of the model's design; texts are translated here."""
        design, u, o2, chain = model.design, g.u, g.o2, g.chain_x
        left = np.array([-1.0, 0.0])
        # A vertical chain at the far left: L2 = O4O2, then h from O2 up to the guide line.
        p0, p1, p2 = np.array([chain, 0.0]), np.array([chain, o2[1]]), np.array([chain, g.guide])
        dims = [linear_dim(p0, p1, left, 0.0, u, self.tr("L2 = {0}").format(dimension_text(design.frame)), True),
                linear_dim(p1, p2, left, 0.0, u,
                           self.tr("h = {0}").format(dimension_text(design.guide_above_crank)), True)]
        reach = chain - 0.6 * u
        extensions: list[Pair] = [((-2.6 * u, 0.0), (reach, 0.0)),
                                  ((o2[0] - design.crank - 0.6 * u, o2[1]), (reach, o2[1])),
                                  ((g.rail_left - 0.3 * u, g.guide), (reach, g.guide))]
        # L3 beside the lever's rightmost limit position.
        tips = g.limits.lever_tip.T
        tip = tips[int(np.argmax(tips[:, 0]))]
        unit = tip / np.hypot(*tip)
        dims.append(linear_dim(np.zeros(2), tip, np.array([unit[1], -unit[0]]), 3.0 * u, u,
                               self.tr("L3 = {0}").format(dimension_text(design.lever))))
        dims.append(crank_dim(o2, design.crank, design.theta, u,
                              self.tr("L1 = {0}").format(dimension_text(design.crank)), self.crank_side))
        # H between the tool tip's two limit positions, under the tool path.
        dims.append(linear_dim(np.array([g.tip_lo, g.tip_y]), np.array([g.tip_hi, g.tip_y]),
                               np.array([0.0, -1.0]), 2.6 * u, u,
                               self.tr("H = {0}").format(dimension_text(model.metrics.stroke_mm))))
        self._segments = [s for dim in dims for s in dim.segments] + extensions
        self._leader_index = sum(len(dim.segments) for dim in dims[:NAMES.index("L1")]) + 1
        self._lines.set_data(*segments(self._segments))
        self._u = u
        l1, l3, h_dim = dims[NAMES.index("L1")], dims[NAMES.index("L3")], dims[NAMES.index("H")]
        normal = np.asarray(l1.arrows[0][1])
        self._spots = {"L1": ("leader", np.asarray(l1.segments[1][0]), np.asarray(l1.segments[1][1]), normal),
                       "L3": ("line", *map(np.asarray, l3.segments[0]), np.array([unit[1], -unit[0]])),
                       "H": ("line", *map(np.asarray, h_dim.segments[0]), np.array([0.0, -1.0]))}
        heads = QPainterPath()
        for tip_pos, direction in (arrow for dim in dims for arrow in dim.arrows):
            heads.addPolygon(arrow_head(np.asarray(tip_pos), np.asarray(direction), u))
        self._heads.setPath(heads)
        for name, item, dim in zip(NAMES, self._texts, dims):
            item.setText(dim.text)
            if item.angle != dim.angle:          # pyqtgraph re-lays the text out on each call
                item.setAngle(dim.angle)
            anchor = (0.5, 0.5) if name in self._spots else dim.anchor    # placed by centre
            if tuple(item.anchor) != tuple(anchor):
                item.setAnchor(anchor)
            item.setPos(*dim.text_pos)
        self._chain = (float(p1[1]), tuple(dim.text_pos for dim in dims[:2]))
        self._chain_top = float(p2[1])
        self.separate_chain_labels()

    def separate_chain_labels(self) -> None:
        """Keep the L2 and h labels apart as drawn now (again after a zoom): each sits at
        the middle of its part of the vertical chain, but where one part is shorter on
        screen than its text (a tiny L2 or h), the other label moves away from the point
        they share, along its own part, until the two no longer touch."""
        if self._chain is None:
            return
        shared, mids = self._chain
        l2, h = self._texts[:2]
        for item, pos in zip((l2, h), mids):
            item.setPos(*pos)
        # h's text no higher than the chain's top: a short h ("h = 206.0" beside a 3.7 m
        # lever) reached above the drawing and was cut at the view's top edge
        above = text_box(h)[3] - self._chain_top
        if above > 0.0:
            h.setPos(mids[1][0], mids[1][1] - above)
        boxes = [text_box(l2), text_box(h)]                  # (left, right, bottom, top), mm
        overlap = min(boxes[0][3], boxes[1][3]) - max(boxes[0][2], boxes[1][2]) + self.chain_gap()
        if overlap > 0.0:
            longer = 1 if above <= 0.0 and abs(mids[1][1] - shared) >= abs(mids[0][1] - shared) else 0
            x, y = self._texts[longer].pos().x(), self._texts[longer].pos().y()
            self._texts[longer].setPos(x, y + math.copysign(overlap, mids[longer][1] - shared))

    def candidates(self, name: str, half: np.ndarray, step: float) -> np.ndarray:
        """Centres (m × 2) where the label ``name`` may go, best first, for a text of half
        size ``half`` (mm at this zoom): L1's out along its leader (the leader follows);
        L3's and H's along their dimension line, then across it."""
        kind, p, q, normal = self._spots[name]
        if kind == "leader":
            reach = float(np.abs(normal) @ half)
            side = np.array([-normal[1], normal[0]])
            out = [q + normal * (k * step + reach) + side * s * step
                   for k in range(0, 6) for s in (0.0, 1.0, -1.0, 2.0, -2.0)]
            ring, _ = around(p, half, normal, float(np.hypot(*(q - p))), step)   # then all round
            return np.concatenate([np.array(out), ring])
        ring, _ = around((p + q) / 2.0, half, normal, 0.3 * self._u, step, RINGS[:4])   # then round its middle
        return np.concatenate([along(p, q, normal, 0.3 * self._u, half), ring])

    def chain_gap(self) -> float:
        """The gap (mm at this zoom) the L2 and h labels keep: CHAIN_GAP_LINES of the
        vertical text's line height (its box's width)."""
        left, right, _, _ = text_box(self._texts[1])
        return CHAIN_GAP_LINES * (right - left)

    def chain_moves(self, name: str) -> np.ndarray:
        """Shifts (m × 2, mm) of the L2 or h label, as it sits now, along its part of the
        chain (its box kept within the part) and then across to the chain's other side."""
        item = self.texts()[name]
        left, right, bottom, top = text_box(item)
        lo, hi = ((0.0, self._chain[0]) if name == "L2" else (self._chain[0], self._chain_top))
        length = top - bottom
        if hi - lo < length:
            return np.zeros((1, 2))
        line_x = right + 0.3 * self._u                      # the text sits left of the chain
        out = []
        for dx in (0.0, line_x + 0.3 * self._u - left):
            for t in (0.5, 0.3, 0.7, 0.1, 0.9, 0.0, 1.0):
                out.append((dx, lo + t * (hi - lo - length) - bottom))
        return np.array(out)

    def shift_label(self, name: str, shift: np.ndarray) -> None:
        item = self.texts()[name]
        item.setPos(item.pos().x() + float(shift[0]), item.pos().y() + float(shift[1]))

    def placed_centres(self) -> dict[str, np.ndarray]:
        """Where the searched labels' centres are now (mm): kept over a rebuild until the
        search after its paint."""
        texts = self.texts()
        return {name: np.array([texts[name].pos().x(), texts[name].pos().y()]) for name in self.placed()}

    def move_label(self, name: str, centre: np.ndarray) -> None:
        """Put the label ``name`` centred at ``centre``; L1's leader then ends at its box."""
        item = self.texts()[name]
        item.setPos(float(centre[0]), float(centre[1]))
        if name == "L1":
            box = text_box(item)
            _, touch, _, normal = self._spots["L1"]
            lead = leader(touch, box, 0.0)
            end = lead[0, 1] if len(lead) else touch
            self._segments[self._leader_index] = (tuple(touch), tuple(end))
            self._lines.set_data(*segments(self._segments))

    def set_visible(self, visible: bool) -> None:
        self._visible = visible
        for item in (self._lines, self._heads, *self._texts):
            item.setVisible(visible)

    def labels(self) -> list[str]:
        return [item.toPlainText() for item in self._texts]

    def texts(self) -> dict[str, pg.TextItem]:
        """The label items by dimension name (NAMES)."""
        return dict(zip(NAMES, self._texts))

    def lines(self) -> np.ndarray:
        """The dimension and extension lines drawn, k × 2 × 2 (mm; none while hidden): the
        pivot's label keeps off them."""
        if not self._visible:
            return np.empty((0, 2, 2))
        return np.column_stack([self._lines.x, self._lines.y]).reshape(-1, 2, 2)

    def fixed_lines(self) -> np.ndarray:
        """The dimension lines and arrow heads drawn, without L1's leader (which follows
        its label), mm, k × 2 × 2; none while hidden."""
        if not self._visible:
            return np.empty((0, 2, 2))
        kept = self._segments[:self._leader_index] + self._segments[self._leader_index + 1:]
        return np.concatenate([np.array(kept, dtype=float).reshape(-1, 2, 2), outline(self._heads)])

    def leader_line(self) -> np.ndarray:
        """L1's leader as drawn now (1 × 2 × 2, mm; none while hidden)."""
        if not self._visible or not self._segments:
            return np.empty((0, 2, 2))
        return np.array([self._segments[self._leader_index]], dtype=float)

    def placed(self) -> tuple[str, ...]:
        """The labels placed by a search (``candidates``), the others sit on their chain."""
        return tuple(self._spots) if self._visible else ()
