"""Helpers for GUI tests: a widget shown as a user sees it, and the assembled window.

A module of its own (not conftest): ``benchmarks/`` has a conftest too, and
``from conftest import …`` would find whichever was imported first.
"""
from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, TypeVar

from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QWidget

from shaperapp.design.model import DesignModel
from shaperapp.widgets import dialog_titles, i18n
from shaperapp.window.main_window import MainWindow

W = TypeVar("W", bound=QWidget)


def shown(qtbot, widget: W, width: int, height: int) -> W:
    """``widget`` handed to qtbot (closed after the test), at ``width`` × ``height``,
    shown and exposed: laid out and painted as a user would see it."""
    qtbot.addWidget(widget)
    widget.resize(width, height)
    widget.show()
    qtbot.waitExposed(widget)
    return widget


@contextmanager
def main_window(folder: Path) -> Iterator[MainWindow]:
    """The assembled window on the default design, shown, with its settings in ``folder``.
    Afterwards it closes without the unsaved-changes question and the language is English."""
    settings = QSettings(str(folder / "s.ini"), QSettings.Format.IniFormat)
    win = MainWindow(DesignModel(), settings)
    win.show()
    try:
        yield win
    finally:
        win.animation.play_action.setChecked(False)
        win.model.set_clean(win.model.path)
        win.close()
        win.deleteLater()
        i18n.set_language("en")
        dialog_titles.uninstall()       # the application as the test found it (see uninstall)


def curve_items(plot_item) -> list:
    """The curve items a stacked plot holds (removed ones are gone, not just emptied)."""
    from shaperapp.plots.items import CurveItem
    return [item for item in plot_item.items if isinstance(item, CurveItem)]
