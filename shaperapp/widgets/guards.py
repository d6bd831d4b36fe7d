"""Event filters that keep input predictable.

* :class:`WheelGuard` — the mouse wheel never changes a choice, number or slider
  the user has not focused: such widgets take focus only by click or Tab, and a
  wheel over them while unfocused scrolls the panel they sit in instead.
* :class:`ShortcutGuard` — the window's shortcuts work wherever the focus is. A
  line edit claims Ctrl+E, Ctrl+Left/Right, Ctrl+Z … for its own editing; for
  the keys of the window's actions the guard declines that claim, so the action
  runs. A bare key (Space to play) still types into a text field.

Neither filters the whole application: a Python filter on the application sees
every event of every widget (each repaint of each label), and the two together
cost about 2 ms of a 10 ms animation frame and 7 ms of an edit. The wheel guard
sits on the choices, numbers and sliders themselves, which see few events; the
shortcut guard follows the focus widget.
"""
from __future__ import annotations

from typing import Callable

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtGui import QAction, QKeyEvent, QKeySequence
from PySide6.QtWidgets import (QAbstractScrollArea, QAbstractSpinBox, QApplication, QComboBox, QLineEdit, QPlainTextEdit,
                               QScrollBar, QSlider, QTextEdit, QWidget)

_WHEEL_TARGETS = (QComboBox, QAbstractSpinBox, QSlider)


def is_text_input(widget: QWidget | None) -> bool:
    """A widget in which a bare key types text."""
    if isinstance(widget, QComboBox):
        return widget.isEditable()
    return isinstance(widget, (QLineEdit, QTextEdit, QPlainTextEdit, QAbstractSpinBox))


def _scroll_area(widget: QWidget) -> QAbstractScrollArea | None:
    parent = widget.parentWidget()
    while parent is not None and not isinstance(parent, QAbstractScrollArea):
        parent = parent.parentWidget()
    return parent


def _wheel_target(obj: QObject) -> bool:
    return isinstance(obj, _WHEEL_TARGETS) and not isinstance(obj, QScrollBar)


class WheelGuard(QObject):
    """Installed on each choice, number and slider (see :func:`guard_wheel`)."""

    def eventFilter(self, obj: QObject, event: QEvent) -> bool:  # noqa: N802 - Qt's name
        if event.type() == QEvent.Type.Wheel and not obj.hasFocus():
            area = _scroll_area(obj)
            if area is not None:              # scroll the panel the widget sits in
                QApplication.sendEvent(area.verticalScrollBar(), event)
            return True
        return False

    def protect(self, widget: QWidget) -> None:
        if widget.property("shaperWheelGuard"):
            return
        widget.setProperty("shaperWheelGuard", True)
        if widget.focusPolicy() == Qt.FocusPolicy.WheelFocus:
            widget.setFocusPolicy(Qt.FocusPolicy.StrongFocus)
        widget.installEventFilter(self)


def _guard() -> WheelGuard | None:
    app = QApplication.instance()
    if app is None:
        return None
    guard = app.findChild(WheelGuard, "shaperWheelGuard")
    if guard is None:
        guard = WheelGuard(app)
        guard.setObjectName("shaperWheelGuard")
        # A window in which a widget gets the focus (a dialog, Qt's file dialog, a floated
        # pane) has its choices guarded before the user can scroll over them.
        app.focusChanged.connect(_guard_focus_window)
    return guard


def guard_wheel(root: QWidget) -> None:
    """Guard every choice, number and slider in ``root`` (itself included); idempotent."""
    guard = _guard()
    if guard is None:
        return
    # Qt picks the targets by type (each kind's list made in C++): asked for every widget,
    # Python wrapped the window's 900-odd widgets one by one to test them (1.3 ms at start).
    found = {id(w): w for kind in _WHEEL_TARGETS for w in root.findChildren(kind)}
    for widget in [root, *found.values()]:
        if _wheel_target(widget):
            guard.protect(widget)


def _guard_focus_window(_old: QWidget | None, new: QWidget | None) -> None:
    if new is not None:
        try:
            guard_wheel(new.window())
        except RuntimeError:          # the focus moved to a widget being destroyed
            pass


def install_wheel_guard() -> None:
    """Guard every present widget now, and each window's when a widget in it gets the focus."""
    for top in QApplication.topLevelWidgets():
        guard_wheel(top)


class ShortcutGuard(QObject):
    """Lets ``window``'s action shortcuts win over a focused widget's own key bindings.

    A key's ShortcutOverride goes to the focus widget, so the guard filters just that
    widget, and moves with the focus."""

    def __init__(self, window: QWidget, before: Callable[[], None]) -> None:
        """``before`` runs when one of the window's shortcuts is pressed, before the
        action is looked up (the window sends pending typing, which may enable Undo)."""
        super().__init__(window)
        self._window = window
        self._before = before
        app = QApplication.instance()
        app.focusChanged.connect(self._follow_focus)
        self._follow_focus(None, app.focusWidget())

    def _follow_focus(self, old: QWidget | None, new: QWidget | None) -> None:
        if old is not None:
            try:
                old.removeEventFilter(self)
            except RuntimeError:          # the old focus widget is being destroyed
                pass
        if new is not None:
            try:
                new.installEventFilter(self)
            except RuntimeError:
                pass

    def eventFilter(self, obj: QObject, event: QEvent) -> bool:  # noqa: N802 - Qt's name
        if event.type() != QEvent.Type.ShortcutOverride or not isinstance(event, QKeyEvent):
            return False
        focus = QApplication.focusWidget()
        if focus is None or obj is not focus or focus.window() is not self._window:
            return False
        pressed = QKeySequence(event.keyCombination())
        bare = event.modifiers() in (Qt.KeyboardModifier.NoModifier, Qt.KeyboardModifier.KeypadModifier)
        if bare and is_text_input(focus):
            return False          # Space, letters … type text
        actions = self._actions_for(pressed)
        if not actions:
            return False
        self._before()
        if any(action.isEnabled() for action in actions):
            event.ignore()        # not claimed by the widget: the shortcut map runs the action
            return True
        return False              # e.g. nothing to undo: the field's own binding may act

    def _actions_for(self, pressed: QKeySequence) -> list[QAction]:
        return [action for action in self._window.findChildren(QAction)
                if any(sequence.matches(pressed) == QKeySequence.SequenceMatch.ExactMatch
                       for sequence in action.shortcuts())]
