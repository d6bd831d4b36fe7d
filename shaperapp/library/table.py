"""A read-only table model over ``core.library.Library.query_rows``.

All SQL stays in core: this model only remembers the query (filter, search,
sort, speed), asks core for the rows and formats them. Clicking a header
re-runs the query sorted by that figure, so sorting 10 000 entries is SQLite's
work, not the view's. Rows come a page at a time (``fetchMore`` as the view
scrolls), like QSqlQueryModel, so the first screen appears at once however
large the library is.
"""
from __future__ import annotations

from typing import Any

from PySide6.QtCore import QAbstractTableModel, QModelIndex, QPersistentModelIndex, Qt, Signal
from PySide6.QtGui import QColor

from core.library import LIST_COLUMNS, Library
from core.library.query import QueryError

from shaperapp.widgets.figure_labels import figure_label, figure_tip, format_figure
from shaperapp.widgets.file_messages import describe_damage

# the columns shown, in order (keys of core's list rows)
COLUMNS = ("name", "variant", "K", "stroke_mm", "theta_deg", "crank_mm", "frame_mm", "lever_mm",
           "rod_mm", "guide_mm", "pressure_angle_max_deg", "rpm", "v_work_max_m_s",
           "v_return_max_m_s", "a_max_m_s2", "mean_torque_N_m", "max_torque_N_m",
           "flywheel_inertia_kg_m2", "tags", "notes", "modified")
_INDEX = [LIST_COLUMNS.index(key) for key in COLUMNS]
_DAMAGED = LIST_COLUMNS.index("damaged")
_TEXT = {"name", "variant", "tags", "notes", "modified"}
PAGE = 256
NOTES_SHOWN = 500       # characters of a note the list gets (its tooltip shows them); the rest stays in the file
NOTES_CELL = 120        # characters of a note's first line its cell shows (the column fits its contents)

Index = QModelIndex | QPersistentModelIndex


class LibraryTableModel(QAbstractTableModel):
    """Rows of the library for a QTableView. ``queryFailed(str)`` carries core's filter error."""

    queryFailed = Signal(str)

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self._library: Library | None = None
        self._rows: list[tuple] = []
        self._complete = True
        self._where = ""
        self._search = ""
        self._sort = "name"
        self._descending = False
        self._rpm: float | None = None

    # ---- query ----------------------------------------------------------------------
    def set_library(self, library: Library | None) -> None:
        self._library = library
        self.refresh()

    def set_query(self, where: str | None = None, search: str | None = None,
                  rpm: float | None | bool = False) -> None:
        """Change some of the query (``rpm=False`` keeps the speed) and re-run it."""
        if where is not None:
            self._where = where
        if search is not None:
            self._search = search
        if rpm is not False:
            self._rpm = rpm  # type: ignore[assignment]
        self.refresh()

    def refresh(self) -> None:
        """Re-run the query (first page); on a bad filter keep the old rows and emit ``queryFailed``."""
        rows: list[tuple] = []
        if self._library is not None:
            try:
                rows = self._page(0)
            except QueryError as exc:
                self.queryFailed.emit(str(exc))
                return
        self.beginResetModel()
        self._rows = rows
        self._complete = len(rows) < PAGE
        self.endResetModel()
        self.queryFailed.emit("")

    def _page(self, offset: int) -> list[tuple]:
        _, rows = self._library.query_rows(self._where, search=self._search, sort=self._sort,  # type: ignore
                                           descending=self._descending, rpm=self._rpm,
                                           limit=PAGE, offset=offset, notes_chars=NOTES_SHOWN + 1)
        return rows

    def canFetchMore(self, parent: Index = QModelIndex()) -> bool:
        return not parent.isValid() and not self._complete and self._library is not None

    def fetchMore(self, parent: Index = QModelIndex()) -> None:
        if not self.canFetchMore(parent):
            return
        try:
            rows = self._page(len(self._rows))
        except QueryError:
            rows = []
        self._complete = len(rows) < PAGE
        if rows:
            self.beginInsertRows(QModelIndex(), len(self._rows), len(self._rows) + len(rows) - 1)
            self._rows += rows
            self.endInsertRows()

    def sort(self, column: int, order: Qt.SortOrder = Qt.SortOrder.AscendingOrder) -> None:
        if not 0 <= column < len(COLUMNS) or COLUMNS[column] == "tags":
            return
        self._sort = COLUMNS[column]
        self._descending = order == Qt.SortOrder.DescendingOrder
        self.refresh()

    # ---- access -----------------------------------------------------------------------
    def name_at(self, row: int) -> str:
        return self._rows[row][LIST_COLUMNS.index("name")]

    def row_of(self, name: str) -> int:
        """The row of ``name``, fetching further pages if needed; -1 if it is not listed."""
        key = LIST_COLUMNS.index("name")
        start = 0
        while True:
            found = next((i for i in range(start, len(self._rows)) if self._rows[i][key] == name), -1)
            if found >= 0 or not self.canFetchMore():
                return found
            start = len(self._rows)
            self.fetchMore()

    def value(self, row: int, key: str) -> Any:
        return self._rows[row][LIST_COLUMNS.index(key)]

    def damaged_at(self, row: int) -> bool:
        """Whether row ``row`` holds stored values that cannot be read (shown as —)."""
        return self._rows[row][_DAMAGED] is not None

    # ---- Qt model -------------------------------------------------------------------
    def rowCount(self, parent: Index = QModelIndex()) -> int:
        return 0 if parent.isValid() else len(self._rows)

    def columnCount(self, parent: Index = QModelIndex()) -> int:
        return 0 if parent.isValid() else len(COLUMNS)

    def data(self, index: Index, role: int = Qt.ItemDataRole.DisplayRole) -> Any:
        if not index.isValid():
            return None
        key = COLUMNS[index.column()]
        row = self._rows[index.row()]
        value = row[_INDEX[index.column()]]
        if row[_DAMAGED] is not None:               # a damaged entry: marked, its reason on hover
            if role == Qt.ItemDataRole.ToolTipRole:
                return self.tr("This design is damaged: %1. 'shaper library check' lists every "
                               "damaged design.").replace("%1", describe_damage(row[_DAMAGED]))
            if role == Qt.ItemDataRole.ForegroundRole:
                return QColor("#b00020")
            if role == Qt.ItemDataRole.DisplayRole and key == "name":
                return self.tr("%1 (damaged)").replace("%1", value or "—")
        if role == Qt.ItemDataRole.DisplayRole:
            if key in ("tags", "notes", "name", "modified"):
                text = (value or "").replace(",", ", ") if key == "tags" else (value or "")
                return _first_line(text) if key == "notes" and text else text
            return format_figure(key, value)
        if role == Qt.ItemDataRole.ToolTipRole and key == "notes":
            return _shown_note(value) if value else None
        if role == Qt.ItemDataRole.TextAlignmentRole:
            if key in _TEXT:
                return int(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter)
            return int(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        return None

    def headerData(self, section: int, orientation: Qt.Orientation,
                   role: int = Qt.ItemDataRole.DisplayRole) -> Any:
        if orientation != Qt.Orientation.Horizontal or not 0 <= section < len(COLUMNS):
            return None
        if role == Qt.ItemDataRole.DisplayRole:
            return figure_label(COLUMNS[section])
        if role == Qt.ItemDataRole.ToolTipRole:
            return figure_tip(COLUMNS[section])
        return None

    def retranslate(self) -> None:
        self.headerDataChanged.emit(Qt.Orientation.Horizontal, 0, len(COLUMNS) - 1)
        if self._rows:
            self.dataChanged.emit(self.index(0, 0), self.index(len(self._rows) - 1, len(COLUMNS) - 1))


def _shown_note(text: str) -> str:
    """A note as the list got it (``NOTES_SHOWN`` + 1 characters at most), with … if cut."""
    return text[:NOTES_SHOWN] + "…" if len(text) > NOTES_SHOWN else text


def _first_line(text: str) -> str:
    """The first line of a note as shown in its cell, cut at ``NOTES_CELL`` characters (…)."""
    lines = text[:NOTES_SHOWN].splitlines()
    first = lines[0] if lines else ""
    return first[:NOTES_CELL] + "…" if len(first) > NOTES_CELL else first
