"""The plot stack's items as made and labelled: its canvas, each plot's axis titles, each
group's legend entries, and which plot a scene point falls in.

Functions of the items they make or read, apart from the stack's widget (signals, hidden
redraws, layout, export), which calls them; none keeps state.
"""
from __future__ import annotations

from collections.abc import Iterable, Mapping

import pyqtgraph as pg
from PySide6.QtCore import QPointF
from PySide6.QtGui import QColor
from PySide6.QtWidgets import QGraphicsView

from shaperapp.widgets.style import TEXT

from .curves import LEGEND_WIDTH, PlotSlots
from .stack_layout import axis_title

LegendEntry = tuple[str, str, QColor, float]     # label, short label, colour, sample width


def stack_canvas() -> pg.GraphicsLayoutWidget:
    """The view the plots are stacked in: white, 4 px between rows, and one repaint of the
    rectangle around all changes."""
    view = pg.GraphicsLayoutWidget()
    view.setBackground("w")
    view.ci.setSpacing(4)
    # pyqtgraph's 9 px above and below the plots: 12 px the lowest plot's x ticks lacked
    # at 1280 × 720 in Chinese with 16 speeds
    view.ci.setContentsMargins(9, 3, 9, 3)
    # One repaint of the rectangle around all changes: a frame's changes (cursors and
    # dots) lie in one narrow strip, and Qt's default repaints every curve once per
    # small dirty rectangle instead (measured 5-10× slower per frame and per edit).
    view.setViewportUpdateMode(QGraphicsView.ViewportUpdateMode.BoundingRectViewportUpdate)
    return view


def label_plot(plot: PlotSlots) -> None:
    """The plot's y title from its series (the name over the unit), in the current language."""
    series = plot.series
    plot.item.setLabel("left", axis_title(series.title(), series.unit),
                       color=TEXT.name(), **{"font-size": "9pt"})


def label_x_axis(plot: PlotSlots, x_axis: tuple[str, bool]) -> None:
    """The plot's x title and whether its ticks step in degrees, ``x_axis`` = (title, degrees)."""
    title, degrees = x_axis
    plot.item.getAxis("bottom").set_degree_steps(degrees)
    plot.item.setLabel("bottom", title, color=TEXT.name(), **{"font-size": "9pt"})


def legend_entries(plots: Iterable[PlotSlots], group: str) -> dict[str, LegendEntry]:
    """The legend of ``group``'s plots: one entry per label of their curves that have one,
    the first curve's, by label."""
    entries: dict[str, LegendEntry] = {}
    for plot in plots:
        if plot.series.group == group:
            for curve in plot.curves:
                if curve.legend and curve.label not in entries:
                    entries[curve.label] = (curve.label, curve.short or curve.label,
                                            curve.colour, max(curve.width, LEGEND_WIDTH))
    return entries


def plot_at(plots: Mapping[str, PlotSlots], shown: Mapping[str, bool],
            scene_pos: QPointF) -> tuple[str, float] | None:
    """The shown plot whose view box holds ``scene_pos`` and the x there, in plot units."""
    for key, plot in plots.items():
        if shown[key] and plot.item.vb.sceneBoundingRect().contains(scene_pos):
            return key, float(plot.item.vb.mapSceneToView(scene_pos).x())
    return None
