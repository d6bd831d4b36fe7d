"""The mechanism sketch: the shaper drawn to scale (mm) at the current crank angle.

The widget assembles three layers over one pyqtgraph view with a locked aspect
ratio — the mechanism (mechanism.py), its dimensions
(dimensions.py) and the optional force arrows (forces.py) — and
exports them (image_export.py). Per design it rebuilds the layers and fits
once; per animation frame it only asks each shown layer to move. Its bar and menu
are built in controls.py; when a new design is fitted, refit.py decides; the paints the
labels wait for are watched by paint_timer.py, and label_view.py reads the view for them.

A frame's labels are placed when the frame is first shown and kept for the design and
zoom (labels.py), so a cycle played twice searches once. An edit's new mechanism is
painted first, its labels placed in the turn after that paint (the previous ones kept
till then; read-backs place them first: issue 40 item 5). Nothing is placed ahead while
idle: that placed every frame of the cycle (361, or 3601 at 0.1°) after each edit and
zoom whether or not the animation ever ran, and its chunks landed inside the window's
first paint, first visits and edits; one frame's placement takes a few ms, and
playback runs on wall-clock time, so a slow frame skips angles instead of slowing
the motion (issue 43 item 4; docs/performance.md).

Navigation: wheel zooms, drag pans, double-click fits, right click opens the
scheme's own menu (Fit, Show dimensions, Show forces). pyqtgraph's English menu
and its export dialog (whose SVG export fails on recent Qt) are not offered.
"""
from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import QEvent, QPointF, QRectF, QTimer
from PySide6.QtGui import QPainter
from PySide6.QtWidgets import QMenu, QVBoxLayout, QWidget

from shaperapp.design.model import DesignModel
from shaperapp.widgets.view_parts import fill_speed_combo

from .controls import SchemeControls
from .dimensions import DimensionLayer
from .draw import WHITE, canvas
from .forces import FORCE_NAMES, ForceLayer  # noqa: F401  (FORCE_NAMES: public names)
from .label_view import label_bounds, label_window, view_key
from .labels import LabelLayout
from .mechanism import Geometry, MechanismLayer
from .paint_timer import PaintTimer
from .readback import SchemeReadBack
from .refit import needs_fit

LABELS_LATE_MS = 100     # a rebuild's labels wait this long for its paint (a scheme not drawn on screen)


class SchemeWidget(SchemeReadBack, QWidget):
    """The shaper mechanism drawn to scale at ``model.angle_index``; zoom, pan, fit, export."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._design = None
        self._geometry: Geometry | None = None
        self._stale = self._angle_stale = True     # a hidden scheme (closed dock) waits
        self._fitted: QRectF | None = None         # the view the last fit showed
        self._opened = False                       # a file was opened: fit at the rebuild
        self._placed_view: tuple = ()              # the view the labels were last placed for
        self._labels_stale = False                 # placing them waits until shown or read back
        self._placing_soon = False                 # a rebuild or placement under way places them at its end
        self._forces_stale = False
        self._update_timer = QTimer(self, singleShot=True, interval=0)
        self._update_timer.timeout.connect(self._update)
        self._plot = canvas()
        # a show's labels are placed as the plot paints, a rebuild's in the turn after, a
        # language's once the new texts are laid out
        self._paints = PaintTimer(self._plot.viewport(), self._catch_up, self._labels_due, LABELS_LATE_MS, self)
        self._view = self._plot.getPlotItem().getViewBox()

        controls = self._controls = SchemeControls(self, self.fit, self.set_dimensions_visible,
                                                   self._apply_forces_visible, self._force_speed_chosen)
        self.fit_action, self.dimensions_action = controls.fit_action, controls.dimensions_action
        self.forces_action, self._menu = controls.forces_action, controls.menu
        self._force_speed_box = controls.speed_box
        self._view.menu_handler = lambda pos: self._menu.popup(pos.toPoint())
        self._view.sigFitRequested.connect(self.fit)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(0)
        layout.addLayout(controls.bar)
        layout.addWidget(self._plot, 1)

        add = self._plot.addItem
        self._mechanism = MechanismLayer(add, self)
        self._dimensions = DimensionLayer(add, self)
        self._forces = ForceLayer(add, self._view, self)
        self._labels = LabelLayout(add, self._mechanism, self._dimensions, self._forces, self)
        self._view.sigTransformChanged.connect(self._zoomed)     # text is screen-sized
        self._retranslate()
        model.resultsChanged.connect(self._on_results)
        model.angleChanged.connect(self._on_angle)
        model.forcesChanged.connect(self._on_forces)
        model.loaded.connect(self._on_loaded)
        self._on_results()

    # ---- public ------------------------------------------------------
    def fit(self) -> None:
        """Show the whole mechanism, its travel and its dimensions."""
        if self._geometry is not None:
            if not self._stale and self._crank_side() != self._dimensions.crank_side:
                self._dimensions.crank_side = self._crank_side()     # L1 along the crank drawn
                self._dimensions.update(self._model, self._geometry)
                self._dimensions_placed()
            self._view.setRange(self._fit_rect(), padding=0.04)
            self._view.updateMatrix()     # now, not while preparing a paint (a second paint)
            self._fitted = self._view.viewRect()

    def _crank_side(self) -> float:
        """-1 when the crank is drawn pointing left of O2, +1 right: the limit position
        whose tangent point L1 is drawn to."""
        frames = self._mechanism.frames
        if frames is None or not len(frames.tip):
            return self._dimensions.crank_side
        pin = self._mechanism.joint_at("A", min(self._model.angle_index, len(frames.tip) - 1))
        return 1.0 if pin[0] > self._geometry.o2[0] else -1.0

    def _refit_for(self, before: QRectF | None) -> None:
        """After a new design (``before``: the previous one's drawing): fitted or kept as
        refit.needs_fit decides."""
        opened, self._opened = self._opened, False
        if needs_fit(opened, before, self._geometry.fit_rect, self._view.viewRect(), self._fitted,
                     self._fit_rect()):
            self.fit()

    def _on_loaded(self) -> None:
        self._opened = True

    def _fit_rect(self) -> QRectF:
        """The drawing, with the force arrows' reach over the cycle while they are shown."""
        rect = self._geometry.fit_rect
        forces = self._forces.extent(self._model, self._geometry) if self.forces_visible() else None
        return rect if forces is None else rect.united(forces)

    def set_dimensions_visible(self, visible: bool) -> None:
        """Show or hide the dimension lines (L1, L2, L3, h, H)."""
        self.dimensions_action.setChecked(visible)
        self._dimensions.set_visible(visible)
        self._dimensions_placed()

    def _dimensions_placed(self) -> None:
        """Every label placed again for the dimensions as they now are."""
        if self._geometry is not None and not self._stale:
            self._place_still()
            self._draw_forces(self._model.angle_index)

    def _place_still(self, hidden_too: bool = False) -> None:
        """The still labels placed for the view as it is now. While the scheme is not on
        screen (the window being built, a closed dock) they are only marked, and placed when
        it is shown or read back (``_catch_up``): each placement is a search of tens of ms,
        and the window's construction placed them twice for views that its first layout
        then changed, before the first paint (issue 43 item 5)."""
        if not (hidden_too or self.isVisible()):
            self._labels_stale = True
            return
        if self._placing_soon:
            return
        self._placing_soon = True
        try:        # reading the view brings its pending matrix up to date, whose signal zooms
            key = self._view_key()
        finally:
            self._placing_soon = False
        self._labels_stale = False
        self._placed_view = key
        view = self._view.viewRect()
        self._labels.place_still(self._view.viewPixelSize(), label_bounds(self._fit_rect(), view),
                                 label_window(view))

    def _view_key(self) -> tuple:
        return view_key(self._view.viewRect(), self._view.viewPixelSize())

    def _zoomed(self, *_) -> None:
        """The texts keep their size on screen: their size in mm changed, so they are placed
        again. pyqtgraph also reports an unchanged transform (a paint after labels moved):
        that costs nothing, or every frame would search and rasterise again."""
        if self._view_key() == self._placed_view:
            return
        self._dimensions.separate_chain_labels()
        if not self._paints.waiting():      # else due after the paint, for the view then
            self._dimensions_placed()

    def dimensions_visible(self) -> bool:
        return self.dimensions_action.isChecked()

    def set_forces_visible(self, visible: bool) -> None:
        """Show or hide the force arrows (chosen crank speed, current angle)."""
        if self.forces_action.isChecked() != bool(visible):
            self.forces_action.setChecked(bool(visible))     # → _apply_forces_visible

    def forces_visible(self) -> bool:
        return self.forces_action.isChecked()

    def set_force_speed(self, index: int) -> None:
        """Draw the forces at crank speed ``index`` of model.rpms (the first by default)."""
        self._force_speed_box.setCurrentIndex(index)

    def force_speed(self) -> int:
        return self._forces.speed

    def _force_speed_chosen(self, index: int) -> None:
        if index >= 0 and index != self._forces.speed:
            self._forces.speed = index
            self._draw_forces(self._model.angle_index)

    def export_image(self, path: str) -> None:
        """Write the sketch as PNG (at least 1600 px wide), another raster type Qt writes,
        or SVG, chosen by the suffix. ValueError for an unknown type, OSError for a missing
        or unwritable folder; nothing is written then."""
        from shaperapp.widgets.image_export import export_scene   # QtSvg: not before the first paint
        self._catch_up()
        source = self._plot.getPlotItem().sceneBoundingRect()
        export_scene(self._plot.scene(), source, path, self.tr("Shaper mechanism"), WHITE)

    def svg_bytes(self) -> bytes:
        """The SVG :meth:`export_image` writes, in memory (for the report)."""
        from shaperapp.widgets.image_export import scene_svg
        self._catch_up()
        return scene_svg(self._plot.scene(), self._plot.getPlotItem().sceneBoundingRect(),
                         self.tr("Shaper mechanism"), WHITE)

    def export_point(self, x_mm: float, y_mm: float) -> QPointF:
        """Where the design point (x, y) (mm, the frame of ``core.linkage.geometry``) lies in the
        picture ``export_image`` writes now, in its px: for marks drawn over it."""
        self._catch_up()
        item = self._plot.getPlotItem()
        return item.getViewBox().mapViewToScene(QPointF(x_mm, y_mm)) - item.sceneBoundingRect().topLeft()

    def render(self, painter: QPainter, target: QRectF) -> None:
        """Paint the sketch as shown into ``target`` of any QPainter (vector output)."""
        from shaperapp.widgets.image_export import render_scene
        self._catch_up()
        source = self._plot.getPlotItem().sceneBoundingRect()
        render_scene(self._plot.scene(), source, painter, target, WHITE)

    def plot_widget(self) -> pg.PlotWidget:
        return self._plot

    def context_menu(self) -> QMenu:
        """The menu a right click opens."""
        return self._menu

    # ---- Qt ----------------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self._controls.retranslate(self._model.rpms)
        self._plot.setToolTip(self.tr("Wheel: zoom, drag: pan, double-click: fit, right click: menu"))
        self._forces.retranslate()
        if self._geometry is not None:
            self._dimensions.update(self._model, self._geometry)
            # placed once the window has laid out its new texts, which may change the view:
            # placed here at once, the search ran for the old view, then again for the new
            # (hidden, when shown or read back, as before)
            self._labels_stale = True
            if self.isVisible():
                self._paints.after_relayout()      # the stale labels, for the view as laid out then

    # ---- model → layers ----------------------------------------------
    def showEvent(self, event) -> None:
        """The labels wait for the plot's paint: at a first start the docks get their sizes
        after this (``Docks.apply_sizes``), and a search here was redone (40-50 ms)."""
        super().showEvent(event)
        self._update()
        self._paints.at_next_paint()

    def _catch_up(self) -> None:
        """Bring the scheme and its labels up to the model: when shown after being hidden,
        and before any read-back or export."""
        self._update()
        if self._labels_stale and not self._stale and self._geometry is not None:
            self._paints.cancel()
            self._place_still(hidden_too=True)
            self._draw_forces(self._model.angle_index)

    def labels_settled(self) -> bool:
        """The labels are placed for the model and view (not waiting for a paint or a show)."""
        return not (self._stale or self._labels_stale)

    def _update(self) -> None:
        """After an edit (once for its results, forces and angle signals): the mechanism,
        dimensions and arrows; a rebuild's labels wait for the turn after the paint."""
        self._update_timer.stop()
        if self._stale:
            self._rebuild()
        elif self._angle_stale:
            self._move(self._model.angle_index)
        elif self._forces_stale:
            self._draw_forces(self._model.angle_index)

    def _labels_due(self) -> None:
        """The turn after a rebuild's paint (a newer rebuild still due waits for its own)."""
        if not self._stale and self.isVisible():
            self._catch_up()

    def _schedule(self) -> None:
        """One rebuild when the model has announced everything an edit changed."""
        if self.isVisible() or self._geometry is None:
            self._update_timer.start()

    def _on_results(self) -> None:
        """Rebuilt after the edit if shown, else when shown: a closed dock does nothing."""
        self._stale = True
        if self._geometry is None:
            self._rebuild()
        else:
            self._schedule()

    def _rebuild(self) -> None:
        """Rebuild every layer for the design; fit once per new design, before the force
        labels are placed (they keep a distance in pixels)."""
        self._stale = False
        fill_speed_combo(self._force_speed_box, self._model.rpms)   # keeps the speed if still there
        self._forces.speed = max(self._force_speed_box.currentIndex(), 0)
        before = None if self._geometry is None else self._geometry.fit_rect
        self._geometry = self._mechanism.rebuild(self._model)
        self._dimensions.crank_side = self._crank_side()
        later = self.isVisible()              # placed after the paint: meanwhile where they were
        kept = self._dimensions.placed_centres() if later and self._placed_view else {}
        self._dimensions.update(self._model, self._geometry)
        for name, centre in kept.items():
            self._dimensions.move_label(name, centre)
        self._labels.rebuild()
        design = self._model.design
        if design != self._design:
            self._design = design
            self._placing_soon = True       # the fit's zoom places nothing: placed once, below
            try:
                self._refit_for(before)
            finally:
                self._placing_soon = False
        if later:
            self._labels_stale = True
            self._paints.after_next_paint()
        else:
            self._place_still()
        self._move(self._model.angle_index)

    def _on_angle(self, index: int) -> None:
        """Only moves items (setPos/setRotation/setPath): no Python-side signal per frame.
        While a rebuild is pending it places the mechanism itself."""
        if self._stale or (not self.isVisible() and self._geometry is not None):
            self._angle_stale = True
            return
        self._move(index)

    def _move(self, index: int) -> None:
        self._angle_stale = False
        if self._mechanism.show(index):
            self._draw_forces(index)

    def _on_forces(self) -> None:
        """Loads or the design changed: redrawn after the edit if shown, else when shown."""
        self._forces_stale = True
        self._schedule()

    def _apply_forces_visible(self, visible: bool) -> None:
        self._forces.set_visible(visible)
        if visible and self._geometry is not None and not self._stale:
            # A view showing the whole mechanism widens to the arrows; a zoomed one stays.
            view = self._view.viewRect()
            if view.contains(self._geometry.fit_rect) and not view.contains(self._fit_rect()):
                self.fit()
        self._draw_forces(self._model.angle_index)

    def _draw_forces(self, index: int) -> None:
        if self._stale:            # never on the previous design's geometry: the rebuild draws
            return
        self._forces_stale = False
        if self._geometry is None:
            return
        if self.forces_visible():
            self._forces.draw(index, self._model, self._geometry)
        if not self._labels_stale:      # else placed with the still labels, after the paint
            caption = self._forces.caption_item()
            reserved = () if caption is None else (self._screen_box(caption),)
            self._labels.place_frame(index, self._view.viewPixelSize(), reserved)
