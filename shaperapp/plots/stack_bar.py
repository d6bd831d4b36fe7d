"""The bar above a plot stack and its context menu: a view's own controls, then Fit; the
menu holds Fit and the box-zoom switch (the stack sets their texts, in its context)."""
from __future__ import annotations

from collections.abc import Callable

from PySide6.QtGui import QAction
from PySide6.QtWidgets import QHBoxLayout, QMenu, QToolButton, QWidget

from shaperapp.widgets.actions import switch_action


class StackBar(QHBoxLayout):
    """``fit_action`` calls ``fit``; ``box_zoom`` (checked: a drag zooms to a box) calls ``set_box_zoom``."""

    def __init__(self, owner: QWidget, fit: Callable[[], None], set_box_zoom: Callable[[bool], None]) -> None:
        super().__init__()
        self.fit_action = QAction(owner)
        self.fit_action.triggered.connect(fit)
        self.box_zoom = switch_action(owner, True, set_box_zoom)
        self.menu = QMenu(owner)
        self.menu.addAction(self.fit_action)
        self.menu.addAction(self.box_zoom)
        fit_button = QToolButton()
        fit_button.setDefaultAction(self.fit_action)
        self.setContentsMargins(4, 2, 4, 2)
        self.addStretch(1)
        self.addWidget(fit_button)

    def add_tool(self, widget: QWidget) -> None:
        """A view's control, left of the Fit button."""
        self.insertWidget(self.count() - 2, widget)
