"""The GB/T 14689 papers of a drawing sheet, landscape, by name.

Why a module of its own: ``shaper drawing``, ``course``, ``class`` and ``gear --help``
print the papers' names, and ``core.drawing.sheet`` (the sheet's items and layout)
imports numpy and the force polygons, most of a help's time (issue 43 item 5).
"""
from __future__ import annotations

from dataclasses import dataclass

Box = tuple[float, float, float, float]          # x0, y0, x1, y1 in paper mm

BINDING_MARGIN = 25.0                           # a of GB/T 14689


@dataclass(frozen=True)
class Paper:
    """A GB/T 14689 sheet in landscape with a binding margin on the left."""

    name: str
    width: float
    height: float
    margin: float          # c: top, right and bottom

    @property
    def border(self) -> Box:
        """The drawing frame (图框): everything drawn lies inside it."""
        return (BINDING_MARGIN, self.margin, self.width - self.margin, self.height - self.margin)


PAPERS = {name: Paper(name, w, h, c) for name, w, h, c in (
    ("A0", 1189.0, 841.0, 10.0), ("A1", 841.0, 594.0, 10.0), ("A2", 594.0, 420.0, 10.0),
    ("A3", 420.0, 297.0, 5.0))}


def paper(name: str) -> Paper:
    """The paper of that name (A0 … A3, any case); KeyError naming the choices."""
    try:
        return PAPERS[name.upper()]
    except KeyError:
        raise KeyError(f"{name!r} is not one of {', '.join(PAPERS)}") from None
