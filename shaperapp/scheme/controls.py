"""The scheme's own controls: Fit, Show dimensions and Show forces as actions (the
right-click menu) and as the bar's button and check boxes, and the forces' crank speed.

Split from view.py so that the widget keeps to its layers, the view and the model's
signals; the widget connects these controls to what they do. Their texts keep the
SchemeWidget translation context they had.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QCheckBox, QComboBox, QHBoxLayout, QMenu, QToolButton, QWidget

from shaperapp.widgets.actions import switch_action
from shaperapp.widgets.view_parts import fill_speed_combo


translate = QCoreApplication.translate   # lupdate extracts translate("SchemeWidget", "…")


class SchemeControls:
    """The actions, the menu and the bar (``bar``, a layout for the widget to add); each
    check box and its action stay in step. The widget's handlers are connected first, in
    the order they always were: an action's handler runs before its box follows it."""

    def __init__(self, parent: QWidget, fit: Callable[[], None], dimensions: Callable[[bool], None],
                 forces: Callable[[bool], None], speed: Callable[[int], None]) -> None:
        self.fit_action = QAction(parent)
        self.fit_action.triggered.connect(fit)
        self.dimensions_action = switch_action(parent, True, dimensions)
        self.forces_action = switch_action(parent, False, forces)
        self.menu = QMenu(parent)
        for action in (self.fit_action, self.dimensions_action, self.forces_action):
            self.menu.addAction(action)
        self.fit_button = QToolButton()
        self.fit_button.setDefaultAction(self.fit_action)
        self.dims_box = QCheckBox()
        self.dims_box.setChecked(True)
        self.dims_box.toggled.connect(self.dimensions_action.setChecked)
        self.dimensions_action.toggled.connect(self.dims_box.setChecked)
        self.forces_box = QCheckBox()
        self.forces_box.setObjectName("forcesBox")
        self.forces_box.setChecked(False)
        self.forces_box.toggled.connect(self.forces_action.setChecked)
        self.forces_action.toggled.connect(self.forces_box.setChecked)
        self.speed_box = QComboBox()         # which crank speed's forces are drawn
        self.speed_box.setObjectName("forceSpeedBox")
        self.speed_box.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToContents)
        self.speed_box.setEnabled(False)
        self.speed_box.currentIndexChanged.connect(speed)
        self.forces_action.toggled.connect(self.speed_box.setEnabled)
        self.bar = QHBoxLayout()
        self.bar.setContentsMargins(4, 2, 4, 0)
        for widget in (self.fit_button, self.dims_box, self.forces_box, self.speed_box):
            self.bar.addWidget(widget)
        self.bar.addStretch(1)

    def retranslate(self, rpms: Sequence[float]) -> None:
        """Every text in the language now installed ("r/min" in the speed list too)."""
        self.fit_action.setText(translate("SchemeWidget", "Fit"))
        self.fit_action.setToolTip(translate("SchemeWidget", "Zoom to show the whole mechanism"))
        self.dimensions_action.setText(translate("SchemeWidget", "Show dimensions"))
        self.dims_box.setText(translate("SchemeWidget", "Show dimensions"))
        self.dims_box.setToolTip(translate("SchemeWidget",
                                           "Show the key dimensions L1, L2, L3, h and the stroke H"))
        self.forces_action.setText(translate("SchemeWidget", "Show forces"))
        self.forces_box.setText(translate("SchemeWidget", "Show forces"))
        self.forces_box.setToolTip(translate(
            "SchemeWidget", "Show the joint forces at the chosen crank speed as arrows, to one scale"))
        self.speed_box.setToolTip(translate("SchemeWidget", "Crank speed of the force arrows"))
        fill_speed_combo(self.speed_box, rpms)
