"""What every part of the PDF report shares: the page's measures, the colours, the fonts
(``Layout``) and the ``Piece`` that is laid out on a page."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QColor, QFont, QFontMetricsF, QPainter, QPdfWriter, QTextDocument

from shaperapp.widgets.fonts import report_font

translate = QCoreApplication.translate
RESOLUTION = 300
PAGE_MM = (210.0, 297.0)
LEFT_MM, RIGHT_MM, TOP_MM, BOTTOM_MM = 18.0, 16.0, 14.0, 24.0
SHRINK = 0.70            # a figure keeps at least this share of its height on a page
KEEP_WHOLE_ROWS = 8      # a table of at most this many rows stays on one page
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
    heading: str = ""
    """A section heading's text: the contents list it with the page it lands on."""


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
        self._advances: dict[str, dict[str, float]] = {}

    def metrics(self, font: QFont) -> QFontMetricsF:
        return QFontMetricsF(font, self.writer)

    def widest(self, font: QFont, texts) -> float:
        """The largest horizontal advance of ``texts`` in ``font`` (0 for none). Each
        text is measured once per font and report: a table's columns are measured again
        for every block of columns and in the smaller type, and a 3600-position table
        repeats many numbers (1.2 million measurements, 1.3 s of a 16-speed report)."""
        cache = self._advances.setdefault(font.key(), {})
        m = None
        widest = 0.0
        for text in texts:
            width = cache.get(text)
            if width is None:
                if m is None:
                    m = self.metrics(font)
                width = cache[text] = m.horizontalAdvance(text)
            widest = max(widest, width)
        return widest

    def document(self, html: str, width: float) -> QTextDocument:
        doc = QTextDocument()
        doc.documentLayout().setPaintDevice(self.writer)
        doc.setDefaultFont(self.body)
        doc.setDocumentMargin(0)
        doc.setHtml(html)
        doc.setTextWidth(width)
        return doc
