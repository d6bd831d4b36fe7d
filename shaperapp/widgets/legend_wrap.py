"""How many columns a pyqtgraph legend's entries take in a given width.

Shared by the plot stacks' group legends and the Compare tab's legend: a legend laid
out in a fixed number of columns ran wider than its pane when its names were long
(two snapshot names on one row at 1366×768 cut the Compare tab's right plots, issue 34)
and took more rows than needed when they were short (16 speeds).
"""
from __future__ import annotations

import pyqtgraph as pg

SAMPLE_WIDTH = 20        # px of pyqtgraph's legend sample (ItemSample's box)


def legend_columns(legend: pg.LegendItem, room: float, most: int | None = None) -> int:
    """The most columns (at least one, at most ``most``) in which ``legend``'s widest
    entries, filled row by row, fit side by side in ``room`` px; 0 for no entries. An
    entry is its sample, its label and the legend's horizontal spacing on each side of
    the label."""
    widths = _entry_widths(legend)
    return next((c for c in range(min(len(widths), most or len(widths)), 1, -1)
                 if sum(max(widths[j::c]) for j in range(c)) <= room), min(len(widths), 1))


def wrap_legend(legend: pg.LegendItem, room: float, columns: int, most: int | None = None) -> int:
    """Lay ``legend``'s entries in :func:`legend_columns` columns; the columns
    (``columns`` is the present count)."""
    count = legend_columns(legend, room, most)
    if not count:
        return 0
    widths = _entry_widths(legend)
    entry = sum(max(widths[j::count]) for j in range(count)) / count
    if count != columns:
        # setColumnCount only re-lays out on a change of count: force it after a rebuild
        legend.columnCount = 0
        legend.setColumnCount(count)
    legend.setMaximumWidth(count * entry)     # packed to the left, not spread
    return count


def _entry_widths(legend: pg.LegendItem) -> list[float]:
    gap = 2 * legend.layout.horizontalSpacing()
    return [SAMPLE_WIDTH + gap + label.minimumWidth() for _, label in legend.items]
