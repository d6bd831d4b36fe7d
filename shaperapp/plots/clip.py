"""Plot items cut to their view for an export: an SVG cannot clip.

On screen a pyqtgraph ViewBox clips its children to the plot area. QSvgGenerator
writes no clip, and QSvgRenderer (which replays an SVG into the PDF report)
ignores clip paths, so the plots' own items (``plot_curves``) give an export
only what lies inside their view. These are the pure parts: which view holds an
item, and a polyline cut to a rectangle.
"""
from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QRectF
from PySide6.QtGui import QPainterPath
from PySide6.QtWidgets import QGraphicsItem


def view_of(item: QGraphicsItem) -> pg.ViewBox | None:
    """The ViewBox whose data area holds ``item``."""
    parent = item.parentItem()
    while parent is not None and not isinstance(parent, pg.ViewBox):
        parent = parent.parentItem()
    return parent


def clip_polyline(x: np.ndarray, y: np.ndarray, rect: QRectF) -> tuple[np.ndarray, np.ndarray]:
    """The parts of the polyline (x, y) inside ``rect`` (Liang–Barsky per segment), as
    points with NaN between the pieces; NaN points break the line as before."""
    x0, x1, y0, y1 = rect.left(), rect.right(), rect.top(), rect.bottom()
    ax, ay, bx, by = x[:-1], y[:-1], x[1:], y[1:]
    dx, dy = bx - ax, by - ay
    lo, hi = np.zeros(ax.shape), np.ones(ax.shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        for p, q in ((-dx, ax - x0), (dx, x1 - ax), (-dy, ay - y0), (dy, y1 - ay)):
            t = q / p
            lo = np.where(p < 0, np.maximum(lo, t), lo)
            hi = np.where(p > 0, np.minimum(hi, t), hi)
            outside = (p == 0) & (q < 0)        # parallel to this edge and beyond it
            hi = np.where(outside, -1.0, hi)
    keep = np.isfinite(dx) & np.isfinite(dy) & (lo <= hi)
    # the cut ends; an end that is not cut is the data point itself (no round-off)
    sx = np.where(lo == 0.0, ax, ax + lo * dx)
    sy = np.where(lo == 0.0, ay, ay + lo * dy)
    ex = np.where(hi == 1.0, bx, ax + hi * dx)
    ey = np.where(hi == 1.0, by, ay + hi * dy)
    xs, ys = [], []
    joined = False                                # the last piece ends where this one starts
    for i in np.flatnonzero(keep):
        if not (joined and lo[i] == 0.0 and keep[i - 1]):
            xs += [np.nan, sx[i]]
            ys += [np.nan, sy[i]]
        xs.append(ex[i])
        ys.append(ey[i])
        joined = hi[i] == 1.0
    return np.array(xs[1:]), np.array(ys[1:])


def clipped_path(x: np.ndarray, y: np.ndarray, connect: str, rect: QRectF) -> QPainterPath | None:
    """The path of the line (x, y) (``connect`` "finite": a polyline broken at NaN;
    "pairs": a segment per two points) cut to ``rect``; None when it lies inside."""
    finite = np.isfinite(x) & np.isfinite(y)
    xf, yf = x[finite], y[finite]
    if ((xf >= rect.left()) & (xf <= rect.right()) & (yf >= rect.top()) & (yf <= rect.bottom())).all():
        return None                                  # the usual case: nothing to cut
    path = QPainterPath()
    if connect == "finite":
        cx, cy = clip_polyline(x, y, rect)
        edges = np.flatnonzero(np.diff(np.concatenate(([0], np.isfinite(cx).view(np.int8), [0]))))
        for start, stop in zip(edges[::2], edges[1::2]):
            path.addPath(pg.arrayToQPath(cx[start:stop], cy[start:stop], connect="all",
                                         finiteCheck=False))
        return path
    for (ax, bx), (ay, by) in zip(x.reshape(-1, 2), y.reshape(-1, 2)):   # each segment alone
        px, py = clip_polyline(np.array([ax, bx]), np.array([ay, by]), rect)
        if px.size == 2:
            path.moveTo(px[0], py[0])
            path.lineTo(px[1], py[1])
    return path
