"""The Positions tab: the course-design table at positions 1 … N and the special ones.

Rows come from ``core.course_design.positions`` (exact special angles, the curves and
dynamics columns). Selecting a row moves the animation there. The model's
animation runs on its crank-angle grid, so the scheme and plots go to the
grid angle nearest the row (within half a step); the row itself, and the
report, keep the exact values. Copy puts tab-separated text on the clipboard,
which pastes into Excel/WPS as cells.
"""
from __future__ import annotations

import math

import numpy as np
from PySide6.QtCore import QAbstractTableModel, QEvent, QModelIndex, QPersistentModelIndex, Qt, QTimer
from PySide6.QtGui import QColor, QGuiApplication, QKeySequence, QShortcut
from PySide6.QtWidgets import (QAbstractItemView, QComboBox, QLabel, QPushButton,
                               QSpinBox, QWidget)

from core.files.dynamics_io import FLAG_COLUMNS
from core.forces.masses import masses_for_design
from core.course_design.positions import (DEFAULT_COUNT, MAX_COUNT, PositionTable, column_texts, display_values,
                                         position_table, positions)
from shaperapp.design.model import DesignModel
from shaperapp.widgets.column_titles import column_titles, special_titles, yes_no
from shaperapp.widgets.frozen_view import FrozenNameView
from shaperapp.widgets.notation import on_screen
from shaperapp.widgets.view_parts import bar_over_body, fill_speed_combo

SPECIAL_FILL = QColor("#eef3f8")
HIDDEN = ("rpm",)        # one speed at a time: shown in the speed box
def flag_texts(values: np.ndarray) -> list[str]:
    """A yes/no column (``FLAG_COLUMNS``, 1 or 0) as the app shows a yes/no; NaN is ''."""
    return ["" if not math.isfinite(v) else yes_no(bool(v)) for v in values]


def row_title(number: int, name: str, specials: dict[str, str]) -> str:
    """A row's identity, shown in the row header that stays in view while the values
    scroll sideways: its number, or the special position's name on two lines."""
    if number:
        return str(number)
    text = specials.get(name, name)
    if len(text) > 18 and " " in text:          # two lines: the header stays narrow
        cut = min((i for i, ch in enumerate(text) if ch == " "), key=lambda i: abs(i - len(text) / 2))
        return text[:cut] + "\n" + text[cut + 1:]
    return text


class PositionsModel(QAbstractTableModel):
    """One speed of a :class:`PositionTable` as text cells (numbers as shown everywhere)."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self._header: list[str] = []
        self._corner = ""
        self._rows: list[str] = []          # row titles: number or special position
        self._cells: list[list[str]] = []
        self._special: list[bool] = []
        self._tips: list[str] = []

    def set_table(self, table: PositionTable, speed: int) -> None:
        self.beginResetModel()
        titles, specials = column_titles(), special_titles()
        cols = [i for i, c in enumerate(table.columns) if c not in HIDDEN]
        k = table.positions.crank_deg.size
        shown = display_values(table.data, table.columns)[speed * k:(speed + 1) * k]
        # plain text in a header: the notation in characters (v_A3A4 → vA3A4, a^k → aᵏ)
        self._header = [on_screen(titles.get(table.columns[i], table.columns[i])) for i in cols]
        self._corner = self.tr("Position")
        self._tips = [table.columns[i] for i in cols]
        texts = [flag_texts(shown[:, i]) if table.columns[i] in FLAG_COLUMNS else column_texts(shown[:, i])
                 for i in cols]
        self._rows = [row_title(int(number), name, specials)
                      for number, name in zip(table.positions.number, table.positions.name)]
        self._cells = [list(row) for row in zip(*texts)] if texts else [[] for _ in self._rows]
        self._special = [bool(name) for name in table.positions.name]
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
            return int(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        if role == Qt.ItemDataRole.BackgroundRole and self._special[index.row()]:
            return SPECIAL_FILL
        return None

    def headerData(self, section, orientation, role=Qt.ItemDataRole.DisplayRole):
        if orientation == Qt.Orientation.Vertical:
            if role == Qt.ItemDataRole.DisplayRole:
                return self._rows[section]
            if role == Qt.ItemDataRole.TextAlignmentRole:
                return int(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter)
            if role == Qt.ItemDataRole.BackgroundRole and self._special[section]:
                return SPECIAL_FILL
            return None
        if role == Qt.ItemDataRole.DisplayRole:
            return self._header[section]
        if role == Qt.ItemDataRole.ToolTipRole:
            return self._tips[section] or None
        return None

    def corner(self) -> str:
        """The title of the row titles' column ("Position")."""
        return self._corner

    def tsv(self, rows: list[int] | None = None) -> str:
        """Tab-separated text with the header, the row titles first (on one line);
        ``rows`` (default all) in table order."""
        rows = range(len(self._cells)) if rows is None else sorted(rows)
        lines = ["\t".join([self._corner] + self._header)] + [
            "\t".join([self._rows[r].replace("\n", " ")] + self._cells[r]) for r in rows]
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
        # The row titles (number or special position) are the vertical header and the
        # crank angle φ, the first column, is frozen beside them: both stay in view while
        # the values scroll sideways, by whole columns (the No. and Position columns
        # scrolled away, then φ did, and the table moved by the pixel; issue 34 item 8).
        self.view = FrozenNameView()
        self.view.setModel(self.table_model)
        self.view.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.view.setAlternatingRowColors(False)
        self.view.verticalHeader().setDefaultAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter)
        self.view.setCornerButtonEnabled(False)
        self.view.horizontalHeader().setDefaultAlignment(Qt.AlignmentFlag.AlignCenter)
        self.view.frozen.horizontalHeader().setDefaultAlignment(Qt.AlignmentFlag.AlignCenter)
        self.view.setWordWrap(False)
        self.view.set_look()
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
        self.view.resizeRowsToContents()
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

