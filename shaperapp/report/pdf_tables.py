"""Tables in the PDF report: column widths, the split into blocks of columns when a
table is wider than the page (``blocks.column_blocks``), one piece per row so that a
page break falls between rows (the header repeated), and the cells' rich text."""
from __future__ import annotations

import html
import re
from typing import Callable

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QFont, QFontMetricsF, QPainter, QPen, QTextDocument

from shaperapp.widgets.notation import typeset

from .blocks import KeyValues, Table, column_blocks, split_table
from .pdf_base import GRID, HEAD_FILL, INK, KEEP_WHOLE_ROWS, SHADE, Layout, Piece


def _cell_widths(lay: Layout, font: QFont, header: list[str], rows: list[list[str]],
                 width: float) -> list[float]:
    m = lay.metrics(font)
    pad = m.averageCharWidth() * 1.6
    widths = []
    for c in range(len(header)):
        longest_word = lay.widest(font, header[c].split())
        cells = lay.widest(font, [r[c] for r in rows])
        widths.append(max(longest_word, cells) + pad)
    spare = width - sum(widths)
    if spare > 0:                      # share the spare width, text columns first
        widths = [w + spare / len(widths) for w in widths]
    return widths


def table_pieces(lay: Layout, block: Table | KeyValues) -> list[Piece]:
    """A table's pieces; one too wide for the page even in the tiny font is split into
    blocks of columns, its identifying columns repeated in each (``column_blocks``)."""
    if isinstance(block, KeyValues):
        return _table_pieces(lay, block, lay.body)
    font = lay.small
    widths = _cell_widths(lay, font, block.header, block.rows, lay.width)
    if sum(widths) > lay.width * 1.001:
        font = lay.tiny
        widths = _cell_widths(lay, font, block.header, block.rows, lay.width)
    blocks = column_blocks(widths, block.key_columns or block.left_columns, lay.width)
    return [piece for part in split_table(block, blocks) for piece in _table_pieces(lay, part, font)]


def _table_pieces(lay: Layout, block: Table | KeyValues, font: QFont) -> list[Piece]:
    if isinstance(block, KeyValues):
        header, rows, caption, shaded, left = [], [list(r) for r in block.rows], "", [], 2
        plain_header = True
    else:
        header, rows, caption, shaded, left = block.header, block.rows, block.caption, block.shaded, \
            block.left_columns
        plain_header = block.plain_header
    widths = _cell_widths(lay, font, header or rows[0], rows, lay.width)
    m = lay.metrics(font)
    row_h = m.height() * 1.45
    wrap = 0
    if isinstance(block, KeyValues) and sum(widths) > lay.width:   # a long value wraps in its cell
        widths[-1] = max(lay.width - sum(widths[:-1]), lay.width / 3)
        wrap = int(Qt.TextFlag.TextWordWrap)
    inset = 0.6 * m.averageCharWidth()
    heights = [row_h + (max(_lines(m, t, w - 2 * inset + 4) for t, w in zip(row, widths)) - 1) * m.height()
               if wrap else row_h for row in rows]
    head_lines = max((_lines(m, keep_units(h), w) for h, w in zip(header, widths)), default=0)
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
            if with_header:
                p.fillRect(QRectF(x, y, total_w, head_h), HEAD_FILL)
                cx = x
                for text, cw in zip(header, widths):
                    _cell(p, QRectF(cx + 2, y, cw - 4, head_h),
                          Qt.AlignmentFlag.AlignCenter | Qt.TextFlag.TextWordWrap,
                          text if plain_header else keep_units(text), font, not plain_header)
                    cx += cw
                y0 = y
                y += head_h
            else:
                y0 = y
            rules = [y]
            left_flags = int(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter) | wrap
            right_flags = int(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter) | wrap
            for r in part:
                if shaded and shaded[r]:
                    p.fillRect(QRectF(x, y, total_w, heights[r]), SHADE)
                cx = x
                for c, (text, cw) in enumerate(zip(rows[r], widths)):
                    rect = QRectF(cx + inset, y, cw - 2 * inset, heights[r])
                    if c < left:
                        _cell(p, rect, left_flags, text, font, True)
                    else:                  # numbers: plain text (what _cell draws unmarked)
                        p.drawText(rect, right_flags, text)
                    cx += cw
                y += heights[r]
                rules.append(y)
            p.setPen(QPen(GRID, 0.15 * lay.mm))
            p.drawRect(QRectF(x, y0, total_w, y - y0))
            cx = x
            for cw in widths[:-1]:
                cx += cw
                p.drawLine(QPointF(cx, y0), QPointF(cx, y))
            for yy in rules:
                p.drawLine(QPointF(x, yy), QPointF(x + total_w, yy))
        return paint

    gap = m.height() * 0.8
    # one piece per row, the first with caption and header, so a page break falls between rows
    pieces = [Piece(cap_h + head_h + heights[0] + (gap if len(rows) == 1 else 0.0),
                    paint_rows([0], True, bool(header)))]
    repeat = Piece(head_h, paint_rows([], False, True)) if header else None
    for r in range(1, len(rows)):
        pieces.append(Piece(heights[r] + (gap if r == len(rows) - 1 else 0.0),
                            paint_rows([r], False, False), header=repeat))
    if len(pieces) <= KEEP_WHOLE_ROWS:                     # a short table is never split
        for piece in pieces[:-1]:
            piece.keep_with_next = True
        return pieces
    for piece in pieces[:2]:                               # no table starts with one row at a page foot
        piece.keep_with_next = True
    pieces[-2].keep_with_next = True                       # nor ends with one row at a page top
    return pieces


def _cell(p: QPainter, rect: QRectF, flags, text: str, font: QFont, rich: bool) -> None:
    """A table cell's text; the program's own labels (``rich``) with their notation
    typeset (``typeset``: J_F, v_A3A4, a^k …), user text always as it is."""
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


_UNIT = re.compile(r"\(([^()\s]*)\)")


def keep_units(text: str) -> str:
    """``text`` with a word joiner after each "/" of a unit in parentheses: a header
    wraps before "(rad/s²)", never inside it ("(rad/" over "s²)", issue 32)."""
    return _UNIT.sub(lambda m: "(" + m[1].replace("/", "/\u2060") + ")", text)


def _lines(m: QFontMetricsF, text: str, width: float) -> int:
    rect = m.boundingRect(QRectF(0, 0, max(width - 4, 1), 1e6), int(Qt.TextFlag.TextWordWrap), text)
    return max(1, round(rect.height() / m.height()))
