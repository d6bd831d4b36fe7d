"""A read-only results table that never hides a row: the shared component of the results pane.

Every row is always shown: the table's height is fixed to its header, its rows and, when
the columns are wider than the pane, the horizontal scroll bar (which then scrolls the
columns while the row titles stay). Columns share the spare width when they fit; when
they scroll, they are of one width that a whole number of them fill, and scroll a whole
column at a time, so no number is ever cut at either edge (scrolled by the pixel,
253.0615 read 53.0615 beside the row titles). Cells
are selectable; Ctrl+C (or the right-click Copy) puts the selection, or the whole table,
with its titles on the clipboard as tab-separated text, which pastes into a spreadsheet
as cells.
"""
from __future__ import annotations

from typing import Callable, Sequence

from PySide6.QtCore import QEvent, QSize, Qt
from PySide6.QtGui import QAction, QFont, QFontMetrics, QGuiApplication, QKeyEvent, QKeySequence
from PySide6.QtWidgets import (QAbstractButton, QAbstractItemView, QAbstractScrollArea, QHeaderView,
                               QSizePolicy, QStyle, QStyleOptionHeader, QTableWidget, QTableWidgetItem,
                               QWidget)

CELL_PADDING = 16            # px beside a cell's text (margins of the item delegate and grid)
TITLES_SHARE = 0.3           # row titles are wrapped when their column keeps at least this share
RIGHT = Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter


class ResultTable(QTableWidget):
    """Row titles (quantity with unit) × column titles (a value, or one per crank speed)."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.setSelectionMode(QAbstractItemView.SelectionMode.ExtendedSelection)
        self.setWordWrap(False)
        self.setVerticalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAsNeeded)
        self.setHorizontalScrollMode(QAbstractItemView.ScrollMode.ScrollPerItem)
        self.setSizeAdjustPolicy(QAbstractScrollArea.SizeAdjustPolicy.AdjustIgnored)
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Fixed)
        rows = self.verticalHeader()
        rows.setSectionResizeMode(QHeaderView.ResizeMode.Fixed)
        rows.setDefaultSectionSize(QFontMetrics(self.font()).height() + 6)
        rows.setDefaultAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter)
        self.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Interactive)
        self.horizontalHeader().setStretchLastSection(False)
        self._rows: list[str] = []          # the row titles as given (shown wrapped where needed)
        self._wrap_width = -1               # px the shown titles are wrapped to (-1: not wrapped)
        self._pinned = 0                    # px the column titles are moved down (pin_header)
        self._least_column = 0              # px the first column's texts need (set by _fit)
        self._widths: list[int] = []        # px each column's texts need (set by _fit)
        # The owner's hook to bring content it fills lazily up to date before a copy.
        self.before_read: Callable[[], None] = lambda: None
        self.copy_action = QAction(self)
        self.copy_action.triggered.connect(self.copy)
        self.addAction(self.copy_action)
        self.setContextMenuPolicy(Qt.ContextMenuPolicy.ActionsContextMenu)
        self._retranslate()

    # ---- content -------------------------------------------------------------
    def set_content(self, rows: Sequence[str], columns: Sequence[str], cells: Sequence[Sequence[str]],
                    tips: Sequence[str] | None = None) -> None:
        """Show ``cells[row][column]`` under the given titles (``tips`` for the row titles).

        Items are created once and then only get new text, with the model's signals
        blocked and one repaint: announcing every cell re-measured the headers each time,
        the slowest part of an edit."""
        if self.rowCount() != len(rows) or self.columnCount() != len(columns):
            self.setRowCount(len(rows))
            self.setColumnCount(len(columns))
        if self._rows != list(rows):
            self._rows = list(rows)
            self._wrap_width = -1
            self.setVerticalHeaderLabels(self._rows)
        if self._titles(Qt.Orientation.Horizontal) != list(columns):
            self.setHorizontalHeaderLabels(list(columns))
        for row, tip in enumerate(tips or ()):
            self.verticalHeaderItem(row).setToolTip(tip)
        self.model().blockSignals(True)
        try:
            for row, texts in enumerate(cells):
                for col, text in enumerate(texts):
                    item = self.item(row, col)
                    if item is None:
                        item = QTableWidgetItem(text)
                        item.setTextAlignment(RIGHT)
                        self.setItem(row, col, item)
                    elif item.text() != text:
                        item.setText(text)
        finally:
            self.model().blockSignals(False)
        self._fit()
        self.viewport().update()

    def text(self, row: int, column: int) -> str:
        item = self.item(row, column)
        return item.text() if item else ""

    def _titles(self, orientation: Qt.Orientation) -> list[str]:
        if orientation == Qt.Orientation.Vertical:
            return list(self._rows)
        count = self.rowCount() if orientation == Qt.Orientation.Vertical else self.columnCount()
        item = self.verticalHeaderItem if orientation == Qt.Orientation.Vertical else self.horizontalHeaderItem
        return [item(i).text() if item(i) else "" for i in range(count)]

    # ---- size: every row shown, columns scroll -------------------------------
    def _fit(self) -> None:
        """Columns as wide as their texts, sharing any spare width; height for every row."""
        metrics = QFontMetrics(self.font())
        head = QFontMetrics(self.horizontalHeader().font())
        widths = []
        for col in range(self.columnCount()):
            title = self.horizontalHeaderItem(col)
            width = head.horizontalAdvance(title.text() if title else "") + CELL_PADDING + 8
            for row in range(self.rowCount()):
                width = max(width, metrics.horizontalAdvance(self.text(row, col)) + CELL_PADDING)
            widths.append(width)
        self._least_column = widths[0] if widths else 0   # the first column's own need
        self._widths = widths
        self._wrap_titles(widths)
        room = self.width() - 2 * self.frameWidth() - self.verticalHeader().sizeHint().width()
        spare = room - sum(widths)
        if widths and spare >= 0:
            widths = [w + spare // len(widths) for w in widths]
            widths[-1] += spare - (spare // len(widths)) * len(widths)
        elif widths:
            widths = whole_columns(widths, room)
        header = self.horizontalHeader()
        for col, width in enumerate(widths):
            if header.sectionSize(col) != width:
                header.resizeSection(col, width)
        self._fit_height(sum(widths) > room)

    def _wrap_titles(self, widths: list[int]) -> None:
        """Long row titles on two lines where that lets every column be seen (with two
        speeds the forces table's 60 r/min column was cut off behind its long titles);
        not where the columns scroll anyway (many speeds).

        The choice is a function of the table's width, its columns and its titles alone,
        measured as the row header measures them (``title_width``): it read the padding
        as the header's width less the widest title shown, but the header measures in
        bold, so that "padding" grew with the widest line shown (22 px beside "Max return
        speed, m/s", 19 beside "Max |acceleration|,"), and the titles wrapped to 135 px
        let that line stand whole, 132 px broke it, and so on every turn of the event loop
        (the speeds table at a pane of 324 px; 22 of the widths 200–420 px looped).

        Once wrapped they stay wrapped down to a scroll bar's width less: wrapped titles
        make the tables taller, which can bring the Results pane's own scroll bar and
        take that width from the tables (b7f7626). Which layout shows within that band
        depends on what came before."""
        header = self.verticalHeader()
        metrics = title_metrics(header)
        padding = title_padding(header)
        total = self.width() - 2 * self.frameWidth()
        longest = max((title_width(metrics, t) for t in self._rows), default=0) + padding
        free = total - sum(widths)
        least = TITLES_SHARE * total
        if self._wrap_width >= 0:       # wrapped: kept while a scroll bar's width narrower
            least -= self.style().pixelMetric(QStyle.PixelMetric.PM_ScrollBarExtent)
        width = free - padding if longest > free >= least else -1
        if width == self._wrap_width:
            return
        self._wrap_width = width
        line = QFontMetrics(self.font()).height() + 6
        for row, title in enumerate(self._rows):
            shown = title if width < 0 else _two_lines(title, metrics, width)
            item = self.verticalHeaderItem(row)
            if item is not None and item.text() != shown:
                item.setText(shown)
            header.resizeSection(row, line + (QFontMetrics(header.font()).height() if "\n" in shown else 0))

    def _least_titles(self) -> int:
        """px the row titles need at their narrowest, each on two lines: a width that does
        not move with their wrapping (the header's own width did, by 24 px in the speeds
        table, and with it the table's least width and so the pane's)."""
        header = self.verticalHeader()
        metrics = title_metrics(header)
        return (max((title_width(metrics, _two_lines(t, metrics, 0)) for t in self._rows), default=0)
                + title_padding(header))

    def _fit_height(self, scrolls: bool) -> None:
        height = (self.horizontalHeader().sizeHint().height() + self.verticalHeader().length()
                  + 2 * self.frameWidth())
        if scrolls:
            height += self.horizontalScrollBar().sizeHint().height()
        if self.height() != height or self.minimumHeight() != height:
            self.setFixedHeight(height)

    def resizeEvent(self, event) -> None:
        super().resizeEvent(event)
        if event.size().width() != event.oldSize().width():
            self._fit()

    def pin_header(self, hidden: int) -> None:
        """Keep the column titles (the speeds) in view while the pane around the table has
        scrolled its top ``hidden`` px out of view: they move down over the rows, as far
        as the last row. The pane scrolls, not the table (every row is shown), so a table
        taller than the pane lost its speeds as soon as its lower rows were reached."""
        header = self.horizontalHeader()
        bar = self.horizontalScrollBar()
        room = (self.height() - 2 * self.frameWidth() - header.height() - self.verticalHeader().defaultSectionSize()
                - (bar.height() if bar.isVisible() else 0))
        pinned = max(0, min(hidden, room))
        if pinned != self._pinned:
            self._pinned = pinned
            self._place_header()

    def _place_header(self) -> None:
        top = self.frameWidth() + self._pinned
        header = self.horizontalHeader()
        header.move(header.x(), top)
        header.raise_()
        corner = self.findChild(QAbstractButton)      # the corner above the row titles
        if corner is not None:
            corner.move(corner.x(), top)
            corner.raise_()

    def updateGeometries(self) -> None:  # noqa: N802 - Qt's name
        super().updateGeometries()           # puts the header back at the top
        if self._pinned:
            self._place_header()

    def minimumSizeHint(self):
        hint = super().minimumSizeHint()
        # the first column as wide as its texts need, not as the spare width made it; the
        # titles at their narrowest, whether or not they are wrapped now (_least_titles)
        first = min(self._least_column, self.horizontalHeader().sectionSize(0)) if self.columnCount() else 0
        hint.setWidth(self._least_titles() + min(first, 120) + 2 * self.frameWidth())
        return hint

    def whole_width(self) -> int:
        """px the table needs to show every column whole beside its row titles, unscrolled."""
        return self.verticalHeader().sizeHint().width() + sum(self._widths) + 2 * self.frameWidth()

    def hidden_rows(self) -> list[int]:
        """Rows not wholly inside the table's own viewport (none, by construction)."""
        height = self.viewport().height()
        return [row for row in range(self.rowCount())
                if self.rowViewportPosition(row) < 0
                or self.rowViewportPosition(row) + self.rowHeight(row) > height]

    # ---- copy ----------------------------------------------------------------
    def tsv(self, selected_only: bool = True) -> str:
        """The selected cells' rows and columns (or all) with their titles, tab-separated."""
        self.before_read()
        indexes = self.selectedIndexes() if selected_only else []
        rows = sorted({i.row() for i in indexes}) or list(range(self.rowCount()))
        cols = sorted({i.column() for i in indexes}) or list(range(self.columnCount()))
        heads = self._titles(Qt.Orientation.Horizontal)
        titles = self._titles(Qt.Orientation.Vertical)
        lines = ["\t".join([""] + [heads[c] for c in cols])]
        lines += ["\t".join([titles[r]] + [self.text(r, c) for c in cols]) for r in rows]
        return "\r\n".join(lines) + "\r\n"

    def copy(self) -> None:
        QGuiApplication.clipboard().setText(self.tsv())

    def keyPressEvent(self, event: QKeyEvent) -> None:
        if event.matches(QKeySequence.StandardKey.Copy):
            self.copy()
            event.accept()
            return
        super().keyPressEvent(event)

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self.copy_action.setText(self.tr("Copy"))
        self.copy_action.setToolTip(self.tr("Copy the selected cells (or the whole table) with their "
                                            "titles as tab-separated text"))


def whole_columns(widths: list[int], room: int) -> list[int]:
    """Columns wider together than ``room`` px, all of the widest one's width or more, so
    that a whole number of them fills ``room``: scrolled a column at a time, every column
    in view is whole."""
    widest = max(widths)
    count = max(1, room // widest)
    return [max(widest, room // count)] * len(widths)


def title_metrics(header: QHeaderView) -> QFontMetrics:
    """The metrics a header sizes its sections by: its font in bold (Qt's
    ``QHeaderView::sectionSizeFromContents`` measures every title as if highlighted)."""
    font = QFont(header.font())
    font.setBold(True)
    return QFontMetrics(font)


def title_width(metrics: QFontMetrics, title: str) -> int:
    """px of a title's widest line as the header measures it (``title_metrics``)."""
    return metrics.size(0, title).width()


def title_padding(header: QHeaderView) -> int:
    """px a header's section adds beside its text: the style's margins, the same for every
    title (a section's width less its text's, for a one-letter title)."""
    option = QStyleOptionHeader()
    option.fontMetrics = title_metrics(header)
    option.text = "x"
    section = header.style().sizeFromContents(QStyle.ContentsType.CT_HeaderSection, option, QSize(), header)
    return section.width() - title_width(option.fontMetrics, option.text)


def _two_lines(title: str, metrics: QFontMetrics, width: int) -> str:
    """``title`` broken at the space that keeps its longer line shortest, if it is wider
    than ``width`` px."""
    if title_width(metrics, title) <= width or " " not in title:
        return title
    spaces = [i for i, ch in enumerate(title) if ch == " "]
    cut = min(spaces, key=lambda i: max(title_width(metrics, title[:i]), title_width(metrics, title[i + 1:])))
    return title[:cut] + "\n" + title[cut + 1:]
