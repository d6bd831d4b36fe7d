"""Drawing scales and where a drawing goes on the paper: GB/T 14690's series of reductions,
a scale's text, and the placement of model coordinates (mm of the design, or a polygon's
m/s) in paper mm. Apart from :mod:`core.drawing.sheet`, the sheet's items and their texts,
which imports them from here (as its writers do from there)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from core.forces.polygons import nice_scale

from .paper import Box

Pair = tuple[float, float]
# GB/T 14690: 1:1, 1:2, 1:5, 1:10 … preferred, 1:1.5, 1:2.5, 1:3, 1:4, 1:6 … allowed (as the report)
SCALE_MANTISSAS = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0)


def standard_scale(extent_mm: float, room_mm: float) -> float:
    """The smallest reduction 1:d of GB/T 14690's series (d = 1, 1.5, 2, 2.5, 3, 4, 5, 6 × 10^k,
    at least 1:1) that draws ``extent_mm`` of the design within ``room_mm`` of paper. Returns d."""
    return max(1.0, nice_scale(extent_mm, room_mm, SCALE_MANTISSAS))


def scale_text(denominator: float) -> str:
    """1:2.5, 1:10 …"""
    return f"1:{number_text(denominator)}"


def number_text(value: float) -> str:
    """A scale's number without trailing zeros: 0.002, 2.5, 10."""
    return f"{value:.6g}" if abs(value) < 1e5 else f"{value:.3e}"


@dataclass(frozen=True)
class Placement:
    """Model coordinates (a drawing's own unit) to paper mm: paper = origin + (model − anchor)/μ.

    ``scale`` μ is the course design's: model units per mm of paper (1:5 in mm is μ = 5
    mm/mm; a velocity polygon at μv = 0.01 is (m/s)/mm)."""

    scale: float
    origin: Pair
    anchor: Pair = (0.0, 0.0)

    def __call__(self, points) -> np.ndarray:
        p = np.asarray(points, dtype=float)
        return (p - np.asarray(self.anchor)) / self.scale + np.asarray(self.origin)

    def length(self, model_length: float) -> float:
        return model_length / self.scale


def fit(bounds: Box, box: Box, scale: float) -> Placement:
    """Centre the model ``bounds`` drawn at ``scale`` in the paper ``box``."""
    mx, my = (bounds[0] + bounds[2]) / 2.0, (bounds[1] + bounds[3]) / 2.0
    return Placement(scale, ((box[0] + box[2]) / 2.0, (box[1] + box[3]) / 2.0), (mx, my))


def shrink(box: Box, by: float) -> Box:
    return (box[0] + by, box[1] + by, box[2] - by, box[3] - by)
