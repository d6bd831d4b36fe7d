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
from PySide6.QtGui import QFont, QFontMetricsF

from .axes import AXIS_WIDTH
from .curves import PlotSlots
from .legend import GroupLegend
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


def axis_title(title: str, unit: str) -> str:
    """A plot's y title (rich text): the name over the unit, and a name longer than a
    plot of MIN_PLOT_PX holds broken at its middle space, so that the title does not
    make its plot taller ("Ram displacement" made the plot 137 px tall, and with the
    acceleration's 130 px the lowest plot fell below a 1280 × 720 window)."""
    font = QFont()
    font.setPointSizeF(9.0)
    room = MIN_PLOT_PX - 2 * TITLE_MARGIN_PX
    if QFontMetricsF(font).horizontalAdvance(title) > room and " " in title.strip():
        spaces = [i for i, ch in enumerate(title) if ch == " "]
        cut = min(spaces, key=lambda i: abs(i - len(title) / 2))
        title = title[:cut] + "<br>" + title[cut + 1:]
    return f"{title}<br>({unit})"


def place_rows(layout: pg.GraphicsLayout, series: Sequence[Series], shown: Mapping[str, bool],
               heads: Mapping[str, pg.GraphicsWidget], plots: Mapping[str, PlotSlots],
               side: bool = False) -> str | None:
    """Empty ``layout``, then put each group's shown plots top to bottom, its legend head
    over them (``side``: beside them, on their rows); the key of the lowest shown plot
    (None if none is shown)."""
    for item in list(layout.items):
        layout.removeItem(item)
    groups: dict[str, list[str]] = {}
    for s in series:
        if shown[s.key]:
            groups.setdefault(s.group, []).append(s.key)
    row, last = 0, None
    for group, keys in groups.items():
        if side:
            layout.addItem(heads[group], row=row, col=1, rowspan=len(keys))
            layout.layout.setAlignment(heads[group], Qt.AlignmentFlag.AlignTop)
        else:
            layout.addItem(heads[group], row=row, col=0)
            row += 1
        for key in keys:
            layout.addItem(plots[key].item, row=row, col=0)
            row += 1
            last = key
    return last


def plots_height(layout: pg.GraphicsLayout, plots: Iterable[PlotSlots]) -> float:
    """The least height of the shown ``plots`` one under the other, with the layout's
    spacing and margins: what the stack needs without the legends above the plots."""
    items = [plot.item for plot in plots]
    _, top, _, bottom = layout.layout.getContentsMargins()
    spacing = layout.layout.verticalSpacing()
    return (top + bottom + spacing * max(len(items) - 1, 0)
            + sum(item.effectiveSizeHint(Qt.SizeHint.MinimumSize).height() for item in items))


def shown_groups(series: Sequence[Series], shown: Mapping[str, bool],
                 plots: Mapping[str, PlotSlots]) -> dict[str, list[PlotSlots]]:
    """The shown plots of each group, in the stack's order."""
    groups: dict[str, list[PlotSlots]] = {}
    for s in series:
        if shown[s.key] and s.key in plots:
            groups.setdefault(s.group, []).append(plots[s.key])
    return groups


BESIDE_MIN_WIDTH_PX = 420
"""The narrowest pane whose legends may stand beside its plots (at 260 and 330 px the lowest
plot was left one x tick label or none: test_tick_labels_never_overlap)."""


def legends_beside(layout: pg.GraphicsLayout, groups: Mapping[str, Sequence[PlotSlots]],
                   legends: Mapping[str, GroupLegend], width: float, port: float) -> bool:
    """Whether the legends go beside their plots: above them the stack would be taller
    than the pane (``port`` px). Also where even the plots alone are taller (the Forces
    tab's four plots in Chinese at 1366 × 768, 16 speeds): beside, the stack scrolls the
    least, and the lowest plot is the nearest to the pane (issue 40 chose that over the
    plots' full width). Decided from sizes that do not depend on where the legends are,
    so it never flips back and forth."""
    if width < BESIDE_MIN_WIDTH_PX:     # a narrow pane: beside, the plots would keep too
        return False                    # little width for two x tick labels
    need = plots_height(layout, [p for plots in groups.values() for p in plots])
    spacing = layout.layout.verticalSpacing()
    above = need + sum(legends[g].top_height(width) + spacing for g in groups)
    return above > port


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
