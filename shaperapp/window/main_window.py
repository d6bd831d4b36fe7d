"""The main window only assembles: panes, docks, actions, menus, toolbar, window state.

It owns no design data (the model does) and no file logic (the document does);
widgets talk only to the model. Central: the plot tabs (Kinematics, Forces,
Positions, Explore, Compare) above the animation bar. Docks (``docks.py``):
inputs, results, mechanism, vector diagrams, library. Menus and toolbar are
built in ``menus.py``, actions behave as ``actions.py`` makes them, the views
built when first shown are made by ``pages.py``, and ``state.py`` fits the window
to the screen and remembers the layout.
"""
from __future__ import annotations

import os

import shiboken6
from PySide6.QtCore import QEvent, QSettings, QTimer
from PySide6.QtGui import QAction, QCloseEvent, QKeySequence
from PySide6.QtWidgets import QApplication, QInputDialog, QMainWindow, QMessageBox, QVBoxLayout, QWidget

from core.base.figure_text import figure_text

from shaperapp.design.document import Document
from shaperapp.design.inputs_pane import InputsPane
from shaperapp.design.model import DesignModel
from shaperapp.design.undo import retranslate_history
from shaperapp.plots.kinematics import PlotsWidget
from shaperapp.results.panel import MetricsPanel
from shaperapp.scheme.view import SchemeWidget
from shaperapp.widgets import dialog_titles, file_dialogs
from shaperapp.widgets import i18n
from shaperapp.widgets.guards import ShortcutGuard, guard_wheel
from shaperapp.widgets.lazy import LazyPage, ViewTabs, build_when_idle
from shaperapp.widgets.messages import describe

from . import pages
from . import state as window_state
from .actions import command, flush_typing, set_tip, stack_action, window_shortcut
from .animation import AnimationBar
from .docks import Docks
from .help import GuideDialog, about_text
from .menus import Menus
from .texts import action_texts

APP_NAME = "Shaper Designer"


class MainWindow(QMainWindow):
    def __init__(self, model: DesignModel, settings: QSettings, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.model = model
        self.settings = settings
        self.document = Document(model, settings, self)
        self.inputs = InputsPane(model)
        self.form = self.inputs.form
        self.metrics = MetricsPanel(model)
        self.scheme = SchemeWidget(model)
        self.animation = AnimationBar(model)
        self.plots = PlotsWidget(model)
        self.tabs = ViewTabs()
        self.tabs.addTab(self.plots, "")
        # The other tabs are built (and their modules imported) when first shown or asked for.
        self._pages = {name: LazyPage(lambda name=name: pages.tab_view(name, model)) for name in pages.TABS}
        for page in self._pages.values():
            self.tabs.addTab(page, "")
        # So are the panes hidden at first (the library) or behind another's tab (the vector diagrams).
        self._pages["polygons"] = LazyPage(
            lambda: pages.polygon_view(model, lambda: self.docks.enlarge_polygons()), defer=True)
        self._pages["library"] = LazyPage(lambda: pages.library_pane(model, settings, self._show_comparison))
        # The cam's and the gear pair's places in the design file exist from the start (Save
        # writes them, Open checks them); their models are made when first used, their tabs
        # when first shown.
        self._part_models = {"cam": pages.cam_part(model, self), "gear": pages.gear_part(model, self)}
        self._pages["cam"] = LazyPage(lambda: pages.cam_tab(model, self.cam_model))
        self.tabs.addTab(self._pages["cam"], "")
        self._pages["gear"] = LazyPage(lambda: pages.gear_tab(model, self.gear_model))
        self.tabs.addTab(self._pages["gear"], "")
        self._idle_build_started = False
        central = QWidget()
        column = QVBoxLayout(central)
        column.setContentsMargins(0, 0, 0, 0)
        column.setSpacing(0)
        column.addWidget(self.tabs, 1)
        column.addWidget(self.animation)
        self.setCentralWidget(central)
        self.docks = Docks(self, {"inputs": self.inputs, "results": self.metrics, "mechanism": self.scheme,
                                  "polygons": self._pages["polygons"], "library": self._pages["library"]})
        self.library_dock = self.docks["library"]

        self._build_actions()
        self.menus = Menus(self)
        self.menu_file, self.menu_edit = self.menus.file, self.menus.edit
        self._fill_recent()
        guard_wheel(self)
        self._shortcut_guard = ShortcutGuard(self, flush_typing)
        self.document.failed.connect(self._show_failure)
        self.document.recentChanged.connect(self._fill_recent)
        self.document.saved.connect(self._on_saved)
        self.document.noted.connect(self.statusBar().showMessage)     # until the next edit's status
        model.pathChanged.connect(self._update_title)
        model.dirtyChanged.connect(self._update_title)
        model.errorChanged.connect(self._show_status)
        model.resultsChanged.connect(self._show_status)
        self._retranslate()
        if window_state.restore(self, settings, self.docks.arrange):
            self.docks.keep_sizes()

    forces = property(lambda self: self._pages["forces"].view())
    positions = property(lambda self: self._pages["positions"].view())
    explore = property(lambda self: self._pages["explore"].view())
    compare = property(lambda self: self._pages["compare"].view())
    cam = property(lambda self: self._pages["cam"].view())
    gear = property(lambda self: self._pages["gear"].view())
    loads = property(lambda self: self.inputs.loads)
    cam_model = property(lambda self: self._part_models["cam"].model)
    gear_model = property(lambda self: self._part_models["gear"].model)

    polygon_view = property(lambda self: self._pages["polygons"].view())
    library = property(lambda self: self._pages["library"].view())

    def showEvent(self, event) -> None:
        super().showEvent(event)
        QTimer.singleShot(0, self, self.docks.apply_sizes)    # the default sizes, once laid out

    def paintEvent(self, event) -> None:
        super().paintEvent(event)
        if not self._idle_build_started:    # the first screen is up: build the rest meanwhile
            self._idle_build_started = True
            build_when_idle([self.inputs.loads_page, *self._pages.values()])

    flush_typing = staticmethod(flush_typing)

    # ---- actions -------------------------------------------------------------
    def _action(self, slot, keys=None) -> QAction:
        return command(self, slot, keys)

    def _build_actions(self) -> None:
        d, keys = self.document, QKeySequence.StandardKey
        self.act_new = self._action(lambda: d.new_dialog(self), keys.New)
        self.act_open = self._action(lambda: d.open_dialog(self), keys.Open)
        self.act_save = self._action(lambda: d.save_dialog(self), keys.Save)
        self.act_save_as = self._action(lambda: d.save_as_dialog(self), keys.SaveAs)
        self.act_csv = self._action(lambda: d.export_csv_dialog(self), "Ctrl+E")
        self.act_forces_csv = self._action(lambda: d.export_forces_csv_dialog(self), "Ctrl+Shift+E")
        self.act_plots_img = self._action(
            lambda: self._export_image(self.tabs.currentWidget(), "plots"), "Ctrl+Shift+P")
        self.act_scheme_img = self._action(lambda: self._export_image(self.scheme, "scheme"), "Ctrl+Shift+M")
        self.act_scheme_dxf = self._action(lambda: d.export_scheme_dxf_dialog(self))
        self.act_report = self._action(self._export_report, "Ctrl+R")
        self.act_sheet = self._action(self._export_sheet)
        self.act_course = self._action(self._export_course)
        self.act_class = self._action(self._class_course)
        # Only tabs that draw plots can export them as an image, or fit them.
        self.tabs.currentChanged.connect(self._on_tab)
        self.act_quit = self._action(self.close, keys.Quit)
        stack = self.model.undo_stack
        self.act_undo = stack_action(self, stack.createUndoAction(self, self.tr("Undo")), stack.undo, keys.Undo)
        self.act_redo = stack_action(self, stack.createRedoAction(self, self.tr("Redo")), stack.redo,
                                     keys.Redo, "Ctrl+Shift+Z", "Ctrl+Y")     # both, as the README says
        stack.undoTextChanged.connect(self._show_undo_text)
        stack.redoTextChanged.connect(self._show_redo_text)
        self.act_goto = self._action(self.go_to_angle_dialog, "Ctrl+G")
        # The widgets own these actions (and their texts); the window only adds shortcuts.
        self.act_play = window_shortcut(self, self.animation.play_action, "Space", "Ctrl+Space")
        self.act_step = window_shortcut(self, self.animation.step_forward_action, "Ctrl+Right")
        self.act_back = window_shortcut(self, self.animation.step_back_action, "Ctrl+Left")
        self.act_fit = window_shortcut(self, self.scheme.fit_action, "Ctrl+0")
        self.act_dims = window_shortcut(self, self.scheme.dimensions_action, "Ctrl+D")
        self.act_forces = window_shortcut(self, self.scheme.forces_action, "Ctrl+F")
        self.act_fit_plots = self._action(self._fit_plots, "Ctrl+Shift+0")
        self.act_reset_layout = self._action(lambda: self.docks.arrange(self.size()))
        self.act_library = self.library_dock.toggleViewAction()
        self.act_library.setShortcut(QKeySequence("Ctrl+L"))
        self.act_library_save = self._action(self._save_to_library, "Ctrl+Shift+L")
        self.act_compare = self._action(lambda: self.tabs.setCurrentWidget(self.compare))
        self.act_about = self._action(self._about)
        self.act_guide = self._action(self._show_guide, keys.HelpContents)
        self._guide: GuideDialog | None = None
        self._language = "en"
        self.lang_actions: dict[str, QAction] = {}
        for code, name in i18n.LANGUAGES:
            action = self._action(lambda _=False, c=code: self.set_language(c))
            action.setText(name)
            action.setCheckable(True)
            self.lang_actions[code] = action

    def _on_tab(self, *_) -> None:
        plots = self.tabs.currentWidget()
        self.act_plots_img.setEnabled(hasattr(plots, "export_image"))
        self.act_fit_plots.setEnabled(hasattr(plots, "stack"))

    def _fit_plots(self) -> None:
        if hasattr(self.tabs.currentWidget(), "stack"):
            self.tabs.currentWidget().stack().fit()

    def _fill_recent(self) -> None:
        menu = self.menus.recent
        menu.clear()
        files = self.document.recent_files()
        for path in files:
            action = menu.addAction(os.path.basename(path))
            action.setToolTip(path)
            action.triggered.connect(lambda _=False, p=path: self.document.open_dialog(self, p))
        menu.setEnabled(bool(files))

    # ---- translation ---------------------------------------------------------
    def set_language(self, code: str) -> None:
        i18n.set_language(code)
        # The window's dialogs are fitted to their titles (and its file dialogs put in its
        # language) by a filter of every event of the application: installed here, by the
        # window that shows dialogs, not by ``i18n`` for every process that translates. A
        # headless writer (``shaper report``/``course``/``class``, an export's child) shows
        # none, and the filter cost it about a tenth of its CPU (docs/performance.md,
        # "The suite's margin, 30 November (night)"). Held until the first paint (``app.main``).
        dialog_titles.install(QApplication.instance())
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
        texts = action_texts(self)
        for action, text, tip in texts:
            set_tip(action, text, tip)
        self.act_library.setText(self.tr("Show &library"))
        for i, title in enumerate((self.tr("Kinematics"), self.tr("Forces"), self.tr("Positions"),
                                   self.tr("Explore"), self.tr("Compare"), self.tr("Cam"), self.tr("Gear"))):
            self.tabs.setTabText(i, title)
        for name in ("cam", "gear"):
            if self._pages[name].is_built():
                self._pages[name].view().retranslate()
        self.docks.retranslate()
        self.menus.retranslate()
        retranslate_history(self.model.undo_stack)
        self._show_undo_text(self.model.undo_stack.undoText())
        self._show_redo_text(self.model.undo_stack.redoText())
        self._update_title()
        self._show_status()

    def _show_undo_text(self, text: str) -> None:
        """'Undo Time ratio K' in the current language (the stack's own prefix is fixed
        when the action is made). The stack outlives the window: skip once it is gone."""
        if shiboken6.isValid(self.act_undo):
            set_tip(self.act_undo, self.tr("&Undo %1").replace("%1", text).strip(), "")

    def _show_redo_text(self, text: str) -> None:
        if shiboken6.isValid(self.act_redo):
            set_tip(self.act_redo, self.tr("&Redo %1").replace("%1", text).strip(), "")

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
                self.tr("K = %1, H = %2 mm, θ = %3°").replace("%1", figure_text("ratio", m.time_ratio))
                .replace("%2", figure_text("length", m.stroke_mm)).replace("%3", figure_text("angle", m.theta_deg)))

    # ---- slots -------------------------------------------------------------
    def _show_failure(self, message: str) -> None:
        QMessageBox.warning(self, self.tr("Shaper Designer"), message)

    def _on_saved(self, path: str) -> None:
        self.statusBar().showMessage(self.tr("Saved %1").replace("%1", path), 4000)

    def _show_comparison(self, candidates: list) -> None:
        self.compare.set_candidates(candidates)
        self.tabs.setCurrentWidget(self.compare)
        if self.height() < 1000:          # on a small screen the docked library leaves the plots no room
            self.library_dock.hide()

    def _save_to_library(self) -> None:
        self.library_dock.show()
        self.library.save_dialog()

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
        from shaperapp.report.dialog import export_report_dialog   # builds offscreen views: load on demand
        self._exporting(self.act_report, export_report_dialog(self.model, self, self._language,
                                                              self.document.last_dir(), self.settings))

    def _exporting(self, action, run) -> None:
        """While an export's child process writes (the window usable meanwhile), its menu
        action is off; at its end what was written shows in the status bar."""
        if run is None:
            return
        action.setEnabled(False)

        def ended() -> None:
            action.setEnabled(True)
            if run.state == "done":
                self.statusBar().showMessage(self.tr("Saved %1").replace("%1", run.saved_as), 4000)
        run.ended.connect(ended)

    def _export_sheet(self) -> None:
        if not self.document.confirm_valid(self, saving=False):
            return
        from shaperapp.drawing.dialog import export_sheet_dialog   # load on demand
        path = export_sheet_dialog(self.model, self, self._language, self.document.last_dir(),
                                   self.settings, cam=self.cam_model,
                                   gear=self.gear_model)
        if path:
            self.statusBar().showMessage(self.tr("Saved %1").replace("%1", path), 4000)

    def _export_course(self) -> None:
        if not self.document.confirm_valid(self, saving=False):
            return
        from shaperapp.course.dialog import export_course_dialog   # load on demand
        self._exporting(self.act_course, export_course_dialog(self.model, self, self._language,
                                                              self.document.last_dir(), self.settings))

    def _class_course(self) -> None:
        from shaperapp.course.class_dialog import class_dialog   # load on demand
        class_dialog(self, self._language, self.document.last_dir())

    def _about(self) -> None:
        QMessageBox.about(self, self.tr("About Shaper Designer"), about_text())

    def _show_guide(self) -> None:
        if self._guide is None:
            self._guide = GuideDialog(self._language, self)
        self._guide.show()
        self._guide.raise_()

    # ---- window state --------------------------------------------------------
    def closeEvent(self, event: QCloseEvent) -> None:
        if not self.document.confirm_discard(self):
            event.ignore()
            return
        window_state.save(self, self.settings)
        if self._guide is not None:
            self._guide.close()
        explore = self._pages["explore"].built_view()
        if explore is not None:
            explore.shutdown()
        if self._part_models["cam"].made():         # (not made now only to be shut)
            self.cam_model.shutdown()
        event.accept()
