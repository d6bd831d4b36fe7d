"""The main window only assembles: widgets, menus, shortcuts, window state.

It owns no design data (the model does) and no file logic (the document
does); widgets talk only to the model.
"""
from __future__ import annotations

import os

import shiboken6
from PySide6.QtCore import QByteArray, QEvent, QSettings, Qt
from PySide6.QtGui import QAction, QCloseEvent, QKeySequence
from PySide6.QtWidgets import (QApplication, QDockWidget, QInputDialog, QLineEdit, QMainWindow,
                               QMessageBox, QScrollArea, QSplitter, QTabWidget, QVBoxLayout, QWidget)

from . import file_dialogs, i18n
from .help import GuideDialog, about_text
from .animation import AnimationBar
from .compare_view import CompareView
from .document import Document
from .explore_view import ExploreView
from .forces_panel import ForcesPanel
from .form import DesignForm
from .guards import ShortcutGuard, install_wheel_guard
from .library_pane import LibraryPane
from .messages import describe
from .metrics_panel import MetricsPanel
from .model import DesignModel
from .plots import PlotsWidget
from .polygon_view import PolygonView
from .positions_view import PositionsView
from .scheme import SchemeWidget

APP_NAME = "Shaper Designer"


class MainWindow(QMainWindow):
    def __init__(self, model: DesignModel, settings: QSettings, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.model = model
        self.settings = settings
        self.document = Document(model, settings, self)
        self.form = DesignForm(model)
        self.metrics = MetricsPanel(model)
        self.scheme = SchemeWidget(model)
        self.animation = AnimationBar(model)
        self.plots = PlotsWidget(model)
        self.forces = ForcesPanel(model)
        self.tabs = QTabWidget()
        self.tabs.addTab(self.plots, "")
        self.tabs.addTab(self.forces, "")
        # Course-design deliverables (issue 9): positions table and vector diagrams.
        self.positions = PositionsView(model)
        self.polygon_view = PolygonView(model)
        self.tabs.addTab(self.positions, "")
        self.tabs.addTab(self.polygon_view, "")
        self.explore = ExploreView(model)          # Explore tab (issue 11)
        self.tabs.addTab(self.explore, "")

        side = QWidget()
        side_layout = QVBoxLayout(side)
        side_layout.addWidget(self.form)
        side_layout.addWidget(self.metrics, 1)
        scroll = QScrollArea()
        scroll.setWidget(side)
        scroll.setWidgetResizable(True)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        scroll.setMinimumWidth(side.minimumSizeHint().width() + scroll.verticalScrollBar().sizeHint().width() + 4)
        middle = QWidget()
        middle_layout = QVBoxLayout(middle)
        middle_layout.setContentsMargins(0, 0, 0, 0)
        middle_layout.addWidget(self.scheme, 1)
        middle_layout.addWidget(self.animation)
        self.splitter = QSplitter(Qt.Orientation.Horizontal)
        self.splitter.addWidget(scroll)
        self.splitter.addWidget(middle)
        self.splitter.addWidget(self.tabs)
        self.splitter.setStretchFactor(0, 0)
        self.splitter.setStretchFactor(1, 3)
        self.splitter.setStretchFactor(2, 3)
        self.splitter.setSizes([400, 500, 740])
        self.setCentralWidget(self.splitter)

        self._build_library()
        self._build_actions()
        self._build_menus()
        install_wheel_guard()
        self._shortcut_guard = ShortcutGuard(self, self.flush_typing)
        QApplication.instance().installEventFilter(self._shortcut_guard)
        self.document.failed.connect(self._show_failure)
        self.document.recentChanged.connect(self._fill_recent)
        self.document.saved.connect(self._on_saved)
        model.pathChanged.connect(self._update_title)
        model.dirtyChanged.connect(self._update_title)
        model.errorChanged.connect(self._show_status)
        model.resultsChanged.connect(self._show_status)
        self._retranslate()
        self._restore()

    # ---- design library (issue 10): a dock, a Compare tab and a Library menu ----
    def _build_library(self) -> None:
        self.library = LibraryPane(self.model, settings=self.settings)
        self.compare = CompareView(self.model)
        self.tabs.addTab(self.compare, "")
        self.library_dock = QDockWidget(self)
        self.library_dock.setObjectName("libraryDock")
        self.library_dock.setWidget(self.library)
        self.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, self.library_dock)
        self.library_dock.hide()
        self.library.compareRequested.connect(self._show_comparison)

    def _show_comparison(self, candidates: list) -> None:
        self.compare.set_candidates(candidates)
        self.tabs.setCurrentWidget(self.compare)
        if self.height() < 1000:          # on a small screen the docked library leaves the plots no room
            self.library_dock.hide()

    def _library_menu(self) -> None:
        self.menu_library = self.menuBar().addMenu("")
        self.act_library = self.library_dock.toggleViewAction()
        self.act_library.setShortcut(QKeySequence("Ctrl+L"))
        self.act_library_save = self._action(self._save_to_library, "Ctrl+Shift+L")
        self.act_compare = self._action(lambda: self.tabs.setCurrentWidget(self.compare))
        for a in (self.act_library, self.act_library_save, self.act_compare):
            self.menu_library.addAction(a)

    def _save_to_library(self) -> None:
        self.library_dock.show()
        self.library.save_dialog()

    def _retranslate_library(self) -> None:
        self.menu_library.setTitle(self.tr("&Library"))
        self.library_dock.setWindowTitle(self.tr("Design library"))
        self.act_library.setText(self.tr("Show &library"))
        self.act_library_save.setText(self.tr("&Save design to library…"))
        self.act_compare.setText(self.tr("&Compare designs"))
        self.tabs.setTabText(self.tabs.indexOf(self.compare), self.tr("Compare"))

    # ---- actions and menus -------------------------------------------------
    def _action(self, slot, shortcut=None) -> QAction:
        """An action that first sends what is typed in the focused field (so Save, Export
        or Undo act on it, not on the value before the debounce)."""
        action = QAction(self)
        if shortcut is not None:
            action.setShortcut(QKeySequence(shortcut))
        action.triggered.connect(lambda *_: (self.flush_typing(), slot()))
        self.addAction(action)
        return action

    @staticmethod
    def flush_typing() -> None:
        """Commit the focused line edit as if the user had left it."""
        focus = QApplication.focusWidget()
        if isinstance(focus, QLineEdit) and not focus.isReadOnly():
            focus.editingFinished.emit()

    def _stack_action(self, action: QAction, step, keys: QKeySequence.StandardKey, extra: str = "") -> QAction:
        """Undo/redo actions from the stack (their text and enabled state follow it),
        triggered through :meth:`flush_typing` first."""
        action.triggered.disconnect()
        action.triggered.connect(lambda *_: (self.flush_typing(), step()))
        shortcuts = QKeySequence.keyBindings(keys)
        if extra and QKeySequence(extra) not in shortcuts:    # the same key twice would be ambiguous
            shortcuts.append(QKeySequence(extra))
        action.setShortcuts(shortcuts)
        self.addAction(action)
        return action

    def _shortcut(self, action: QAction, shortcut: str) -> QAction:
        action.setShortcut(QKeySequence(shortcut))
        action.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
        self.addAction(action)
        return action

    def _build_actions(self) -> None:
        d = self.document
        self.act_new = self._action(lambda: d.new_dialog(self), QKeySequence.StandardKey.New)
        self.act_open = self._action(lambda: d.open_dialog(self), QKeySequence.StandardKey.Open)
        self.act_save = self._action(lambda: d.save_dialog(self), QKeySequence.StandardKey.Save)
        self.act_save_as = self._action(lambda: d.save_as_dialog(self), QKeySequence.StandardKey.SaveAs)
        self.act_csv = self._action(lambda: d.export_csv_dialog(self), "Ctrl+E")
        self.act_forces_csv = self._action(lambda: d.export_forces_csv_dialog(self), "Ctrl+Shift+E")
        self.act_plots_img = self._action(
            lambda: self._export_image(self.tabs.currentWidget(), "plots"), "Ctrl+Shift+P")
        self.act_scheme_img = self._action(lambda: self._export_image(self.scheme, "scheme"), "Ctrl+Shift+M")
        self.act_report = self._action(self._export_report, "Ctrl+R")
        # Only tabs that draw plots can export them as an image.
        self.tabs.currentChanged.connect(lambda *_: self.act_plots_img.setEnabled(
            hasattr(self.tabs.currentWidget(), "export_image")))
        self.act_quit = self._action(self.close, QKeySequence.StandardKey.Quit)
        stack = self.model.undo_stack
        self.act_undo = self._stack_action(stack.createUndoAction(self, self.tr("Undo")), stack.undo,
                                           QKeySequence.StandardKey.Undo)
        self.act_redo = self._stack_action(stack.createRedoAction(self, self.tr("Redo")), stack.redo,
                                           QKeySequence.StandardKey.Redo, "Ctrl+Shift+Z")
        stack.undoTextChanged.connect(self._show_undo_text)
        stack.redoTextChanged.connect(self._show_redo_text)
        self.act_goto = self._action(self.go_to_angle_dialog, "Ctrl+G")
        # The widgets own these actions (and their texts); the window only adds shortcuts.
        self.act_play = self._shortcut(self.animation.play_action, "Space")
        self.act_play.setShortcuts([QKeySequence("Space"), QKeySequence("Ctrl+Space")])
        self.act_step = self._shortcut(self.animation.step_forward_action, "Ctrl+Right")
        self.act_back = self._shortcut(self.animation.step_back_action, "Ctrl+Left")
        self.act_fit = self._shortcut(self.scheme.fit_action, "Ctrl+0")
        self.act_dims = self._shortcut(self.scheme.dimensions_action, "Ctrl+D")
        self.act_forces = self._shortcut(self.scheme.forces_action, "Ctrl+F")
        self.act_about = self._action(self._about)
        self.act_guide = self._action(self._show_guide, QKeySequence.StandardKey.HelpContents)
        self._guide: GuideDialog | None = None
        self._language = "en"
        self.lang_actions: dict[str, QAction] = {}
        for code, name in i18n.LANGUAGES:
            action = self._action(lambda _=False, c=code: self.set_language(c))
            action.setText(name)
            action.setCheckable(True)
            self.lang_actions[code] = action

    def _build_menus(self) -> None:
        bar = self.menuBar()
        self.menu_file = bar.addMenu("")
        for a in (self.act_new, self.act_open):
            self.menu_file.addAction(a)
        self.menu_recent = self.menu_file.addMenu("")
        for a in (self.act_save, self.act_save_as):
            self.menu_file.addAction(a)
        self.menu_file.addSeparator()
        for a in (self.act_csv, self.act_forces_csv, self.act_plots_img, self.act_scheme_img):
            self.menu_file.addAction(a)
        self.menu_file.addAction(self.act_report)
        self.menu_file.addSeparator()
        self.menu_file.addAction(self.act_quit)
        self.menu_edit = bar.addMenu("")
        self.menu_edit.addAction(self.act_undo)
        self.menu_edit.addAction(self.act_redo)
        self.menu_view = bar.addMenu("")
        self.menu_view.addAction(self.act_fit)
        self.menu_view.addAction(self.act_dims)
        self.menu_view.addAction(self.act_forces)
        self.menu_lang = self.menu_view.addMenu("")
        for action in self.lang_actions.values():
            self.menu_lang.addAction(action)
        self.menu_anim = bar.addMenu("")
        for a in (self.act_play, self.act_step, self.act_back, self.act_goto):
            self.menu_anim.addAction(a)
        self._library_menu()
        self.menu_help = bar.addMenu("")
        self.menu_help.addAction(self.act_guide)
        self.menu_help.addAction(self.act_about)
        self._fill_recent()

    def _fill_recent(self) -> None:
        self.menu_recent.clear()
        files = self.document.recent_files()
        for path in files:
            action = self.menu_recent.addAction(os.path.basename(path))
            action.setToolTip(path)
            action.triggered.connect(lambda _=False, p=path: self.document.open_dialog(self, p))
        self.menu_recent.setEnabled(bool(files))

    # ---- translation ---------------------------------------------------------
    def set_language(self, code: str) -> None:
        i18n.set_language(code)
        self._language = code
        if self._guide is not None:
            self._guide.set_language(code)
        self.settings.setValue("language", code)
        for c, action in self.lang_actions.items():
            action.setChecked(c == code)

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        texts = [
            (self.act_new, self.tr("&New"), self.tr("Start a new design from the defaults")),
            (self.act_open, self.tr("&Open…"), self.tr("Open a design file")),
            (self.act_save, self.tr("&Save"), self.tr("Save the design")),
            (self.act_save_as, self.tr("Save &As…"), self.tr("Save the design under a new name")),
            (self.act_csv, self.tr("Export curves to &CSV…"), self.tr("All speeds, at the form's angle step")),
            (self.act_forces_csv, self.tr("Export &forces to CSV…"),
             self.tr("Crank torque, power and joint forces, all speeds")),
            (self.act_plots_img, self.tr("Export &plots (PNG/SVG)…"), self.tr("Save the plots of the current tab as an image")),
            (self.act_scheme_img, self.tr("Export sc&heme (PNG/SVG)…"), self.tr("Save the mechanism drawing as an image")),
            (self.act_report, self.tr("Export &report (PDF/HTML)…"),
             self.tr("The design report: dimensions, positions table, polygons, forces, flywheel")),
            (self.act_quit, self.tr("&Quit"), ""),
            (self.act_goto, self.tr("&Go to Crank Angle…"), self.tr("Move the mechanism to a crank angle you type")),
            (self.act_about, self.tr("&About"), ""),
            (self.act_guide, self.tr("User &guide"), self.tr("Conventions, method, glossary and command line")),
        ]
        for action, text, tip in texts:
            action.setText(text)
            action.setStatusTip(tip)
        self.tabs.setTabText(0, self.tr("Kinematics"))
        self.tabs.setTabText(1, self.tr("Forces"))
        self.tabs.setTabText(2, self.tr("Positions"))
        self.tabs.setTabText(3, self.tr("Vector diagrams"))
        self.tabs.setTabText(self.tabs.indexOf(self.explore), self.tr("Explore"))
        self.menu_file.setTitle(self.tr("&File"))
        self.menu_recent.setTitle(self.tr("Open &Recent"))
        self.menu_view.setTitle(self.tr("&View"))
        self.menu_edit.setTitle(self.tr("&Edit"))
        self._show_undo_text(self.model.undo_stack.undoText())
        self._show_redo_text(self.model.undo_stack.redoText())
        self.menu_lang.setTitle(self.tr("&Language"))
        self.menu_anim.setTitle(self.tr("&Animation"))
        self.menu_help.setTitle(self.tr("&Help"))
        self._retranslate_library()
        self._update_title()
        self._show_status()

    def _show_undo_text(self, text: str) -> None:
        """'Undo Time ratio K' in the current language (the stack's own prefix is fixed
        when the action is made). The stack outlives the window: skip once it is gone."""
        if shiboken6.isValid(self.act_undo):
            self.act_undo.setText(self.tr("&Undo %1").replace("%1", text).strip())

    def _show_redo_text(self, text: str) -> None:
        if shiboken6.isValid(self.act_redo):
            self.act_redo.setText(self.tr("&Redo %1").replace("%1", text).strip())

    def _update_title(self, *_) -> None:
        """The file name; Qt appends the application's display name, which
        ``i18n.set_language`` sets in the same language."""
        name = os.path.basename(self.model.path) if self.model.path else self.tr("Untitled")
        self.setWindowTitle(f"{name}[*]")
        self.setWindowModified(self.model.dirty)

    def _show_status(self) -> None:
        error = self.model.error
        if error is not None:
            self.statusBar().showMessage(describe(error))
        else:
            m = self.model.metrics
            self.statusBar().showMessage(
                self.tr("K = %1, H = %2 mm, θ = %3°").replace("%1", f"{m.time_ratio:.4f}")
                .replace("%2", f"{m.stroke_mm:.2f}").replace("%3", f"{m.theta_deg:.3f}"))

    # ---- slots -------------------------------------------------------------
    def _show_failure(self, message: str) -> None:
        QMessageBox.warning(self, self.tr("Shaper Designer"), message)

    def _on_saved(self, path: str) -> None:
        self.statusBar().showMessage(self.tr("Saved %1").replace("%1", path), 4000)

    def _export_image(self, widget, stem: str) -> None:
        if not self.document.confirm_valid(self, saving=False):
            return
        start = os.path.join(self.document.last_dir(), f"{stem}.png")
        path = file_dialogs.save_file_name(self, self.tr("Export image"), start,
                                           self.tr("PNG image (*.png);;SVG drawing (*.svg)"))
        if path:
            self.export_image_to(widget, path)

    def export_image_to(self, widget, path: str) -> bool:
        """Write ``widget``'s image to ``path``; any failure is shown naming ``path``."""
        folder = os.path.dirname(os.path.abspath(path))
        if not os.path.isdir(folder):
            reason = self.tr("the folder %1 does not exist").replace("%1", folder)
        else:
            try:
                widget.export_image(path)
            except OSError as exc:
                reason = exc.strerror or str(exc)
            except ValueError as exc:     # e.g. a suffix that is not an image type
                reason = str(exc)
            else:
                if os.path.exists(path):
                    return True
                reason = self.tr("nothing was written")
        self._show_failure(self.tr("Could not export the image to %1: %2").replace("%1", path)
                           .replace("%2", reason))
        return False

    def go_to_angle_dialog(self) -> None:
        """Ask for a crank angle and move the mechanism there."""
        value, ok = QInputDialog.getDouble(self, self.tr("Go to crank angle"),
                                           self.tr("Crank angle φ (0–360°):"), self.model.crank_deg,
                                           0.0, 360.0, 3)
        if ok:
            self.model.set_angle_deg(value)

    def _export_report(self) -> None:
        if not self.document.confirm_valid(self, saving=False):
            return
        from .report.dialog import export_report_dialog   # builds offscreen views: load on demand
        path = export_report_dialog(self.model, self, str(self.settings.value("language", "en")),
                                    self.document.last_dir())
        if path:
            self.statusBar().showMessage(self.tr("Saved %1").replace("%1", path), 4000)

    def _about(self) -> None:
        QMessageBox.about(self, self.tr("About Shaper Designer"), about_text())

    def _show_guide(self) -> None:
        if self._guide is None:
            self._guide = GuideDialog(self._language, self)
        self._guide.show()
        self._guide.raise_()

    # ---- window state --------------------------------------------------------
    def _restore(self) -> None:
        geometry = self.settings.value("geometry")
        if isinstance(geometry, QByteArray) and not geometry.isEmpty():
            self.restoreGeometry(geometry)
        else:
            self.resize(1560, 940)
        state = self.settings.value("splitter")
        if isinstance(state, QByteArray):
            self.splitter.restoreState(state)

    def closeEvent(self, event: QCloseEvent) -> None:
        if not self.document.confirm_discard(self):
            event.ignore()
            return
        self.settings.setValue("geometry", self.saveGeometry())
        self.settings.setValue("splitter", self.splitter.saveState())
        if self._guide is not None:
            self._guide.close()
        self.explore.shutdown()
        event.accept()
