"""The window's menu bar and toolbar, built from the window's actions.

Every action has one home in a menu; the toolbar repeats the main ones with
icons. The View menu lists each pane (its dock's toggle action), the toolbar
and Reset layout.
"""
from __future__ import annotations

from typing import Protocol

from PySide6.QtCore import QCoreApplication, QSize
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QMenuBar, QToolBar

from .actions import fit_icon, standard_icon


class _Panes(Protocol):
    def toggle_actions(self) -> list: ...


class MenuHost(Protocol):
    """What the menus need of the window: its menu bar, a place for the toolbar, the
    panes. toggles and the actions. A protocol, so that this module does not import the
    window that imports it (issue 43: no import cycle, a TYPE_CHECKING one included)."""

    docks: _Panes
    lang_actions: dict[str, QAction]
    act_new: QAction
    act_open: QAction
    act_save: QAction
    act_save_as: QAction
    act_csv: QAction
    act_forces_csv: QAction
    act_plots_img: QAction
    act_scheme_img: QAction
    act_scheme_dxf: QAction
    act_report: QAction
    act_sheet: QAction
    act_course: QAction
    act_quit: QAction
    act_undo: QAction
    act_redo: QAction
    act_reset_layout: QAction
    act_fit: QAction
    act_fit_plots: QAction
    act_dims: QAction
    act_forces: QAction
    act_play: QAction
    act_step: QAction
    act_back: QAction
    act_goto: QAction
    act_library: QAction
    act_library_save: QAction
    act_compare: QAction
    act_guide: QAction
    act_about: QAction

    def menuBar(self) -> QMenuBar: ...
    def addToolBar(self, toolbar: QToolBar) -> None: ...


class Menus:
    """File, Edit, View, Animation, Library and Help menus, and the main toolbar."""

    def __init__(self, w: MenuHost) -> None:
        bar = w.menuBar()
        self.file = bar.addMenu("")
        self.file.addActions([w.act_new, w.act_open])
        self.recent = self.file.addMenu("")
        self.file.addActions([w.act_save, w.act_save_as])
        self.file.addSeparator()
        self.file.addActions([w.act_csv, w.act_forces_csv, w.act_plots_img, w.act_scheme_img,
                               w.act_scheme_dxf, w.act_report, w.act_sheet, w.act_course, w.act_class])
        self.file.addSeparator()
        self.file.addAction(w.act_quit)
        self.edit = bar.addMenu("")
        self.edit.addActions([w.act_undo, w.act_redo])
        self.view = bar.addMenu("")
        self.panes = self.view.addMenu("")
        self.panes.addActions(w.docks.toggle_actions())
        self.toolbar = QToolBar(w)
        self.toolbar.setObjectName("mainToolBar")
        self.toolbar.setIconSize(QSize(20, 20))
        self.toolbar.setMovable(True)
        self.panes.addSeparator()
        self.panes.addAction(self.toolbar.toggleViewAction())
        self.view.addAction(w.act_reset_layout)
        self.view.addSeparator()
        self.view.addActions([w.act_fit, w.act_fit_plots, w.act_dims, w.act_forces])
        self.lang = self.view.addMenu("")
        self.lang.addActions(list(w.lang_actions.values()))
        self.anim = bar.addMenu("")
        self.anim.addActions([w.act_play, w.act_step, w.act_back, w.act_goto])
        self.library = bar.addMenu("")
        self.library.addActions([w.act_library, w.act_library_save, w.act_compare])
        self.help = bar.addMenu("")
        self.help.addActions([w.act_guide, w.act_about])
        self._fill_toolbar(w)
        w.addToolBar(self.toolbar)

    def _fill_toolbar(self, w: MenuHost) -> None:
        icons = ((w.act_new, "SP_FileIcon"), (w.act_open, "SP_DialogOpenButton"),
                 (w.act_save, "SP_DialogSaveButton"), (w.act_undo, "SP_ArrowBack"),
                 (w.act_redo, "SP_ArrowForward"), (w.act_report, "SP_FileDialogDetailedView"))
        for action, name in icons:
            action.setIcon(standard_icon(w, name))
        w.act_fit.setIcon(fit_icon(w))
        w.act_fit_plots.setIcon(fit_icon(w, curve=True))
        groups = ((w.act_new, w.act_open, w.act_save), (w.act_undo, w.act_redo), (w.act_report,),
                  (w.act_back, w.act_play, w.act_step), (w.act_fit, w.act_fit_plots))
        for i, group in enumerate(groups):
            if i:
                self.toolbar.addSeparator()
            self.toolbar.addActions(list(group))

    def retranslate(self) -> None:
        translate = QCoreApplication.translate
        titles = ((self.file, translate("MainWindow", "&File")),
                  (self.recent, translate("MainWindow", "Open &Recent")),
                  (self.edit, translate("MainWindow", "&Edit")),
                  (self.view, translate("MainWindow", "&View")),
                  (self.panes, translate("MainWindow", "&Panes")),
                  (self.lang, translate("MainWindow", "&Language")),
                  (self.anim, translate("MainWindow", "&Animation")),
                  (self.library, translate("MainWindow", "&Library")),
                  (self.help, translate("MainWindow", "&Help")))
        for menu, text in titles:
            menu.setTitle(text)
        self.toolbar.setWindowTitle(translate("MainWindow", "Main toolbar"))
        self.toolbar.toggleViewAction().setText(translate("MainWindow", "&Toolbar"))
