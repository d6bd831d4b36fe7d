"""A drawing's outline in mm as a polygon on screen, filled from the array in one go.

The Gear tab's outlines have thousands of points, and a polygon built point by point was
most of a frame (0.12 s a paint, issue 35's Gear tab); the Cam tab's profile and pitch
curve were built the same way. Both views map mm to px alike: a point of the drawing at
a given place in the widget, a scale in px a mm, y up.
"""
from __future__ import annotations

import numpy as np
from pyqtgraph.functions import arrayToQPolygonF
from PySide6.QtGui import QPolygonF


def screen_polygon(points: np.ndarray, centre: tuple[float, float], middle: np.ndarray,
                   scale: float) -> QPolygonF:
    """``points`` (n, 2) mm as a polygon on screen: ``middle`` at ``centre``, ``scale`` px a
    mm, y up."""
    if len(points) == 0:
        return QPolygonF()              # pyqtgraph cannot fill a polygon of no points
    xs = centre[0] + (points[:, 0] - middle[0]) * scale
    ys = centre[1] - (points[:, 1] - middle[1]) * scale
    return arrayToQPolygonF(xs, ys)
