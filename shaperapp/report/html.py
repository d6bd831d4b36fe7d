"""The same report as one self-contained HTML file (figures as inline SVG).

Figures are painted by the same functions as in the PDF, into a QSvgGenerator
sized in millimetres, so a printed page shows the polygons at their scale μ.
"""
from __future__ import annotations

import html
import math

from PySide6.QtCore import QBuffer, QByteArray, QIODevice, QRectF, QSize
from PySide6.QtGui import QFont, QPainter
from PySide6.QtSvg import QSvgGenerator

from shaperapp.widgets.fonts import report_font
from shaperapp.widgets.notation import typeset

from .blocks import (Figure, Heading, KeyValues, Paragraph, Report, Table, column_blocks, contents,
                     cover_rows, split_table)

SVG_DPI = 96.0
STYLE = """
body { font-family: %(family)s, sans-serif; font-size: 10pt; color: #1b262c; max-width: 190mm;
       margin: 12mm auto; }
.title { border: 1.5px solid #1b262c; margin-bottom: 8mm; }
.title h1 { text-align: center; font-size: 17pt; margin: 4mm 0; }
.title table { width: 100%%; border-collapse: collapse; }
.title td, .title th { border-top: 1px solid #1b262c; text-align: left; padding: 1.5mm 2mm; }
.title th { font-weight: normal; font-size: 8pt; white-space: nowrap; width: 1%%; }
.title td { width: 49%%; }
.title th + td + th { border-left: 1px solid #1b262c; }
h2 { font-size: 12.5pt; border-bottom: 1px solid #90a4ae; margin-top: 7mm; }
table.data { border-collapse: collapse; margin: 2mm 0 5mm; font-size: 8pt; }
table.data th { background: #dfe7ee; font-weight: normal; padding: 1mm 1.5mm; }
table.data td, table.data th { border: 1px solid #90a4ae; padding: 0.6mm 1.5mm; }
table.data td { text-align: right; white-space: nowrap; }
table.data td.l { text-align: left; }
table.data tr.special { background: #eef3f8; }
table.kv td { padding: 0.5mm 4mm 0.5mm 0; }
.caption { font-weight: bold; margin: 2mm 0 0; }
figure { margin: 4mm 0; page-break-inside: avoid; }
figcaption { font-style: italic; font-size: 8.5pt; }
nav.contents ol { list-style: none; padding-left: 0; }
nav.contents li { margin: 1mm 0; }
"""


def figure_svg(figure: Figure, font: QFont) -> str:
    """The figure painted into an SVG of its size in mm (true scale when printed)."""
    px = SVG_DPI / 25.4
    size = QSize(math.ceil(figure.width_mm * px), math.ceil(figure.height_mm * px))
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    generator = QSvgGenerator()
    generator.setOutputDevice(buffer)
    generator.setSize(size)
    generator.setViewBox(QRectF(0, 0, size.width(), size.height()))
    generator.setResolution(int(SVG_DPI))
    painter = QPainter(generator)
    try:
        painter.setFont(font)
        figure.paint(painter, QRectF(0, 0, size.width(), size.height()), px)
    finally:
        painter.end()
    buffer.close()
    text = bytes(data).decode("utf-8")
    return text[text.index("<svg"):]


def _label(text: str) -> str:
    """A label of the program's own (never user text), escaped, its notation typeset."""
    return typeset(html.escape(text))


PAGE_MM = 190.0          # the body's max-width
CHAR_MM, CELL_PAD_MM = 1.6, 3.4     # an 8 pt character (a CJK one counts twice), a cell's padding


def _text_mm(text: str) -> float:
    return CHAR_MM * sum(2 if ord(ch) > 0x2e80 else 1 for ch in text)


def _tables(block: Table) -> str:
    """``block``, split into blocks of columns when it is wider than the page (as in
    the PDF, widths estimated from the characters: a browser prints what is wider cut)."""
    widths = [max([_text_mm(w) for w in block.header[c].split()]
                  + [_text_mm(r[c]) for r in block.rows]) + CELL_PAD_MM for c in range(len(block.header))]
    blocks = column_blocks(widths, block.key_columns or block.left_columns, PAGE_MM)
    return "\n".join(_table(part) for part in split_table(block, blocks))


def _table(block: Table) -> str:
    out = []
    if block.caption:
        out.append(f'<p class="caption">{html.escape(block.caption)}</p>')
    head = (html.escape if block.plain_header else _label)
    out.append('<table class="data"><tr>' + "".join(f"<th>{head(h)}</th>" for h in block.header)
               + "</tr>")
    for r, row in enumerate(block.rows):
        special = ' class="special"' if block.shaded and block.shaded[r] else ""
        cells = "".join(("<td class='l'>" + _label(v) if c < block.left_columns else "<td>" + html.escape(v))
                        + "</td>" for c, v in enumerate(row))
        out.append(f"<tr{special}>{cells}</tr>")
    out.append("</table>")
    return "\n".join(out)


def report_html(report: Report) -> str:
    font = report_font(report.language, 8.0)
    rows = cover_rows(report)
    cell = lambda label, value, span="": f"<th>{html.escape(label)}</th><td{span}>{html.escape(value)}</td>"  # noqa: E731
    cells = [cell(*rows[0], ' colspan="3"')] + ["".join(cell(*r) for r in rows[k:k + 2])
                                                 for k in range(1, len(rows), 2)]
    body = [f'<div class="title"><h1>{html.escape(report.title)}</h1><table>'
            + "".join(f"<tr>{row}</tr>" for row in cells) + "</table></div>"]
    title, headings = contents(report)
    body.append(f'<nav class="contents"><h2>{html.escape(title)}</h2><ol>'
                + "".join(f'<li><a href="#section-{k}">{html.escape(text)}</a></li>'
                          for k, text in enumerate(headings, 1)) + "</ol></nav>")
    sections = iter(range(1, len(headings) + 1))
    for block in report.blocks:
        if isinstance(block, Heading):
            body.append(f'<h2 id="section-{next(sections)}">{html.escape(block.text)}</h2>')
        elif isinstance(block, Paragraph):
            body.append(f"<p>{block.html}</p>")
        elif isinstance(block, KeyValues):
            body.append('<table class="kv">' + "".join(
                f"<tr><td>{_label(k)}</td><td>{_label(v)}</td></tr>" for k, v in block.rows)
                + "</table>")
        elif isinstance(block, Table):
            body.append(_tables(block))
        elif isinstance(block, Figure):
            caption = f"<figcaption>{html.escape(block.caption)}</figcaption>" if block.caption else ""
            body.append(f"<figure>{figure_svg(block, font)}{caption}</figure>")
    lang = "zh-CN" if report.language.startswith("zh") else "en"
    style = STYLE % {"family": ", ".join(f"'{f}'" for f in report_font(report.language).families())}
    return (f'<!DOCTYPE html>\n<html lang="{lang}"><head><meta charset="utf-8">'
            f"<title>{html.escape(report.title)} — {html.escape(report.name)}</title>"
            f"<style>{style}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")
