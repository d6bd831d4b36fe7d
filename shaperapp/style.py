"""Shared look: one colour per crank speed, link colours, fonts for the scheme.

Every widget asks here, so the 60 r/min curve has the same colour in every plot.
"""
from __future__ import annotations

from PySide6.QtGui import QColor

SPEED_COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf",
                 "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22")
WORK_FILL = QColor(46, 125, 50, 28)      # light green band behind the working stroke
RETURN_FILL = QColor(198, 40, 40, 22)    # light red band behind the return stroke
CURSOR = QColor("#444444")
LINK = QColor("#263238")
FRAME = QColor("#607d8b")
TOOL_PATH = QColor("#ef6c00")
FORCE = QColor("#c2185b")              # force arrows on the scheme (magenta: not a speed colour)


def speed_colour(index: int) -> QColor:
    return QColor(SPEED_COLOURS[index % len(SPEED_COLOURS)])
