"""How wide a pyqtgraph axis beside a plot must be for its title and tick labels not to
overlap: the title turned on its side, then the widest label, measured as pyqtgraph
places them (issue 34 item 8: "(N·m)" over the minus of −4000, the Chinese colour-bar
title over its ticks). The sheets measure their labels the same way."""
from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QFontMetricsF

TITLE_NUDGE_PX = 5       # pyqtgraph draws a side axis' title this far outside the axis' box


def axis_width(axis: pg.AxisItem) -> float:
    """The width a left or right ``axis`` needs: its title's height (turned on its side),
    the widest tick label it draws for its present range, the tick and the gaps."""
    title = axis.label.boundingRect().height() - TITLE_NUDGE_PX if axis.label.isVisible() else 0.0
    widest = 0.0
    if axis.style["showValues"]:
        metrics = QFontMetricsF(axis.style["tickFont"] or axis.font())
        levels = axis.tickValues(axis.range[0], axis.range[1], max(axis.geometry().height(), 1.0))
        if levels:
            spacing, values = levels[0]
            strings = axis.tickStrings(values, axis.autoSIPrefixScale * axis.scale, spacing)
            box = QRectF(0, 0, 100, 100)
            widest = max((metrics.boundingRect(box, Qt.AlignmentFlag.AlignCenter, s).width()
                          for s in strings), default=0.0)
    gap = max(0, axis.style["tickLength"]) + axis.style["tickTextOffset"][0]
    return title + widest + gap + 1.0
