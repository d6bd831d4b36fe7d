"""The scheme's force layer: core's joint forces as arrows, to one length scale.

The optional layer (off by default) draws the joint forces of core's
kinetostatics (``model.dynamics``) at one crank speed (the first unless chosen) as arrows on the
mechanism: one length scale per design, arrow heads of a fixed size in mm. Its
geometry for every crank angle is prepared once per solution; a frame only
rebuilds one small path and moves a few labels, and nothing at all while the
layer is hidden. Magnitude labels keep off the joint names, pins and dimension
labels (the scheme passes them as obstacles).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from PySide6.QtCore import QObject, QPointF, QRectF
from PySide6.QtGui import QColor, QFont, QPainterPath
from PySide6.QtWidgets import QGraphicsItem

from shaperapp.design.model import DesignModel
from shaperapp.widgets.style import FORCE

from .draw import Pair, Tag, Z_BLOCK, Z_LABEL, body, pen
from .mechanism import PIN_FIXED, PIN_MOVING, Geometry
from .place import Obstacles

FORCE_NAMES = ("O2", "A", "O4", "B", "C", "guide", "cut")
FORCE_SHARE = 0.35         # the cycle's largest force is drawn about this many L3 long
FORCE_HEAD = 0.04          # arrow head length in L3 (shorter only on arrows shorter than 1.7 heads)
FORCE_HEAD_HALF = 0.3      # half-width of an arrow head per head length
FORCE_LABEL_GAP = 0.4      # gap between an arrow's free end and its label, u
LABEL_ROOM = 3.0           # room kept beside the arrows' reach for their labels when fitting, u
FORCE_ZERO = 1e-9          # a force below this share of the largest one is not drawn
Z_FORCE = Z_BLOCK + 0.5    # over links and blocks, under the pin markers
Z_FORCE_LABEL = Z_LABEL + 1
FORCE_LABEL_FILL = QColor(255, 255, 255, 210)
_COMPASS = tuple((math.cos(math.radians(a)), math.sin(math.radians(a))) for a in range(0, 360, 45))


@dataclass(frozen=True)
class ForceFrames:
    """The force arrows for every crank-angle index, prepared once per dynamics solution.

    ``coords[i, k]`` holds, for force ``FORCE_NAMES[k]`` at index ``i``, in mm: the
    arrow's start, the end of its shaft, its tip, the two back corners of its head
    and its free end, where the label goes (12 numbers).
    """

    source: object              # the model.dynamics these were built from
    geometry: object            # ... on this scheme geometry (the tool point's offset)
    coords: np.ndarray          # (n, k, 12)
    shown: np.ndarray           # (n, k) bool: drawn at that index
    magnitude: np.ndarray       # (n, k) N
    outward: np.ndarray         # (n, k, 2) unit direction away from the arrow at its free end
    mm_per_N: float             # the one length scale; NaN when every force is zero
    ref_force_N: float          # the caption's round force ...
    ref_mm: float               # ... and its length, mm
    unit_N: float               # 1000 (labels in kN) or 1 (labels in N)
    rpm: float
    speed: int                  # index of that crank speed in model.rpms


def label_spots(x: float, y: float, ox: float, oy: float, gap: float):
    """Where a label may go beside the free end (x, y) of an arrow pointing out along
    (ox, oy): straight on first, then the compass directions nearest to it, then the
    same farther out; each as (x, y, anchor x, anchor y) with the box on that side."""
    directions = [(ox, oy)] + sorted(_COMPASS, key=lambda e: -(e[0] * ox + e[1] * oy))
    for distance in (gap, 3.0 * gap, 6.0 * gap, 10.0 * gap):
        for ex, ey in directions:
            m = max(abs(ex), abs(ey))
            yield x + ex * distance, y + ey * distance, 0.5 - 0.5 * ex / m, 0.5 + 0.5 * ey / m


def nice_scale(largest_N: float, target_mm: float) -> tuple[float, float, float]:
    """(mm per N, round force F_ref = 10^k N, its length 10…100 mm rounded to whole mm).

    The largest force then lands within 5 % of ``target_mm``.
    """
    exact = target_mm / largest_N
    ref = 10.0 ** math.ceil(math.log10(10.0 / exact) - 1e-12)
    length = float(round(exact * ref))
    return length / ref, ref, length


def build_force_frames(model: DesignModel, g: Geometry, speed: int = 0) -> ForceFrames | None:
    """Every force arrow at every crank angle of speed ``speed`` (an index of
    model.rpms), from model.dynamics."""
    dyn, design, sh = model.dynamics, model.design, model.motion.shape
    n = sh.phi.size
    if dyn.crank_angle.size != n:
        return None
    s = speed
    u = g.u
    a, b, c = sh.crank_pin.T, sh.lever_tip.T, sh.ram_joint.T
    zero = np.zeros(n)

    def vec(x, y) -> np.ndarray:
        """(n, 2) from x and y, each an (n,) array or a constant."""
        return np.stack([zero + x, zero + y], axis=1)

    # The guide's resultant is drawn only where its line of action crosses the ram;
    # outside (or NaN) the guide carries essentially a couple, which no arrow shows.
    offset = dyn.guide_offset_mm[s]
    on_ram = np.isfinite(offset) & (offset >= g.ram_rear) & (offset <= g.ram_front)
    guide_x = c[:, 0] + np.where(on_ram, offset, 0.0)
    pin_o, pin_m = PIN_FIXED * u, PIN_MOVING * u
    rod_c = (c, vec(dyn.c_x[s], dyn.c_y[s])) if dyn.c_x is not None else (c, vec(0.0, 0.0))
    forces = {  # name: (point of application, force on the body in N, pin radius there)
        "O2": (vec(g.o2[0], g.o2[1]), vec(dyn.o2_x[s], dyn.o2_y[s]), pin_o),
        "A": (a, vec(dyn.a_x[s], dyn.a_y[s]), pin_m),
        "O4": (vec(0.0, 0.0), vec(dyn.o4_x[s], dyn.o4_y[s]), pin_o),
        "B": (b, -vec(dyn.b_x[s], dyn.b_y[s]), pin_m),
        "C": (*rod_c, pin_m),
        "guide": (vec(guide_x, g.guide), vec(0.0, dyn.guide_normal[s]), 0.0),
        "cut": (vec(c[:, 0] + g.tip_dx, g.tip_y), vec(-dyn.cut_force[s], 0.0), 0.0),
    }
    point = np.stack([forces[k][0] for k in FORCE_NAMES])          # (k, n, 2)
    force = np.stack([forces[k][1] for k in FORCE_NAMES])
    rim = np.array([forces[k][2] for k in FORCE_NAMES])[:, None, None]
    # Arrows start at their pin's rim and point away from it, except: the cutting force
    # ends at the tool point, and the rod's forces at B and C lie on the far side of
    # their pin from the rod (ending at the pin when they pull toward the rod), so
    # they never run along the rod itself.
    tip_at_point = np.zeros(force.shape[:2], dtype=bool)
    tip_at_point[FORCE_NAMES.index("cut")] = True
    if design.rod is not None:
        for name, other in (("B", c), ("C", b)):
            k = FORCE_NAMES.index(name)
            toward = np.einsum("ij,ij->i", force[k], other - point[k])
            tip_at_point[k] = toward > 0.0
    tip_at_point = tip_at_point[..., None]
    magnitude = np.hypot(force[..., 0], force[..., 1])            # (k, n)
    largest = float(np.max(magnitude))
    if not largest > 0.0 or not math.isfinite(largest):
        mm_per_N, ref, ref_mm = math.nan, math.nan, math.nan
        shown = np.zeros(magnitude.shape, dtype=bool)
        scale = 0.0
    else:
        mm_per_N, ref, ref_mm = nice_scale(largest, FORCE_SHARE * design.lever)
        shown = magnitude > FORCE_ZERO * largest
        shown[FORCE_NAMES.index("guide")] &= on_ram
        scale = mm_per_N
    arrow = force * scale                                          # (k, n, 2) mm
    length = magnitude * scale
    safe = np.where(length > 0.0, length, 1.0)[..., None]
    d = np.where(length[..., None] > 0.0, arrow / safe, np.array([1.0, 0.0]))
    normal = np.stack([-d[..., 1], d[..., 0]], axis=-1)
    head = np.minimum(FORCE_HEAD * design.lever, 0.6 * length)[..., None]
    start = np.where(tip_at_point, point - d * rim - arrow, point + d * rim)
    tip = start + arrow
    base = tip - d * head
    free = np.where(tip_at_point, start, tip)                     # the label's end
    out = np.where(tip_at_point, -d, d)
    coords = np.concatenate([
        start, tip - d * (0.6 * head), tip,
        base + normal * (FORCE_HEAD_HALF * head), base - normal * (FORCE_HEAD_HALF * head),
        free], axis=-1)                                            # (k, n, 12)
    return ForceFrames(
        source=dyn, geometry=g, coords=np.ascontiguousarray(coords.transpose(1, 0, 2)),
        shown=np.ascontiguousarray(shown.T), magnitude=np.ascontiguousarray(magnitude.T),
        outward=np.ascontiguousarray(out.transpose(1, 0, 2)), mm_per_N=mm_per_N,
        ref_force_N=ref, ref_mm=ref_mm, unit_N=1000.0 if largest >= 1000.0 else 1.0,
        rpm=float(dyn.rpm[s]), speed=s)


class ForceLayer(QObject):
    """One path for every shaft and head, one tag per force, a caption in the corner."""

    def __init__(self, add: Callable[[object], None], corner: QGraphicsItem,
                 parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.frames: ForceFrames | None = None
        self._names: list[str] = []
        self._pending: list = []        # the labels of the arrows last drawn, to be placed
        self._visible = False
        self.speed = 0                  # index of the crank speed drawn
        self._path = body(FORCE, Z_FORCE, pen(FORCE, 2.0))
        self._path.setVisible(False)
        add(self._path)
        tag_font = QFont()
        tag_font.setPointSize(9)
        tag_font.setBold(True)
        self._tags = [Tag(FORCE, FORCE_LABEL_FILL, tag_font, True) for _ in FORCE_NAMES]
        for tag in self._tags:
            tag.setZValue(Z_FORCE_LABEL)
            tag.setVisible(False)
            add(tag)
        caption_font = QFont()
        caption_font.setPointSize(9)
        self._caption = Tag(FORCE, FORCE_LABEL_FILL, caption_font, False)
        self._caption.setParentItem(corner)        # fixed in the view's top-left corner
        self._caption.setZValue(1e6)
        self._caption.setVisible(False)
        self.retranslate()

    def retranslate(self) -> None:
        self._formats = {1000.0: self.tr("{0:.1f} kN"), 1.0: self.tr("{0:.0f} N")}
        if self.frames is not None:
            self._show_caption()

    def set_visible(self, visible: bool) -> None:
        self._visible = visible
        self._path.setVisible(visible)
        self._caption.setVisible(visible)
        if not visible:
            for tag in self._tags:
                tag.setVisible(False)
            self._names = []
            self._pending = []

    def _current_frames(self, model: DesignModel, g: Geometry) -> ForceFrames | None:
        """The arrows of this design, geometry and speed, built when one of them changed."""
        ff = self.frames
        speed = min(max(self.speed, 0), len(model.dynamics.rpm) - 1)
        if ff is None or ff.source is not model.dynamics or ff.geometry is not g or ff.speed != speed:
            ff = self.frames = build_force_frames(model, g, speed)
            self._show_caption()
        return ff

    def extent(self, model: DesignModel, g: Geometry) -> QRectF | None:
        """Where the arrows reach over the whole cycle, mm, with room for their labels
        (None while hidden or without forces): Fit shows them all, the cutting force
        ahead of the tool included."""
        if not self._visible:
            return None
        ff = self._current_frames(model, g)
        if ff is None or not ff.shown.any():
            return None
        drawn = ff.coords[ff.shown]                                  # (m, 12)
        xs, ys = drawn[:, 0::2], drawn[:, 1::2]
        room = LABEL_ROOM * g.u
        return QRectF(QPointF(float(xs.min()) - room, float(ys.min()) - room),
                      QPointF(float(xs.max()) + room, float(ys.max()) + room))

    def draw(self, index: int, model: DesignModel, g: Geometry) -> None:
        """Put the prepared arrows of crank-angle ``index`` into the one force path; the
        labels wait for ``place_labels`` (the joint names are placed clear of the arrows
        first, the magnitudes then clear of both)."""
        self._pending = []
        if not self._visible:
            return
        ff = self._current_frames(model, g)
        names: list[str] = []
        path = QPainterPath()
        labels = self._pending
        if ff is not None and index < len(ff.shown):
            text = self._formats[ff.unit_N]
            rows = zip(FORCE_NAMES, self._tags, ff.coords[index].tolist(),
                       ff.shown[index].tolist(), ff.magnitude[index].tolist(),
                       ff.outward[index].tolist())
            for name, tag, row, shown, magnitude, outward in rows:
                if not shown:
                    tag.setVisible(False)
                    continue
                sx, sy, ex, ey, tx, ty, lx, ly, rx, ry, px, py = row
                path.moveTo(sx, sy)
                path.lineTo(ex, ey)
                path.moveTo(tx, ty)
                path.lineTo(lx, ly)
                path.lineTo(rx, ry)
                path.closeSubpath()
                names.append(name)
                labels.append((magnitude, tag, text.format(magnitude / ff.unit_N), px, py, outward))
        else:
            for tag in self._tags:
                tag.setVisible(False)
        self._names = names
        self._path.setPath(path)

    def lines(self, index: int) -> np.ndarray:
        """The arrows drawn at crank-angle ``index`` as segments (shaft, head), mm; none
        while hidden."""
        ff = self.frames
        if not self._visible or ff is None or index >= len(ff.shown):
            return np.empty((0, 2, 2))
        c = ff.coords[index][ff.shown[index]].reshape(-1, 6, 2)
        start, end, tip, left, right = (c[:, k] for k in range(5))
        return np.stack([np.stack(pair, axis=1) for pair in
                         ((start, end), (tip, left), (left, right), (right, tip))], axis=1).reshape(-1, 2, 2)

    def place_labels(self, u: float, mm_per_px: tuple[float, float], obstacles: Obstacles) -> None:
        """Put each magnitude label of the arrows drawn at its arrow's free end, or beside
        it, where it keeps clear of every line and label already placed (larger forces
        first); a label with no free spot is left out."""
        labels, self._pending = self._pending, []
        px_w, px_h = mm_per_px
        if not (px_w > 0.0 and px_h > 0.0):
            for _, tag, *_rest in labels:
                tag.setVisible(False)
            return
        gap = FORCE_LABEL_GAP * u
        for _, tag, text, fx, fy, (ox, oy) in sorted(labels, key=lambda item: -item[0]):
            w, h = tag.set_text(text)
            w, h = w * px_w, h * px_h
            spots = list(label_spots(fx, fy, ox, oy, gap))
            boxes = np.array([(cx - ax * w, cx - ax * w + w, cy + ay * h - h, cy + ay * h)
                              for cx, cy, ax, ay in spots])
            k = obstacles.first_clear(boxes)
            tag.setVisible(k >= 0)
            if k >= 0:
                cx, cy, ax, ay = spots[k]
                tag.move(cx, cy, (ax, ay))
                obstacles.add(boxes[k])

    def pending_key(self) -> tuple:
        """What the labels waiting to be placed say and where their arrows end: with the
        arrows' own lines, all a frame's placement depends on besides the drawing."""
        return tuple((text, fx, fy) for _, _, text, fx, fy, _ in self._pending)

    def label_state(self) -> list[tuple]:
        """The magnitude labels as placed now, for ``restore_labels``."""
        return [(tag, tag.isVisible(), tag.text(), tag.x(), tag.y(), tag.anchor()) for tag in self._tags]

    def restore_labels(self, state: list[tuple]) -> None:
        """Put the magnitude labels back as ``label_state`` saw them (a frame seen before)."""
        self._pending = []
        for tag, visible, text, x, y, anchor in state:
            tag.setVisible(visible)
            if visible:
                tag.set_text(text)
                tag.move(x, y, anchor)

    def _show_caption(self) -> None:
        ff = self.frames
        if ff is None:
            self._caption.place("", 6.0, 4.0, (0.0, 0.0))
            return
        rpm = f"{ff.rpm:g}"
        if not math.isfinite(ff.mm_per_N):
            text = self.tr("Forces at {0} r/min: all zero").format(rpm)
        else:
            if ff.ref_force_N >= 1000.0:
                force = self.tr("{0:g} kN").format(ff.ref_force_N / 1000.0)
            else:
                force = self.tr("{0:g} N").format(ff.ref_force_N)
            text = self.tr("Forces at {0} r/min, scale: {1:g} mm ≙ {2}").format(
                rpm, ff.ref_mm, force)
        self._caption.place(text, 6.0, 4.0, (0.0, 0.0))

    # ---- read back -----------------------------------------------------
    def drawn(self) -> dict[str, Pair]:
        """{name: (start, tip)} in mm of the arrows drawn now, read back from the path."""
        if not self._visible:
            return {}
        path = self._path.path()
        assert path.elementCount() == 6 * len(self._names)
        out = {}
        for k, name in enumerate(self._names):
            start, tip = path.elementAt(6 * k), path.elementAt(6 * k + 2)
            out[name] = ((start.x, start.y), (tip.x, tip.y))
        return out

    def labels(self) -> dict[str, str]:
        return {name: tag.text() for name, tag in zip(FORCE_NAMES, self._tags) if tag.isVisible()}

    def tags(self) -> dict[str, Tag]:
        """The shown magnitude labels by force name."""
        return {name: tag for name, tag in zip(FORCE_NAMES, self._tags) if tag.isVisible()}

    def caption(self) -> str:
        return self._caption.text() if self._caption.isVisible() else ""

    def caption_item(self):
        """The caption's item while it is shown (None otherwise): the view reads its box for
        the labels to keep off (it stands over the drawing in the view's corner)."""
        return self._caption if self._caption.isVisible() and self._caption.text() else None
