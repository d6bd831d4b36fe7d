"""The mechanism sketch: the shaper drawn to scale (mm) at the current crank angle.

Every position comes from core (``model.motion.shape``, ``model.metrics`` and
``core.kinematics.shape`` at the limit angles); this module only chooses how
to draw them. Link bodies, pins and blocks are rigid shapes built once per
design in their own local frame, so an animation frame only moves them with
``setPos`` / ``setRotation`` using arrays prepared per design, and redraws
the travelled tool path from at most a handful of prepared points. No
pyqtgraph ``setData`` runs per frame: it is slower and, with PySide6 6.12,
every Python-side signal emit leaks a reference (see ``_on_angle``).

The optional force layer (``forces_action``, off by default) draws the joint
forces of core's kinetostatics (``model.dynamics``) at the first crank speed
as arrows on the same drawing: one length scale per design, arrow heads of a
fixed size in mm. Its geometry for every crank angle is prepared once per
solution; a frame only rebuilds one small path and moves a few labels, and
nothing at all while the layer is hidden.

Sizes that are not design data (bar widths, pins, the ram's height, the tool,
the supports) scale with the drawing unit ``u = L3 / 40`` so that any design
looks alike; they never change a dimension of the mechanism.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pyqtgraph as pg
from pyqtgraph.exporters import ImageExporter
from PySide6.QtCore import QEvent, QPointF, QRectF, Qt
from PySide6.QtGui import (QAction, QBrush, QColor, QFont, QPainter, QPainterPath, QPen,
                           QPolygonF)
from PySide6.QtSvg import QSvgGenerator
from PySide6.QtWidgets import (QCheckBox, QGraphicsEllipseItem, QGraphicsItem, QGraphicsPathItem,
                               QGraphicsRectItem, QGraphicsSimpleTextItem, QHBoxLayout,
                               QToolButton, QVBoxLayout, QWidget)

from core.kinematics import shape as core_shape

from .model import DesignModel
from .style import CURSOR, FORCE, FRAME, LINK, TOOL_PATH

EXPORT_WIDTH = 1600        # minimum width of an exported raster image, px
UNITS_PER_LEVER = 40.0     # drawing unit u = L3 / 40
RETURN_LIFT = 0.35         # the return stroke of the tool path is drawn this many u higher
LIMIT_TOL_DEG = 1e-6       # a grid angle this close to a limit position counts as on it
LINK_FILL = QColor(LINK.red(), LINK.green(), LINK.blue(), 38)
BLOCK_FILL = QColor(FRAME).lighter(150)
RAM_FILL = QColor(FRAME.red(), FRAME.green(), FRAME.blue(), 30)
PATH_LIGHT = QColor(TOOL_PATH.red(), TOOL_PATH.green(), TOOL_PATH.blue(), 90)
DIM = QColor(CURSOR)
WHITE = QColor("#ffffff")
Z_FRAME, Z_GHOST, Z_RAM, Z_PATH, Z_CRANK, Z_LEVER, Z_BLOCK, Z_JOINT, Z_DIM, Z_LABEL = range(10)
MOVING = ("A", "B", "C")
PIN_FIXED, PIN_MOVING = 0.5, 0.38   # pin marker radii, u
# Force layer: what is drawn, how long and where.
FORCE_NAMES = ("O2", "A", "O4", "B", "C", "guide", "cut")
FORCE_SHARE = 0.35         # the cycle's largest force is drawn about this many L3 long
FORCE_HEAD = 0.04          # arrow head length in L3 (shorter only on arrows shorter than 1.7 heads)
FORCE_HEAD_HALF = 0.3      # half-width of an arrow head per head length
FORCE_LABEL_GAP = 0.4      # gap between an arrow's free end and its label, u
FORCE_ZERO = 1e-9          # a force below this share of the largest one is not drawn
Z_FORCE = Z_BLOCK + 0.5    # over links and blocks, under the pin markers
Z_FORCE_LABEL = Z_LABEL + 1
FORCE_LABEL_FILL = QColor(255, 255, 255, 210)
Pair = tuple[tuple[float, float], tuple[float, float]]


def _pen(colour: QColor, width: float = 1.5, style: Qt.PenStyle = Qt.SolidLine) -> QPen:
    """A cosmetic pen: its width stays in screen pixels at any zoom."""
    pen = QPen(colour, width, style)
    pen.setCosmetic(True)
    return pen


def _stadium(length: float, width: float) -> QPainterPath:
    """A bar with round ends from (0, 0) to (length, 0) in its local frame."""
    path = QPainterPath()
    half = width / 2.0
    path.addRoundedRect(QRectF(-half, -half, length + width, width), half, half)
    return path


def _rect(x0: float, y0: float, x1: float, y1: float) -> QRectF:
    return QRectF(QPointF(min(x0, x1), min(y0, y1)), QPointF(max(x0, x1), max(y0, y1)))


def _body(fill: QColor, z: float, pen: QPen | None = None) -> QGraphicsPathItem:
    item = QGraphicsPathItem()
    item.setPen(pen or _pen(LINK, 1.4))
    item.setBrush(QBrush(fill))
    item.setZValue(z)
    return item


def _segments(pairs: list[Pair]) -> tuple[np.ndarray, np.ndarray]:
    """Point pairs → x, y arrays for a PlotDataItem with connect='pairs'."""
    pts = np.array([p for pair in pairs for p in pair], dtype=float).reshape(-1, 2)
    return pts[:, 0], pts[:, 1]


def _arrow_head(tip: np.ndarray, direction: np.ndarray, u: float) -> QPolygonF:
    """A filled arrow head in mm with its tip at ``tip``, pointing along ``direction``."""
    d = direction / np.hypot(*direction)
    n = np.array([-d[1], d[0]])
    base = tip - d * 0.9 * u
    pts = (tip, base + n * 0.22 * u, base - n * 0.22 * u, tip)
    return QPolygonF([QPointF(float(p[0]), float(p[1])) for p in pts])


@dataclass(frozen=True)
class _Frames:
    """Everything one animation frame needs, one row per crank-angle index."""

    joints: np.ndarray          # (n, k, 2) moving joints A, B[, C], mm
    crank_deg: np.ndarray       # (n,) rotation of the crank body about O2
    lever_deg: np.ndarray       # (n,) rotation of the lever body about O4
    rod_deg: np.ndarray | None  # (n,) rotation of the rod body about B
    ram_x: np.ndarray           # (n,) x of the ram's reference point C
    labels: np.ndarray          # (n, k, 2) where the labels A, B[, C] go
    tip: np.ndarray             # (n, 2) tool tip; the return stroke lifted by RETURN_LIFT·u
    corners: np.ndarray         # indices where the tool path turns (stroke ends), ascending


@dataclass(frozen=True)
class _ForceFrames:
    """The force arrows for every crank-angle index, prepared once per dynamics solution.

    ``coords[i, k]`` holds, for force ``FORCE_NAMES[k]`` at index ``i``, in mm: the
    arrow's start, the end of its shaft, its tip, the two back corners of its head
    and its free end, where the label goes (12 numbers).
    """

    source: object              # the model.dynamics these were built from
    coords: np.ndarray          # (n, k, 12)
    shown: np.ndarray           # (n, k) bool: drawn at that index
    magnitude: np.ndarray       # (n, k) N
    outward: np.ndarray         # (n, k, 2) unit direction away from the arrow at its free end
    mm_per_N: float             # the one length scale; NaN when every force is zero
    ref_force_N: float          # the caption's round force ...
    ref_mm: float               # ... and its length, mm
    unit_N: float               # 1000 (labels in kN) or 1 (labels in N)
    rpm: float


class _Tag(QGraphicsRectItem):
    """A short text on a light box, anchored at its position (anchor as pg.TextItem)."""

    PAD = 2.0

    def __init__(self, colour: QColor, fill: QColor, font: QFont, screen_fixed: bool) -> None:
        super().__init__()
        self.setPen(QPen(Qt.NoPen))
        self.setBrush(QBrush(fill))
        if screen_fixed:      # in the plot: text upright and the same size at any zoom
            self.setFlag(QGraphicsItem.ItemIgnoresTransformations, True)
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


_COMPASS = tuple((math.cos(math.radians(a)), math.sin(math.radians(a))) for a in range(0, 360, 45))


def _label_spots(x: float, y: float, ox: float, oy: float, gap: float):
    """Where a label may go beside the free end (x, y) of an arrow pointing out along
    (ox, oy): straight on first, then the compass directions nearest to it, then the
    same farther out; each as (x, y, anchor x, anchor y) with the box on that side."""
    directions = [(ox, oy)] + sorted(_COMPASS, key=lambda e: -(e[0] * ox + e[1] * oy))
    for distance in (gap, 3.0 * gap):
        for ex, ey in directions:
            m = max(abs(ex), abs(ey))
            yield x + ex * distance, y + ey * distance, 0.5 - 0.5 * ex / m, 0.5 + 0.5 * ey / m


def _nice_scale(largest_N: float, target_mm: float) -> tuple[float, float, float]:
    """(mm per N, round force F_ref = 10^k N, its length 10…100 mm rounded to whole mm).

    The largest force then lands within 5 % of ``target_mm``.
    """
    exact = target_mm / largest_N
    ref = 10.0 ** math.ceil(math.log10(10.0 / exact) - 1e-12)
    length = float(round(exact * ref))
    return length / ref, ref, length


@dataclass(frozen=True)
class _Dimension:
    """One dimension: line segments, arrow tips (pos, outward direction) and its text."""

    segments: list[Pair]
    arrows: list[Pair]
    text: str
    text_pos: tuple[float, float]
    anchor: tuple[float, float]
    angle: float = 0.0


def _anchor(normal: np.ndarray) -> tuple[float, float]:
    """Text anchor that puts a label on the ``normal`` side of its point (y up)."""
    return (0.5 - 0.5 * float(normal[0]), 0.5 + 0.5 * float(normal[1]))


def _linear_dim(p: np.ndarray, q: np.ndarray, normal: np.ndarray, offset: float,
                u: float, text: str, vertical_text: bool = False) -> _Dimension:
    """Dimension p–q with its line ``offset`` along the unit ``normal`` (0: no extension lines)."""
    a, b = p + normal * offset, q + normal * offset
    segments = [(tuple(a), tuple(b))]
    if offset > 0:
        segments += [(tuple(p + normal * 0.5 * u), tuple(a + normal * 0.6 * u)),
                     (tuple(q + normal * 0.5 * u), tuple(b + normal * 0.6 * u))]
    arrows = [(tuple(a), tuple(a - b)), (tuple(b), tuple(b - a))]
    mid = tuple((a + b) / 2.0 + normal * 0.3 * u)
    if vertical_text:
        return _Dimension(segments, arrows, text, mid, (0.5, 1.0), 90.0)
    return _Dimension(segments, arrows, text, mid, _anchor(normal))


class SchemeWidget(QWidget):
    """The shaper mechanism drawn to scale at ``model.angle_index``; zoom, pan, fit, export."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._frames: _Frames | None = None
        self._force_frames: _ForceFrames | None = None
        self._drawn_force_names: list[str] = []
        self._design = None
        self._fit_rect = QRectF()
        self._plot = pg.PlotWidget(background="w")
        self._plot.setAntialiasing(True)
        item = self._plot.getPlotItem()
        item.hideAxis("left")
        item.hideAxis("bottom")
        item.hideButtons()
        item.setMenuEnabled(False, True)     # keep the view's menu, drop "Plot Options"
        self._view = item.getViewBox()
        self._view.setAspectLocked(True, ratio=1.0)
        self._view.disableAutoRange()

        self.fit_action = QAction(self)
        self.fit_action.triggered.connect(self.fit)
        self.dimensions_action = QAction(self)
        self.dimensions_action.setCheckable(True)
        self.dimensions_action.setChecked(True)
        self.dimensions_action.toggled.connect(self.set_dimensions_visible)
        self._view.menu.addSeparator()
        self._view.menu.addAction(self.fit_action)
        self._view.menu.addAction(self.dimensions_action)
        self.forces_action = QAction(self)
        self.forces_action.setCheckable(True)
        self.forces_action.setChecked(False)
        self.forces_action.toggled.connect(self._apply_forces_visible)
        self._view.menu.addAction(self.forces_action)
        self._fit_button = QToolButton()
        self._fit_button.setDefaultAction(self.fit_action)
        self._dims_box = QCheckBox()
        self._dims_box.setChecked(True)
        self._dims_box.toggled.connect(self.dimensions_action.setChecked)
        self.dimensions_action.toggled.connect(self._dims_box.setChecked)
        self._forces_box = QCheckBox()
        self._forces_box.setObjectName("forcesBox")
        self._forces_box.setChecked(False)
        self._forces_box.toggled.connect(self.forces_action.setChecked)
        self.forces_action.toggled.connect(self._forces_box.setChecked)
        bar = QHBoxLayout()
        bar.setContentsMargins(4, 2, 4, 0)
        bar.addWidget(self._fit_button)
        bar.addWidget(self._dims_box)
        bar.addWidget(self._forces_box)
        bar.addStretch(1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(0)
        layout.addLayout(bar)
        layout.addWidget(self._plot, 1)

        self._create_items()
        self._retranslate()
        model.resultsChanged.connect(self._on_results)
        model.angleChanged.connect(self._on_angle)
        model.forcesChanged.connect(self._on_forces)
        self._on_results()

    # ---- public ------------------------------------------------------
    def fit(self) -> None:
        """Show the whole mechanism, its travel and its dimensions."""
        self._view.setRange(self._fit_rect, padding=0.04)

    def set_dimensions_visible(self, visible: bool) -> None:
        """Show or hide the dimension lines (L1, L2, L3, h, H)."""
        self.dimensions_action.setChecked(visible)
        for dim_item in self._dim_items():
            dim_item.setVisible(visible)

    def dimensions_visible(self) -> bool:
        return self.dimensions_action.isChecked()

    def set_forces_visible(self, visible: bool) -> None:
        """Show or hide the force arrows (first crank speed, current angle)."""
        if self.forces_action.isChecked() != bool(visible):
            self.forces_action.setChecked(bool(visible))     # → _apply_forces_visible

    def forces_visible(self) -> bool:
        return self.forces_action.isChecked()

    def drawn_forces(self) -> dict[str, Pair]:
        """The force arrows drawn now as {name: (start, tip)} in mm, read back from the drawn path.

        Names are those of ``FORCE_NAMES`` that are drawn: the arrow runs from start to
        tip along the force on the body named in core (see docs/forces.md): "O2" frame on
        crank, "A" block on lever, "O4" frame on lever, "B" rod or tip block on lever,
        "C" rod on ram, "guide" guide on ram, "cut" workpiece on tool. Every arrow starts
        at its point of application except "cut", whose tip touches the tool point.
        Empty while the layer is hidden.
        """
        if not self.forces_visible():
            return {}
        path = self._force_path.path()
        names = self._drawn_force_names
        assert path.elementCount() == 6 * len(names)
        out = {}
        for k, name in enumerate(names):
            start, tip = path.elementAt(6 * k), path.elementAt(6 * k + 2)
            out[name] = ((start.x, start.y), (tip.x, tip.y))
        return out

    def force_labels(self) -> dict[str, str]:
        """The magnitude labels next to the drawn force arrows."""
        return {name: tag.text() for name, tag in zip(FORCE_NAMES, self._force_tags)
                if tag.isVisible()}

    def force_caption(self) -> str:
        """The force layer's caption (speed and length scale); empty while hidden."""
        return self._force_caption.text() if self._force_caption.isVisible() else ""

    def export_image(self, path: str) -> None:
        """Write the sketch as PNG (at least 1600 px wide) or SVG, chosen by the suffix."""
        suffix = Path(path).suffix.lower()
        if suffix == ".svg":
            self._export_svg(str(path))
            return
        if suffix not in (".png", ".jpg", ".jpeg", ".bmp"):
            raise ValueError(self.tr("Cannot export to '{0}': use .png or .svg").format(suffix))
        exporter = ImageExporter(self._plot.getPlotItem())
        params = exporter.parameters()
        params["background"] = WHITE
        params["width"] = max(EXPORT_WIDTH, int(params["width"]))
        exporter.export(str(path))

    def _export_svg(self, path: str) -> None:
        """Render the plot's scene through QSvgGenerator.

        pyqtgraph 0.14's SVGExporter fails on the closed paths ("… Z") that
        recent Qt writes (pyqtgraph issue #3495), so the scene is rendered
        directly; items are switched to export mode so they paint vectors.
        """
        source = self._plot.getPlotItem().sceneBoundingRect()
        target = QRectF(0.0, 0.0, source.width(), source.height())
        generator = QSvgGenerator()
        generator.setFileName(path)
        generator.setSize(target.size().toSize())
        generator.setViewBox(target)
        generator.setTitle(self.tr("Shaper mechanism"))
        painter = QPainter(generator)
        items = [it for it in self._plot.scene().items() if hasattr(it, "setExportMode")]
        try:
            for it in items:
                it.setExportMode(True, {"antialias": True, "background": WHITE, "painter": painter})
            painter.setRenderHint(QPainter.Antialiasing)
            painter.fillRect(target, WHITE)
            self._plot.scene().render(painter, target, source)
        finally:
            for it in items:
                it.setExportMode(False)
            painter.end()

    def drawn_joints(self) -> dict[str, tuple[float, float]]:
        """Joint positions as the pin markers show them now, mm (for checks and tests)."""
        return {name: (pin.x(), pin.y()) for name, pin in self._pins.items() if pin.isVisible()}

    def drawn_link_ends(self) -> dict[str, tuple[float, float]]:
        """Where the far end of each moved link body lands now, mm (for checks and tests)."""
        design = self._model.design
        ends = {"crank": (self._crank, design.crank), "lever": (self._lever, design.lever)}
        if design.rod is not None:
            ends["rod"] = (self._rod, design.rod)
        out = {}
        for name, (body, length) in ends.items():
            point = body.mapToParent(QPointF(length, 0.0))
            out[name] = (point.x(), point.y())
        return out

    def dimension_labels(self) -> list[str]:
        """The texts of the dimension labels now drawn."""
        return [item.toPlainText() for item in self._dim_texts]

    def tool_path(self) -> tuple[np.ndarray, np.ndarray]:
        """Vertices of the travelled part of the tool-tip trace as drawn now, mm."""
        path = self._path_done.path()
        pts = [path.elementAt(i) for i in range(path.elementCount())]
        return np.array([p.x for p in pts]), np.array([p.y for p in pts])

    def plot_widget(self) -> pg.PlotWidget:
        return self._plot

    # ---- Qt ----------------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self.fit_action.setText(self.tr("Fit"))
        self.fit_action.setToolTip(self.tr("Zoom to show the whole mechanism"))
        self.dimensions_action.setText(self.tr("Show dimensions"))
        self._dims_box.setText(self.tr("Show dimensions"))
        self._dims_box.setToolTip(self.tr("Show the key dimensions L1, L2, L3, h and the stroke H"))
        self.forces_action.setText(self.tr("Show forces"))
        self._forces_box.setText(self.tr("Show forces"))
        self._forces_box.setToolTip(self.tr(
            "Show the joint forces at the first crank speed as arrows, to one scale"))
        self._force_formats = {1000.0: self.tr("{0:.1f} kN"), 1.0: self.tr("{0:.0f} N")}
        self._plot.setToolTip(self.tr("Wheel: zoom, drag: pan, right click: more"))
        if self._frames is not None:
            self._update_dimensions()
        if self._force_frames is not None and self.forces_visible():
            self._update_force_caption()
            self._draw_forces(self._model.angle_index)

    # ---- items, created once -----------------------------------------
    def _create_items(self) -> None:
        add = self._plot.addItem
        self._ground = pg.PlotDataItem(pen=_pen(FRAME, 1.2), connect="pairs")
        self._guide_line = pg.PlotDataItem(pen=_pen(FRAME, 1.0, Qt.DashDotLine))
        self._ghost_lines = pg.PlotDataItem(pen=_pen(FRAME, 1.0, Qt.DashLine), connect="pairs")
        self._circle = pg.PlotDataItem(pen=_pen(FRAME, 1.0, Qt.DashLine))
        self._path_all = pg.PlotDataItem(pen=_pen(PATH_LIGHT, 1.2))
        self._dim_lines = pg.PlotDataItem(pen=_pen(DIM, 1.0), connect="pairs")
        for z, it in ((Z_FRAME, self._ground), (Z_GHOST, self._guide_line),
                      (Z_GHOST, self._ghost_lines), (Z_GHOST, self._circle),
                      (Z_PATH, self._path_all), (Z_DIM, self._dim_lines)):
            it.setZValue(z)
            add(it)
        self._path_done = _body(QColor(0, 0, 0, 0), Z_PATH, _pen(TOOL_PATH, 2.6))
        self._path_done.setBrush(QBrush(Qt.NoBrush))
        self._ram = _body(RAM_FILL, Z_RAM)
        self._tool = _body(BLOCK_FILL, Z_RAM)
        self._tool.setParentItem(self._ram)
        self._crank = _body(LINK_FILL, Z_CRANK)
        self._lever = _body(LINK_FILL, Z_LEVER)
        self._block_a = _body(BLOCK_FILL, Z_BLOCK)
        self._block_b = _body(BLOCK_FILL, Z_BLOCK)
        self._rod = _body(LINK_FILL, Z_BLOCK)
        self._dim_heads = _body(DIM, Z_DIM, QPen(Qt.NoPen))
        self._pins: dict[str, QGraphicsEllipseItem] = {}
        for name in ("O4", "O2", *MOVING):
            pin = QGraphicsEllipseItem()
            pin.setPen(_pen(LINK, 1.5))
            pin.setBrush(QBrush(WHITE))
            pin.setZValue(Z_JOINT)
            self._pins[name] = pin
        for it in (self._path_done, self._ram, self._crank, self._lever, self._block_a,
                   self._block_b, self._rod, self._dim_heads, *self._pins.values()):
            add(it)
        font = QFont()
        font.setPointSize(11)
        font.setBold(True)
        font.setItalic(True)
        self._labels: dict[str, pg.TextItem] = {}
        for name, text in (("O2", "O\u2082"), ("O4", "O\u2084"), ("A", "A"), ("B", "B"), ("C", "C")):
            label = pg.TextItem(text, color=LINK, anchor=(0.5, 0.5))
            label.setFont(font)
            label.setZValue(Z_LABEL)
            add(label)
            self._labels[name] = label
        self._dim_texts = [pg.TextItem(color=DIM, fill=QColor(255, 255, 255, 200)) for _ in range(5)]
        for it in self._dim_texts:
            it.setZValue(Z_DIM)
            add(it)
        # Force layer: one path for every shaft and head, one tag per force, a caption.
        self._force_path = _body(FORCE, Z_FORCE, _pen(FORCE, 2.0))
        self._force_path.setVisible(False)
        add(self._force_path)
        tag_font = QFont()
        tag_font.setPointSize(9)
        tag_font.setBold(True)
        self._force_tags = [_Tag(FORCE, FORCE_LABEL_FILL, tag_font, True) for _ in FORCE_NAMES]
        for tag in self._force_tags:
            tag.setZValue(Z_FORCE_LABEL)
            tag.setVisible(False)
            add(tag)
        caption_font = QFont()
        caption_font.setPointSize(9)
        self._force_caption = _Tag(FORCE, FORCE_LABEL_FILL, caption_font, False)
        self._force_caption.setParentItem(self._view)     # fixed in the view's top-left corner
        self._force_caption.setZValue(1e6)
        self._force_caption.setVisible(False)

    def _dim_items(self) -> list:
        return [self._dim_lines, self._dim_heads, *self._dim_texts]

    # ---- per design --------------------------------------------------
    def _on_results(self) -> None:
        """Rebuild everything that depends on the design; fit once per new design."""
        design, motion, metrics = self._model.design, self._model.motion, self._model.metrics
        sh = motion.shape
        u = design.lever / UNITS_PER_LEVER
        a, b, c = sh.crank_pin.T, sh.lever_tip.T, sh.ram_joint.T
        o2 = np.array([0.0, design.frame])
        rod = design.rod is not None
        guide = design.guide
        # The ram's limit positions from core's measured metrics; the lever's from core's shape.
        self._limits = core_shape(design, np.radians([metrics.work_start_deg, metrics.work_end_deg]))
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
        ram.addRect(_rect(-rear, y_lo, front, y_hi))
        if not rod:
            ram.addRect(_rect(-0.8 * u, b_lo - block_half - 0.2 * u, 0.8 * u, b_hi + block_half + 0.2 * u))
            ram.setFillRule(Qt.OddEvenFill)
        self._ram.setPath(ram)
        self._ram.setPos(0.0, guide)
        tool, tip_local = self._tool_shape(front, y_lo, u)
        self._tool.setPath(tool)
        self._build_bodies(design, sh, u, block_half)
        self._frames = self._build_frames(design, motion, metrics, u, tip_local)
        self._labels["C"].setVisible(rod)
        self._pins["C"].setVisible(rod)

        # Static drawing: supports, guide way, crank circle, lever limits, tool path.
        x0, x1 = ram_lo - rear - 3.0 * u, ram_hi + front + 3.0 * u
        self._ground.setData(*_segments(self._support(np.zeros(2), u) + self._support(o2, u)
                                        + self._rail(x0, x1, guide + y_hi, u)))
        self._guide_line.setData([x0, x1], [guide, guide])
        self._ghost_lines.setData(*_segments([((0.0, 0.0), tuple(p)) for p in self._limits.lever_tip.T]))
        self._circle.setData(a[:, 0], a[:, 1])
        tip = self._frames.tip
        self._path_all.setData(tip[:, 0], tip[:, 1])
        self._pins["O4"].setPos(0.0, 0.0)
        self._pins["O2"].setPos(*o2)
        self._labels["O2"].setPos(o2[0] + 2.0 * u, o2[1] + 0.9 * u)
        self._labels["O4"].setPos(2.4 * u, 0.9 * u)

        chain = min(x0, float(a[:, 0].min()), float(b[:, 0].min()), -2.0 * u) - 2.5 * u
        self._geometry = dict(o2=o2, u=u, guide=guide, rail_left=x0, chain_x=chain,
                              tip_y=guide + tip_local[1], tip_lo=ram_lo + tip_local[0],
                              tip_hi=ram_hi + tip_local[0], tip_dx=tip_local[0],
                              ram_rear=-rear, ram_front=front)
        self._update_dimensions()
        bottom = min(-3.5 * u, guide + tip_local[1] - 6.0 * u)
        self._fit_rect = QRectF(QPointF(chain - 3.0 * u, bottom), QPointF(x1 + u, guide + y_hi + 1.5 * u))
        self._on_angle(self._model.angle_index)
        if design != self._design:
            self._design = design
            self.fit()

    def _build_bodies(self, design, sh, u: float, block_half: float) -> None:
        """Crank, slotted lever, blocks, rod and pins as shapes in their own frames."""
        self._crank.setPath(_stadium(design.crank, 1.1 * u))
        self._crank.setPos(0.0, design.frame)
        slot_lo = max(float(sh.slide.min()) - 1.6 * u, 0.9 * u)          # the block's travel
        slot_hi = min(float(sh.slide.max()) + 1.6 * u, design.lever - 0.9 * u)
        lever = _stadium(design.lever, 1.6 * u)
        lever.addRoundedRect(QRectF(slot_lo, -0.35 * u, slot_hi - slot_lo, 0.7 * u), 0.35 * u, 0.35 * u)
        lever.setFillRule(Qt.OddEvenFill)
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
            self._rod.setPath(_stadium(design.rod, 1.0 * u))
        for name, pin in self._pins.items():
            r = (PIN_FIXED if name.startswith("O") else PIN_MOVING) * u
            pin.setRect(QRectF(-r, -r, 2.0 * r, 2.0 * r))

    @staticmethod
    def _build_frames(design, motion, metrics, u: float, tip_local: tuple[float, float]) -> _Frames:
        """Per-index transforms and points, all from core's arrays."""
        sh = motion.shape
        a, b, c = sh.crank_pin.T, sh.lever_tip.T, sh.ram_joint.T
        rod = design.rod is not None
        o2 = np.array([0.0, design.frame])
        radial = (a - o2) / design.crank
        along = b / design.lever
        side = -1.0 if rod and design.rod_side == "leading" else 1.0   # B's label away from the rod
        across = side * np.stack([along[:, 1], -along[:, 0]], axis=1)
        labels = [a + 1.9 * u * radial, b + 2.0 * u * across]
        if rod:
            labels.append(c + np.array([0.0, -2.4 * u]))
        tip = np.stack([c[:, 0] + tip_local[0], np.full(len(c), design.guide + tip_local[1])], axis=1)
        # Return stroke: strictly between the limits (a limit on the grid counts as cutting).
        phase = (np.degrees(motion.crank_angle) - metrics.work_start_deg) % 360.0
        returning = (phase > metrics.work_angle_deg + LIMIT_TOL_DEG) & (phase < 360.0 - LIMIT_TOL_DEG)
        tip[returning, 1] += RETURN_LIFT * u
        turns = np.flatnonzero(returning[1:] != returning[:-1])
        return _Frames(
            joints=np.stack([a, b, c] if rod else [a, b], axis=1),
            crank_deg=np.degrees(np.arctan2(a[:, 1] - o2[1], a[:, 0] - o2[0])),
            lever_deg=90.0 - np.degrees(sh.lever),
            rod_deg=np.degrees(sh.rod) if rod else None, ram_x=c[:, 0],
            labels=np.stack(labels, axis=1), tip=tip,
            corners=np.unique(np.concatenate([turns, turns + 1])))

    @staticmethod
    def _tool_shape(front: float, y_lo: float, u: float) -> tuple[QPainterPath, tuple[float, float]]:
        """Tool post and bit hanging under the ram's front end; returns the shape and the tip."""
        path = QPainterPath()
        path.addRect(_rect(front - 2.6 * u, y_lo, front - 1.0 * u, y_lo - 2.0 * u))
        tip = (front - 0.7 * u, y_lo - 3.3 * u)
        bit = QPainterPath()
        bit.moveTo(front - 2.3 * u, y_lo - 2.0 * u)
        bit.lineTo(front - 1.0 * u, y_lo - 2.0 * u)
        bit.lineTo(*tip)
        bit.lineTo(front - 1.9 * u, y_lo - 2.9 * u)
        bit.closeSubpath()
        path.addPath(bit)
        return path, tip

    @staticmethod
    def _support(p: np.ndarray, u: float) -> list[Pair]:
        """A fixed pivot: triangle, ground line and hatching under ``p``."""
        x, y = float(p[0]), float(p[1])
        base = y - 2.0 * u
        pairs = [((x, y), (x - 1.2 * u, base)), ((x, y), (x + 1.2 * u, base)),
                 ((x - 2.0 * u, base), (x + 2.0 * u, base))]
        for hx in np.linspace(x - 1.7 * u, x + 2.0 * u, 6):
            pairs.append(((hx, base), (hx - 0.7 * u, base - 0.7 * u)))
        return pairs

    @staticmethod
    def _rail(x0: float, x1: float, y: float, u: float) -> list[Pair]:
        """The ram's guide way along its top: a line hatched on the frame side."""
        pairs = [((x0, y), (x1, y))]
        for hx in np.arange(x0, x1 - 0.6 * u, 1.4 * u):
            pairs.append(((hx, y), (hx + 0.7 * u, y + 0.7 * u)))
        return pairs

    def _update_dimensions(self) -> None:
        """Place the dimension lines for the current design; texts are translated here."""
        design, g = self._model.design, self._geometry
        u, o2, guide, chain = g["u"], g["o2"], g["guide"], g["chain_x"]
        left = np.array([-1.0, 0.0])
        # A vertical chain at the far left: L2 = O4O2, then h from O2 up to the guide line.
        p0, p1, p2 = np.array([chain, 0.0]), np.array([chain, o2[1]]), np.array([chain, guide])
        dims = [_linear_dim(p0, p1, left, 0.0, u, self.tr("L2 = {0:.1f}").format(design.frame), True),
                _linear_dim(p1, p2, left, 0.0, u,
                            self.tr("h = {0:.1f}").format(design.guide_above_crank), True)]
        reach = chain - 0.6 * u
        extensions: list[Pair] = [((-2.6 * u, 0.0), (reach, 0.0)),
                                  ((o2[0] - design.crank - 0.6 * u, o2[1]), (reach, o2[1])),
                                  ((g["rail_left"] - 0.3 * u, guide), (reach, guide))]
        # L3 beside the lever's rightmost limit position.
        tips = self._limits.lever_tip.T
        tip = tips[int(np.argmax(tips[:, 0]))]
        along = tip / np.hypot(*tip)
        dims.append(_linear_dim(np.zeros(2), tip, np.array([along[1], -along[0]]), 3.0 * u, u,
                                self.tr("L3 = {0:.1f}").format(design.lever)))
        # L1 as a radius of the crank circle, pointing down-left, away from the ram.
        d = np.array([-math.cos(math.radians(40)), -math.sin(math.radians(40))])
        end = o2 + d * design.crank
        dims.append(_Dimension([(tuple(o2), tuple(end))], [(tuple(end), tuple(d))],
                               self.tr("L1 = {0:.1f}").format(design.crank),
                               tuple(o2 + d * (design.crank + 0.4 * u)), _anchor(d)))
        # H between the tool tip's two limit positions, under the tool path.
        y = g["tip_y"]
        dims.append(_linear_dim(np.array([g["tip_lo"], y]), np.array([g["tip_hi"], y]),
                                np.array([0.0, -1.0]), 2.6 * u, u,
                                self.tr("H = {0:.1f}").format(self._model.metrics.stroke_mm)))
        self._dim_lines.setData(*_segments([s for dim in dims for s in dim.segments] + extensions))
        heads = QPainterPath()
        for tip_pos, direction in (arrow for dim in dims for arrow in dim.arrows):
            heads.addPolygon(_arrow_head(np.asarray(tip_pos), np.asarray(direction), u))
        self._dim_heads.setPath(heads)
        for item, dim in zip(self._dim_texts, dims):
            item.setText(dim.text)
            item.setAngle(dim.angle)
            item.setAnchor(dim.anchor)
            item.setPos(*dim.text_pos)

    # ---- per frame ---------------------------------------------------
    def _on_angle(self, index: int) -> None:
        """Move everything to crank-angle ``index`` with setPos/setRotation/setPath only.

        pyqtgraph's setData emits Python-side signals; with PySide6 6.12 on
        Python < 3.12 each emit drops a reference to True, so a per-frame
        setData would eventually crash a long animation. Plain QGraphicsItem
        calls emit nothing and are faster.
        """
        f = self._frames
        if f is None or index >= len(f.tip):
            return
        joints = f.joints[index]
        for name, (x, y) in zip(MOVING, joints):
            self._pins[name].setPos(x, y)
        for name, (x, y) in zip(MOVING, f.labels[index]):
            self._labels[name].setPos(x, y)
        self._crank.setRotation(f.crank_deg[index])
        self._lever.setRotation(f.lever_deg[index])
        self._block_a.setPos(joints[0, 0], joints[0, 1])
        self._block_a.setRotation(f.lever_deg[index])
        self._block_b.setPos(joints[1, 0], joints[1, 1])
        if f.rod_deg is not None:
            self._rod.setPos(joints[1, 0], joints[1, 1])
            self._rod.setRotation(f.rod_deg[index])
        self._ram.setX(f.ram_x[index])
        # Within one stroke the tip moves straight and monotonically, so the stroke ends
        # and the current point are the whole travelled polyline.
        vertices = f.tip[[0, *f.corners[f.corners < index], index]]
        path = QPainterPath(QPointF(*vertices[0]))
        for x, y in vertices[1:]:
            path.lineTo(x, y)
        self._path_done.setPath(path)
        if self.forces_action.isChecked():
            self._draw_forces(index)

    # ---- force layer -------------------------------------------------
    def _apply_forces_visible(self, visible: bool) -> None:
        self._force_path.setVisible(visible)
        self._force_caption.setVisible(visible)
        if visible:
            self._draw_forces(self._model.angle_index)
        else:
            for tag in self._force_tags:
                tag.setVisible(False)

    def _on_forces(self) -> None:
        """Loads or the design changed: redraw now if shown (rebuilt there), else later."""
        if self.forces_action.isChecked():
            self._draw_forces(self._model.angle_index)

    def _draw_forces(self, index: int) -> None:
        """Put the prepared arrows of crank-angle ``index`` into the one force path."""
        ff = self._force_frames
        if ff is None or ff.source is not self._model.dynamics:
            ff = self._force_frames = self._build_forces()
            self._update_force_caption()
        names: list[str] = []
        path = QPainterPath()
        labels = []
        if ff is not None and index < len(ff.shown):
            text = self._force_formats[ff.unit_N]
            rows = zip(FORCE_NAMES, self._force_tags, ff.coords[index].tolist(),
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
                labels.append((magnitude, tag, text.format(magnitude / ff.unit_N), px, py,
                               outward))
            self._place_force_labels(labels)
        else:
            for tag in self._force_tags:
                tag.setVisible(False)
        self._drawn_force_names = names
        self._force_path.setPath(path)

    def _place_force_labels(self, labels: list) -> None:
        """Put each magnitude label at its arrow's free end, or beside it, where it overlaps
        neither the joint names nor a label already placed (larger forces first); a label
        with no free spot is left out."""
        px_w, px_h = self._view.viewPixelSize()                 # mm per screen pixel
        if not (px_w > 0.0 and px_h > 0.0):
            for _, tag, *_rest in labels:
                tag.setVisible(False)
            return
        gap = FORCE_LABEL_GAP * self._geometry["u"]
        taken = []
        for label in self._labels.values():
            if label.isVisible():
                box, pos = label.boundingRect(), label.pos()
                w, h = 0.5 * box.width() * px_w, 0.5 * box.height() * px_h
                taken.append((pos.x() - w, pos.x() + w, pos.y() - h, pos.y() + h))
        for pin in self._pins.values():
            if pin.isVisible():
                r, x, y = 0.5 * pin.rect().width(), pin.x(), pin.y()
                taken.append((x - r, x + r, y - r, y + r))
        for _, tag, text, fx, fy, (ox, oy) in sorted(labels, key=lambda item: -item[0]):
            w, h = tag.set_text(text)
            w, h = w * px_w, h * px_h
            for cx, cy, ax, ay in _label_spots(fx, fy, ox, oy, gap):
                left, top = cx - ax * w, cy + ay * h
                box = (left, left + w, top - h, top)
                if not any(box[0] < t[1] and t[0] < box[1] and box[2] < t[3] and t[2] < box[3]
                           for t in taken):
                    tag.move(cx, cy, (ax, ay))
                    tag.setVisible(True)
                    taken.append(box)
                    break
            else:
                tag.setVisible(False)

    def _update_force_caption(self) -> None:
        ff = self._force_frames
        if ff is None:
            self._force_caption.place("", 6.0, 4.0, (0.0, 0.0))
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
        self._force_caption.place(text, 6.0, 4.0, (0.0, 0.0))

    def _build_forces(self) -> _ForceFrames | None:
        """Every force arrow at every crank angle of the first speed, from model.dynamics."""
        model, g = self._model, self._geometry
        dyn, design, sh = model.dynamics, model.design, model.motion.shape
        n = sh.phi.size
        if dyn.crank_angle.size != n or self._frames is None:
            return None
        u = g["u"]
        a, b, c = sh.crank_pin.T, sh.lever_tip.T, sh.ram_joint.T
        zero = np.zeros(n)

        def vec(x, y) -> np.ndarray:
            """(n, 2) from x and y, each an (n,) array or a constant."""
            return np.stack([zero + x, zero + y], axis=1)

        # The guide's resultant is drawn only where its line of action crosses the ram;
        # outside (or NaN) the guide carries essentially a couple, which no arrow shows.
        offset = dyn.guide_offset_mm[0]
        on_ram = np.isfinite(offset) & (offset >= g["ram_rear"]) & (offset <= g["ram_front"])
        guide_x = c[:, 0] + np.where(on_ram, offset, 0.0)
        pin_o, pin_m = PIN_FIXED * u, PIN_MOVING * u
        rod_c = (c, vec(dyn.c_x[0], dyn.c_y[0])) if dyn.c_x is not None else (c, vec(0.0, 0.0))
        forces = {  # name: (point of application, force on the body in N, pin radius there)
            "O2": (vec(g["o2"][0], g["o2"][1]), vec(dyn.o2_x[0], dyn.o2_y[0]), pin_o),
            "A": (a, vec(dyn.a_x[0], dyn.a_y[0]), pin_m),
            "O4": (vec(0.0, 0.0), vec(dyn.o4_x[0], dyn.o4_y[0]), pin_o),
            "B": (b, -vec(dyn.b_x[0], dyn.b_y[0]), pin_m),
            "C": (*rod_c, pin_m),
            "guide": (vec(guide_x, g["guide"]), vec(0.0, dyn.guide_normal[0]), 0.0),
            "cut": (vec(c[:, 0] + g["tip_dx"], g["tip_y"]), vec(-dyn.cut_force[0], 0.0), 0.0),
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
            mm_per_N, ref, ref_mm = _nice_scale(largest, FORCE_SHARE * design.lever)
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
        return _ForceFrames(
            source=dyn, coords=np.ascontiguousarray(coords.transpose(1, 0, 2)),
            shown=np.ascontiguousarray(shown.T), magnitude=np.ascontiguousarray(magnitude.T),
            outward=np.ascontiguousarray(out.transpose(1, 0, 2)), mm_per_N=mm_per_N,
            ref_force_N=ref, ref_mm=ref_mm, unit_N=1000.0 if largest >= 1000.0 else 1.0,
            rpm=float(dyn.rpm[0]))
