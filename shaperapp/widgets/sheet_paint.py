"""Paint a :class:`core.drawing.sheet.Sheet` with QPainter: the drawing sheets (PDF, SVG and
the preview, ``shaperapp.drawing.render``) and the report's gear figure, which draws the
meshing sheet's pair (``shaperapp.report.gear_figure``); shared here, below both.

The sheet is in paper mm with y up; the painter here works in mm with y down,
so every point is flipped once and texts are drawn upright. Line widths and
dash patterns are those of the sheet's layers (GB/T 4457.4, as the DXF has
them), so the three files of one sheet look alike. A text comes out at its
character height (the capitals' height) and never wider than the sheet's
estimate of it: the layout's no-overlap guarantee holds on paper too. The
estimate is each character's own advance in this font (``core.drawing.advances``),
so only CJK characters are condensed, to the square the sheet reckons them.
"""
from __future__ import annotations

import itertools

import numpy as np
from pyqtgraph.functions import create_qpolygonf, ndarray_from_qpolygonf
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QFont, QFontMetricsF, QPainter, QPainterPath, QPen, QPolygonF

from core.drawing.dxf import LAYERS, LINETYPES, THICK_MM
from core.drawing.sheet import Circle, Polyline, Sheet, Text, is_square, text_width
from core.drawing.text_runs import closed_up

from .fonts import drawing_lettering, report_font

INK = QColor(0, 0, 0)


def _pen(layer: str, svg: bool = False) -> QPen:
    """The layer's pen in paper mm: its width and its GB/T 4457.4 dashes in mm."""
    spec = LAYERS[layer]
    width = spec.lineweight / 100.0 if spec.lineweight > 0 else THICK_MM / 2.0
    pen = QPen(INK, width)
    pen.setCapStyle(Qt.PenCapStyle.FlatCap)
    pen.setJoinStyle(Qt.PenJoinStyle.MiterJoin)
    if spec.linetype in LINETYPES:
        pattern = [abs(v) if v else 0.3 for v in LINETYPES[spec.linetype][1][1:]]
        unit = svg_dash_unit(pen) if svg else width
        pen.setDashPattern([v / unit for v in pattern])
    return pen


def svg_dash_unit(pen: QPen) -> float:
    """What QSvgGenerator multiplies a pen's dash pattern by: the pen's width, except for a
    width that rounds to 0 (QPen.width(), an int), which it takes as 1, as for a cosmetic
    pen. Why: a thin line (0.25 mm) got dashes 4 times the PDF's, 48 mm for 12, and the
    crank circle showed as a few arcs (the PDF engine multiplies by the true width)."""
    return pen.widthF() if pen.width() != 0 else 1.0


def paint_sheet(sheet: Sheet, painter: QPainter, language: str = "en", svg: bool = False) -> None:
    """Paint ``sheet`` with ``painter`` whose coordinates are paper mm, y down, origin at
    the sheet's upper left corner; ``svg`` when the painter is a QSvgGenerator's (its dash
    patterns are reckoned differently, see :func:`svg_dash_unit`)."""
    height = sheet.paper.height
    font = drawing_lettering(report_font(language))
    font.setPixelSize(100)
    metrics = QFontMetricsF(font)
    cap = metrics.capHeight() or 70.0
    painter.setRenderHint(QPainter.RenderHint.Antialiasing, True)
    painter.fillRect(QRectF(0, 0, sheet.paper.width, height), QColor(255, 255, 255))
    for item in sheet.items:
        if isinstance(item, Text):
            for run in closed_up(item, lambda run: _drawn_width(run, metrics, cap)[0]):    # a subscript is a smaller text of its own
                _text(painter, run, height, font, metrics, cap)
            continue
        painter.setPen(_pen(item.layer, svg))
        if isinstance(item, Circle):
            painter.setBrush(QBrush(INK) if item.filled else Qt.BrushStyle.NoBrush)
            painter.drawEllipse(QPointF(item.center[0], height - item.center[1]), item.radius, item.radius)
        elif isinstance(item, Polyline):
            poly = _polygon(item.points, height)
            if item.filled:
                path = QPainterPath()
                path.addPolygon(poly)
                path.closeSubpath()
                painter.fillPath(path, QBrush(INK))
            if item.closed:
                painter.setBrush(Qt.BrushStyle.NoBrush)
                painter.drawPolygon(poly)
            else:
                painter.drawPolyline(poly)


def _polygon(points, height: float) -> QPolygonF:
    """``points`` (paper mm, y up) as a polygon in the painter's y-down mm, filled through
    numpy (pyqtgraph's helpers): a QPointF made per point was most of painting a sheet's
    curves. The same doubles as ``QPointF(x, height - y)``."""
    pts = np.asarray(points, dtype=float).reshape(-1, 2)
    poly = create_qpolygonf(len(pts))
    if len(pts):
        out = ndarray_from_qpolygonf(poly)
        out[:, 0] = pts[:, 0]
        out[:, 1] = height - pts[:, 1]
    return poly


def _segments(item: Text, metrics: QFontMetricsF, cap: float) -> list[tuple[str, float, float]]:
    """``item``'s text in runs of CJK and of other characters, each with its advance in the
    font's pixels and the squeeze that keeps it within the sheet's estimate of it. Why
    apart: the estimate sets a CJK character square (``WIDE_ADVANCE``), narrower than the
    CJK font draws it, and every other character at its own advance; one squeeze for the
    whole text condensed the letters of "模数 m" with the Chinese."""
    k = item.height / cap
    segments = []
    for _, chars in itertools.groupby(item.text, is_square):
        part = "".join(chars)
        advance = metrics.horizontalAdvance(part)
        squeeze = min(1.0, text_width(part, item.height) / k / advance) if advance > 0 else 1.0
        segments.append((part, advance, squeeze))
    return segments


def _drawn_width(item: Text, metrics: QFontMetricsF, cap: float) -> tuple[float, float]:
    """The width ``item`` is drawn at, paper mm, and the least squeeze of its characters
    other than CJK (1 where the estimate holds them: :func:`_segments`)."""
    segments = _segments(item, metrics, cap)
    width = sum(advance * squeeze for _, advance, squeeze in segments) * item.height / cap
    narrow = [squeeze for part, _, squeeze in segments if not is_square(part[0])]
    return width, min(narrow, default=1.0)


def _text(painter: QPainter, item: Text, height: float, font: QFont, metrics: QFontMetricsF,
          cap: float) -> None:
    k = item.height / cap
    segments = _segments(item, metrics, cap)
    width = sum(advance * squeeze for _, advance, squeeze in segments)
    dx = {"l": 0.0, "c": -width / 2.0, "r": -width}[item.align[0]]
    dy = {"b": 0.0, "m": cap / 2.0, "t": cap}[item.align[1]]
    painter.save()
    painter.translate(item.position[0], height - item.position[1])
    painter.rotate(-item.rotation)
    painter.scale(k, k)
    painter.setFont(font)
    painter.setPen(QPen(INK))
    painter.translate(dx, dy)
    for part, advance, squeeze in segments:
        painter.save()
        painter.scale(squeeze, 1.0)
        painter.drawText(QPointF(0.0, 0.0), part)
        painter.restore()
        painter.translate(advance * squeeze, 0.0)
    painter.restore()
