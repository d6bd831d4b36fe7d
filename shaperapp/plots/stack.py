"""Synchronized cycle plots: one component, configured by each view with its series.

A view (kinematics, forces) describes what to draw as a list of ``Series`` (key,
unit, translated name and axis title, and a function of the model giving the
curves) and answers a few questions through ``StackSource`` (shaded bands,
legend keys, the x axis, where the cursor is). The stack does the rest the same
way for every view: stacked plots with linked x axes, one cursor per plot (one
per speed where each speed has its own x), a dot on every curve at the cursor,
legends that wrap, bands with labels, the mouse read-out, navigation and fit,
and image export.

Plot items are created once (stack_items.py) and fed with ``setData``, so a design
change redraws in a few milliseconds and the animation only moves cursors and dots.
While the stack is hidden (a tab in the background) it redraws nothing: it
catches up when shown, or when one of its read-back methods is called.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence

import pyqtgraph as pg
from PySide6.QtCore import QEvent, QObject, QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QGraphicsScene, QVBoxLayout, QWidget

from shaperapp.design.model import DesignModel
from shaperapp.widgets.lazy import lay_out_page
from shaperapp.widgets.scroll import vertical_scroll

from .axes import cache_static, styled_plot_item
from .curves import PlotSlots, finite_range
from .legend import GroupLegend
from .readout import Readout
from .series import Series, StackSource
from .stack_bar import StackBar
from .stack_items import label_plot, label_x_axis, legend_entries, plot_at, stack_canvas
from .stack_layout import (fit_axis_widths, fit_heights, fitted_y, legends_beside, place_rows,
                           plots_height, show_x_values, shown_groups)

class PlotStack(QWidget):
    """Stacked, x-linked cycle plots of one view (see the module docstring)."""

    clicked = Signal(float)          # x of a left click in a plot, in plot units

    def __init__(self, model: DesignModel, source: StackSource, series: Sequence[Series],
                 export_title: Callable[[], str], parent: QWidget | None = None,
                 hidden: Sequence[str] = ()) -> None:
        super().__init__(parent)
        self._model, self._source, self._series = model, source, list(series)
        self._export_title = export_title
        self._stale = self._cursor_stale = True
        self._hidden: set[str] = set()                   # labels switched off in a legend
        self._x_range = (0.0, 1.0)
        self._x_axis: tuple[str, bool] | None = None

        self._view = stack_canvas()
        self._view.installEventFilter(self)
        if self._series[0].key in hidden:
            raise ValueError(f"the first plot ({self._series[0].key!r}) carries the x axis and stays shown")
        # A plot hidden at first (the lever's) is built when first shown or asked for: a
        # pyqtgraph plot takes several milliseconds to make, at every start (issue 24).
        self._plots: dict[str, PlotSlots] = {}
        self._shown = {s.key: s.key not in hidden for s in self._series}
        # one legend per group (a comprehension over the series made one per series and
        # kept the last: five legends of the kinematics' six were built for nothing)
        self._legends = {group: GroupLegend(self._on_legend_toggle)
                         for group in dict.fromkeys(s.group for s in self._series)}
        self._side = False                               # legends beside their plots
        for key in [s.key for s in self._series if self._shown[s.key]]:
            self._build_plot(key)
        self._plots[self._series[0].key].item.vb.sigXRangeChanged.connect(self._fit_y)
        self._cache_static(True)

        self._bar = StackBar(self, self.fit, self._set_box_zoom)
        self.fit_action, self.box_zoom_action, self._menu = self._bar.fit_action, self._bar.box_zoom, self._bar.menu
        self._readout = Readout(model, source, self._series[0].key, lambda key: self._plots[key],
                                lambda group: self._legends[group].title(),
                                lambda: not self._stale)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(0)
        layout.addLayout(self._bar)
        self._scroll = vertical_scroll()
        self._scroll.setWidget(self._view)          # the view's events, filtered here, read _scroll
        self._scroll.viewport().installEventFilter(self)
        layout.addWidget(self._scroll, 1)
        layout.addWidget(self._readout)

        scene = self._view.scene()
        scene.contextMenu = []                   # no pyqtgraph "Export..." anywhere
        scene.sigMouseClicked.connect(self._on_click)
        self._mouse_proxy = pg.SignalProxy(scene.sigMouseMoved, rateLimit=60,
                                           slot=self._on_mouse_moved)
        model.angleChanged.connect(self._on_angle)
        self._relayout()
        self.retranslate()

    # ---- configuration by the view -------------------------------------
    def add_tool(self, widget: QWidget) -> None:
        """Put a view's control in the bar above the plots (left of the Fit button)."""
        self._bar.add_tool(widget)

    def add_menu_action(self, action: QAction) -> None:
        self._menu.addAction(action)

    def set_plot_visible(self, key: str, visible: bool) -> None:
        if key == self._series[0].key and not visible:
            raise ValueError(f"the first plot ({key!r}) carries the x axis and stays shown")
        if self._shown[key] != visible:
            self._shown[key] = visible
            if key not in self._plots:
                self._build_plot(key)
            self._relayout()
            self._fit_y()

    def _build_plot(self, key: str) -> PlotSlots:
        """Make one plot, x-linked to the first, labelled, drawn when next refreshed."""
        series = next(s for s in self._series if s.key == key)
        plot = PlotSlots(styled_plot_item(0.0), series)
        first = self._series[0].key
        if key != first:
            plot.item.setXLink(self._plots[first].item)
        plot.item.vb.sigFitRequested.connect(self.fit)
        plot.item.vb.menu_handler = self._show_menu
        self._plots[key] = plot
        self._plots = {s.key: self._plots[s.key] for s in self._series if s.key in self._plots}
        label_plot(plot)
        if self._x_axis is not None:                    # built after the first refresh
            label_x_axis(plot, self._x_axis)
            cache_static([plot.item], True)
            self._stale = True
            if self.isVisible():
                self.refresh()
        return plot

    def plot_visible(self, key: str) -> bool:
        return self._shown[key]

    def retranslate(self) -> None:
        """Texts from the series and the source again; the view calls this on a language
        change, after its own texts (the series' names read them)."""
        self.fit_action.setText(self.tr("Fit all"))
        self.fit_action.setToolTip(self.tr("Show the whole cycle again (or double-click a plot)"))
        self.box_zoom_action.setText(self.tr("Drag zooms to a box"))
        self.box_zoom_action.setToolTip(self.tr("Left drag: zoom to a box; off: pan"))
        self._view.setToolTip(self.tr(
            "Wheel: zoom x; wheel over an axis: zoom y; drag: zoom to a box; "
            "double-click: fit; click: set the crank angle; right click: menu"))
        self._readout.retranslate()
        for plot in self._plots.values():
            label_plot(plot)
        self._fit_heights()
        self._stale = True
        if self.isVisible():
            self.refresh()

    # ---- model → plots --------------------------------------------------
    def invalidate(self) -> None:
        """The model's results changed: redraw now if shown, else when shown."""
        self._stale = True
        if self.isVisible():
            self.refresh()

    def refresh(self) -> None:
        """Redraw every curve, band, legend and the x axis from the model, then fit."""
        self._stale = False
        source, model = self._source, self._model
        for plot in self._plots.values():
            plot.draw(plot.series.curves(model), self._hidden)
        bands, first = source.bands(), self._series[0].key
        added = False                       # new items, to be drawn from pixmaps too
        for key, plot in self._plots.items():
            added |= plot.set_bands(bands, labelled=key == first)
        keys, titles, units = source.legend_keys(), source.group_titles(), source.legend_units()
        for group, legend in self._legends.items():
            entries = legend_entries(self._plots.values(), group)
            self._hidden &= set(entries) | {c.label for p in self._plots.values() for c in p.curves}
            added |= legend.set_entries(list(entries.values()), keys.get(group, []), self._hidden)
            legend.set_title(titles.get(group, ""))
            legend.set_unit(units.get(group, ""))
        x_title, lo, hi, degrees = source.x_axis()
        if (x_title, degrees) != self._x_axis:      # relabelling re-lays out every axis
            self._x_axis = (x_title, degrees)
            for plot in self._plots.values():
                label_x_axis(plot, self._x_axis)
            self._show_x_axis()
        self._x_range = (lo, hi)
        if added:
            self._cache_static(True)
        self._fit_legends()
        self._fit_heights()
        self.fit(settle=True)
        self._cursor_stale = True
        self._on_angle(model.angle_index)
        self._readout.update_text()

    def fit(self, settle: bool = False) -> None:
        """Whole cycle in x, every plot's curves in y (drops the user's zoom). ``settle``
        (after an edit) keeps a y range that still fits well (see stack_layout.fitted_y)."""
        for plot in self._plots.values():
            plot.item.vb.y_zoomed = False
        master = self._plots[self._series[0].key].item
        master.setXRange(*self._x_range, padding=0.0)
        self._fit_y(settle=settle)

    def _fit_y(self, *_: object, settle: bool = False) -> None:
        """Fit y of each shown plot to its visible curves within the shown x range, unless
        the user zoomed that plot's y. Done by hand, once: pyqtgraph's auto-range would
        re-range (and repaint) on every cursor move."""
        x0, x1 = self._plots[self._series[0].key].item.vb.viewRange()[0]
        for key, plot in self._plots.items():
            if not self._shown[key] or plot.item.vb.y_zoomed:
                continue
            lo, hi = finite_range(plot.visible_values(x0, x1))
            y_range = fitted_y(lo, hi, tuple(plot.item.vb.viewRange()[1]), settle)
            if y_range is not None:
                plot.item.vb.setYRange(*y_range, padding=0.0)
                # now, not in the next paint's preparation, which would cost a second paint
                plot.item.vb.updateMatrix()
            plot.place_band_labels()
        fit_axis_widths(p.item for key, p in self._plots.items() if self._shown[key])

    def _on_angle(self, index: int) -> None:
        """Only cursors and dots move with the animation; nothing while hidden."""
        if not self.isVisible() and not self._cursor_stale:
            self._cursor_stale = True
        if not self.isVisible():
            return
        self._cursor_stale = False
        xs = self._source.cursor_x(index)
        for key, plot in self._plots.items():
            if self._shown[key]:
                plot.move_cursor(xs)
        self._readout.follow_cursor(index)

    def _on_legend_toggle(self, label: str, shown: bool) -> None:
        self._hidden = (self._hidden - {label}) if shown else (self._hidden | {label})
        for plot in self._plots.values():
            plot.apply_hidden(self._hidden)
        self._cursor_stale = True
        self._on_angle(self._model.angle_index)
        self._readout.update_text()

    # ---- layout ---------------------------------------------------------
    def _relayout(self) -> None:
        """Legend heads and shown plots, top to bottom; x values only under the lowest."""
        self._place_rows()
        self._fit_heights()
        # An emptied layout shrank the central item to its minimum: back to the view's size.
        self._view.ci.setGeometry(self._view.range)
        self._show_x_axis()
        self._cursor_stale = True
        if self.isVisible():
            self._on_angle(self._model.angle_index)

    def _place_rows(self) -> None:
        self._last = place_rows(self._view.ci, self._series, self._shown,
                                {g: legend.head for g, legend in self._legends.items()}, self._plots,
                                self._side)

    def _show_x_axis(self) -> None:
        show_x_values(self._plots, self._last)

    def _fit_legends(self) -> None:
        for legend in self._legends.values():
            legend.fit_width(self._view.width())

    def _fit_heights(self) -> None:
        if self._stale:     # the refresh due (at the show or a read-back) fits them, once:
            return          # before the first paint the window's layout fitted them 8 times
        fit_heights(self._view, self._plots.values())
        if self._place_legends():
            fit_heights(self._view, self._plots.values())

    def _place_legends(self) -> bool:
        """Legends above their plots, or beside them where above they would push the
        lowest plot below the pane and beside they would not (16 speeds on a 1280×720
        screen pushed the acceleration plot half out of the window); whether the
        layout changed."""
        groups = shown_groups(self._series, self._shown, self._plots)
        # the pane as tall as it is with the read-out at its most lines: a read-out that
        # wraps when the mouse moves over another plot must not move the legends
        readout = self._readout
        port = self._scroll.viewport().height() - max(0, min(readout.maximumHeight(), 4 * readout.height())
                                                      - readout.height())
        side = legends_beside(self._view.ci, groups, self._legends, self._view.width(), port)
        changed = side != self._side
        if changed:
            self._side = side
            for legend in self._legends.values():
                legend.set_side(side)
            self._place_rows()
            self._view.ci.setGeometry(self._view.range)
            self._show_x_axis()
            if not side:
                self._fit_legends()
        if side:
            for group, plots in groups.items():
                self._legends[group].fit_side(plots_height(self._view.ci, plots))
        return changed or side

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        if (watched is self._scroll.viewport() and event.type() == QEvent.Type.Resize
                and event.oldSize().height() != event.size().height()):
            self._fit_heights()             # taller or shorter: the legends above or beside
        if watched is self._view and event.type() == QEvent.Type.Resize:
            self._fit_legends()
            if event.oldSize().width() != event.size().width():    # legends re-wrapped
                self._fit_heights()
            for plot in self._plots.values():
                plot.place_band_labels()
        return super().eventFilter(watched, event)

    def showEvent(self, event) -> None:
        super().showEvent(event)
        if self._stale:
            lay_out_page(self)
            self.refresh()
        elif self._cursor_stale:
            self._on_angle(self._model.angle_index)

    def _set_box_zoom(self, on: bool) -> None:
        mode = pg.ViewBox.RectMode if on else pg.ViewBox.PanMode
        for plot in self._plots.values():
            plot.item.vb.setMouseMode(mode)

    def _show_menu(self, screen_pos: QPointF) -> None:
        self._menu.popup(screen_pos.toPoint())

    # ---- mouse and read-out --------------------------------------------
    def _on_click(self, event) -> None:
        if event.button() != Qt.MouseButton.LeftButton or event.isAccepted() or event.double():
            return
        hit = plot_at(self._plots, self._shown, event.scenePos())
        if hit is not None:
            self.clicked.emit(hit[1])

    def _on_mouse_moved(self, args: tuple) -> None:
        self._readout.hover(plot_at(self._plots, self._shown, args[0]))

    # ---- read back and export -----------------------------------------
    def ensure_current(self) -> None:
        """Catch up now with the model if hidden changes are pending."""
        if self._stale:
            self.refresh()
        if self._cursor_stale:
            xs = self._source.cursor_x(self._model.angle_index)
            for key, plot in self._plots.items():
                plot.move_cursor(xs)
            self._cursor_stale = False

    def is_current(self) -> bool:
        """Whether everything drawn matches the model (False while hidden changes wait)."""
        return not self._stale and not self._cursor_stale

    def plot(self, key: str) -> PlotSlots:
        if key not in self._plots:
            self._build_plot(key)
        self.ensure_current()
        return self._plots[key]

    def legend(self, group: str) -> GroupLegend:
        self.ensure_current()
        return self._legends[group]

    def readout_text(self) -> str:
        """The read-out as plain text (spaces for non-breaking ones, no word joiners)."""
        return self._readout.plain_text()

    def export_view(self) -> tuple[QGraphicsScene, QRectF, str, Callable[[bool], None]]:
        """What an export draws, brought up to date: the scene, the plots' rectangle in it,
        the title, and the switch that turns the items' caching off while exporting."""
        self.ensure_current()
        return (self._view.scene(), self._view.ci.sceneBoundingRect(), self._export_title(),
                lambda exporting: self._cache_static(not exporting))

    def _cache_static(self, on: bool) -> None:
        cache_static([p.item for p in self._plots.values()] + [g.head for g in self._legends.values()], on)
