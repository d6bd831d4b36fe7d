"""Where a plot stack puts its items and how much of each it shows: legend heads and
plots in rows, heights that make the stack scroll rather than squeeze, x values only
under the lowest plot, and y ranges that settle instead of jumping after an edit.

These are the stack's rules of arrangement, apart from its widget (signals, hidden
redraws, export), so that they can be read in one place; each takes the items it
arranges and keeps no state.
"""
from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence

import pyqtgraph as pg
from PySide6.QtCore import Qt

from .axes import AXIS_WIDTH
from .curves import PlotSlots
from .series import Series

Y_PADDING = 0.08         # share of the data's span added above and below when fitting y
# After an edit a plot keeps its y range while that still holds the curves with at least
# half the padding and is at most this much taller than a fresh fit: nudging an input
# does not make every axis jump (and redraw its ticks and grid).
SETTLE_SPAN = 1.25
# The least height of a plot's view box: room for three tick labels at the axis' closest
# spacing (plot_axes.MIN_LABELS); a plot is also at least as tall as its axis title is
# long. Where the pane is shorter than the plots need, the stack scrolls (16 speeds on a
# 1366×768 laptop gave each Forces plot 60 px, two ticks and titles running together).
MIN_PLOT_PX = 104
TITLE_MARGIN_PX = 8      # free space along the axis beyond a title's ends


def place_rows(layout: pg.GraphicsLayout, series: Sequence[Series], shown: Mapping[str, bool],
               heads: Mapping[str, pg.GraphicsWidget], plots: Mapping[str, PlotSlots]) -> str | None:
    """Empty ``layout``, then put each group's legend head over its shown plots, top to
    bottom; the key of the lowest shown plot (None if none is shown)."""
    for item in list(layout.items):
        layout.removeItem(item)
    row, group, last = 0, None, None
    for s in series:
        if not shown[s.key]:
            continue
        if s.group != group:
            group = s.group
            layout.addItem(heads[group], row=row, col=0)
            row += 1
        layout.addItem(plots[s.key].item, row=row, col=0)
        row += 1
        last = s.key
    return last


def show_x_values(plots: Mapping[str, PlotSlots], lowest: str | None) -> None:
    """Tick values and the x title only under the lowest shown plot; grids on all."""
    for key, plot in plots.items():
        bottom = plot.item.getAxis("bottom")
        bottom.setStyle(showValues=key == lowest)
        bottom.showLabel(key == lowest)


def fit_heights(view: pg.GraphicsLayoutWidget, plots: Iterable[PlotSlots]) -> None:
    """Each plot at least MIN_PLOT_PX and its title's length tall; the view at least
    as tall as its layout then needs, so the stack scrolls instead of squeezing."""
    for plot in plots:
        title = plot.item.getAxis("left").label.boundingRect().width() + 2 * TITLE_MARGIN_PX
        plot.item.vb.setMinimumHeight(max(MIN_PLOT_PX, math.ceil(title)))
    layout = view.ci.layout
    layout.invalidate()
    need = layout.effectiveSizeHint(Qt.SizeHint.MinimumSize).height()
    view.setMinimumHeight(math.ceil(need) + 2 * view.frameWidth())


def fit_axis_widths(items: Iterable[pg.PlotItem]) -> None:
    """One left-axis width for all ``items`` (so the stacked plots line up): at least
    AXIS_WIDTH, and wide enough that no title covers a tick label of its plot."""
    axes = [item.getAxis("left") for item in items]
    width = max([AXIS_WIDTH] + [math.ceil(axis.needed_width()) for axis in axes])
    for axis in axes:
        if axis.fixedWidth != width:
            axis.setWidth(width)


def fitted_y(lo: float, hi: float, shown: tuple[float, float],
             settle: bool) -> tuple[float, float] | None:
    """The y range for data spanning ``lo``..``hi`` (padded by Y_PADDING), or None to keep
    the ``shown`` range: only when ``settle`` (after an edit) and it still holds the data
    with half the padding and is at most SETTLE_SPAN times the fresh fit's height."""
    pad = Y_PADDING * (hi - lo)
    y0, y1 = shown
    if settle and y0 <= lo - pad / 2 and y1 >= hi + pad / 2 and y1 - y0 <= SETTLE_SPAN * (hi - lo + 2 * pad):
        return None
    return lo - pad, hi + pad
