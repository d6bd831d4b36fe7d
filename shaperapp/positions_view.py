"""The Positions tab: the course-design table at positions 1 … N and the special ones.

Rows come from ``core.positions`` (exact special angles, the curves and
dynamics columns). Selecting a row moves the animation there. The model's
animation runs on its crank-angle grid, so the scheme and plots go to the
grid angle nearest the row (within half a step); the row itself, and the
report, keep the exact values. Copy puts tab-separated text on the clipboard,
which pastes into Excel/WPS as cells.
"""
from __future__ import annotations

from PySide6.QtCore import QAbstractTableModel, QEvent, QModelIndex, QPersistentModelIndex, Qt, QTimer
from PySide6.QtGui import QColor, QGuiApplication, QKeySequence, QShortcut
from PySide6.QtWidgets import (QAbstractItemView, QComboBox, QLabel, QPushButton,
                               QSpinBox, QTableView, QWidget)

from core.dynamics import masses_for_design
from core.positions import (DEFAULT_COUNT, MAX_COUNT, PositionTable, display_values, number_text,
                            position_table, positions)
from .column_titles import column_titles, special_titles
from .model import DesignModel
from .view_parts import bar_over_body, fill_speed_combo

SPECIAL_FILL = QColor("#eef3f8")
HIDDEN = ("rpm",)        # one speed at a time: shown in the speed box


class PositionsModel(QAbstractTableModel):
    """One speed of a :class:`PositionTable` as text cells (numbers as shown everywhere)."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self._header: list[str] = []
        self._cells: list[list[str]] = []
        self._special: list[bool] = []
        self._tips: list[str] = []

    def set_table(self, table: PositionTable, speed: int) -> None:
        self.beginResetModel()
        titles, specials = column_titles(), special_titles()
        cols = [i for i, c in enumerate(table.columns) if c not in HIDDEN]
        k = table.positions.crank_deg.size
        shown = display_values(table.data)[speed * k:(speed + 1) * k]
        self._header = [self.tr("No."), self.tr("Position")] + [titles.get(table.columns[i], table.columns[i])
                                                              for i in cols]
        self._tips = ["", ""] + [table.columns[i] for i in cols]
        self._cells, self._special = [], []
        for row, (number, name) in enumerate(zip(table.positions.number, table.positions.name)):
            lead = [str(number) if number else "", specials.get(name, "")]
            self._cells.append(lead + [number_text(shown[row, i]) for i in cols])
            self._special.append(bool(name))
        self.endResetModel()

    def rowCount(self, parent=QModelIndex()) -> int:
        return 0 if parent.isValid() else len(self._cells)

    def columnCount(self, parent=QModelIndex()) -> int:
        return 0 if parent.isValid() else len(self._header)

    def data(self, index, role=Qt.ItemDataRole.DisplayRole):
        if not index.isValid():
            return None
        if role == Qt.ItemDataRole.DisplayRole:
            return self._cells[index.row()][index.column()]
        if role == Qt.ItemDataRole.TextAlignmentRole:
            left = index.column() == 1
            return int((Qt.AlignmentFlag.AlignLeft if left else Qt.AlignmentFlag.AlignRight)
                       | Qt.AlignmentFlag.AlignVCenter)
        if role == Qt.ItemDataRole.BackgroundRole and self._special[index.row()]:
            return SPECIAL_FILL
        return None

    def headerData(self, section, orientation, role=Qt.ItemDataRole.DisplayRole):
        if orientation != Qt.Orientation.Horizontal:
            return None
        if role == Qt.ItemDataRole.DisplayRole:
            return self._header[section]
        if role == Qt.ItemDataRole.ToolTipRole:
            return self._tips[section] or None
        return None

    def tsv(self, rows: list[int] | None = None) -> str:
        """Tab-separated text with the header; ``rows`` (default all) in table order."""
        rows = range(len(self._cells)) if rows is None else sorted(rows)
        lines = ["\t".join(self._header)] + ["\t".join(self._cells[r]) for r in rows]
        return "\r\n".join(lines) + "\r\n"


class PositionsView(QWidget):
    """Speed and count selectors, the table and a Copy button."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.model = model
        self._table: PositionTable | None = None
        self._stale = True
        self.speed_box = QComboBox()
        self.count_label = QLabel()
        self.count_box = QSpinBox()
        self.count_box.setRange(1, MAX_COUNT)
        self.count_box.setValue(DEFAULT_COUNT)
        self.copy_button = QPushButton()
        self.table_model = PositionsModel(self)
        self.view = QTableView()
        self.view.setModel(self.table_model)
        self.view.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.view.setAlternatingRowColors(False)
        self.view.verticalHeader().setVisible(False)
        self.view.horizontalHeader().setDefaultAlignment(Qt.AlignmentFlag.AlignCenter)
        self.view.setWordWrap(False)
        bar_over_body(self, (self.speed_box, self.count_label, self.count_box), self.copy_button,
                      self.view)
        self.copy_shortcut = QShortcut(QKeySequence.StandardKey.Copy, self.view)
        self.copy_shortcut.activated.connect(self.copy)
        self.copy_button.clicked.connect(self.copy)
        self.speed_box.currentIndexChanged.connect(lambda _: self._show())
        self.count_box.valueChanged.connect(lambda _: self._recount())
        self.view.selectionModel().currentRowChanged.connect(self._on_row)
        # One edit emits resultsChanged and then forcesChanged: the table (which needs both)
        # is rebuilt once, when control returns to the event loop.
        self._pending = QTimer(self, singleShot=True, interval=0)
        self._pending.timeout.connect(self._catch_up)
        model.resultsChanged.connect(self._invalidate)
        model.forcesChanged.connect(self._invalidate)
        self._retranslate()

    # ---- public ------------------------------------------------------------
    def table(self) -> PositionTable:
        """The current table (computed on demand)."""
        if self._stale or self._table is None:
            design = self.model.design
            masses = masses_for_design(design, self.model.masses)
            where = positions(design, self.count_box.value(), (), masses.idle_fraction)
            self._table = position_table(design, where, self.model.rpms, masses)
            self._stale = False
        return self._table

    def set_count(self, count: int) -> None:
        self.count_box.setValue(count)

    def copy(self) -> None:
        """Selected rows (or the whole table) as tab-separated text on the clipboard."""
        rows = sorted({i.row() for i in self.view.selectionModel().selectedRows()})
        QGuiApplication.clipboard().setText(self.table_model.tsv(rows or None))

    def crank_deg(self, row: int) -> float:
        return float(self.table().positions.crank_deg[row])

    # ---- internals -----------------------------------------------------------
    def _invalidate(self) -> None:
        self._stale = True
        self._fill_speeds()
        if self.isVisible():
            self._pending.start()

    def _recount(self) -> None:
        self._stale = True
        self._catch_up()

    def _catch_up(self) -> None:
        if self.isVisible() and (self._stale or self.table_model.rowCount() == 0):
            self._show()

    def showEvent(self, event) -> None:
        super().showEvent(event)
        self._catch_up()

    def _show(self) -> None:
        table = self.table()
        speed = min(max(self.speed_box.currentIndex(), 0), table.rpm.size - 1)
        row = self.view.currentIndex().row()
        self.table_model.set_table(table, speed)
        self.view.resizeColumnsToContents()
        if 0 <= row < self.table_model.rowCount():
            self.view.selectionModel().blockSignals(True)
            self.view.selectRow(row)
            self.view.selectionModel().blockSignals(False)

    def _on_row(self, current: QModelIndex | QPersistentModelIndex, _previous) -> None:
        if current.isValid():
            self.model.set_angle_deg(self.crank_deg(current.row()))

    def _fill_speeds(self) -> None:
        fill_speed_combo(self.speed_box, self.model.rpms)

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self.count_label.setText(self.tr("Positions:"))
        self.count_box.setToolTip(self.tr("Number of equally spaced crank positions, "
                                          "numbered from the limit position that starts the working stroke"))
        self.copy_button.setText(self.tr("Copy"))
        self.copy_button.setToolTip(self.tr("Copy the selected rows (or all) as tab-separated text "
                                            "for Excel or WPS"))
        self._fill_speeds()
        if self._table is not None:
            self._show()

