"""The scheme's static shapes: a fixed pivot's support, the ram's guide way and the tool.

Pure functions of a position and the drawing unit ``u`` (segments or a painter path,
mm), split from mechanism.py so that the layer keeps to its items and their motion.
"""
from __future__ import annotations

import numpy as np
from PySide6.QtGui import QPainterPath

from .draw import Pair, rect


def tool_shape(front: float, y_lo: float, u: float) -> tuple[QPainterPath, tuple[float, float]]:
    """Tool post and bit hanging under the ram's front end; returns the shape and the tip."""
    path = QPainterPath()
    path.addRect(rect(front - 2.6 * u, y_lo, front - 1.0 * u, y_lo - 2.0 * u))
    tip = (front - 0.7 * u, y_lo - 3.3 * u)
    bit = QPainterPath()
    bit.moveTo(front - 2.3 * u, y_lo - 2.0 * u)
    bit.lineTo(front - 1.0 * u, y_lo - 2.0 * u)
    bit.lineTo(*tip)
    bit.lineTo(front - 1.9 * u, y_lo - 2.9 * u)
    bit.closeSubpath()
    path.addPath(bit)
    return path, tip

def support(p: np.ndarray, u: float) -> list[Pair]:
    """A fixed pivot: triangle, ground line and hatching under ``p``."""
    x, y = float(p[0]), float(p[1])
    base = y - 2.0 * u
    pairs = [((x, y), (x - 1.2 * u, base)), ((x, y), (x + 1.2 * u, base)),
             ((x - 2.0 * u, base), (x + 2.0 * u, base))]
    for hx in np.linspace(x - 1.7 * u, x + 2.0 * u, 6):
        pairs.append(((hx, base), (hx - 0.7 * u, base - 0.7 * u)))
    return pairs

def rail(x0: float, x1: float, y: float, u: float) -> list[Pair]:
    """The ram's guide way along its top: a line hatched on the frame side."""
    pairs = [((x0, y), (x1, y))]
    for hx in np.arange(x0, x1 - 0.6 * u, 1.4 * u):
        pairs.append(((hx, y), (hx + 0.7 * u, y + 0.7 * u)))
    return pairs
