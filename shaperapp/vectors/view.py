"""Vector diagrams beside the scheme: velocity, acceleration and force polygons.

Follows the animation: at every crank angle the chosen polygon is computed by
``core.forces.polygons`` from the exact solution and drawn by the one painting
function (``polygon_paint.paint_polygon``) at true scale on screen (the
screen's millimetres), with a scale μ that is either chosen automatically —
the round value that fills the view at this position, as a student would
choose it for each drawing — or typed by the user.
"""
from __future__ import annotations

import math

from PySide6.QtCore import QEvent, QRectF, Qt, Signal
from PySide6.QtGui import QFontMetricsF, QPainter, QPaintEvent
from PySide6.QtWidgets import (QCheckBox, QComboBox, QFileDialog, QFrame, QLabel, QLineEdit,
                               QMessageBox, QScrollArea, QSizePolicy, QStyle, QToolButton, QWidget)

from core.forces.masses import masses_for_design
from core.forces.polygons import KINDS, Polygon, polygons
from shaperapp.design.model import DesignModel
from shaperapp.widgets.view_parts import bar_over_body, fill_speed_combo

from .export import export_polygon
from .paint import auto_scale, needed_height, paint_polygon, titles


class _Canvas(QWidget):
    """Paints the view's current polygon; all state lives in the view."""

    def __init__(self, view: "PolygonView") -> None:
        super().__init__(view)
        self._view = view
        self.setMinimumSize(200, 140)
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
        self.setAttribute(Qt.WidgetAttribute.WA_OpaquePaintEvent)

    def paintEvent(self, event: QPaintEvent) -> None:
        painter = QPainter(self)
        painter.fillRect(self.rect(), Qt.GlobalColor.white)
        self._view.paint(painter, self._view.canvas_rect())
        painter.end()


class PolygonView(QWidget):
    """Kind and speed selectors, the scale (auto or typed), the drawing and an export button."""

    scaleChanged = Signal()
    enlargeRequested = Signal()      # the window floats the pane large, or docks it again

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.model = model
        self._user_scale: dict[str, float | None] = {kind: None for kind in KINDS}
        self.kind_box = QComboBox()
        self.speed_box = QComboBox()
        self.auto_box = QCheckBox()
        self.auto_box.setChecked(True)
        self.scale_edit = QLineEdit()
        self.scale_edit.setFixedWidth(int(QFontMetricsF(self.font()).horizontalAdvance('0.00025')) + 16)
        self.scale_label = QLabel()
        self.unit_label = QLabel()
        self.export_button = QToolButton()      # an icon: the pane beside the scheme is narrow
        self.export_button.setIcon(self.style().standardIcon(QStyle.StandardPixmap.SP_DialogSaveButton))
        self.enlarge_button = QToolButton()
        self.enlarge_button.setIcon(self.style().standardIcon(QStyle.StandardPixmap.SP_TitleBarMaxButton))
        self.enlarge_button.clicked.connect(self.enlargeRequested)
        self.canvas = _Canvas(self)
        self._solved: tuple = (None, {}, None, None)      # (key, polygons, design, loads)
        self._stale = True
        # The canvas is at least as tall as its caption and whole legend (the acceleration
        # polygon's last rows were cut off in a short pane): the pane scrolls beyond that.
        self.scroll = QScrollArea()
        self.scroll.setWidgetResizable(True)
        self.scroll.setFrameShape(QFrame.Shape.NoFrame)
        self.scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.scroll.setWidget(self.canvas)
        bar_over_body(self, (self.kind_box, self.speed_box), self.export_button, self.scroll,
                      (self.scale_label, self.scale_edit, self.unit_label, self.auto_box,
                       self.enlarge_button))
        self.kind_box.currentIndexChanged.connect(self._on_kind)
        self.speed_box.currentIndexChanged.connect(lambda _: self._refresh())
        self.auto_box.toggled.connect(self._on_auto)
        self.scale_edit.editingFinished.connect(self._on_scale_edited)
        self.export_button.clicked.connect(self._export_dialog)
        model.resultsChanged.connect(self._on_results)
        model.forcesChanged.connect(self._on_results)
        model.angleChanged.connect(self._on_angle)
        self._retranslate()
        self._fill_speeds()
        self._show_scale()

    # ---- public ------------------------------------------------------------
    def kind(self) -> str:
        return KINDS[max(self.kind_box.currentIndex(), 0)]

    def set_kind(self, kind: str) -> None:
        self.kind_box.setCurrentIndex(KINDS.index(kind))

    def speed_index(self) -> int:
        return min(max(self.speed_box.currentIndex(), 0), len(self.model.rpms) - 1)

    def polygon(self, kind: str | None = None) -> Polygon:
        """The polygon at the animation's crank angle and the chosen speed."""
        kind = kind or self.kind()
        return self._polygons_at(self.model.crank_deg)[kind]

    def scale(self, kind: str | None = None) -> float:
        """μ in use: the typed one, else the automatic one for this cycle and view size."""
        kind = kind or self.kind()
        user = self._user_scale[kind]
        return user if user is not None else self._auto_scale(kind)

    def set_scale(self, kind: str, scale: float | None) -> None:
        """Fix μ for ``kind`` (unit per mm), or None for automatic."""
        if scale is not None and not (math.isfinite(scale) and scale > 0):
            raise ValueError("scale must be a positive number")
        self._user_scale[kind] = scale
        self._show_scale()
        self.canvas.update()
        self.scaleChanged.emit()

    def export_image(self, path: str) -> None:
        """Write the current polygon at true scale (μ per drawing mm) as PNG or SVG."""
        export_polygon(path, self.polygon(), self.scale())

    def paint(self, painter: QPainter, rect: QRectF) -> None:
        kind = self.kind()
        polygon = self.polygon(kind)
        scale = self.scale(kind)
        if self._user_scale[kind] is None and self.scale_edit.text() != f"{scale:g}":
            self.scale_edit.setText(f"{scale:g}")     # the automatic μ follows angle and size
        paint_polygon(painter, rect, polygon, scale, px_per_mm=self._px_per_mm(),
                      font=self.canvas.font(), title=False)

    # ---- internals ------------------------------------------------------------
    def _px_per_mm(self) -> float:
        return self.canvas.logicalDpiX() / 25.4

    def _polygons_at(self, crank_deg: float) -> dict[str, Polygon]:
        """The polygons of this position, solved once: a repaint asks for them for the
        automatic scale, the scale field and the drawing (the model replaces its design
        and loads objects when they change, so those are compared by identity)."""
        design, loads, rpm = self.model.design, self.model.masses, self.model.rpms[self.speed_index()]
        key = (rpm, crank_deg)
        if self._solved[0] != key or self._solved[2] is not design or self._solved[3] is not loads:
            masses = masses_for_design(design, loads)
            self._solved = (key, polygons(design, crank_deg, rpm, masses), design, loads)
        return self._solved[1]

    def _auto_scale(self, kind: str) -> float:
        """Round μ so that the polygon at this position fills the canvas at true scale."""
        metrics = QFontMetricsF(self.canvas.font(), self.canvas)
        return auto_scale(self.polygon(kind), self.canvas_rect(), metrics, self._px_per_mm(), title=False)

    def _fit_canvas(self) -> None:
        """The canvas' least height for this polygon at this width (see __init__)."""
        metrics = QFontMetricsF(self.canvas.font(), self.canvas)
        port = self.scroll.viewport()
        rect = QRectF(0.0, 0.0, port.width(), max(port.height(), 140)).adjusted(10, 8, -10, -8)
        need = needed_height(self.polygon(), metrics, rect, title=False) + 16
        self.canvas.setMinimumHeight(max(140, math.ceil(need)))

    def canvas_rect(self) -> QRectF:
        """Where the drawing goes: the canvas' visible height (a legend taller than that
        runs on below, where the pane scrolls)."""
        height = min(self.canvas.height(), max(self.scroll.viewport().height(), 140))
        return QRectF(0.0, 0.0, self.canvas.width(), height).adjusted(10, 8, -10, -8)

    def _on_angle(self, _: int) -> None:
        if self.isVisible():
            self._fit_canvas()          # a note appears at a limit position
        self.canvas.update()

    def _on_results(self) -> None:
        """New results: shown now if the view is visible, else when it is shown (the
        automatic scale needs the polygon: no work for a closed or tabbed-away view)."""
        self._stale = True
        if self.isVisible():
            self._catch_up()

    def _catch_up(self) -> None:
        if self._stale:
            self._stale = False
            self._fill_speeds()
            self._refresh()

    def showEvent(self, event) -> None:
        super().showEvent(event)
        self._catch_up()

    def _refresh(self) -> None:
        self._fit_canvas()
        self._show_scale()
        self.canvas.update()

    def resizeEvent(self, event) -> None:
        super().resizeEvent(event)
        self._fit_canvas()
        self._show_scale()

    def _fill_speeds(self) -> None:
        fill_speed_combo(self.speed_box, self.model.rpms)

    def _on_kind(self, _: int) -> None:
        self._fit_canvas()
        self._show_scale()
        self.canvas.update()

    def _on_auto(self, auto: bool) -> None:
        self.set_scale(self.kind(), None if auto else self.scale())

    def _on_scale_edited(self) -> None:
        try:
            value = float(self.scale_edit.text().replace(",", "."))
        except ValueError:
            value = -1.0
        if not (math.isfinite(value) and value > 0):
            self._show_scale()
            self.scale_edit.setToolTip(self.tr("The scale must be a positive number"))
            return
        self.set_scale(self.kind(), value)

    def _show_scale(self) -> None:
        kind = self.kind()
        symbol = {"velocity": "μv", "acceleration": "μa", "force": "μF"}[kind]
        unit = {"velocity": "(m/s)/mm", "acceleration": "(m/s²)/mm", "force": "N/mm"}[kind]
        self.scale_label.setText(symbol + " =")
        self.unit_label.setText(unit)
        auto = self._user_scale[kind] is None
        for w, value in ((self.auto_box, auto),):
            w.blockSignals(True)
            w.setChecked(value)
            w.blockSignals(False)
        self.scale_edit.setText(f"{self.scale(kind):g}")
        self.scale_edit.setReadOnly(auto)

    def _export_dialog(self) -> None:
        path, _ = QFileDialog.getSaveFileName(self, self.tr("Export vector diagram"),
                                              f"{self.kind()}-polygon.svg",
                                              self.tr("SVG drawing (*.svg);;PNG image (*.png)"))
        if not path:
            return
        try:
            self.export_image(path)
        except (OSError, ValueError) as exc:
            QMessageBox.warning(self, self.tr("Export vector diagram"),
                                self.tr("Could not write %1: %2").replace("%1", path)
                                .replace("%2", str(exc)))

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        index = self.kind_box.currentIndex()
        self.kind_box.blockSignals(True)
        self.kind_box.clear()
        names = titles()
        for kind in KINDS:
            self.kind_box.addItem(names[kind])
        self.kind_box.setCurrentIndex(max(index, 0))
        self.kind_box.blockSignals(False)
        self.auto_box.setText(self.tr("Automatic scale"))
        self.auto_box.setToolTip(self.tr("The round scale that fills the view at this position"))
        self.export_button.setText(self.tr("Export…"))
        self.export_button.setToolTip(self.tr("Save the diagram at true scale as SVG or PNG"))
        self.enlarge_button.setToolTip(self.tr(
            "Show the diagram in a large window, or dock it again; a typed scale μ is kept"))
        self._fill_speeds()
        self.canvas.update()
