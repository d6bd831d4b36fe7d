"""The report as an A4 PDF: QPdfWriter + QPainter, offscreen, vector throughout.

Blocks are laid out in a first pass (tables split across pages with their
header repeated, a heading never left alone at a page foot, figures moved to
the next page when they do not fit), then painted with a title block on the
first page and a framed footer (design name, date, page i / n) on every page.
"""
from __future__ import annotations

import html
from dataclasses import dataclass
from typing import Callable

from PySide6.QtCore import QBuffer, QByteArray, QCoreApplication, QIODevice, QMarginsF, QPointF, QRectF, Qt
from PySide6.QtGui import (QColor, QFont, QFontMetricsF, QPageLayout, QPageSize, QPainter,
                           QPdfWriter, QPen, QTextDocument)

from .blocks import Figure, Heading, KeyValues, Paragraph, Report, Table, cover_rows, typeset
from shaperapp.widgets.fonts import report_font
from shaperapp.widgets.pdf_text import repair_text_layer

translate = QCoreApplication.translate
RESOLUTION = 300
PAGE_MM = (210.0, 297.0)
LEFT_MM, RIGHT_MM, TOP_MM, BOTTOM_MM = 18.0, 16.0, 14.0, 24.0
SHRINK = 0.70            # a figure keeps at least this share of its height on a page
TITLE_MM = 48.0          # the title and cover block on the first page, with the gap under it
GRID = QColor("#90a4ae")
SHADE = QColor("#eef3f8")
HEAD_FILL = QColor("#dfe7ee")
INK = QColor("#1b262c")


@dataclass
class Piece:
    """Something placed on a page: its height and how to paint it at (x, y, width)."""

    height: float
    paint: Callable[[QPainter, float, float, float], None]
    keep_with_next: bool = False
    header: "Piece | None" = None
    """A table row's header, painted first when the row starts a new page."""
    part: str = "text"
    """"figure" for a figure's drawing, "text" for everything else (``page_boxes``)."""
    min_height: float = 0.0
    """A figure may shrink to this height to stay on a page (``paginate``)."""


class Layout:
    """Fonts and measures on the PDF device (device units: 1/300 inch)."""

    def __init__(self, writer: QPdfWriter, language: str) -> None:
        self.writer = writer
        self.mm = RESOLUTION / 25.4
        self.body = report_font(language, 9.5)
        self.small = report_font(language, 7.5)
        self.tiny = report_font(language, 6.5)
        self.bold = QFont(self.body)
        self.bold.setBold(True)
        self.h1 = QFont(self.body)
        self.h1.setPointSizeF(12.5)
        self.h1.setBold(True)
        self.title = QFont(self.body)
        self.title.setPointSizeF(17.0)
        self.title.setBold(True)
        self.width = (PAGE_MM[0] - LEFT_MM - RIGHT_MM) * self.mm

    def metrics(self, font: QFont) -> QFontMetricsF:
        return QFontMetricsF(font, self.writer)

    def document(self, html: str, width: float) -> QTextDocument:
        doc = QTextDocument()
        doc.documentLayout().setPaintDevice(self.writer)
        doc.setDefaultFont(self.body)
        doc.setDocumentMargin(0)
        doc.setHtml(html)
        doc.setTextWidth(width)
        return doc


# ---- blocks → pieces -----------------------------------------------------------
def _heading(lay: Layout, block: Heading) -> list[Piece]:
    m = lay.metrics(lay.h1)
    height = m.height() * 2.0

    def paint(p: QPainter, x: float, y: float, w: float) -> None:
        p.setFont(lay.h1)
        p.setPen(INK)
        p.drawText(QPointF(x, y + m.height() * 1.3), block.text)
        p.setPen(QPen(GRID, 0.3 * lay.mm))
        p.drawLine(QPointF(x, y + m.height() * 1.6), QPointF(x + w, y + m.height() * 1.6))
    return [Piece(height, paint, keep_with_next=True)]


def _paragraph(lay: Layout, block: Paragraph) -> list[Piece]:
    doc = lay.document(block.html, lay.width)
    gap = lay.metrics(lay.body).height() * 0.5

    def paint(p: QPainter, x: float, y: float, w: float) -> None:
        p.save()
        p.translate(x, y)
        doc.drawContents(p)
        p.restore()
    return [Piece(doc.size().height() + gap, paint, keep_with_next=block.keep_with_next)]


def _cell_widths(lay: Layout, font: QFont, header: list[str], rows: list[list[str]],
                 width: float) -> list[float]:
    m = lay.metrics(font)
    pad = m.averageCharWidth() * 1.6
    widths = []
    for c in range(len(header)):
        longest_word = max((m.horizontalAdvance(w) for w in header[c].split()), default=0.0)
        cells = max((m.horizontalAdvance(r[c]) for r in rows), default=0.0)
        widths.append(max(longest_word, cells) + pad)
    spare = width - sum(widths)
    if spare > 0:                      # share the spare width, text columns first
        widths = [w + spare / len(widths) for w in widths]
    return widths


def _table(lay: Layout, block: Table | KeyValues) -> list[Piece]:
    if isinstance(block, KeyValues):
        header, rows, caption, shaded, left = [], [list(r) for r in block.rows], "", [], 2
        plain_header = True
    else:
        header, rows, caption, shaded, left = block.header, block.rows, block.caption, block.shaded, \
            block.left_columns
        plain_header = block.plain_header
    font = lay.body if isinstance(block, KeyValues) else lay.small
    widths = _cell_widths(lay, font, header or rows[0], rows, lay.width)
    if sum(widths) > lay.width * 1.001:
        font = lay.tiny
        widths = _cell_widths(lay, font, header or rows[0], rows, lay.width)
    m = lay.metrics(font)
    row_h = m.height() * 1.45
    head_lines = max((_lines(m, h, w) for h, w in zip(header, widths)), default=0)
    head_h = head_lines * m.height() + 0.45 * m.height() if header else 0.0
    cap_m = lay.metrics(lay.bold)
    cap_h = cap_m.height() * 1.5 if caption else 0.0
    total_w = sum(widths)

    def paint_rows(part: list[int], with_caption: bool, with_header: bool) -> Callable:
        def paint(p: QPainter, x: float, y: float, w: float) -> None:
            p.setPen(INK)
            if with_caption and caption:
                p.setFont(lay.bold)
                p.drawText(QPointF(x, y + cap_m.ascent() + 0.1 * cap_m.height()), caption)
                y += cap_h
            p.setFont(font)
            top_h = head_h if with_header else 0.0
            if with_header:
                p.fillRect(QRectF(x, y, total_w, head_h), HEAD_FILL)
                cx = x
                for text, cw in zip(header, widths):
                    _cell(p, QRectF(cx + 2, y, cw - 4, head_h),
                          Qt.AlignmentFlag.AlignCenter | Qt.TextFlag.TextWordWrap, text, font,
                          not plain_header)
                    cx += cw
                y0 = y
                y += head_h
            else:
                y0 = y
            for r in part:
                if shaded and shaded[r]:
                    p.fillRect(QRectF(x, y, total_w, row_h), SHADE)
                cx = x
                for c, (text, cw) in enumerate(zip(rows[r], widths)):
                    align = Qt.AlignmentFlag.AlignLeft if c < left else Qt.AlignmentFlag.AlignRight
                    _cell(p, QRectF(cx + 0.6 * m.averageCharWidth(), y, cw - 1.2 * m.averageCharWidth(), row_h),
                          align | Qt.AlignmentFlag.AlignVCenter, text, font, c < left)
                    cx += cw
                y += row_h
            p.setPen(QPen(GRID, 0.15 * lay.mm))
            p.drawRect(QRectF(x, y0, total_w, y - y0))
            cx = x
            for cw in widths[:-1]:
                cx += cw
                p.drawLine(QPointF(cx, y0), QPointF(cx, y))
            for k in range(len(part) + 1):
                yy = y0 + top_h + k * row_h
                p.drawLine(QPointF(x, yy), QPointF(x + total_w, yy))
        return paint

    gap = m.height() * 0.8
    # one piece per row, the first with caption and header, so a page break falls between rows
    pieces = [Piece(cap_h + head_h + row_h + (gap if len(rows) == 1 else 0.0),
                    paint_rows([0], True, bool(header)))]
    repeat = Piece(head_h, paint_rows([], False, True)) if header else None
    for r in range(1, len(rows)):
        pieces.append(Piece(row_h + (gap if r == len(rows) - 1 else 0.0),
                            paint_rows([r], False, False), header=repeat))
    for piece in pieces[:2] if len(pieces) > 3 else ():   # no table starts with one row at a page foot
        piece.keep_with_next = True
    if len(pieces) > 3:                                    # nor ends with one row at a page top
        pieces[-2].keep_with_next = True
    return pieces


def _cell(p: QPainter, rect: QRectF, flags, text: str, font: QFont, rich: bool) -> None:
    """A table cell's text; the program's own labels (``rich``) with their notation
    typeset (``typeset``: J_F, v_A2A3, a^k …), user text always as it is."""
    marked = typeset(html.escape(text)) if rich else ""
    if not rich or marked == html.escape(text):
        p.drawText(rect, int(flags), text)
        return
    doc = QTextDocument()
    doc.documentLayout().setPaintDevice(p.device())
    doc.setDefaultFont(font)
    doc.setDocumentMargin(0)
    where = "center" if flags & Qt.AlignmentFlag.AlignHCenter else \
        "right" if flags & Qt.AlignmentFlag.AlignRight else "left"
    doc.setHtml(f'<div align="{where}" style="color:{INK.name()}">{marked}</div>')
    doc.setTextWidth(rect.width())
    p.save()
    p.translate(rect.left(), rect.top() + (rect.height() - doc.size().height()) / 2)
    doc.drawContents(p)
    p.restore()


def _lines(m: QFontMetricsF, text: str, width: float) -> int:
    rect = m.boundingRect(QRectF(0, 0, max(width - 4, 1), 1e6), int(Qt.TextFlag.TextWordWrap), text)
    return max(1, round(rect.height() / m.height()))


def _figure(lay: Layout, block: Figure) -> list[Piece]:
    m = lay.metrics(lay.small)
    cap_doc = lay.document(f"<i>{html.escape(block.caption)}</i>", lay.width) if block.caption else None
    cap_h = cap_doc.size().height() + 0.4 * m.height() if cap_doc else 0.0
    w = min(block.width_mm * lay.mm, lay.width)
    h = block.height_mm * lay.mm * (w / (block.width_mm * lay.mm))

    def paint(p: QPainter, x: float, y: float, width: float) -> None:
        p.save()
        p.setFont(lay.small)
        p.setPen(INK)
        block.paint(p, QRectF(x + (width - w) / 2, y, w, drawing.height), lay.mm)
        p.restore()

    def caption(p: QPainter, x: float, y: float, width: float) -> None:
        if cap_doc is not None:
            p.save()
            p.translate(x, y + 0.2 * m.height())
            cap_doc.drawContents(p)
            p.restore()
    # the drawing and its caption: two pieces on one page (keep_with_next)
    drawing = Piece(h, paint, keep_with_next=True, part="figure", min_height=SHRINK * h)
    return [drawing, Piece(cap_h + m.height() * 0.8, caption)]


def pieces_of(lay: Layout, report: Report) -> list[Piece]:
    out: list[Piece] = []
    for block in report.blocks:
        if isinstance(block, Heading):
            out += _heading(lay, block)
        elif isinstance(block, Paragraph):
            out += _paragraph(lay, block)
        elif isinstance(block, (Table, KeyValues)):
            out += _table(lay, block)
        elif isinstance(block, Figure):
            out += _figure(lay, block)
    return out


# ---- pagination and painting ------------------------------------------------------
def paginate(pieces: list[Piece], first_top: float, top: float, bottom: float) -> list[list[tuple[Piece, float]]]:
    """Pages of (piece, y); a continued table gets its header repeated."""
    pages: list[list[tuple[Piece, float]]] = [[]]
    y = first_top
    for i, piece in enumerate(pieces):
        need = piece.height
        j = i
        while pieces[j].keep_with_next and j + 1 < len(pieces):   # a heading and its intro
            j += 1                                                # stay with what follows
            need += pieces[j].height
        if need > bottom - top:
            need = piece.height + (bottom - top) / 4
        chain = [p for p in pieces[i:j + 1] if p.min_height]
        if y + need > bottom and chain and y + need - sum(p.height - p.min_height for p in chain) <= bottom:
            cut = y + need - bottom       # figures shrink a little rather than leave a gap
            for p in chain:
                take = min(cut, p.height - p.min_height)
                p.height -= take
                cut -= take
            need = bottom - y
        if y + need > bottom + 1e-6 and pages[-1]:
            pages.append([])
            y = top
            if piece.header is not None:
                pages[-1].append((piece.header, y))
                y += piece.header.height
        pages[-1].append((piece, y))
        y += piece.height
    return pages


def pdf_bytes(report: Report, parts: tuple[str, ...] = ("text", "figure")) -> tuple[bytes, int]:
    """The PDF of ``report`` in memory, its text layer repaired (``pdf_text``), and its
    page count; the caller writes it (atomically, so a failed save never leaves half a report). ``parts`` leaves out
    the pieces of other parts (and the title block and footers unless "text"): the
    tests print the figures alone to find ink outside their boxes."""
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    pages = _paint_pdf(report, QPdfWriter(buffer), parts)
    buffer.close()
    return repair_text_layer(bytes(data.data())), pages


def page_boxes(report: Report) -> list[list[tuple[str, QRectF]]]:
    """Per page, the part ("text" or "figure") and box (in mm from the page's top left)
    of every piece laid out on it, as :func:`pdf_bytes` places them."""
    buffer = QBuffer()
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    writer = QPdfWriter(buffer)
    lay, pages = _layout(report, writer)
    mm = lay.mm
    return [[(piece.part, QRectF(LEFT_MM, y / mm, lay.width / mm, piece.height / mm))
             for piece, y in page] for page in pages]


def _layout(report: Report, writer: QPdfWriter) -> tuple[Layout, list[list[tuple[Piece, float]]]]:
    writer.setResolution(RESOLUTION)
    writer.setPageLayout(QPageLayout(QPageSize(QPageSize.PageSizeId.A4), QPageLayout.Orientation.Portrait,
                                     QMarginsF(0, 0, 0, 0)))
    writer.setTitle(f"{report.title} — {report.name}")
    writer.setCreator("Shaper Designer")
    lay = Layout(writer, report.language)
    mm = lay.mm
    top, bottom = TOP_MM * mm, (PAGE_MM[1] - BOTTOM_MM) * mm
    return lay, paginate(pieces_of(lay, report), top + TITLE_MM * mm, top, bottom)


def _paint_pdf(report: Report, writer: QPdfWriter, parts: tuple[str, ...] = ("text", "figure")) -> int:
    lay, pages = _layout(report, writer)
    mm = lay.mm
    painter = QPainter(writer)
    try:
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        for n, page in enumerate(pages):
            if n:
                writer.newPage()
            if n == 0 and "text" in parts:
                _title_block(painter, lay, report, TOP_MM * mm, (TITLE_MM - 6) * mm)
            for piece, y in page:
                if piece.part in parts:
                    piece.paint(painter, LEFT_MM * mm, y, lay.width)
            if "text" in parts:
                _footer(painter, lay, report, n + 1, len(pages))
    finally:
        painter.end()
    return len(pages)


def _title_block(p: QPainter, lay: Layout, report: Report, y: float, height: float) -> None:
    """The title over the cover block (``cover_rows``): four rows of two label–value cells."""
    x, w = LEFT_MM * lay.mm, lay.width
    p.setPen(QPen(INK, 0.35 * lay.mm))
    p.drawRect(QRectF(x, y, w, height))
    title_h = 14.0 * lay.mm
    p.setFont(lay.title)
    p.drawText(QRectF(x, y, w, title_h), int(Qt.AlignmentFlag.AlignCenter), report.title)
    rows = cover_rows(report)
    row_h = (height - title_h) / 4
    label_w = max(lay.metrics(lay.small).horizontalAdvance(label) for label, _ in rows) + 4 * lay.mm
    p.setPen(QPen(INK, 0.2 * lay.mm))
    for k, (label, value) in enumerate(rows):       # the design alone on the first row
        column = (k + 1) % 2 if k else 0
        cw = w if k == 0 else w / 2
        cx, cy = x + column * w / 2, y + title_h + ((k + 1) // 2) * row_h
        p.drawLine(QPointF(x, cy), QPointF(x + w, cy))
        if column:
            p.drawLine(QPointF(cx, cy), QPointF(cx, cy + row_h))
        p.setFont(lay.small)
        p.drawText(QRectF(cx + 2 * lay.mm, cy, label_w, row_h), int(Qt.AlignmentFlag.AlignVCenter), label)
        p.setFont(lay.body)
        room = cw - label_w - 4 * lay.mm
        text = lay.metrics(lay.body).elidedText(value, Qt.TextElideMode.ElideRight, room)
        p.drawText(QRectF(cx + 2 * lay.mm + label_w, cy, room, row_h), int(Qt.AlignmentFlag.AlignVCenter), text)


def _footer(p: QPainter, lay: Layout, report: Report, page: int, pages: int) -> None:
    mm = lay.mm
    x, w = LEFT_MM * mm, lay.width
    y = (PAGE_MM[1] - BOTTOM_MM + 8.0) * mm
    h = 9.0 * mm
    p.setPen(QPen(INK, 0.25 * mm))
    p.drawRect(QRectF(x, y, w, h))
    widths = [0.38, 0.30, 0.16, 0.16]
    texts = [report.name, translate("Report", "Design report"), report.date,
             translate("Report", "Page %1 / %2").replace("%1", str(page)).replace("%2", str(pages))]
    p.setFont(lay.small)
    cx = x
    for i, (frac, text) in enumerate(zip(widths, texts)):
        if i:
            p.drawLine(QPointF(cx, y), QPointF(cx, y + h))
        p.drawText(QRectF(cx + 2 * mm, y, frac * w - 4 * mm, h), int(Qt.AlignmentFlag.AlignVCenter), text)
        cx += frac * w
