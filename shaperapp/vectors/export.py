"""A vector polygon written to a file at true scale: SVG sized in mm, or PNG, painted by
``polygon_paint.paint_polygon`` like the screen and the report."""
from __future__ import annotations

import errno
import math
from pathlib import Path

from PySide6.QtCore import QBuffer, QByteArray, QIODevice, QRectF, QSize, Qt
from PySide6.QtGui import QFont, QFontMetricsF, QImage, QPainter
from PySide6.QtSvg import QSvgGenerator

from core.files.atomic import atomic_write
from core.forces.polygons import Polygon, paper

from .paint import _bounds, layout, paint_polygon, titles, translate

SVG_DPI = 96.0
PNG_PX_PER_MM = 8.0
LEGEND_MM = 62.0
MARGIN_MM = 8.0


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
    if suffix == ".svg":
        px = SVG_DPI / 25.4
    elif suffix in (".png", ".jpg", ".jpeg", ".bmp"):
        px = PNG_PX_PER_MM
    else:
        raise ValueError(translate("PolygonPainter", "Cannot export to '%1': use .png or .svg").replace("%1", suffix))
    w_mm, h_mm = drawing_size_mm(polygon, scale)
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    # The page is sized for a legend beside the drawing; where the layout puts it below (a
    # tall, narrow drawing, as at a limit position with its note) the page grows until the
    # drawing fits its area, or it ran under the note and legend and lost its arrowheads
    # to the clip (seen comparing the PNG with the SVG).
    for _ in range(8):
        size = QSize(math.ceil(w_mm * px), math.ceil(h_mm * px))
        device = _device(suffix, size, px, buffer, polygon)
        font = QFont()                        # the application font, as a painter starts with
        font.setPointSizeF(9.0)
        rect = _page_rect(size, px)
        area = layout(rect, polygon, QFontMetricsF(font, device))[0]
        box = _bounds(paper(polygon, scale))
        short = max(box.height() * px - area.height(), 0.0)
        if short <= 0.5:
            break
        h_mm += short / px + 2.0
    painter = QPainter(device)
    try:
        if suffix == ".svg":
            painter.fillRect(QRectF(0, 0, size.width(), size.height()), Qt.GlobalColor.white)
        paint_polygon(painter, rect, polygon, scale, px_per_mm=px, font=font)
    finally:
        painter.end()
    if suffix != ".svg" and not device.save(buffer, suffix[1:].upper()):
        raise OSError(errno.EIO, f"could not encode {target}", str(target))
    buffer.close()
    atomic_write(target, bytes(data))


def _page_rect(size: QSize, px: float) -> QRectF:
    return QRectF(MARGIN_MM * px, MARGIN_MM * px / 2, size.width() - 2 * MARGIN_MM * px,
                  size.height() - MARGIN_MM * px)


def _device(suffix: str, size: QSize, px: float, buffer: QBuffer, polygon: Polygon):
    if suffix == ".svg":
        device = QSvgGenerator()
        device.setOutputDevice(buffer)
        device.setSize(size)
        device.setViewBox(QRectF(0, 0, size.width(), size.height()))
        device.setResolution(int(SVG_DPI))
        device.setTitle(titles()[polygon.kind])
        return device
    device = QImage(size, QImage.Format.Format_ARGB32)
    device.setDotsPerMeterX(round(px * 1000))
    device.setDotsPerMeterY(round(px * 1000))
    device.fill(Qt.GlobalColor.white)
    return device
