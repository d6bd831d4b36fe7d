"""The drawing sheets as files: PDF, SVG (painted by ``shaperapp.widgets.sheet_paint``,
which the preview and the report's gear figure share) and DXF (``core.drawing.sheet_dxf``).
"""
from __future__ import annotations

import errno
from typing import Sequence

from PySide6.QtCore import QBuffer, QByteArray, QIODevice, QMarginsF, QRectF, QSizeF
from PySide6.QtGui import QPageLayout, QPageSize, QPainter, QPdfWriter
from PySide6.QtSvg import QSvgGenerator

from core.files.atomic import atomic_write
from core.drawing.sheet import Sheet

from shaperapp.widgets.pdf_page import exact_page
from shaperapp.widgets.pdf_text import repair_text_layer
from shaperapp.widgets.sheet_paint import INK, paint_sheet, svg_dash_unit  # noqa: F401 (the sheets' painter, here as before)

PDF_RESOLUTION = 1200          # dots per inch of the PDF's coordinates
SVG_UNITS_PER_MM = 10.0        # SVG user units per mm (viewBox in mm: width="841mm")


def pdf_bytes(sheet: Sheet, language: str = "en", title: str = "") -> bytes:
    """The sheet as a one-page PDF of exactly its paper size, its text layer repaired
    (``pdf_text``: the Chinese in it is searchable)."""
    return pages_pdf([sheet], language, title)


def pages_pdf(sheets: Sequence[Sheet], language: str = "en", title: str = "") -> bytes:
    """Sheets of one paper as the pages of one PDF (the class's task sheets and answer key),
    each page exactly the paper's size, the text layer repaired."""
    paper = sheets[0].paper
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    writer = QPdfWriter(buffer)
    writer.setResolution(PDF_RESOLUTION)
    size = QPageSize(QSizeF(paper.width, paper.height), QPageSize.Unit.Millimeter,
                     paper.name, QPageSize.SizeMatchPolicy.ExactMatch)
    writer.setPageLayout(QPageLayout(size, QPageLayout.Orientation.Portrait, QMarginsF(0, 0, 0, 0)))
    writer.setTitle(title)
    writer.setCreator("Shaper Designer")
    painter = QPainter(writer)
    dots = PDF_RESOLUTION / 25.4
    painter.scale(dots, dots)
    for number, sheet in enumerate(sheets):
        if number:
            writer.newPage()
        paint_sheet(sheet, painter, language)
    painter.end()
    buffer.close()
    return repair_text_layer(exact_page(bytes(data.data()), paper.width, paper.height))


def svg_bytes(sheet: Sheet, language: str = "en", title: str = "") -> bytes:
    """The sheet as SVG, its size in mm and its viewBox in paper units."""
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    device = QSvgGenerator()
    device.setOutputDevice(buffer)
    w, h = sheet.paper.width, sheet.paper.height
    device.setSize(QSizeF(w * SVG_UNITS_PER_MM, h * SVG_UNITS_PER_MM).toSize())
    device.setViewBox(QRectF(0, 0, w * SVG_UNITS_PER_MM, h * SVG_UNITS_PER_MM))
    device.setResolution(round(25.4 * SVG_UNITS_PER_MM))
    device.setTitle(title)
    painter = QPainter(device)
    painter.scale(SVG_UNITS_PER_MM, SVG_UNITS_PER_MM)
    paint_sheet(sheet, painter, language, svg=True)
    painter.end()
    buffer.close()
    return bytes(data.data())


def write_sheet(sheet: Sheet, path: str, language: str = "en", title: str = "",
                cad_font: str = "gb") -> None:
    """PDF, SVG or DXF by the name's suffix, atomically, a DXF's texts in ``cad_font``
    (``core.drawing.CAD_FONTS``); OSError (a WriteError) names the path."""
    suffix = path.lower().rsplit(".", 1)[-1]
    if suffix == "dxf":
        # imported here, not above: ezdxf's import is ~0.5 s of CPU that a PDF or SVG
        # never uses (a course without --dxf, a report: issue 43 item 4)
        from core.drawing.sheet_dxf import save_sheet_dxf
        save_sheet_dxf(sheet, path, cad_font)
        return
    data = pdf_bytes(sheet, language, title) if suffix == "pdf" else svg_bytes(sheet, language, title)
    if not data:
        raise OSError(errno.EIO, "the writer produced nothing", path)
    atomic_write(path, data)
