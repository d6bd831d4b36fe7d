"""The one painting function for vector polygons: screen, PNG/SVG and the report.

``paint_polygon`` draws a :class:`core.polygons.Polygon` at a scale μ (unit per
drawing mm): every vector is one ``drawLine`` in drawing millimetres (value/μ,
y up) under a single painter transform, so what is drawn is exactly what
``core.polygons.paper`` says — the tests record those lines. Because the
screen view, the image export and the report all call this function, they
cannot disagree.
"""
from __future__ import annotations

import errno
import math
from pathlib import Path

from PySide6.QtCore import (QBuffer, QByteArray, QCoreApplication, QIODevice, QLineF, QPointF,
                            QRectF, QSize, Qt)
from PySide6.QtGui import QColor, QFont, QFontMetricsF, QImage, QPainter, QPen, QPolygonF
from PySide6.QtSvg import QSvgGenerator

from core.atomic import atomic_write
from core.polygons import Polygon, nice_scale, paper

translate = QCoreApplication.translate   # lupdate extracts translate("Context", "text")

ROLE_COLOURS = {"absolute": "#263238", "relative": "#1565c0", "normal": "#2e7d32",
                "tangential": "#ef6c00", "coriolis": "#c2185b", "force": "#263238"}
FORCE_COLOURS = ("#c62828", "#6a1b9a", "#1565c0", "#00838f", "#2e7d32", "#ef6c00", "#263238")
SVG_DPI = 96.0
PNG_PX_PER_MM = 8.0
LEGEND_MM = 62.0
MARGIN_MM = 8.0
PAD_LINES = 2.0          # free space around the drawing, in text lines
_SUB = str.maketrans("0123456789'", "₀₁₂₃₄₅₆₇₈₉′")


def titles() -> dict[str, str]:
    return {"velocity": translate("PolygonPainter", "Velocity polygon"), "acceleration": translate("PolygonPainter", "Acceleration polygon"),
            "force": translate("PolygonPainter", "Force polygon of the ram–rod group")}


def scale_caption(polygon: Polygon, scale: float) -> str:
    """e.g. 'μv = 0.01 (m/s)/mm'."""
    symbol = {"velocity": "μv", "acceleration": "μa", "force": "μF"}[polygon.kind]
    unit = "N" if polygon.kind == "force" else f"({polygon.unit})"
    return f"{symbol} = {scale:g} {unit}/mm"


def point_label(name: str) -> str:
    """a2 → a₂, n3' → n₃′."""
    return name.translate(_SUB)


def vector_colour(polygon: Polygon, index: int) -> QColor:
    if polygon.kind == "force":
        return QColor(FORCE_COLOURS[index % len(FORCE_COLOURS)])
    return QColor(ROLE_COLOURS[polygon.vectors[index].role])


def _split(key: str) -> tuple[str, str, str]:
    """'a^k_A3A2' → ('a', 'k', 'A3A2'); 'F_I5' → ('F', '', 'I5')."""
    base, _, sub = key.partition("_")
    base, _, sup = base.partition("^")
    return base, sup, sub


def draw_symbol(painter: QPainter, x: float, y: float, key: str, font: QFont) -> float:
    """Draw a vector symbol with its super- and subscript at baseline (x, y); returns its width."""
    base, sup, sub = _split(key)
    small = QFont(font)
    small.setPointSizeF(font.pointSizeF() * 0.72)
    big_m, small_m = QFontMetricsF(font, painter.device()), QFontMetricsF(small, painter.device())
    painter.setFont(font)
    painter.drawText(QPointF(x, y), base)
    x += big_m.horizontalAdvance(base)
    width = 0.0
    if sup:
        painter.setFont(small)
        painter.drawText(QPointF(x, y - big_m.ascent() * 0.45), sup)
        width = small_m.horizontalAdvance(sup)
    if sub:
        painter.setFont(small)
        painter.drawText(QPointF(x, y + big_m.descent() * 0.9), sub)
        width = max(width, small_m.horizontalAdvance(sub))
    painter.setFont(font)
    return big_m.horizontalAdvance(base) + width


def _bounds(points: dict[str, tuple[float, float]]) -> QRectF:
    xs = [p[0] for p in points.values()]
    ys = [p[1] for p in points.values()]
    return QRectF(min(xs), min(ys), max(max(xs) - min(xs), 1e-9), max(max(ys) - min(ys), 1e-9))


def _arrow_head(tip: QPointF, direction: QPointF, size: float) -> QPolygonF:
    length = math.hypot(direction.x(), direction.y()) or 1.0
    dx, dy = direction.x() / length, direction.y() / length
    back = QPointF(tip.x() - dx * size, tip.y() - dy * size)
    side = QPointF(-dy * size * 0.32, dx * size * 0.32)
    return QPolygonF([tip, back + side, back - side])


def paint_polygon(painter: QPainter, rect: QRectF, polygon: Polygon, scale: float,
                  px_per_mm: float | None = None, font: QFont | None = None,
                  legend: bool = True, centre_mm: tuple[float, float] | None = None) -> float:
    """Draw ``polygon`` at μ = ``scale`` into ``rect`` (device units).

    ``px_per_mm`` maps a drawing millimetre to device units (true scale on paper);
    None fits the drawing into the space left by the caption and legend.
    ``centre_mm`` is the point of the drawing (in mm at μ = 1, i.e. in the
    polygon's unit) put at the centre of the drawing area; default the centre
    of this polygon. Returns the px-per-mm used.
    """
    font = QFont(font) if font is not None else QFont(painter.font())
    if font.pointSizeF() <= 0:
        font.setPointSizeF(9.0)
    metrics = QFontMetricsF(font, painter.device())
    line = metrics.height()
    painter.save()
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    painter.setFont(font)
    painter.setPen(QColor("#263238"))
    head = f"{titles()[polygon.kind]}   φ = {polygon.crank_deg:.2f}°, {polygon.rpm:g} r/min"
    painter.drawText(QPointF(rect.left(), rect.top() + metrics.ascent()), head)
    painter.drawText(QPointF(rect.left(), rect.top() + line + metrics.ascent()),
                     scale_caption(polygon, scale))
    rows = _legend_rows(polygon)
    area, legend_box = layout(rect, polygon, metrics, legend)
    pts = paper(polygon, scale)
    box = _bounds(pts)
    pad = PAD_LINES * line
    if px_per_mm is None:
        px_per_mm = max(min((area.width() - 2 * pad) / box.width(),
                            (area.height() - 2 * pad) / box.height()), 1e-6)
    centre = area.center()
    mid = box.center() if centre_mm is None else QPointF(centre_mm[0] / scale, centre_mm[1] / scale)

    def to_device(p: tuple[float, float]) -> QPointF:
        return QPointF(centre.x() + (p[0] - mid.x()) * px_per_mm,
                       centre.y() - (p[1] - mid.y()) * px_per_mm)

    painter.save()
    painter.setClipRect(area)
    painter.translate(centre.x() - mid.x() * px_per_mm, centre.y() + mid.y() * px_per_mm)
    painter.scale(px_per_mm, -px_per_mm)            # drawing mm, y up
    head_mm = max(1.2 * line, 6.0) / px_per_mm
    for i, vec in enumerate(polygon.vectors):
        colour = vector_colour(polygon, i)
        pen = QPen(colour)
        pen.setCosmetic(True)
        pen.setWidthF(1.6 if vec.role in ("absolute", "force") else 1.3)
        if vec.role in ("normal", "tangential"):
            pen.setStyle(Qt.PenStyle.DashLine)
        painter.setPen(pen)
        tail, tip = QPointF(*pts[vec.tail]), QPointF(*pts[vec.head])
        if vec.magnitude == 0.0:
            continue
        painter.drawLine(QLineF(tail, tip))
        length = math.hypot(tip.x() - tail.x(), tip.y() - tail.y())
        if length > 1e-9:
            painter.setBrush(colour)
            solid = QPen(colour)
            solid.setCosmetic(True)
            painter.setPen(solid)
            painter.drawPolygon(_arrow_head(tip, tip - tail, min(head_mm, 0.45 * length)))
    painter.restore()
    painter.setPen(QColor("#263238"))
    painter.setFont(font)
    if polygon.kind == "force":
        for i, vec in enumerate(polygon.vectors):
            a, b = to_device(pts[vec.tail]), to_device(pts[vec.head])
            mid_pt = (a + b) / 2.0
            painter.setPen(vector_colour(polygon, i))
            draw_symbol(painter, mid_pt.x() + 0.3 * line, mid_pt.y() - 0.2 * line, vec.key, font)
    else:
        _label_points(painter, pts, to_device, metrics)
    if legend_box is not None:
        _draw_legend(painter, legend_box, polygon, rows, font, line)
    painter.restore()
    return px_per_mm


def layout(rect: QRectF, polygon: Polygon, metrics: QFontMetricsF,
           legend: bool = True) -> tuple[QRectF, QRectF | None]:
    """(drawing area, legend box or None) of ``paint_polygon`` in ``rect``: the caption
    on top, the legend beside the drawing when the space is wide, else below it."""
    line = metrics.height()
    area = QRectF(rect.left(), rect.top() + 2.4 * line, rect.width(), rect.height() - 2.4 * line)
    if not legend:
        return area, None
    rows = _legend_rows(polygon)
    legend_w = max((metrics.horizontalAdvance(k.replace("^", "").replace("_", "")) + metrics.horizontalAdvance(t)
                    for k, t in rows), default=0.0) + 2.6 * line
    if area.width() > area.height() * 1.1:
        box = QRectF(area.right() - legend_w, area.top(), legend_w, area.height())
        area.setRight(area.right() - legend_w - line)
    else:
        box = QRectF(area.left(), area.bottom() - line * (len(rows) + 0.5), area.width(),
                     line * (len(rows) + 0.5))
        area.setBottom(box.top() - 0.5 * line)
    return area, box


def auto_scale(polygon: Polygon, rect: QRectF, metrics: QFontMetricsF, px_per_mm: float) -> float:
    """The round μ at which ``paint_polygon`` fills ``rect`` with this polygon at true scale."""
    area, _ = layout(rect, polygon, metrics)
    return fit_scale(_bounds(paper(polygon, 1.0)), area, px_per_mm, PAD_LINES * metrics.height())


def fit_scale(extent: QRectF, area: QRectF, px_per_mm: float, pad: float) -> float:
    """The round μ at which a drawing of ``extent`` (in the polygon's unit) fits ``area``
    (device units, less ``pad`` on each side) at ``px_per_mm``."""
    width_mm = max(area.width() - 2 * pad, 1.0) / px_per_mm
    height_mm = max(area.height() - 2 * pad, 1.0) / px_per_mm
    need = max(extent.width() / width_mm, extent.height() / height_mm)
    return nice_scale(need, 1.0)


def _label_points(painter: QPainter, pts, to_device, metrics: QFontMetricsF) -> None:
    """Point letters, pushed away from the drawing's centre; points closer than a text
    line on the page share one label ("p′, c′")."""
    line = metrics.height()
    groups: list[tuple[QPointF, tuple[float, float], list[str]]] = []
    for name, p in pts.items():
        dev = to_device(p)
        for anchor, _, names in groups:
            if math.hypot(dev.x() - anchor.x(), dev.y() - anchor.y()) < 0.9 * line:
                names.append(point_label(name))
                break
        else:
            groups.append((dev, p, [point_label(name)]))
    cx = sum(p[0] for p in pts.values()) / len(pts)
    cy = sum(p[1] for p in pts.values()) / len(pts)
    for dev, (x, y), names in groups:
        text = ", ".join(names)
        dx, dy = x - cx, y - cy
        norm = math.hypot(dx, dy) or 1.0
        w = metrics.horizontalAdvance(text)
        ox = dx / norm * (0.5 * w + 0.45 * line) - 0.5 * w
        oy = -dy / norm * 0.9 * line + 0.35 * line
        painter.drawText(QPointF(dev.x() + ox, dev.y() + oy), text)


def _legend_rows(polygon: Polygon) -> list[tuple[str, str]]:
    """(symbol, '= magnitude unit'); round-off noise (below 1e-9 of the largest) shows as 0."""
    floor = 1e-9 * polygon.largest()
    return [(v.key, f"= {v.magnitude if v.magnitude > floor else 0.0:.4g} {polygon.unit}")
            for v in polygon.vectors]


def _draw_legend(painter: QPainter, box: QRectF, polygon: Polygon, rows, font: QFont,
                 line: float) -> None:
    y = box.top() + line
    for i, (key, text) in enumerate(rows):
        colour = vector_colour(polygon, i)
        pen = QPen(colour)
        pen.setWidthF(1.5)
        if polygon.vectors[i].role in ("normal", "tangential"):
            pen.setStyle(Qt.PenStyle.DashLine)
        painter.setPen(pen)
        painter.drawLine(QLineF(box.left(), y - 0.3 * line, box.left() + 0.9 * line, y - 0.3 * line))
        painter.setPen(QColor("#263238"))
        width = draw_symbol(painter, box.left() + 1.2 * line, y, key, font)
        painter.drawText(QPointF(box.left() + 1.6 * line + width, y), text)
        y += line


def drawing_size_mm(polygon: Polygon, scale: float) -> tuple[float, float]:
    """Page size for a true-scale export: the drawing plus margins, caption and legend."""
    box = _bounds(paper(polygon, scale))
    width = box.width() + 2 * MARGIN_MM + LEGEND_MM + 12.0
    height = max(box.height() + 2 * MARGIN_MM + 14.0, 8.0 * len(polygon.vectors) + 20.0)
    return max(width, 120.0), height


def export_polygon(path: str, polygon: Polygon, scale: float) -> None:
    """Write ``polygon`` at true scale: SVG (sized in mm) or a raster image by suffix,
    atomically (rendered in memory, then ``atomic_write``); OSError names the path."""
    target = Path(path)
    suffix = target.suffix.lower()
    w_mm, h_mm = drawing_size_mm(polygon, scale)
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    if suffix == ".svg":
        px = SVG_DPI / 25.4
        size = QSize(math.ceil(w_mm * px), math.ceil(h_mm * px))
        device = QSvgGenerator()
        device.setOutputDevice(buffer)
        device.setSize(size)
        device.setViewBox(QRectF(0, 0, size.width(), size.height()))
        device.setResolution(int(SVG_DPI))
        device.setTitle(titles()[polygon.kind])
    elif suffix in (".png", ".jpg", ".jpeg", ".bmp"):
        px = PNG_PX_PER_MM
        size = QSize(math.ceil(w_mm * px), math.ceil(h_mm * px))
        device = QImage(size, QImage.Format.Format_ARGB32)
        device.setDotsPerMeterX(round(px * 1000))
        device.setDotsPerMeterY(round(px * 1000))
        device.fill(Qt.GlobalColor.white)
    else:
        raise ValueError(translate("PolygonPainter", "Cannot export to '%1': use .png or .svg").replace("%1", suffix))
    painter = QPainter(device)
    try:
        font = QFont(painter.font())
        font.setPointSizeF(9.0)
        rect = QRectF(MARGIN_MM * px, MARGIN_MM * px / 2, size.width() - 2 * MARGIN_MM * px,
                      size.height() - MARGIN_MM * px)
        if suffix == ".svg":
            painter.fillRect(QRectF(0, 0, size.width(), size.height()), Qt.GlobalColor.white)
        paint_polygon(painter, rect, polygon, scale, px_per_mm=px, font=font)
    finally:
        painter.end()
    if suffix != ".svg" and not device.save(buffer, suffix[1:].upper()):
        raise OSError(errno.EIO, f"could not encode {target}", str(target))
    buffer.close()
    atomic_write(target, bytes(data))
