"""The report as an A4 PDF: QPdfWriter + QPainter, offscreen, vector throughout.

Blocks are laid out in a first pass (tables split across pages with their
header repeated, a heading never left alone at a page foot, figures moved to
the next page when they do not fit), then painted with a title block on the
first page and a framed footer (design name, date, page i / n) on every page.
"""
from __future__ import annotations

import html

from PySide6.QtCore import QBuffer, QByteArray, QIODevice, QMarginsF, QPointF, QRectF, Qt
from PySide6.QtGui import QFont, QPageLayout, QPageSize, QPainter, QPdfWriter, QPen

from core.base.progress import Progress

from .blocks import Figure, Heading, KeyValues, Paragraph, Report, Table, contents, cover_rows
from .pdf_base import (BOTTOM_MM, GRID, INK, LEFT_MM, PAGE_MM, RESOLUTION, SHRINK, TITLE_MM, TOP_MM,
                       Layout, Piece, translate)
from .pdf_tables import table_pieces
from shaperapp.widgets.pdf_page import exact_page
from shaperapp.widgets.pdf_text import repair_text_layer


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
    return [Piece(height, paint, keep_with_next=True, heading=block.text)]


def _contents(lay: Layout, report: Report, pages: dict[str, int]) -> list[Piece]:
    """The contents under the cover (:func:`blocks.contents`): each section's heading and its
    page, with dot leaders. The pages are those ``pages`` holds when the piece is painted
    (filled in after the layout: the contents' height does not depend on them, so one
    layout serves)."""
    m = lay.metrics(lay.body)
    line = m.height() * 1.25
    title, headings = contents(report)

    def paint_title(p: QPainter, x: float, y: float, w: float) -> None:
        p.setFont(lay.h1)
        p.setPen(INK)
        p.drawText(QPointF(x, y + lay.metrics(lay.h1).height() * 1.1), title)

    def entry(text: str) -> Piece:
        def paint(p: QPainter, x: float, y: float, w: float) -> None:
            page = str(pages.get(text, ""))
            p.setFont(lay.body)
            p.setPen(INK)
            base = y + m.ascent()
            p.drawText(QPointF(x, base), text)
            p.drawText(QPointF(x + w - m.horizontalAdvance(page), base), page)
            start = x + m.horizontalAdvance(text) + m.horizontalAdvance(" ")
            end = x + w - m.horizontalAdvance(page) - m.horizontalAdvance(" ")
            dot = m.horizontalAdvance(". ")
            count = int(max(end - start, 0.0) // dot)
            p.drawText(QPointF(end - count * dot, base), ". " * count)
        return Piece(line, paint, keep_with_next=True)
    out = [Piece(lay.metrics(lay.h1).height() * 1.6, paint_title, keep_with_next=True)]
    out += [entry(text) for text in headings]
    out[-1].keep_with_next = False
    out[-1].height += m.height()
    return out


def _paragraph(lay: Layout, block: Paragraph) -> list[Piece]:
    doc = lay.document(block.html, lay.width)
    gap = lay.metrics(lay.body).height() * 0.5

    def paint(p: QPainter, x: float, y: float, w: float) -> None:
        p.save()
        p.translate(x, y)
        doc.drawContents(p)
        p.restore()
    return [Piece(doc.size().height() + gap, paint, keep_with_next=block.keep_with_next)]


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
    drawing = Piece(h, paint, keep_with_next=True, part="figure",
                    min_height=0.0 if block.to_scale else SHRINK * h)
    return [drawing, Piece(cap_h + m.height() * 0.8, caption)]


def pieces_of(lay: Layout, report: Report) -> list[Piece]:
    out: list[Piece] = []
    for block in report.blocks:
        if isinstance(block, Heading):
            out += _heading(lay, block)
        elif isinstance(block, Paragraph):
            out += _paragraph(lay, block)
        elif isinstance(block, (Table, KeyValues)):
            out += table_pieces(lay, block)
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


def pdf_bytes(report: Report, parts: tuple[str, ...] = ("text", "figure"),
              progress: Progress = Progress()) -> tuple[bytes, int]:
    """The PDF of ``report`` in memory, its text layer repaired (``pdf_text``), and its
    page count, every page exactly A4 (``pdf_page``); the caller writes it (atomically, so a failed save never leaves half a report). ``parts`` leaves out
    the pieces of other parts (and the title block and footers unless "text"): the
    tests print the figures alone to find ink outside their boxes. ``progress`` hears of
    the layout and of every page painted (Cancelled when it says stop)."""
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    pages = _paint_pdf(report, QPdfWriter(buffer), parts, progress)
    buffer.close()
    return repair_text_layer(exact_page(bytes(data.data()), *PAGE_MM)), pages


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
    body = pieces_of(lay, report)
    numbers: dict[str, int] = {}
    pages = paginate(_contents(lay, report, numbers) + body, top + TITLE_MM * mm, top, bottom)
    for n, page in enumerate(pages, 1):
        numbers.update({piece.heading: n for piece, _ in page if piece.heading and piece.heading not in numbers})
    return lay, pages


LAYOUT_SHARE = 0.2         # of the PDF's progress: the layout; the pages share the rest


def _paint_pdf(report: Report, writer: QPdfWriter, parts: tuple[str, ...] = ("text", "figure"),
               progress: Progress = Progress()) -> int:
    lay, pages = _layout(report, writer)
    progress.done(LAYOUT_SHARE)
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
            progress.done(LAYOUT_SHARE + (1.0 - LAYOUT_SHARE) * (n + 1) / len(pages))
    finally:
        painter.end()
    return len(pages)


def _title_block(p: QPainter, lay: Layout, report: Report, y: float, height: float) -> None:
    """The title over the cover block (``cover_rows``): four rows of two label–value cells."""
    x, w = LEFT_MM * lay.mm, lay.width
    p.setPen(QPen(INK, 0.35 * lay.mm))
    p.drawRect(QRectF(x, y, w, height))
    title_h = 14.0 * lay.mm
    room = w - 2 * CELL_PAD_MM * lay.mm          # the frame's margin, as the cells' texts keep
    p.setFont(_fitting(lay, lay.title, report.title, room))
    p.drawText(QRectF(x + CELL_PAD_MM * lay.mm, y, room, title_h),
               int(Qt.AlignmentFlag.AlignCenter | Qt.TextFlag.TextWordWrap), report.title)
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
        p.drawText(QRectF(cx + CELL_PAD_MM * lay.mm, cy, label_w, row_h), int(Qt.AlignmentFlag.AlignVCenter), label)
        room = cw - label_w - 4 * lay.mm
        font, flags, text = _cover_value(lay, value, room, row_h)
        p.setFont(font)
        p.drawText(QRectF(cx + 2 * lay.mm + label_w, cy, room, row_h), flags, text)


CELL_PAD_MM = 2.0       # a cover text's least distance from its cell's lines


def _fitting(lay: Layout, font: QFont, text: str, room: float) -> QFont:
    """``font``, made smaller (to the body size at least) until ``text`` fits ``room`` on one
    line: the English title ran to 1 mm from the cover's frame at 17 pt."""
    fitted = QFont(font)
    while lay.metrics(fitted).horizontalAdvance(text) > room and fitted.pointSizeF() > lay.body.pointSizeF():
        fitted.setPointSizeF(max(fitted.pointSizeF() - 0.5, lay.body.pointSizeF()))
    return fitted


def _cover_value(lay: Layout, value: str, room: float, row_h: float) -> tuple[QFont, int, str]:
    """A cover value in the body type, or (a long design name) in the small type on up
    to two lines, elided only if even that is too long: the name is the report's, and
    the footer can only show its start."""
    middle = int(Qt.AlignmentFlag.AlignVCenter)
    if lay.metrics(lay.body).horizontalAdvance(value) <= room:
        return lay.body, middle, value
    m = lay.metrics(lay.small)
    wrap = middle | int(Qt.TextFlag.TextWordWrap)
    if m.boundingRect(QRectF(0, 0, room, 1e6), wrap, value).height() <= min(2 * m.lineSpacing(), row_h) + 1:
        return lay.small, wrap, value
    return lay.small, middle, m.elidedText(value, Qt.TextElideMode.ElideRight, room)


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
        room = frac * w - 4 * mm            # a long design name ends in "…", never cut mid-letter
        text = lay.metrics(lay.small).elidedText(text, Qt.TextElideMode.ElideRight, room)
        p.drawText(QRectF(cx + 2 * mm, y, room, h), int(Qt.AlignmentFlag.AlignVCenter), text)
        cx += frac * w
