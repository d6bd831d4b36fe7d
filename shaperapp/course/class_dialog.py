"""File › Class course design…: a class's task table in, ``shaper class`` run on it (issue 41,
item 5).

The dialog reads the table and the base design with the command's own reader
(``core.cli.tasks.read_tasks``), so the rows it shows, each marked with its error, are the
ones the command takes and refuses, before anything runs. Run starts ``shaper class`` as
a process of its own (its workers are processes too; the window stays responsive) and
advances the progress bar by the lines it prints, one per finished student. Cancel sends
that process SIGINT: it starts no new student and waits for those being written, so every
file left is complete. At the end the folder can be opened.
"""
from __future__ import annotations

import os
import signal
import sys

from PySide6.QtCore import QCoreApplication, QProcess, QUrl, Qt
from PySide6.QtGui import QBrush, QColor, QDesktopServices
from PySide6.QtWidgets import (QCheckBox, QComboBox, QDialog, QDialogButtonBox, QFileDialog, QFormLayout,
                               QHBoxLayout, QLabel, QLineEdit, QProgressBar, QPushButton, QTableWidget,
                               QTableWidgetItem, QVBoxLayout, QWidget)

from core.drawing.sheet import PAPERS
from shaperapp.widgets.child_signals import children_take_sigint
from shaperapp.widgets.i18n import join_sentences

translate = QCoreApplication.translate
BAD = QColor(255, 220, 220)


class ClassDialog(QDialog):
    """Pick the table, the base design and the folder; see the rows; run, cancel, open."""

    def __init__(self, language: str, start_dir: str = "", parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setWindowTitle(translate("ClassDialog", "Class course design"))
        self._language, self._start = language, start_dir
        self._process: QProcess | None = None
        self._good = 0
        self._finished = 0
        self._failed = 0
        self._rows: dict[str, int] = {}          # a ready student's folder name → its row
        self._told: set[str] = set()             # the students the run said something of
        self._tails = {"out": "", "err": ""}     # a line the process has not finished printing
        self.tasks, self.base, self.folder = QLineEdit(), QLineEdit(), QLineEdit()
        self.sheet = QComboBox()
        self.sheet.addItems(list(PAPERS))
        self.sheet.setCurrentText("A1")
        self.dxf = QCheckBox(translate("ClassDialog", "DXF too"))
        form = QFormLayout()
        form.addRow(translate("ClassDialog", "Task table (CSV):"), self._picker(self.tasks, self._pick_tasks))
        form.addRow(translate("ClassDialog", "Base design:"), self._picker(self.base, self._pick_base))
        form.addRow(translate("ClassDialog", "Output folder:"), self._picker(self.folder, self._pick_folder))
        form.addRow(translate("ClassDialog", "Sheets:"), self._row(self.sheet, self.dxf))
        self.table = QTableWidget(0, 4)
        self.table.setHorizontalHeaderLabels([translate("ClassDialog", "Line"), translate("ClassDialog", "Student"),
                                              translate("ClassDialog", "Number"), translate("ClassDialog", "Check")])
        self.table.horizontalHeader().setStretchLastSection(True)
        self.table.verticalHeader().hide()      # its 1, 2, … beside the Line column's 2, 3, … read as one number
        self.table.setEditTriggers(QTableWidget.EditTrigger.NoEditTriggers)
        self.summary = QLabel()
        self.summary.setWordWrap(True)
        self.progress = QProgressBar()
        self.progress.setFormat("%v / %m")
        self.buttons = QDialogButtonBox()
        self.run_button = self.buttons.addButton(translate("ClassDialog", "Run"), QDialogButtonBox.ButtonRole.AcceptRole)
        self.cancel_button = self.buttons.addButton(translate("ClassDialog", "Cancel"),
                                                    QDialogButtonBox.ButtonRole.RejectRole)
        self.open_button = self.buttons.addButton(translate("ClassDialog", "Open folder"),
                                                  QDialogButtonBox.ButtonRole.ActionRole)
        self.open_button.setEnabled(False)
        self.run_button.setEnabled(False)
        self.run_button.clicked.connect(self.run)
        self.cancel_button.clicked.connect(self.cancel)
        self.open_button.clicked.connect(self.open_folder)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.table, 1)
        layout.addWidget(self.summary)
        layout.addWidget(self.progress)
        layout.addWidget(self.buttons)
        for edit in (self.tasks, self.base):
            edit.editingFinished.connect(self.check)
        self.folder.textChanged.connect(self._update_run)
        self.resize(760, 520)

    @staticmethod
    def _row(*widgets: QWidget) -> QWidget:
        box = QWidget()
        row = QHBoxLayout(box)
        row.setContentsMargins(0, 0, 0, 0)
        for widget in widgets:
            row.addWidget(widget)
        row.addStretch(1)
        return box

    def _picker(self, edit: QLineEdit, pick) -> QWidget:
        button = QPushButton(translate("ClassDialog", "Browse…"))
        button.clicked.connect(pick)
        box = self._row(edit, button)
        box.layout().setStretch(0, 1)
        return box

    def _pick_tasks(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, translate("ClassDialog", "Task table"), self._start,
                                              translate("ClassDialog", "CSV (*.csv);;All files (*)"))
        if path:
            self.tasks.setText(path)
            if not self.folder.text():
                self.folder.setText(os.path.splitext(path)[0])
            self.check()

    def _pick_base(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, translate("ClassDialog", "Base design"), self._start,
                                              translate("ClassDialog", "Designs (*.json);;All files (*)"))
        if path:
            self.base.setText(path)
            self.check()

    def _pick_folder(self) -> None:
        path = QFileDialog.getExistingDirectory(self, translate("ClassDialog", "Output folder"), self._start)
        if path:
            self.folder.setText(path)

    def check(self) -> None:
        """Read the table as ``shaper class`` will, and show every row with its error."""
        from core.cli.tasks import TableError, read_tasks
        from core.files.design_file import load_design
        from core.base.errors import FileFormatError

        from shaperapp.widgets.file_messages import describe_file_error

        from .class_messages import table_message
        self.table.setRowCount(0)
        self._good = 0
        self._rows = {}
        path, base = self.tasks.text().strip(), self.base.text().strip() or None
        if not path:
            self._update_run()
            return
        try:
            if base is not None:
                load_design(base)
            students, _ = read_tasks(path, base)
        except (TableError, FileFormatError) as exc:
            reason = (table_message(str(exc)) if isinstance(exc, TableError)
                      else describe_file_error(exc))
            self.summary.setText(translate("ClassDialog", "The table cannot be used: %1").replace("%1", reason))
            self._update_run()
            return
        self.table.setRowCount(len(students))
        for row, s in enumerate(students):
            error = table_message(s.error) if s.error else ""
            texts = [str(s.line), s.name, s.number, error or translate("ClassDialog", "ready")]
            for column, text in enumerate(texts):
                item = QTableWidgetItem(text)
                if s.error:
                    item.setBackground(QBrush(BAD))
                    item.setToolTip(error)
                self.table.setItem(row, column, item)
        self._rows = {s.folder: row for row, s in enumerate(students) if not s.error}
        self._good = len(self._rows)
        bad = len(students) - self._good
        self.summary.setText(translate("ClassDialog", "%1 students ready, %2 rows with errors (left out).")
                             .replace("%1", str(self._good)).replace("%2", str(bad)))
        self._update_run()

    def _update_run(self) -> None:
        running = self._process is not None
        self.run_button.setEnabled(not running and self._good > 0 and bool(self.folder.text().strip()))

    def arguments(self) -> list[str]:
        """``shaper class``'s words for the dialog's choices."""
        words = ["-m", "core", "class", "--tasks", self.tasks.text().strip(), "-o", self.folder.text().strip(),
                 "--lang", "zh" if self._language.startswith("zh") else "en", "--sheet", self.sheet.currentText()]
        if self.base.text().strip():
            words += ["--base", self.base.text().strip()]
        return words + (["--dxf"] if self.dxf.isChecked() else [])

    def run(self) -> None:
        self._finished = self._failed = 0
        self._told = set()
        self._tails = {"out": "", "err": ""}
        for row in self._rows.values():
            self._mark(row, translate("ClassDialog", "ready"))
        self.progress.setRange(0, self._good)
        self.progress.setValue(0)
        self.open_button.setEnabled(False)
        process = QProcess(self)
        process.setProgram(sys.executable)
        process.setArguments(self.arguments())
        process.readyReadStandardOutput.connect(self._read)
        process.finished.connect(self._done)
        self._process = process
        self._errors = ""
        self._key_before = _stamp(os.path.join(self.folder.text().strip(), "answer-key.json"))
        process.readyReadStandardError.connect(self._read_errors)
        with children_take_sigint():     # Cancel is a SIGINT: the child must take it
            process.start()
        self._update_run()
        self.summary.setText(translate("ClassDialog", "Writing the class's files…"))

    def _read(self) -> None:
        self._take("out", bytes(self._process.readAllStandardOutput()).decode("utf-8", "replace"))

    def _read_errors(self) -> None:
        text = bytes(self._process.readAllStandardError()).decode("utf-8", "replace")
        self._errors += text
        self._take("err", text)

    def _take(self, stream: str, text: str) -> None:
        """The whole lines of what the process printed: each student written, current or
        failed is said on its row, as ``shaper class`` says it, and advances the bar."""
        from .class_run import student_outcome
        lines = (self._tails[stream] + text).split("\n")
        self._tails[stream] = lines.pop()
        for line in (line.rstrip("\r") for line in lines):
            if stream == "out":
                outcome = student_outcome(line, list(self._rows))
                if outcome is not None and outcome[0] not in self._told:
                    self._told.add(outcome[0])
                    self._finished += 1
                    self._mark(self._rows[outcome[0]], translate("ClassDialog", "written") if outcome[1] == "written"
                               else translate("ClassDialog", "up to date, not written again"))
                continue
            for name, row in self._rows.items():
                head = f"shaper: error: {name}: "
                if line.startswith(head) and name not in self._told:
                    self._told.add(name)
                    self._failed += 1
                    self._mark(row, translate("ClassDialog", "failed: %1").replace("%1", line[len(head):]), bad=True)
        self.progress.setValue(min(self._finished + self._failed, self._good))

    def _mark(self, row: int, text: str, bad: bool = False) -> None:
        """Row ``row``'s Check cell says ``text`` (red for a failure, as a bad row is)."""
        item = self.table.item(row, 3)
        if item is None:
            return
        item.setText(text)
        item.setToolTip(text if bad else "")
        for column in range(self.table.columnCount()):
            cell = self.table.item(row, column)
            if cell is not None:
                cell.setBackground(QBrush(BAD) if bad else QBrush())

    def cancel(self) -> None:
        """Stop a run (every file left complete), else close the dialog."""
        if self._process is None:
            self.reject()
            return
        self.cancel_button.setEnabled(False)
        self.summary.setText(translate("ClassDialog", "Cancelling: the students being written are finished…"))
        os.kill(self._process.processId(), signal.SIGINT)

    def _done(self, status: int, _exit) -> None:
        cancelled = not self.cancel_button.isEnabled()
        self._process = None
        self.cancel_button.setEnabled(True)
        from .class_messages import table_message      # the command's English, in the UI's language
        folder = self.folder.text().strip()
        key = _stamp(os.path.join(folder, "answer-key.json"))
        errors = [line.removeprefix("shaper: error: ") for line in self._errors.splitlines()
                  if line.startswith("shaper: error: ")]
        for tail in ("out", "err"):             # a last line printed without its newline
            if self._tails[tail]:
                self._take(tail, "\n")
        for name in set(self._rows) - self._told:       # never reached: cancelled, or the run failed
            self._mark(self._rows[name], translate("ClassDialog", "not written (cancelled)") if cancelled
                       else translate("ClassDialog", "not written"))
        if cancelled:
            text = translate("ClassDialog", "Cancelled: %1 students written, each complete.")
        elif status in (0, 2) and key is not None and key != self._key_before:   # this run's answer key
            text = translate("ClassDialog", "Done: %1 students written; the task sheets and the answer key are "
                             "in the folder.")
            if status == 2:     # the count of students not written, a sentence of its own
                text = join_sentences(text, table_message(errors[-1] if errors else ""))
        else:           # an answer key an earlier run left is not this run's success
            last = errors[-1] if errors else (self._errors.strip().splitlines()[-1:] or [""])[0]
            text = translate("ClassDialog", "Failed: %1").replace("%1", table_message(last))
        text = text.replace("%1", str(self._finished))
        from .class_messages import notes_text
        notes = notes_text([line.removeprefix("shaper: note: ") for line in self._errors.splitlines()
                            if line.startswith("shaper: note: ")])
        if notes:       # what the run left or replaced (an earlier run's folders, DXFs, files)
            text += "\n" + translate("ClassDialog", "Notes (%1):").replace("%1", str(len(notes))) + "\n" + \
                "\n".join(notes[:NOTES_SHOWN]) + ("\n…" if len(notes) > NOTES_SHOWN else "")
        self.summary.setText(text)
        self.open_button.setEnabled(os.path.isdir(folder))
        self._update_run()

    def open_folder(self) -> None:
        QDesktopServices.openUrl(QUrl.fromLocalFile(self.folder.text().strip()))

    def closeEvent(self, event) -> None:         # noqa: N802 (Qt's name)
        if self._process is not None:
            self.cancel()
            self._process.waitForFinished(-1)
        super().closeEvent(event)


NOTES_SHOWN = 5


def _stamp(path: str) -> int | None:
    """The file's modification time in ns, None when there is none: tells this run's file
    from an earlier run's (every file is replaced whole, so a new one has a new time)."""
    try:
        return os.stat(path).st_mtime_ns
    except OSError:
        return None


def class_dialog(parent: QWidget, language: str, start_dir: str) -> None:
    dialog = ClassDialog(language, start_dir, parent)
    dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
    dialog.show()
