"""The Library pane's buttons: two rows of text buttons, Import and Export as menus.

In one row the pane's twelve buttons hid Import, Import folder, Export and Export all behind
the toolbar's » on a 1366 × 768 laptop, where the pane is a tab beside the Results (about
410 px wide), in English and in Chinese. Two rows (the designs in and out of the library;
the library's own edits), with the imports and the exports as one menu button each, show
every button there. Each button takes the keyboard's focus (Tab), as the fields beside it
do: a toolbar's buttons otherwise take none, and a menu button opens with Space.
"""
from __future__ import annotations

from typing import Callable, Sequence

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QMenu, QToolBar, QToolButton, QVBoxLayout, QWidget


def text_bar(parent: QWidget | None = None) -> QToolBar:
    """A row of text-only buttons."""
    bar = QToolBar(parent)
    bar.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextOnly)
    return bar


def bar_rows(*bars: QToolBar) -> QVBoxLayout:
    """The rows one under the other with no space between them and no margins round their
    buttons: the second row takes from the list below it as little as a row of buttons
    needs (at 1280 × 720 the list keeps its five rows)."""
    rows = QVBoxLayout()
    rows.setSpacing(0)
    for bar in bars:
        bar.setContentsMargins(0, 0, 0, 0)
        bar.layout().setContentsMargins(0, 0, 0, 0)
        rows.addWidget(bar)
    return rows


def bar_action(bar: QToolBar, slot: Callable[[], object]) -> QAction:
    """A button on ``bar`` that calls ``slot``; its text is set when translated."""
    action = bar.addAction("")
    action.triggered.connect(lambda _=False: slot())
    bar.widgetForAction(action).setFocusPolicy(Qt.FocusPolicy.TabFocus)
    return action


def menu_button(bar: QToolBar, slots: Sequence[Callable[[], object]]) -> tuple[QToolButton, list[QAction]]:
    """A button on ``bar`` whose menu holds one action per slot (its texts set when
    translated): the button and the actions."""
    button = QToolButton(bar)
    button.setPopupMode(QToolButton.ToolButtonPopupMode.InstantPopup)
    button.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextOnly)
    button.setFocusPolicy(Qt.FocusPolicy.TabFocus)
    menu = QMenu(button)
    actions = []
    for slot in slots:
        action = menu.addAction("")
        action.triggered.connect(lambda _=False, slot=slot: slot())
        actions.append(action)
    button.setMenu(menu)
    bar.addWidget(button)
    return button, actions
