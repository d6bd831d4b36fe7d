"""The Library pane: keep designs by name, find them, open and compare them.

Built from the model like every widget; the library work is in
:class:`~shaperapp.library.actions.LibraryActions`, the rows come from core's
query through :class:`~shaperapp.library.table.LibraryTableModel`. The pane asks
for names, files and confirmations; ``compareRequested(list)`` hands the
selected designs (core ``Candidate`` objects) to whoever shows comparisons.
"""
from __future__ import annotations

import os

from PySide6.QtCore import QEvent, QSettings, Qt, QTimer, Signal
from PySide6.QtWidgets import (QAbstractItemView, QComboBox, QFileDialog, QHBoxLayout, QInputDialog,
                               QLabel, QLineEdit, QMessageBox, QPushButton, QSizePolicy, QVBoxLayout,
                               QWidget)

from core.space.compare import MAX_DESIGNS
from core.library.store import LibraryError, resolve_path

from shaperapp.design.model import DesignModel
from shaperapp.widgets.busy import arrow_cursor, busy_cursor
from shaperapp.widgets.frozen_view import FrozenNameView
from shaperapp.widgets.file_messages import describe_file_error

from .actions import LibraryActions
from .dialogs import SaveDialog, ask_refused_library
from .filter import core_filter
from .stale import StaleFiguresBar
from .toolbar import bar_action, bar_rows, menu_button, text_bar
from .table import LibraryTableModel

POLL_MS = 1500           # how often another program's changes are looked for


class LibraryPane(QWidget):
    compareRequested = Signal(list)

    def __init__(self, model: DesignModel, parent: QWidget | None = None,
                 settings: QSettings | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._settings = settings
        self.actions = LibraryActions(model, self)
        self.table_model = LibraryTableModel(self)
        self._opened = False
        self._version = -1

        self.path_label = QLabel()
        self.path_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        # the path is cut where the pane is narrower (its tooltip holds it whole): at its full
        # width it made the pane at least as wide as the library's path (482 px for a path
        # in /tmp), too wide to dock beside the Results at 1366 × 768
        self.path_label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.change_button = QPushButton()
        self.change_button.clicked.connect(self.choose_library_dialog)
        self.search_edit = QLineEdit()
        self.search_edit.setClearButtonEnabled(True)
        self.filter_edit = QLineEdit()
        self.filter_edit.setClearButtonEnabled(True)
        self.speed_box = QComboBox()
        self.speed_box.setEditable(True)
        self.speed_box.setInsertPolicy(QComboBox.InsertPolicy.NoInsert)
        self.message_label = QLabel()
        self.message_label.setWordWrap(True)
        self.stale_bar = StaleFiguresBar()
        self.stale_bar.refreshed.connect(self._refresh)
        self.stale_bar.failed.connect(self._show_failure)
        self.view = FrozenNameView()
        self.view.setModel(self.table_model)
        self.view.setSortingEnabled(True)
        self.view.sortByColumn(0, Qt.SortOrder.AscendingOrder)
        self.view.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.view.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.view.verticalHeader().setVisible(False)
        self.view.setAlternatingRowColors(True)
        self.view.setWordWrap(False)
        self.view.horizontalHeader().setResizeContentsPrecision(200)   # not all 10 000 rows
        self.view.set_look()
        # sized again to the rows after every query (names were cut "base K…" after an add)
        self.table_model.modelReset.connect(self.view.resizeColumnsToContents)
        self.view.doubleClicked.connect(lambda _: self.open_selected())
        self.view.selectionModel().selectionChanged.connect(self._update_enabled)

        # Two rows (toolbar.py): the designs in and out of the library, then its own edits.
        self.toolbar, self.edit_bar = text_bar(), text_bar()
        self.act_save = bar_action(self.toolbar, self.save_dialog)
        self.act_open = bar_action(self.toolbar, self.open_selected)
        self.act_compare = bar_action(self.toolbar, self.compare_selected)
        self.toolbar.addSeparator()
        self.import_button, (self.act_import, self.act_import_folder) = menu_button(
            self.toolbar, (self.import_dialog, self.import_folder_dialog))
        self.export_button, (self.act_export, self.act_export_all) = menu_button(
            self.toolbar, (self.export_dialog, self.export_all_dialog))
        self.act_rename = bar_action(self.edit_bar, self.rename_dialog)
        self.act_duplicate = bar_action(self.edit_bar, self.duplicate_selected)
        self.act_delete = bar_action(self.edit_bar, self.delete_selected)
        self.edit_bar.addSeparator()
        stack = self.actions.undo_stack
        self.act_undo = bar_action(self.edit_bar, stack.undo)
        self.act_redo = bar_action(self.edit_bar, stack.redo)
        stack.indexChanged.connect(self._update_undo)

        top = QHBoxLayout()
        top.addWidget(self.path_label, 1)
        top.addWidget(self.change_button)
        query = QHBoxLayout()
        query.addWidget(self.search_edit, 2)
        query.addWidget(self.filter_edit, 3)
        query.addWidget(self.speed_box, 1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addLayout(top)
        layout.addLayout(bar_rows(self.toolbar, self.edit_bar))
        layout.addLayout(query)
        layout.addWidget(self.message_label)
        layout.addWidget(self.stale_bar)
        layout.addWidget(self.view, 1)

        self.search_edit.textChanged.connect(lambda text: self.table_model.set_query(search=text))
        self.filter_edit.textChanged.connect(lambda text: self.table_model.set_query(where=core_filter(text)))
        self.speed_box.currentTextChanged.connect(self._speed_changed)
        self.table_model.queryFailed.connect(self._show_query_error)
        self.actions.changed.connect(self._refresh)
        self.actions.libraryChanged.connect(self._library_changed)
        self.actions.failed.connect(self._show_failure)
        self.actions.noted.connect(self.message_label.setText)
        self.actions.refused.connect(self._refused)
        self._timer = QTimer(self)
        self._timer.setInterval(POLL_MS)
        self._timer.timeout.connect(self._poll)
        self._retranslate()
        self._update_enabled()

    # ---- opening the library (lazily, when first shown) ----------------------------------
    def showEvent(self, event) -> None:
        super().showEvent(event)
        if not self._opened:
            self._opened = True
            self.open_library(None)

    def open_library(self, path: str | None) -> bool:
        """Open a library file (None: the configured one) and list it."""
        self._opened = True
        if path is None and self._settings is not None:
            stored = self._settings.value("libraryPath", "")
            path = stored if isinstance(stored, str) and stored and not os.environ.get("SHAPER_LIBRARY") else None
        return self.actions.open_library(path)

    def _library_changed(self) -> None:
        library = self.actions.library
        self.table_model.set_library(library)
        self.view.resizeColumnsToContents()
        self._version = library.data_version() if library is not None else -1
        self.path_label.setText(str(library.path) if library is not None else self.tr("No library is open."))
        if library is not None and library.read_only is not None:
            self.path_label.setText(self.tr("%1 (read-only: %2)").replace("%1", str(library.path))
                                    .replace("%2", library.read_only))
        self.path_label.setToolTip(self.path_label.text())
        self.stale_bar.update_for(library)
        if library is not None:
            self._timer.start()
            if self._settings is not None and library.path != resolve_path(None):
                self._settings.setValue("libraryPath", str(library.path))
        else:
            self._timer.stop()
        self._update_enabled()

    def _poll(self) -> None:
        """Show what another program wrote to the same library."""
        library = self.actions.library
        if library is None or not self.isVisible():
            return
        try:
            version = library.data_version()
        except LibraryError:
            return
        if version != self._version:
            self._version = version
            self.table_model.refresh()
            self.stale_bar.update_for(library)

    def _refresh(self) -> None:
        selected = self.selected_names()
        self.table_model.refresh()
        if self.actions.library is not None:
            self._version = self.actions.library.data_version()
        self.stale_bar.update_for(self.actions.library)
        self.select_names(selected)

    # ---- selection ------------------------------------------------------------------------------
    def selected_names(self) -> list[str]:
        rows = sorted({i.row() for i in self.view.selectionModel().selectedRows()})
        return [self.table_model.name_at(r) for r in rows]

    def select_names(self, names: list[str]) -> None:
        selection = self.view.selectionModel()
        flags = selection.SelectionFlag.Select | selection.SelectionFlag.Rows
        self.view.clearSelection()
        for name in names:
            row = self.table_model.row_of(name)
            if row >= 0:
                selection.select(self.table_model.index(row, 0), flags)

    def _update_undo(self, *_) -> None:
        """Undo/Redo enabled as the pane's own stack allows; the tooltip names the step."""
        stack = self.actions.undo_stack
        self.act_undo.setEnabled(stack.canUndo())
        self.act_redo.setEnabled(stack.canRedo())
        self.act_undo.setToolTip(self.tr("Undo: %1").replace("%1", stack.undoText()) if stack.canUndo() else "")
        self.act_redo.setToolTip(self.tr("Redo: %1").replace("%1", stack.redoText()) if stack.canRedo() else "")

    def _update_enabled(self, *_) -> None:
        count = len(self.selected_names())
        has_library = self.actions.library is not None
        writable = has_library and self.actions.library.read_only is None    # type: ignore[union-attr]
        for action in (self.act_save, self.act_import, self.act_import_folder):
            action.setEnabled(writable)
        self.act_export_all.setEnabled(has_library)
        self.import_button.setEnabled(writable)
        self.export_button.setEnabled(has_library)
        for action in (self.act_open, self.act_export):
            action.setEnabled(count == 1)
        for action in (self.act_rename, self.act_duplicate):
            action.setEnabled(count == 1 and writable)
        self.act_delete.setEnabled(count >= 1 and writable)
        self.act_compare.setEnabled(2 <= count <= MAX_DESIGNS)

    # ---- actions ------------------------------------------------------------------------------
    def save_dialog(self) -> None:
        dialog = SaveDialog(self)
        if dialog.exec() != SaveDialog.DialogCode.Accepted:
            return
        name, notes, tags = dialog.values()
        replace = False
        if self.actions.exists(name):
            answer = QMessageBox.question(self, self.tr("Design library"),
                                          self.tr("“%1” is already in the library. Replace it?").replace("%1", name))
            if answer != QMessageBox.StandardButton.Yes:
                return
            replace = True
        if self.actions.save_current(name, notes, tags, replace_existing=replace):
            self.select_names([name])

    def open_selected(self) -> None:
        names = self.selected_names()
        if len(names) != 1:
            return
        if self._model.dirty:
            answer = QMessageBox.question(self, self.tr("Design library"), self.tr(
                "The design on screen has unsaved changes. Open “%1” anyway?").replace("%1", names[0]))
            if answer != QMessageBox.StandardButton.Yes:
                return
        self.actions.open_in_model(names[0])

    def compare_selected(self) -> None:
        candidates = self.actions.candidates(self.selected_names())
        if len(candidates) >= 2:
            self.compareRequested.emit(candidates)

    def rename_dialog(self) -> None:
        names = self.selected_names()
        if len(names) != 1:
            return
        new, ok = QInputDialog.getText(self, self.tr("Rename design"), self.tr("New name:"), text=names[0])
        if ok and new.strip() and new.strip() != names[0] and self.actions.rename(names[0], new):
            self.select_names([new.strip()])

    def duplicate_selected(self) -> None:
        names = self.selected_names()
        if len(names) == 1:
            self.actions.duplicate(names[0])

    def delete_selected(self) -> None:
        self.actions.delete(self.selected_names())      # undoable, so no question asked

    def import_dialog(self) -> None:
        paths, _ = QFileDialog.getOpenFileNames(self, self.tr("Import design files"), self._last_dir(),
                                                self.tr("Shaper designs (*.shaper.json *.json);;All files (*)"))
        if paths:
            self.import_paths(paths)

    def import_folder_dialog(self) -> None:
        folder = QFileDialog.getExistingDirectory(self, self.tr("Import a folder of designs"), self._last_dir())
        if folder:
            self.import_paths([folder])

    def import_paths(self, paths: list[str]) -> None:
        with busy_cursor():             # every file is read and its figures computed: 1.5 s for 300
            names, refused = self.actions.import_paths(paths)
        text = self.tr("Imported %1 design(s).").replace("%1", str(len(names)))
        if refused:
            text += "\n\n" + self.tr("These files were not imported:") + "\n" + "\n".join(
                f"{p.name}: {describe_file_error(why)}" for p, why in refused[:20])
            QMessageBox.warning(self, self.tr("Design library"), text)
        else:
            self.message_label.setText(text)

    def export_dialog(self) -> None:
        names = self.selected_names()
        if len(names) != 1:
            return
        from core.library.names import safe_file_name
        start = os.path.join(self._last_dir(), safe_file_name(names[0]) + ".shaper.json")
        path, _ = QFileDialog.getSaveFileName(self, self.tr("Export design"), start,
                                              self.tr("Shaper designs (*.shaper.json *.json)"))
        if path:
            self.actions.export(names[0], path)

    def export_all_dialog(self) -> None:
        folder = QFileDialog.getExistingDirectory(self, self.tr("Export all designs to a folder"), self._last_dir())
        if not folder:
            return
        with busy_cursor():             # one file per entry
            written = self.actions.export_all(folder)
        if written:
            self.message_label.setText(self.tr("Exported the library to %1").replace("%1", folder))

    def choose_library_dialog(self) -> None:
        start = str(self.actions.library.path) if self.actions.library else self._last_dir()
        path, _ = QFileDialog.getSaveFileName(
            self, self.tr("Open or create a design library"), start,
            self.tr("Design libraries (*.sqlite);;All files (*)"),
            options=QFileDialog.Option.DontConfirmOverwrite)
        if path:
            self.open_library(path)

    def _last_dir(self) -> str:
        value = self._settings.value("lastDir", "") if self._settings is not None else ""
        return value if isinstance(value, str) and os.path.isdir(value) else os.getcwd()

    # ---- feedback -------------------------------------------------------------------------------
    def _speed_changed(self, text: str) -> None:
        if self.speed_box.currentIndex() == 0 and text == self.speed_box.itemText(0):
            self.table_model.set_query(rpm=None)
            return
        try:
            rpm = float(text.replace("r/min", "").strip())
        except ValueError:
            self.message_label.setText(self.tr("Type a crank speed in r/min."))
            return
        self.table_model.set_query(rpm=rpm)

    def _show_query_error(self, message: str) -> None:
        self.filter_edit.setStyleSheet("QLineEdit { background: #ffe0e0; }" if message else "")
        self.filter_edit.setToolTip(message)
        self.message_label.setText(self.tr("Filter not understood; write conditions such as "
                                           "K>=1.4, variant=rod, name~cut.") if message else "")
        self._update_enabled()

    def _show_failure(self, message: str) -> None:
        with arrow_cursor():            # said in the middle of an import or export
            QMessageBox.warning(self, self.tr("Design library"), message)

    def _refused(self, error: LibraryError) -> None:
        choice = ask_refused_library(self, self.actions.message(error))
        if choice == "copy":
            copy = self.actions.copy_aside(error)
            if copy:
                QMessageBox.information(self, self.tr("Design library"),
                                        self.tr("A copy was saved as %1").replace("%1", copy))
                self.choose_library_dialog()
        elif choice == "other":
            self.choose_library_dialog()

    # ---- translation ---------------------------------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        texts = ((self.act_save, self.tr("Save current…"), self.tr("Save the design on screen to the library")),
                 (self.act_open, self.tr("Open"), self.tr("Open the selected design (double-click works too)")),
                 (self.act_compare, self.tr("Compare"), self.tr("Compare the 2 to 6 selected designs")),
                 (self.act_rename, self.tr("Rename…"), ""), (self.act_duplicate, self.tr("Duplicate"), ""),
                 (self.act_delete, self.tr("Delete"), self.tr("Delete the selected designs (undoable)")),
                 (self.act_import, self.tr("Import…"), self.tr("Add design files to the library")),
                 (self.act_import_folder, self.tr("Import folder…"), self.tr("Add every design file of a folder")),
                 (self.act_export, self.tr("Export…"), self.tr("Write the selected design as a design file")),
                 (self.act_export_all, self.tr("Export all…"), self.tr("Write every design into a folder")),
                 (self.act_undo, self.tr("Undo"), ""), (self.act_redo, self.tr("Redo"), ""))
        for action, text, tip in texts:
            action.setText(text)
            action.setToolTip(tip or text)
        self.import_button.setText(self.tr("Import"))
        self.import_button.setToolTip(self.tr("Add design files, or every design file of a folder, to the library"))
        self.export_button.setText(self.tr("Export"))
        self.export_button.setToolTip(self.tr("Write the selected design, or every design, as design files"))
        self.change_button.setText(self.tr("Other library…"))
        self.search_edit.setPlaceholderText(self.tr("Search name, notes, tags"))
        self.filter_edit.setPlaceholderText(self.tr("Filter, e.g. K>=1.4, variant=rod, a_max<5"))
        first = self.tr("Figures at each design's first speed")
        if self.speed_box.count() == 0:
            self.speed_box.addItems([first, "40", "60"])
        else:
            self.speed_box.setItemText(0, first)
        self.speed_box.setToolTip(self.tr("Crank speed of the speed-dependent columns, r/min"))
        if self.actions.library is None:
            self.path_label.setText(self.tr("No library is open."))
        self.table_model.retranslate()
        self._update_undo()
