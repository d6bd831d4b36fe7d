"""The on/off actions the views' menus and bars share (box zoom, dimensions, forces)."""
from __future__ import annotations

from collections.abc import Callable

from PySide6.QtGui import QAction
from PySide6.QtWidgets import QWidget


def switch_action(parent: QWidget, checked: bool, toggled: Callable[[bool], None]) -> QAction:
    """A checkable action that starts ``checked`` and calls ``toggled`` with each new state
    (its text is set by its owner, in the owner's translation context)."""
    action = QAction(parent)
    action.setCheckable(True)
    action.setChecked(checked)
    action.toggled.connect(toggled)
    return action
