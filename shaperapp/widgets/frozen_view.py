"""A table with its first column (what identifies a row) frozen at the left.

Scrolled sideways to the figures, the library's list lost the names that say which
design a row is, and the Positions tab the crank angle of each row (issue 34 item 8).
Qt's "Frozen Column" example does it with a second view over the first column: the
same model and selection, scrolled with the table's rows, as wide as that column and
its rows as tall as the table's, its header sorting as the table's does. Sideways the
table moves by whole columns: each position, the last too, starts a column at the
frozen one's edge.
"""
from __future__ import annotations

from PySide6.QtCore import QAbstractItemModel, QModelIndex, Qt
from PySide6.QtWidgets import QAbstractItemView, QHeaderView, QTableView, QWidget


class FrozenNameView(QTableView):
    """A table view whose column 0 stays in view while the other columns scroll."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.frozen = QTableView(self)
        frozen = self.frozen
        frozen.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        frozen.verticalHeader().hide()
        frozen.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Fixed)
        frozen.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        frozen.setVerticalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        frozen.setFrameShape(QTableView.Shape.NoFrame)
        frozen.setStyleSheet("QTableView { border-right: 1px solid palette(mid); }")
        for view in (self, frozen):
            view.setVerticalScrollMode(QAbstractItemView.ScrollMode.ScrollPerPixel)
        # by the pixel, snapped to the column edges (_snap): by the item, the column scrolled
        # to lies under the frozen one and the next starts wherever its width ends
        self.setHorizontalScrollMode(QAbstractItemView.ScrollMode.ScrollPerPixel)
        self.horizontalHeader().sectionResized.connect(self._on_resized)
        # rows of two lines (the Positions tab's special positions) are as tall in both views
        self.verticalHeader().sectionResized.connect(lambda row, _old, size: frozen.setRowHeight(row, size))
        self.horizontalHeader().sortIndicatorChanged.connect(self._mirror_sort)
        frozen.horizontalHeader().sectionClicked.connect(self._sort_by_name)
        frozen.verticalScrollBar().valueChanged.connect(self.verticalScrollBar().setValue)
        self.verticalScrollBar().valueChanged.connect(frozen.verticalScrollBar().setValue)
        frozen.doubleClicked.connect(self.doubleClicked)
        self._last_x = 0
        self.horizontalScrollBar().valueChanged.connect(self._snap)
        self.viewport().stackUnder(frozen)

    def setModel(self, model: QAbstractItemModel) -> None:  # noqa: N802 - Qt's name
        super().setModel(model)
        self.frozen.setModel(model)
        self.frozen.setSelectionModel(self.selectionModel())
        model.modelReset.connect(self._show_first_column_only)
        model.columnsInserted.connect(self._show_first_column_only)
        self._show_first_column_only()

    def set_look(self) -> None:
        """The frozen column takes the table's look (selection, colours, wrapping)."""
        frozen = self.frozen
        frozen.setSelectionBehavior(self.selectionBehavior())
        frozen.setSelectionMode(self.selectionMode())
        frozen.setEditTriggers(self.editTriggers())
        frozen.setAlternatingRowColors(self.alternatingRowColors())
        frozen.setWordWrap(self.wordWrap())
        frozen.horizontalHeader().setSortIndicatorShown(self.isSortingEnabled())
        header = self.horizontalHeader()
        frozen.horizontalHeader().setSortIndicator(header.sortIndicatorSection(), header.sortIndicatorOrder())

    def _show_first_column_only(self, *_: object) -> None:
        model = self.model()
        for column in range(model.columnCount() if model is not None else 0):
            self.frozen.setColumnHidden(column, column != 0)
        self._on_resized(0, 0, self.columnWidth(0))

    def _edges(self) -> list[int]:
        """The scroll positions that start a column at the frozen column's right edge."""
        header = self.horizontalHeader()
        edges, x = [], 0
        for visual in range(header.count()):
            logical = header.logicalIndex(visual)
            if not header.isSectionHidden(logical):
                edges.append(x - self.columnWidth(0) if visual else 0)
                x += header.sectionSize(logical)
        return edges

    def _snap(self, value: int) -> None:
        """Scrolled sideways, the column beside the frozen one starts at its edge: a column
        half under it showed the last digits of its numbers ("53.0615" for 253.0615)."""
        bar = self.horizontalScrollBar()
        fits = [e for e in self._edges() if 0 <= e <= bar.maximum()] + [bar.maximum()]
        if value not in fits:      # on to the next edge the way it moved: a small step still moves
            ahead = [e for e in fits if e > value] if value > self._last_x else [e for e in fits if e < value]
            value = min(ahead, key=lambda e: abs(e - value)) if ahead else value
        self._last_x = value
        if bar.value() != value:
            bar.setValue(value)

    def _mirror_sort(self, section: int, order: Qt.SortOrder) -> None:
        self.frozen.horizontalHeader().setSortIndicator(section, order)

    def _sort_by_name(self, section: int) -> None:
        header = self.horizontalHeader()
        ascending = Qt.SortOrder.AscendingOrder
        order = ascending
        if header.sortIndicatorSection() == section and header.sortIndicatorOrder() == ascending:
            order = Qt.SortOrder.DescendingOrder
        self.sortByColumn(section, order)

    def _on_resized(self, column: int, _old: int, size: int) -> None:
        if column == 0:
            self.frozen.setColumnWidth(0, size)
            self._place()

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        self._place()

    def updateGeometries(self) -> None:  # noqa: N802 - Qt's name
        super().updateGeometries()
        bar = self.horizontalScrollBar()
        if bar.maximum() > 0:
            # the end on an edge too (blank beyond the last column), not a column cut by
            # the frozen one
            bar.setMaximum(min((e for e in self._edges() if e >= bar.maximum()), default=bar.maximum()))
        self._place()

    def _place(self) -> None:
        frame = self.frameWidth()
        # its header as tall as the table's (a taller title elsewhere, e.g. in Chinese,
        # would put its rows a few pixels off the table's)
        self.frozen.horizontalHeader().setFixedHeight(self.horizontalHeader().height())
        self.frozen.setGeometry(self.verticalHeader().width() + frame, frame, self.columnWidth(0),
                                self.viewport().height() + self.horizontalHeader().height())

    def scrollTo(self, index: QModelIndex, hint=QAbstractItemView.ScrollHint.EnsureVisible) -> None:  # noqa: N802
        """To a name: only up or down, the frozen column shows it wherever the rest is."""
        x = self.horizontalScrollBar().value()
        super().scrollTo(index, hint)
        if index.column() == 0:
            self.horizontalScrollBar().setValue(x)
