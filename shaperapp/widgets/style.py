"""Shared look: one colour per crank speed, link colours, and how numbers are written.

Every widget asks here, so the 60 r/min curve has the same colour in every plot
and a value reads the same in the plots, the scheme and the animation bar.
"""
from __future__ import annotations

from PySide6.QtGui import QColor

# Sixteen colours, one per allowed crank speed: matplotlib's tab10 followed by six darker
# hues picked so that every pair differs by ΔE(CIELAB) > 26 and none is close to the grey
# of shared curves, the cursor or the magenta force arrows (checked in test_gui_plot_stack).
SPEED_COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf",
                 "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#aa00ff", "#311b92",
                 "#637939", "#393b79", "#000000", "#00897b")
WORK_FILL = QColor(46, 125, 50, 28)      # light green band behind the working stroke
RETURN_FILL = QColor(198, 40, 40, 22)    # light red band behind the return stroke
CURSOR = QColor("#444444")
LINK = QColor("#263238")
FRAME = QColor("#607d8b")
TOOL_PATH = QColor("#ef6c00")
FORCE = QColor("#c2185b")              # force arrows on the scheme (magenta: not a speed colour)
TEXT = QColor("#212121")               # text drawn in plots and on the scheme


def speed_colour(index: int) -> QColor:
    """The colour of the ``index``-th crank speed (distinct for the 16 allowed speeds)."""
    return QColor(SPEED_COLOURS[index % len(SPEED_COLOURS)])


def fmt(value: float, spec: str) -> str:
    """``format(value, spec)`` without a negative zero: a value that rounds to zero is
    written "0.000", never "-0.000" (core's exact zeros come out as ±1e-17)."""
    text = format(value, spec)
    if text.startswith("-") and not any(c in "123456789" for c in text.split("e")[0]):
        return text[1:]
    return text


def crank_text(degrees: float) -> str:
    """A crank angle as every read-out writes it (the animation bar, the plots' cursor):
    one place, so that two read-outs of one angle cannot round it differently."""
    return fmt(degrees, ".1f")


def configure_plots() -> None:
    """pyqtgraph's global look, the same for the window, the report and the benchmarks
    (which must measure what a user sees): white background, black text, antialiased.

    Also keeps Qt's raster fills on the painting thread (``QT_NO_GUI_THREADPOOL``, unless
    the user set it): Qt hands every fill taller than 96 rows (the plots' and the
    scheme's backgrounds and bands) to a thread pool and waits for it, and on a busy
    2-core machine the hand-off cost more than the fill: 6 ms of a 48 ms edit
    (docs/performance.md). Call before the first paint; the pool is made then."""
    import os

    import pyqtgraph as pg
    os.environ.setdefault("QT_NO_GUI_THREADPOOL", "1")
    pg.setConfigOptions(background="w", foreground="k", antialias=True)
