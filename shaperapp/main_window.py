"""The main window only assembles: widgets, menus, shortcuts, window state.

It owns no design data (the model does) and no file logic (the document
does); widgets talk only to the model.
"""
from __future__ import annotations

import os

from PySide6.QtCore import QByteArray, QEvent, QSettings, Qt
from PySide6.QtGui import QAction, QCloseEvent, QKeySequence
from PySide6.QtWidgets import (QFileDialog, QMainWindow, QMessageBox, QScrollArea, QSplitter,
                               QTabWidget, QVBoxLayout, QWidget)

from . import i18n
from .animation import AnimationBar
from .document import Document
from .explore_view import ExploreView
from .forces_panel import ForcesPanel
from .form import DesignForm
from .messages import describe
from .metrics_panel import MetricsPanel
from .model import DesignModel
from .plots import PlotsWidget
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

        self._build_actions()
        self._build_menus()
        self.document.failed.connect(self._show_failure)
        self.document.recentChanged.connect(self._fill_recent)
        self.document.saved.connect(self._on_saved)
        model.pathChanged.connect(self._update_title)
        model.dirtyChanged.connect(self._update_title)
        model.errorChanged.connect(self._show_status)
        model.resultsChanged.connect(self._show_status)
        self._retranslate()
        self._restore()

    # ---- actions and menus -------------------------------------------------
    def _action(self, slot, shortcut=None) -> QAction:
        action = QAction(self)
        if shortcut is not None:
            action.setShortcut(QKeySequence(shortcut))
        action.triggered.connect(slot)
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
        self.act_quit = self._action(self.close, QKeySequence.StandardKey.Quit)
        # The widgets own these actions (and their texts); the window only adds shortcuts.
        self.act_play = self._shortcut(self.animation.play_action, "Ctrl+Space")
        self.act_step = self._shortcut(self.animation.step_forward_action, "Ctrl+Right")
        self.act_back = self._shortcut(self.animation.step_back_action, "Ctrl+Left")
        self.act_fit = self._shortcut(self.scheme.fit_action, "Ctrl+0")
        self.act_dims = self._shortcut(self.scheme.dimensions_action, "Ctrl+D")
        self.act_forces = self._shortcut(self.scheme.forces_action, "Ctrl+F")
        self.act_about = self._action(self._about)
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
        self.menu_file.addSeparator()
        self.menu_file.addAction(self.act_quit)
        self.menu_view = bar.addMenu("")
        self.menu_view.addAction(self.act_fit)
        self.menu_view.addAction(self.act_dims)
        self.menu_view.addAction(self.act_forces)
        self.menu_lang = self.menu_view.addMenu("")
        for action in self.lang_actions.values():
            self.menu_lang.addAction(action)
        self.menu_anim = bar.addMenu("")
        for a in (self.act_play, self.act_step, self.act_back):
            self.menu_anim.addAction(a)
        self.menu_help = bar.addMenu("")
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
            (self.act_quit, self.tr("&Quit"), ""),
            (self.act_about, self.tr("&About"), ""),
        ]
        for action, text, tip in texts:
            action.setText(text)
            action.setStatusTip(tip)
        self.tabs.setTabText(0, self.tr("Kinematics"))
        self.tabs.setTabText(1, self.tr("Forces"))
        self.tabs.setTabText(2, self.tr("Explore"))
        self.menu_file.setTitle(self.tr("&File"))
        self.menu_recent.setTitle(self.tr("Open &Recent"))
        self.menu_view.setTitle(self.tr("&View"))
        self.menu_lang.setTitle(self.tr("&Language"))
        self.menu_anim.setTitle(self.tr("&Animation"))
        self.menu_help.setTitle(self.tr("&Help"))
        self._update_title()
        self._show_status()

    def _update_title(self, *_) -> None:
        name = os.path.basename(self.model.path) if self.model.path else self.tr("Untitled")
        self.setWindowTitle(f"{name}[*] — {self.tr('Shaper Designer')}")
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
        start = os.path.join(self.document.last_dir(), f"{stem}.png")
        path, _ = QFileDialog.getSaveFileName(self, self.tr("Export image"), start,
                                              self.tr("PNG image (*.png);;SVG drawing (*.svg)"))
        if not path:
            return
        try:
            widget.export_image(path)
        except OSError as exc:
            self._show_failure(self.tr("Could not write %1: %2").replace("%1", path)
                               .replace("%2", exc.strerror or str(exc)))

    def _about(self) -> None:
        QMessageBox.about(self, self.tr("About Shaper Designer"), self.tr(
            "Shaper Designer: synthesis and kinematics of the quick-return mechanism "
            "of a shaper (crank, slotted lever, ram).\nLengths in mm, speeds in r/min."))

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
        self.explore.shutdown()
        event.accept()
