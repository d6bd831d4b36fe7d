"""The scheme's mechanism layer: frame, crank, slotted lever, blocks, rod, ram, tool path.

Every position comes from core (``model.motion.shape``, ``model.metrics`` and
``core.linkage.kinematics.shape`` at the limit angles); this layer only chooses how to
draw them. Link bodies, pins and blocks are rigid shapes built once per design
in their own local frame, so an animation frame only moves them with
``setPos`` / ``setRotation`` using arrays prepared per design, and redraws the
travelled tool path from at most a handful of prepared points. No pyqtgraph
``setData`` runs per frame: it is slower and, with PySide6 6.12, every
Python-side signal emit leaks a reference.

Sizes that are not design data (bar widths, pins, the ram's height, the tool,
the supports) scale with the drawing unit ``u = L3 / 40`` so that any design
looks alike; they never change a dimension of the mechanism.

The per-frame arrays are computed in frames.py, the static shapes (supports, guide
way, tool) in shapes.py and the items' outlines as segments in outlines.py; this module
keeps the Qt items, their motion and what the labels read back from them.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QObject, QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QPainterPath
from PySide6.QtWidgets import QGraphicsEllipseItem

from core.linkage.kinematics import Shape
from core.linkage.kinematics import shape as core_shape

from shaperapp.design.model import DesignModel
from shaperapp.plots.items import CurveItem
from shaperapp.widgets.style import FRAME, LINK, TOOL_PATH

from .draw import (BLOCK_FILL, LINK_FILL, PATH_LIGHT, RAM_FILL, WHITE, Box, Z_BLOCK,
                          Z_CRANK, Z_FRAME, Z_GHOST, Z_JOINT, Z_LABEL, Z_LEVER, Z_PATH, Z_RAM,
                          body, joint_fonts, pen, rect, segments, stadium, text_box)
from .frames import Frames, build_frames
from .outlines import outline
from .place import posed
from .shapes import rail, support, tool_shape

UNITS_PER_LEVER = 40.0     # drawing unit u = L3 / 40
MOVING = ("A", "B", "C")
JOINT_LABEL_CLEAR = 1.4      # × u from a joint to its label's near edge: past the lever's half width (0.8 u)
LEVER_HALF_WIDTH = 0.8       # × u
LEFT = np.array([-1.0, 0.0])
SWEPT_STEPS = 180
"""About as many crank angles over the cycle as the still labels keep the moving bodies
clear at (every second angle at the default 1°, as ever: 2° apart at most). A finer step
draws the same bodies at more angles, not elsewhere; the labels' search over all of them
grew with it, 119 ms an edit at 0.1° and about 1.2 s at 0.01° (the lines burnt and the
link axes checked)."""
PIN_FIXED, PIN_MOVING = 0.5, 0.38   # pin marker radii, u


@dataclass(frozen=True)
class Geometry:
    """Where things are for the other layers, per design, mm."""

    o2: np.ndarray               # crank centre
    u: float                     # drawing unit
    guide: float                 # height of the ram guide line
    rail_left: float             # left end of the guide way
    chain_x: float               # x of the vertical dimension chain at the far left
    tip_y: float                 # height of the tool point while cutting
    tip_lo: float                # tool point x at the two limit positions
    tip_hi: float
    tip_dx: float                # tool point x relative to the ram joint C
    ram_rear: float              # the ram's body from C: rear and front ends
    ram_front: float
    limits: Shape                # core's shape at the two limit positions
    fit_rect: QRectF             # the whole drawing, for Fit


class MechanismLayer(QObject):
    """The moving mechanism and its static frame; ``rebuild`` per design, ``show`` per frame."""

    def __init__(self, add: Callable[[object], None], parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.frames: Frames | None = None
        self._index = 0
        self._o2 = np.zeros(2)
        self._ground = CurveItem(pen(FRAME, 1.2), connect="pairs")
        self._guide_line = CurveItem(pen(FRAME, 1.0, Qt.PenStyle.DashDotLine))
        self._ghost_lines = CurveItem(pen(FRAME, 1.0, Qt.PenStyle.DashLine), connect="pairs")
        self._circle = CurveItem(pen(FRAME, 1.0, Qt.PenStyle.DashLine))
        self._path_all = CurveItem(pen(PATH_LIGHT, 1.2))
        for z, it in ((Z_FRAME, self._ground), (Z_GHOST, self._guide_line),
                      (Z_GHOST, self._ghost_lines), (Z_GHOST, self._circle),
                      (Z_PATH, self._path_all)):
            it.setZValue(z)
            add(it)
        self._path_done = body(QColor(0, 0, 0, 0), Z_PATH, pen(TOOL_PATH, 2.6))
        self._path_done.setBrush(QBrush(Qt.BrushStyle.NoBrush))
        self.ram = body(RAM_FILL, Z_RAM)
        self._tool = body(BLOCK_FILL, Z_RAM)
        self._tool.setParentItem(self.ram)
        self._crank = body(LINK_FILL, Z_CRANK)
        self._lever = body(LINK_FILL, Z_LEVER)
        self._block_a = body(BLOCK_FILL, Z_BLOCK)
        self._block_b = body(BLOCK_FILL, Z_BLOCK)
        self._rod = body(LINK_FILL, Z_BLOCK)
        self.pins: dict[str, QGraphicsEllipseItem] = {}
        for name in ("O4", "O2", *MOVING):
            pin = QGraphicsEllipseItem()
            pin.setPen(pen(LINK, 1.5))
            pin.setBrush(QBrush(WHITE))
            pin.setZValue(Z_JOINT)
            self.pins[name] = pin
        for it in (self._path_done, self.ram, self._crank, self._lever, self._block_a,
                   self._block_b, self._rod, *self.pins.values()):
            add(it)
        font = joint_fonts()[False]
        self.labels: dict[str, pg.TextItem] = {}
        for name, text in (("O2", "O\u2082"), ("O4", "O\u2084"), ("A", "A"), ("B", "B"), ("C", "C")):
            label = pg.TextItem(text, color=LINK, anchor=(0.5, 0.5))
            label.setFont(font)
            label.setZValue(Z_LABEL)
            add(label)
            self.labels[name] = label

    # ---- per design ----------------------------------------------------
    def rebuild(self, model: DesignModel) -> Geometry:
        """Shapes, static lines and per-frame arrays of the model's design."""
        design, motion, metrics = model.design, model.motion, model.metrics
        sh = motion.shape
        u = design.lever / UNITS_PER_LEVER
        a, b, c = sh.crank_pin.T, sh.lever_tip.T, sh.ram_joint.T
        o2 = np.array([0.0, design.frame])
        rod = design.rod is not None
        guide = design.guide
        # The ram's limit positions from core's measured metrics; the lever's from core's shape.
        limits = core_shape(design, np.radians([metrics.work_start_deg, metrics.work_end_deg]))
        origin = float(c[0, 0] - motion.ram_x[0])
        ram_lo, ram_hi = origin + metrics.ram_min_mm, origin + metrics.ram_max_mm

        # The ram in its local frame (origin at C on the guide line); the block variant's ram
        # is tall enough for the block at B to slide in its vertical slot.
        block_half = 1.1 * u
        y_lo, y_hi = -1.3 * u, 1.3 * u
        b_lo, b_hi = float(b[:, 1].min()) - guide, float(b[:, 1].max()) - guide
        if not rod:
            y_lo = min(y_lo, b_lo - block_half - 0.5 * u)
            y_hi = max(y_hi, b_hi + block_half + 0.5 * u)
        rear = 3.0 * u
        right_edge = max(float(a[:, 0].max()), float(b[:, 0].max()))
        front = max(0.5 * design.stroke, right_edge + 5.0 * u - ram_lo)   # tool clear of the links
        ram = QPainterPath()
        ram.addRect(rect(-rear, y_lo, front, y_hi))
        if not rod:
            ram.addRect(rect(-0.8 * u, b_lo - block_half - 0.2 * u, 0.8 * u, b_hi + block_half + 0.2 * u))
            ram.setFillRule(Qt.FillRule.OddEvenFill)
        self.ram.setPath(ram)
        self.ram.setPos(0.0, guide)
        tool, tip_local = tool_shape(front, y_lo, u)
        self._tool.setPath(tool)
        self._build_bodies(design, sh, u, block_half)
        self.frames = build_frames(design, motion, metrics, u, tip_local)
        self.labels["C"].setVisible(rod)
        self.pins["C"].setVisible(rod)

        # Static drawing: supports, guide way, crank circle, lever limits, tool path.
        x0, x1 = ram_lo - rear - 3.0 * u, ram_hi + front + 3.0 * u
        self._ground.set_data(*segments(support(np.zeros(2), u) + support(o2, u)
                                       + rail(x0, x1, guide + y_hi, u)))
        self._guide_line.set_data([x0, x1], [guide, guide])
        self._ghost_lines.set_data(*segments([((0.0, 0.0), tuple(p)) for p in limits.lever_tip.T]))
        self._circle.set_data(a[:, 0], a[:, 1])
        tip = self.frames.tip
        self._path_all.set_data(tip[:, 0], tip[:, 1])
        self.pins["O4"].setPos(0.0, 0.0)
        left = limits.lever_tip.T[int(np.argmin(limits.lever_tip[0]))]
        corner = LEFT + left / np.hypot(*left)       # O4's label: between the lever's left limit and the level
        self.pivot_direction = corner / np.hypot(*corner)
        self._o2 = o2
        self._bodies, self._drawn = None, (design, rod)     # the labels' lines: when first asked
        self.pins["O2"].setPos(*o2)

        chain = min(x0, float(a[:, 0].min()), float(b[:, 0].min()), -2.0 * u) - 2.5 * u
        bottom = min(-3.5 * u, guide + tip_local[1] - 6.0 * u)
        return Geometry(o2=o2, u=u, guide=guide, rail_left=x0, chain_x=chain,
                        tip_y=guide + tip_local[1], tip_lo=ram_lo + tip_local[0],
                        tip_hi=ram_hi + tip_local[0], tip_dx=tip_local[0], ram_rear=-rear,
                        ram_front=front, limits=limits,
                        fit_rect=QRectF(QPointF(chain - 3.0 * u, bottom),
                                        QPointF(x1 + u, guide + y_hi + 1.5 * u)))

    def _build_bodies(self, design, sh, u: float, block_half: float) -> None:
        """Crank, slotted lever, blocks, rod and pins as shapes in their own frames."""
        self._crank.setPath(stadium(design.crank, 1.1 * u))
        self._crank.setPos(0.0, design.frame)
        slot_lo = max(float(sh.slide.min()) - 1.6 * u, 0.9 * u)          # the block's travel
        slot_hi = min(float(sh.slide.max()) + 1.6 * u, design.lever - 0.9 * u)
        lever = stadium(design.lever, 2.0 * LEVER_HALF_WIDTH * u)
        lever.addRoundedRect(QRectF(slot_lo, -0.35 * u, slot_hi - slot_lo, 0.7 * u), 0.35 * u, 0.35 * u)
        lever.setFillRule(Qt.FillRule.OddEvenFill)
        self._lever.setPath(lever)
        block = QPainterPath()
        block.addRect(QRectF(-1.2 * u, -0.55 * u, 2.4 * u, 1.1 * u))
        self._block_a.setPath(block)
        block_b = QPainterPath()
        block_b.addRect(QRectF(-0.7 * u, -block_half, 1.4 * u, 2.0 * block_half))
        self._block_b.setPath(block_b)
        rod = design.rod is not None
        self._block_b.setVisible(not rod)
        self._rod.setVisible(rod)
        if rod:
            self._rod.setPath(stadium(design.rod, 1.0 * u))
        for name, pin in self.pins.items():
            r = (PIN_FIXED if name.startswith("O") else PIN_MOVING) * u
            pin.setRect(QRectF(-r, -r, 2.0 * r, 2.0 * r))

    def _label_lines(self) -> list:
        """The bodies' lines the labels keep off: when their search first asks (after the paint)."""
        if self._bodies is None:
            self._bodies = self._body_poses(self._drawn[1])
            self._frame_ends, self._frame_margins = self._frame_parts(*self._drawn)
        return self._bodies

    def _body_poses(self, rod: bool) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
        """Each moving body's outline in its own frame (k × 2 × 2) with its rotation (n,)
        and position (n × 2) at every crank angle: the lines labels keep off, per frame
        or over the whole cycle, without asking Qt."""
        f, n = self.frames, len(self.frames.tip)
        zero = np.zeros(n)
        ram_pos = np.column_stack([f.ram_x, np.full(n, self.ram.y())])
        parts = [(self._crank, f.crank_deg, np.broadcast_to(self._o2, (n, 2))),
                 (self._lever, f.lever_deg, np.zeros((n, 2))),
                 (self._block_a, f.lever_deg, f.joints[:, 0]), (self.ram, zero, ram_pos),
                 (self._tool, zero, ram_pos), (self.pins["A"], zero, f.joints[:, 0]),
                 (self.pins["B"], zero, f.joints[:, 1])]
        parts.append((self._rod, f.rod_deg, f.joints[:, 1]) if rod else (self._block_b, zero, f.joints[:, 1]))
        if rod:
            parts.append((self.pins["C"], zero, f.joints[:, 2]))
        return [(outline(item), angle, pos) for item, angle, pos in parts]

    def _frame_parts(self, design, rod: bool) -> tuple[np.ndarray, np.ndarray]:
        """What a moving joint's name keeps off at each crank angle, (n, k, 2, 2) segments
        and each one's margin (k,), mm: the blocks', ram's and tool's outlines (a few
        straight sides), and each round-ended link and pin as its centre line with its half
        width (the same outline, as a capsule, in far fewer segments than its curve)."""
        f, n = self.frames, len(self.frames.tip)
        zero, ram_pos = np.zeros(n), np.column_stack([f.ram_x, np.full(n, self.ram.y())])
        point = np.zeros((1, 2, 2))
        parts = [(outline(self._block_a), f.lever_deg, f.joints[:, 0], 0.0),
                 (outline(self.ram), zero, ram_pos, 0.0), (outline(self._tool), zero, ram_pos, 0.0),
                 (np.array([[[0.0, 0.0], [design.crank, 0.0]]]), f.crank_deg,
                  np.broadcast_to(self._o2, (n, 2)), 0.55 * f.u),
                 (np.array([[[0.0, 0.0], [design.lever, 0.0]]]), f.lever_deg, np.zeros((n, 2)),
                  LEVER_HALF_WIDTH * f.u)]
        parts += [(point, zero, f.joints[:, k], PIN_MOVING * f.u) for k in range(f.joints.shape[1])]
        parts.append((np.array([[[0.0, 0.0], [design.rod, 0.0]]]), f.rod_deg, f.joints[:, 1], 0.5 * f.u)
                     if rod else (outline(self._block_b), zero, f.joints[:, 1], 0.0))
        ends = np.concatenate([posed(local, angle, pos).reshape(n, -1, 2, 2)
                               for local, angle, pos, _ in parts], axis=1)
        margins = np.concatenate([np.full(len(local), margin) for local, _, _, margin in parts])
        return ends, margins

    def joint_at(self, name: str, index: int) -> np.ndarray:
        """Where joint ``name`` is at crank-angle ``index``, mm (O4 and O2 stay put)."""
        if name == "O4":
            return np.zeros(2)
        return self._o2 if name == "O2" else self.frames.joints[index, MOVING.index(name)]

    def frame_obstacles(self, index: int) -> tuple[np.ndarray, np.ndarray]:
        """The moving bodies at crank-angle ``index``: segments (k × 2 × 2) and margins (k,), mm."""
        self._label_lines()
        return self._frame_ends[index], self._frame_margins

    def static_lines(self) -> np.ndarray:
        """The lines that stay put within a design (frame, guide, limits, circle, tool
        path, fixed pins), mm, k × 2 × 2."""
        items = (self._ground, self._guide_line, self._ghost_lines, self._circle, self._path_all,
                 self.pins["O4"], self.pins["O2"])
        parts = [posed(outline(item), np.zeros(1), np.array([item.pos().x(), item.pos().y()])) for item in items]
        return np.concatenate(parts)

    def frame_lines(self, index: int | None = None) -> np.ndarray:
        """The moving bodies' outlines at crank-angle ``index``, or over the whole cycle
        (every second angle, or about SWEPT_STEPS of them at a finer step) when None, and
        the tool path travelled, mm."""
        pick = slice(None, None, self._stride(SWEPT_STEPS, 2)) if index is None else slice(index, index + 1)
        parts = [posed(local, angle[pick], pos[pick]) for local, angle, pos in self._label_lines()]
        if index is not None:
            parts.append(outline(self._path_done))
        return np.concatenate(parts)

    def _stride(self, steps: int, least: int) -> int:
        """Every how many frames to take over the cycle: every ``least``-th (as for every
        step of 0.5° or more before), or fewer where that gives more than about ``steps``
        steps, never fewer than ``steps`` (so never farther apart than 360°/``steps``)."""
        return max(least, (len(self.frames.tip) - 1) // steps)

    def link_axes(self, index: int | None = None) -> tuple[np.ndarray, np.ndarray]:
        """The lever's and the crank's centre lines at crank-angle ``index`` (or at every
        angle, or about 2·SWEPT_STEPS of them at a finer step, when None) and each one's half width, mm: no label lies on a link, even
        inside its outline."""
        f = self.frames
        pick = slice(None, None, self._stride(2 * SWEPT_STEPS, 1)) if index is None else slice(index, index + 1)
        a, b = f.joints[pick, 0], f.joints[pick, 1]
        lever = np.stack([np.zeros_like(b), b], axis=1)
        crank = np.stack([np.broadcast_to(self._o2, a.shape), a], axis=1)
        margins = np.concatenate([np.full(len(lever), LEVER_HALF_WIDTH * f.u), np.full(len(crank), 0.55 * f.u)])
        return np.concatenate([lever, crank]), margins

    def label_directions(self, index: int) -> dict[str, np.ndarray]:
        """Where each joint's label goes first, as a unit direction from its joint: A's
        across the lever away from O2, O2's away from the lever, B's away from the rod,
        C's down; O4's into the corner left of the lever's left limit."""
        f = self.frames
        out = {"A": f.away[index, 0], "O2": f.away[index, 1], "O4": self.pivot_direction}
        for k, name in enumerate(MOVING[1:], start=1):
            if self.labels[name].isVisible():
                d = f.labels[index, k] - f.joints[index, k]
                out[name] = d / np.hypot(*d)
        return out

    # ---- per frame ---------------------------------------------------
    def show(self, index: int) -> bool:
        """Move everything to crank-angle ``index`` with setPos/setRotation/setPath only;
        False when there is no such index (nothing moved)."""
        f = self.frames
        if f is None or index >= len(f.tip):
            return False
        joints = f.joints[index]
        for name, (x, y) in zip(MOVING, joints):
            self.pins[name].setPos(x, y)
        self._index = index
        self._crank.setRotation(f.crank_deg[index])
        self._lever.setRotation(f.lever_deg[index])
        self._block_a.setPos(joints[0, 0], joints[0, 1])
        self._block_a.setRotation(f.lever_deg[index])
        self._block_b.setPos(joints[1, 0], joints[1, 1])
        if f.rod_deg is not None:
            self._rod.setPos(joints[1, 0], joints[1, 1])
            self._rod.setRotation(f.rod_deg[index])
        self.ram.setX(f.ram_x[index])
        # Within one stroke the tip moves straight and monotonically, so the stroke ends
        # and the current point are the whole travelled polyline.
        vertices = f.tip[[0, *f.corners[f.corners < index], index]]
        path = QPainterPath(QPointF(*vertices[0]))
        for x, y in vertices[1:]:
            path.lineTo(x, y)
        self._path_done.setPath(path)
        return True

    # ---- read back -----------------------------------------------------
    def obstacles(self) -> list[Box]:
        """Joint names and pin markers as drawn now, mm: where no other label may go."""
        boxes = [text_box(label) for label in self.labels.values() if label.isVisible()]
        for pin in self.pins.values():
            if pin.isVisible():
                r, x, y = 0.5 * pin.rect().width(), pin.x(), pin.y()
                boxes.append((x - r, x + r, y - r, y + r))
        return boxes

    def joints(self) -> dict[str, tuple[float, float]]:
        return {name: (pin.x(), pin.y()) for name, pin in self.pins.items() if pin.isVisible()}

    def link_ends(self, model: DesignModel) -> dict[str, tuple[float, float]]:
        design = model.design
        ends = {"crank": (self._crank, design.crank), "lever": (self._lever, design.lever)}
        if design.rod is not None:
            ends["rod"] = (self._rod, design.rod)
        out = {}
        for name, (item, length) in ends.items():
            point = item.mapToParent(QPointF(length, 0.0))
            out[name] = (point.x(), point.y())
        return out

    def tool_path(self) -> tuple[np.ndarray, np.ndarray]:
        path = self._path_done.path()
        pts = [path.elementAt(i) for i in range(path.elementCount())]
        return np.array([p.x for p in pts]), np.array([p.y for p in pts])

    def ram_extent(self) -> tuple[float, float]:
        """x of the ram body's rear and front ends as drawn now, mm."""
        r = self.ram.mapRectToParent(self.ram.path().boundingRect())
        return r.left(), r.right()
