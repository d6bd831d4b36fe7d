"""Compare view: 2 to 6 designs overlaid at one speed, with a side-by-side table.

The overlay curves (ram x, v, a and crank torque; each design in one colour and
line style) are the shared ``compare_plots.ComparePlots``, which the report uses too. The table
shows every figure of ``core.space.compare``: each value, its difference from the
first design in brackets, and the best value of a row in bold with a ★.
Everything shown is computed by core; this widget only draws and exports.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, QPoint, QRectF, QSize, QSizeF, Qt, QTime, Signal
from PySide6.QtGui import QBrush, QColor, QFont, QFontMetrics, QPainter
from PySide6.QtWidgets import (QDoubleSpinBox, QFileDialog, QGridLayout, QHBoxLayout, QHeaderView,
                               QLabel, QListWidget, QMessageBox, QPushButton, QSplitter, QTableWidget,
                               QTableWidgetItem, QVBoxLayout, QWidget)

from core.space.compare import (MAX_DESIGNS, Candidate, Comparison, compare, difference_text,
                          distinguishing_choices, distinguishing_inputs, table_csv)
from core.base.errors import DesignError, FileFormatError
from core.files.io import atomic_write, load_design
from core.library.names import file_stem, unique_name

from shaperapp.design.model import DesignModel
from shaperapp.widgets.figure_labels import figure_label, figure_tip, format_figure
from shaperapp.widgets.image_export import export_painting
from shaperapp.widgets.file_messages import describe_file_error, describe_os_error
from shaperapp.widgets.messages import describe

from .plots import COLOURS, ComparePlots

WHITE = QColor("white")
BEST_BRUSH = QBrush(QColor(200, 235, 200))
COLUMN_MAX_PX = 150     # a design's column: its name cut to this unless a value is wider


class CompareView(QWidget):
    """``candidatesChanged`` whenever the list of designs changes."""

    candidatesChanged = Signal()

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._candidates: list[Candidate] = []
        self.comparison: Comparison | None = None

        self.list = QListWidget()
        self.list.setMaximumHeight(72)
        # A name longer than the list is cut at its end, where the snapshot's time is (what
        # tells entries apart comes first), and whole in its tooltip and in the legend; a
        # horizontal scroll bar took a row of the list.
        self.list.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.list.setTextElideMode(Qt.TextElideMode.ElideRight)
        self.add_current_button = QPushButton()
        self.add_current_button.clicked.connect(self.add_current)
        self.add_file_button = QPushButton()
        self.add_file_button.clicked.connect(self.add_file_dialog)
        self.remove_button = QPushButton()
        self.remove_button.clicked.connect(self.remove_selected)
        self.speed = QDoubleSpinBox()
        self.speed.setRange(0.1, 1000.0)
        self.speed.setDecimals(1)
        self.speed.setValue(model.rpms[0])
        self.speed.setKeyboardTracking(False)
        self.speed.valueChanged.connect(self._speed_changed)
        # The speed is the design on screen's first until the user chooses one: set once when
        # the tab was built (at idle, before a file was opened), it compared two designs at
        # 60 r/min at the default design's 40 while the screen and both files said 60.
        self._speed_chosen = False
        self._following = False
        model.resultsChanged.connect(self._follow_speed)
        self.speed_label = QLabel()
        self.export_csv_button = QPushButton()
        self.export_csv_button.clicked.connect(lambda: self._export_dialog("csv"))
        self.export_image_button = QPushButton()
        self.export_image_button.clicked.connect(lambda: self._export_dialog("image"))
        self.hint = QLabel()
        self.hint.setWordWrap(True)

        self.plots = ComparePlots()
        self.table = QTableWidget()
        self.table.setEditTriggers(QTableWidget.EditTrigger.NoEditTriggers)
        # Rows one text line high (30 px rows showed one at a time at 1366×768).
        rows = self.table.verticalHeader()
        rows.setSectionResizeMode(QHeaderView.ResizeMode.Fixed)
        rows.setDefaultSectionSize(QFontMetrics(self.table.font()).height() + 6)
        self.content = QSplitter(Qt.Orientation.Vertical)     # what PNG/SVG exports show
        self.content.addWidget(self.plots)
        self.content.addWidget(self.table)
        self.content.setStretchFactor(0, 4)                   # the plots need the height; the
        self.content.setStretchFactor(1, 1)                   # table scrolls (or drag the bar)

        # The speed under the list and the exports beside the entry buttons, not in a row
        # of their own: at 1280×720 in Chinese that row's 30 px left the ram acceleration
        # plot 71 px tall, with a single y tick label ("0").
        speed = QHBoxLayout()
        speed.addWidget(self.speed_label)
        speed.addWidget(self.speed)
        speed.addStretch(1)
        entries = QVBoxLayout()
        entries.addWidget(self.list, 1)
        entries.addLayout(speed)
        side = QGridLayout()
        for row, (entry, export) in enumerate(((self.add_current_button, self.export_csv_button),
                                               (self.add_file_button, self.export_image_button),
                                               (self.remove_button, None))):
            side.addWidget(entry, row, 0)
            if export is not None:
                side.addWidget(export, row, 1)
        side.setRowStretch(3, 1)
        picks = QHBoxLayout()                  # kept narrow: the view shares a tab with the plots
        picks.addLayout(entries, 1)
        picks.addLayout(side)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addLayout(picks)
        layout.addWidget(self.hint)
        layout.addWidget(self.content, 1)
        self._retranslate()
        self.recompute()

    def _speed_changed(self) -> None:
        self._speed_chosen = self._speed_chosen or not self._following
        self.recompute()

    def _follow_speed(self) -> None:
        """The design on screen's first speed, until the user has chosen one."""
        if not self._speed_chosen and self.speed.value() != self._model.rpms[0]:
            self._following = True
            self.speed.setValue(self._model.rpms[0])
            self._following = False

    # ---- candidates ---------------------------------------------------------------------
    def set_candidates(self, candidates: list[Candidate]) -> None:
        """Compare exactly these designs (the first is the reference)."""
        self._candidates = list(candidates)[:MAX_DESIGNS]
        self._changed()

    def add_candidate(self, candidate: Candidate) -> bool:
        """Add one design; refused (False, with a message) past MAX_DESIGNS or when the same
        design (inputs and loads) is already compared: two entries would differ only in name."""
        if len(self._candidates) >= MAX_DESIGNS:
            self._say(self.tr("At most %1 designs can be compared.").replace("%1", str(MAX_DESIGNS)))
            return False
        same = [c.label for c in self._candidates
                if c.spec == candidate.spec and c.masses == candidate.masses]
        if same:
            self._say(self.tr("This design is already compared, as “%1”.").replace("%1", same[0]))
            return False
        label = unique_name(candidate.label, [c.label for c in self._candidates])
        self._candidates.append(Candidate(label, candidate.spec, candidate.masses))
        self._changed()
        return True

    def add_current(self) -> bool:
        """Add a snapshot of the design on screen: later edits do not change the entry, so
        its label says what it is (:meth:`snapshot_label`)."""
        m = self._model
        return self.add_candidate(Candidate(self.snapshot_label(), m.valid_spec, m.masses))

    def snapshot_label(self) -> str:
        """The name of the design on screen as an entry: its file or library name while the
        screen shows it unchanged; else "Design on screen" (or "NAME modified") with the
        inputs that tell it from the other entries and the time of the snapshot. The old
        fixed "Design on screen" kept naming a frozen K 1.4 after K became 1.6."""
        m = self._model
        name = m.source_name
        if name and not m.dirty:
            return name
        inputs = distinguishing_inputs(m.valid_spec, [c.spec for c in self._candidates])
        words = {"chord": self.tr("chord"), "sagitta": self.tr("sagitta"),
                 "trailing": self.tr("trailing rod"), "leading": self.tr("leading rod"),
                 "loads": self.tr("other loads")}
        choices = distinguishing_choices(Candidate("", m.valid_spec, m.masses), self._candidates)
        inputs = ", ".join([inputs] + [words[c] for c in choices])
        when = QTime.currentTime().toString("HH:mm:ss")
        text = (self.tr("%1 modified, %2 (snapshot %3)") if name else
                self.tr("Design on screen, %2 (snapshot %3)"))
        return text.replace("%2", inputs).replace("%3", when).replace("%1", name)   # a name may hold "%2"

    def add_file(self, path: str) -> bool:
        try:
            doc = load_design(path)
        except FileFormatError as exc:
            self._fail(self.tr("Could not open the design: %1").replace("%1", describe_file_error(exc)))
            return False
        return self.add_candidate(Candidate(file_stem(path), doc["spec"], doc["masses"]))

    def add_file_dialog(self) -> None:
        paths, _ = QFileDialog.getOpenFileNames(self, self.tr("Add design files"), "",
                                                self.tr("Shaper designs (*.shaper.json *.json);;All files (*)"))
        for path in paths:
            self.add_file(path)

    def remove_selected(self) -> None:
        rows = sorted({i.row() for i in self.list.selectedIndexes()}, reverse=True)
        for row in rows:
            del self._candidates[row]
        self._changed()

    def candidates(self) -> list[Candidate]:
        return list(self._candidates)

    def _changed(self) -> None:
        self.list.clear()
        for i, c in enumerate(self._candidates):
            self.list.addItem(c.label)
            self.list.item(i).setForeground(QColor(COLOURS[i % len(COLOURS)]))
            self.list.item(i).setToolTip(c.label)
        self._model.set_comparison_candidates(self._candidates)    # for the report
        self.candidatesChanged.emit()
        self.recompute()

    # ---- computing and showing ----------------------------------------------------------
    def recompute(self) -> None:
        """Compare the designs at the chosen speed; keep the last result on an error."""
        if len(self._candidates) < 2:
            self.comparison = None
            self._say(self._pick_hint())
            self._show()
            return
        try:
            self.comparison = compare(self._candidates, self.speed.value())
        except DesignError as exc:
            self._say(describe(exc))
            return
        self._say("")
        self._show()

    def _say(self, text: str) -> None:
        """Show ``text`` above the plots; an empty hint takes no room from them."""
        self.hint.setText(text)
        self.hint.setVisible(bool(text))

    def _pick_hint(self) -> str:
        return self.tr("Pick 2 to 6 designs: select them in the library and press "
                       "Compare, or add the design on screen or design files here.")

    def _show(self) -> None:
        result = self.comparison
        self.export_csv_button.setEnabled(result is not None)
        self.export_image_button.setEnabled(result is not None)
        self._fill_table()
        self.plots.show_comparison(result)

    def _fill_table(self) -> None:
        result = self.comparison
        self.table.clear()
        if result is None:
            self.table.setRowCount(0)
            self.table.setColumnCount(0)
            return
        rows = result.rows
        self.table.setColumnCount(len(result.labels))
        self.table.setRowCount(len(rows))
        self.table.setHorizontalHeaderLabels(list(result.labels))
        self.table.setVerticalHeaderLabels([figure_label(r.key) for r in rows])
        bold = QFont(self.table.font())
        bold.setBold(True)
        for i, row in enumerate(rows):
            self.table.verticalHeaderItem(i).setToolTip(figure_tip(row.key))
            for k, value in enumerate(row.values):
                text = format_figure(row.key, value) + difference_text(row, k)
                item = QTableWidgetItem(("★ " if k in row.best else "") + text)
                item.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
                if k in row.best:
                    item.setFont(bold)
                    item.setBackground(BEST_BRUSH)
                    item.setToolTip(self.tr("Best in this row"))
                self.table.setItem(i, k, item)
        for k, label in enumerate(result.labels):       # the whole name, however the column cuts it
            self.table.horizontalHeaderItem(k).setToolTip(label)
        self.table.resizeColumnsToContents()
        # A snapshot's name ("Design on screen, K 1.4 (snapshot 12:03:15)") made each column
        # 305 px: on a laptop the scroll bar then took the table's second row. A column is
        # at most as wide as its widest value or COLUMN_MAX_PX, the name cut at its end
        # (what tells entries apart comes first in it) and whole in its tooltip.
        header = self.table.horizontalHeader()
        for k in range(self.table.columnCount()):
            values = self.table.sizeHintForColumn(k)
            self.table.setColumnWidth(k, min(header.sectionSize(k), max(values, COLUMN_MAX_PX)))
        header.setTextElideMode(Qt.TextElideMode.ElideRight)

    # ---- export ----------------------------------------------------------------------------
    def export_csv(self, path: str) -> None:
        """The figure table as ``shaper library compare --csv`` writes it; OSError on failure."""
        if self.comparison is not None:
            atomic_write(path, table_csv(self.comparison))

    def export_image(self, path: str) -> None:
        """Curves and the whole table as one picture: SVG for ``.svg``, else a raster type
        by suffix (``image_export.image_type`` refuses anything else, naming the path).
        ValueError, and nothing written, while there is nothing to compare: the picture
        would be an empty plot with an empty table frame (as the Explore tab refuses a map
        not yet computed)."""
        if self.comparison is None:
            raise ValueError(self.tr("There is nothing to export yet: pick 2 to 6 designs to "
                                     "compare first."))
        table = self.table
        # the headers' geometry is laid out lazily: right after a new comparison it is
        # still the last one's (a table frame drawn below the canvas), so lay it out now
        table.updateGeometries()
        frame = 2 * table.frameWidth()
        table_size = QSize(table.verticalHeader().width() + table.horizontalHeader().length() + frame,
                           table.horizontalHeader().height() + table.verticalHeader().length() + frame)
        plots_size = self.plots.size()
        title_h = 28
        width = max(plots_size.width(), table_size.width())
        height = title_h + plots_size.height() + table_size.height()

        def paint(painter: QPainter, page: QRectF) -> None:
            painter.setPen(QColor("black"))
            painter.drawText(QRectF(8, 0, page.width() - 16, title_h), Qt.AlignmentFlag.AlignVCenter,
                             self.title())
            self.plots.render_plots(painter, QRectF(0, title_h, plots_size.width(), plots_size.height()))
            table.render(painter, QPoint(0, title_h + plots_size.height()))

        old_size = table.size()
        for bar in (table.setVerticalScrollBarPolicy, table.setHorizontalScrollBarPolicy):
            bar(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        table.resize(table_size)               # the whole table, not the part scrolled into view
        table.updateGeometries()
        try:
            export_painting(path, QSizeF(width, height), paint, self.tr("Design comparison"), WHITE)
        finally:
            table.resize(old_size)
            for bar in (table.setVerticalScrollBarPolicy, table.setHorizontalScrollBarPolicy):
                bar(Qt.ScrollBarPolicy.ScrollBarAsNeeded)

    def title(self) -> str:
        """One line saying what is compared, for exported pictures."""
        if self.comparison is None:
            return ""
        return (self.tr("Comparison at %1 r/min; differences from “%2” in brackets; ★ best")
                .replace("%1", f"{self.comparison.rpm:g}").replace("%2", self.comparison.labels[0]))

    def _export_dialog(self, kind: str) -> None:
        if kind == "csv":
            path, _ = QFileDialog.getSaveFileName(self, self.tr("Export comparison to CSV"), "comparison.csv",
                                                  self.tr("CSV files (*.csv)"))
        else:
            path, _ = QFileDialog.getSaveFileName(self, self.tr("Export comparison image"), "comparison.png",
                                                  self.tr("PNG image (*.png);;SVG drawing (*.svg)"))
        if not path:
            return
        try:
            self.export_csv(path) if kind == "csv" else self.export_image(path)
        except OSError as exc:
            self._fail(self.tr("Could not write %1: %2").replace("%1", path)
                       .replace("%2", describe_os_error(exc)))
        except ValueError as exc:      # nothing to compare, or a suffix that is no image type
            self._fail(self.tr("Could not write %1: %2").replace("%1", path).replace("%2", str(exc)))

    def _fail(self, message: str) -> None:
        QMessageBox.warning(self, self.tr("Compare designs"), message)

    # ---- translation ---------------------------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self.add_current_button.setText(self.tr("Add design on screen"))
        self.add_current_button.setToolTip(self.tr(
            "Adds a snapshot of the design on screen, named with its time: later edits do "
            "not change it"))
        self.add_file_button.setText(self.tr("Add file…"))
        self.remove_button.setText(self.tr("Remove"))
        self.speed_label.setText(self.tr("Speed (r/min):"))
        self.export_csv_button.setText(self.tr("Export CSV…"))
        self.export_image_button.setText(self.tr("Export PNG/SVG…"))
        if len(self._candidates) < 2:          # the hint stayed in the language it was set in
            self._say(self._pick_hint())
        self._fill_table()

    def sizeHint(self) -> QSize:
        return QSize(800, 700)
