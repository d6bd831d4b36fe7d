"""What of the scheme's view its labels are placed for: the view's key, the window whose
lines are rasterised, the bounds a label stays inside.

Pure functions of rectangles (mm), split from view.py so that the widget keeps to its
layers and signals; the label search (labels.py) takes what they return.
"""
from __future__ import annotations

from PySide6.QtCore import QRectF

WINDOW_MARGIN = 0.25       # the window rasterised: the view and this share of it around


def view_key(view: QRectF, pixel: tuple[float, float]) -> tuple:
    """The view's range and pixel size: the labels' placement depends on nothing else of it."""
    return (view.left(), view.top(), view.width(), view.height(), *pixel)


def label_window(view: QRectF) -> tuple[float, float, float, float]:
    """The view and a quarter of it around, mm: where a label can be seen, and so where
    the lines it keeps off are rasterised (a label farther out is off screen)."""
    dx, dy = WINDOW_MARGIN * view.width(), WINDOW_MARGIN * view.height()
    return view.left() - dx, view.right() + dx, view.top() - dy, view.bottom() + dy


def label_bounds(drawing: QRectF, view: QRectF) -> tuple[float, float, float, float]:
    """The ``drawing``'s extent (the arrows' reach included while shown), or the view where
    it shows more (zoomed out): labels stay inside."""
    r = drawing.united(view)
    return r.left(), r.right(), r.top(), r.bottom()
