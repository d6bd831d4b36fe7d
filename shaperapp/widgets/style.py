"""Shared look: one colour per crank speed, link colours, and how numbers are written.

Every widget asks here, so the 60 r/min curve has the same colour in every plot
and a value reads the same in the plots, the scheme and the animation bar.
"""
from __future__ import annotations

from PySide6.QtGui import QColor

# Sixteen colours, one per allowed crank speed, that a reader tells apart as thin lines on
# white: every pair differs by CIEDE2000 ΔE00 > 20 (tab10 with six darker hues had pairs at
# 10.6, 85/95 r/min of 30…105, which readers confused), each has L* 30…72 and ΔE00 ≥ 30 from
# the white page, and ΔE00 ≥ 12 from the grey of shared curves, the cursor and the magenta
# force arrows. Chosen by farthest-point selection over the sRGB grid of step 34 with those
# bounds, then one swap pass (min ΔE00 21.0; checked in test_gui_plot_stack). The first
# speeds, the most used, get the colours farthest apart. The plots, the animation bar and
# the report's figures (drawn from the plots) all take them from here.
SPEED_COLOURS = ("#2266aa", "#aaaa00", "#ff2200", "#ff66ff", "#226644", "#882266",
                 "#884400", "#44aaaa", "#aa8888", "#88aaff", "#6600ff", "#ee8800",
                 "#00aa44", "#aa0022", "#ff0066", "#666600")
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
