"""The report's gear figure: the pair in mesh as the meshing sheet draws it, to a stated scale.

The drawing is the sheet's own (``core.drawing.gear_sheet.mesh_items``, painted by the
sheet's painter ``shaperapp.widgets.sheet_paint.paint_sheet``): the same teeth, circles, line of
action and labels, never a second drawing of the geometry. Its scale is chosen when the
report is built, so the caption can state it; the figure then keeps its height on the page
(``Figure.to_scale``), as a shrunk figure would no longer be at the scale it states.
"""
from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtCore import QRectF
from PySide6.QtGui import QPainter

from core.drawing.gear_sheet import CENTRE_MARK, mesh_items, mesh_scale, window
from core.drawing.sheet import Paper, Sheet
from core.gear import GearPair
from shaperapp.widgets.sheet_paint import paint_sheet

from .blocks import Paint

WIDTH_MM = 170.0          # the report's figure width
ROOM_MM = 125.0           # the most height the drawing may take on the page
MARGIN_MM = 8.0           # above and below the drawing: the labels of points at its edge
SMALLER = 0.6
"""The share of the sheet's sizes the figure prints its annotations at (3.5 mm labels, the
18 mm arc of α′, line widths): the sheet's are for A2, and at a report's figure size they
crowd the pitch point. The pair is laid out at μ·SMALLER on a sheet 1/SMALLER as large and
printed at SMALLER of that, so its scale on the page is the stated μ."""


@dataclass(frozen=True)
class GearFigure:
    """The figure's ``scale`` μ (model mm per mm on the page, a standard scale as the
    sheet's), its size in mm, its ``paint`` and the ``sheet`` it paints (laid out at
    1/SMALLER of the page's size)."""
    scale: float
    width_mm: float
    height_mm: float
    paint: Paint
    sheet: Sheet


def gear_figure(pair: GearPair, language: str) -> GearFigure:
    """The pair in mesh at the largest standard scale that fits the report's figure."""
    scale = mesh_scale(pair, WIDTH_MM, ROOM_MM)
    bounds = window(pair)
    height = (bounds[3] - bounds[1]) / scale + 2 * CENTRE_MARK * SMALLER + 2 * MARGIN_MM
    width, tall = WIDTH_MM / SMALLER, height / SMALLER          # the sheet it is laid out on
    _, items = mesh_items(pair, (0.0, 0.0, width, tall), scale * SMALLER)
    sheet = Sheet(Paper("figure", width, tall, 0.0), tuple(items))

    def paint(painter: QPainter, rect: QRectF, px_per_mm: float) -> None:
        painter.save()
        painter.translate(rect.center().x() - WIDTH_MM / 2 * px_per_mm,
                          rect.center().y() - height / 2 * px_per_mm)
        painter.scale(px_per_mm * SMALLER, px_per_mm * SMALLER)
        paint_sheet(sheet, painter, language)
        painter.restore()
    return GearFigure(scale, WIDTH_MM, height, paint, sheet)
