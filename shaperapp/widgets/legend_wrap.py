"""How many columns a pyqtgraph legend's entries take in a given width.

Shared by the plot stacks' group legends and the Compare tab's legend: a legend laid
out in a fixed number of columns ran wider than its pane when its names were long
(two snapshot names on one row at 1366×768 cut the Compare tab's right plots, issue 34)
and took more rows than needed when they were short (16 speeds).
"""
from __future__ import annotations

import pyqtgraph as pg

SAMPLE_WIDTH = 20        # px of pyqtgraph's legend sample (ItemSample's box)


def wrap_legend(legend: pg.LegendItem, room: float, columns: int, most: int | None = None) -> int:
    """Lay ``legend``'s entries in the most columns whose widest entries (filled row by
    row) fit side by side in ``room`` px, at least one and at most ``most``; the columns
    (``columns`` is the present count). An entry is its sample, its label and the legend's horizontal
    spacing on each side of the label."""
    items = legend.items
    if not items:
        return 0
    gap = 2 * legend.layout.horizontalSpacing()
    widths = [SAMPLE_WIDTH + gap + label.minimumWidth() for _, label in items]
    count = next((c for c in range(min(len(items), most or len(items)), 1, -1)
                  if sum(max(widths[j::c]) for j in range(c)) <= room), 1)
    entry = sum(max(widths[j::count]) for j in range(count)) / count
    if count != columns:
        # setColumnCount only re-lays out on a change of count: force it after a rebuild
        legend.columnCount = 0
        legend.setColumnCount(count)
    legend.setMaximumWidth(count * entry)     # packed to the left, not spread
    return count
