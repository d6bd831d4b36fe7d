"""How the window's actions are made: commands that first send what is being typed,
undo/redo taken from the stack, window-wide shortcuts for the widgets' own actions,
and the toolbar's icons.

The window decides which actions exist and what they do; this module only makes
them behave alike.
"""
from __future__ import annotations

import math
from typing import Callable

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QAction, QIcon, QKeySequence, QPainter, QPen, QPixmap
from PySide6.QtWidgets import QApplication, QLineEdit, QStyle, QWidget

Keys = str | QKeySequence.StandardKey | None


def flush_typing() -> None:
    """Commit the focused line edit as if the user had left it."""
    focus = QApplication.focusWidget()
    if isinstance(focus, QLineEdit) and not focus.isReadOnly():
        focus.editingFinished.emit()


def command(parent: QWidget, slot: Callable[[], object], keys: Keys = None) -> QAction:
    """An action that first sends what is typed in the focused field (so Save, Export
    or Undo act on it, not on the value before the debounce)."""
    action = QAction(parent)
    if keys is not None:
        action.setShortcut(QKeySequence(keys))
    action.triggered.connect(lambda *_: (flush_typing(), slot()))
    parent.addAction(action)
    return action


def stack_action(parent: QWidget, action: QAction, step: Callable[[], None],
                 keys: QKeySequence.StandardKey, *extra: str) -> QAction:
    """Undo/redo actions from the stack (their text and enabled state follow it),
    triggered through :func:`flush_typing` first."""
    action.triggered.disconnect()
    action.triggered.connect(lambda *_: (flush_typing(), step()))
    shortcuts = QKeySequence.keyBindings(keys)
    for key in extra:
        if QKeySequence(key) not in shortcuts:    # the same key twice would be ambiguous
            shortcuts.append(QKeySequence(key))
    action.setShortcuts(shortcuts)
    parent.addAction(action)
    return action


def window_shortcut(parent: QWidget, action: QAction, *keys: str) -> QAction:
    """A widget's own action, reachable by ``keys`` anywhere in the window."""
    action.setShortcuts([QKeySequence(k) for k in keys])
    action.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
    parent.addAction(action)
    return action


def standard_icon(widget: QWidget, name: str) -> QIcon:
    return widget.style().standardIcon(getattr(QStyle.StandardPixmap, name))


def fit_icon(widget: QWidget, curve: bool = False, size: int = 32) -> QIcon:
    """Four corner brackets around a dot (the mechanism) or a wave (the plots): 'show
    everything' (the style has no such icon)."""
    pixmap = QPixmap(size, size)
    pixmap.fill(Qt.GlobalColor.transparent)
    painter = QPainter(pixmap)
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    pen = QPen(widget.palette().windowText().color(), size / 12)
    painter.setPen(pen)
    m, c = size * 0.15, size * 0.3
    for x, dx in ((m, 1), (size - m, -1)):
        for y, dy in ((m, 1), (size - m, -1)):
            painter.drawLine(QPointF(x, y), QPointF(x + dx * c, y))
            painter.drawLine(QPointF(x, y), QPointF(x, y + dy * c))
    if curve:
        wave = [QPointF(size * (0.3 + 0.4 * i / 8), size * (0.5 - 0.16 * math.sin(math.pi * i / 4)))
                for i in range(9)]
        painter.drawPolyline(wave)
    else:
        painter.drawEllipse(QRectF(size * 0.4, size * 0.4, size * 0.2, size * 0.2))
    painter.end()
    return QIcon(pixmap)


def set_tip(action: QAction, text: str, tip: str) -> None:
    """Menu text, status tip, and a tooltip naming the shortcut (for the toolbar)."""
    action.setText(text)
    action.setStatusTip(tip)
    plain = text.replace("&&", "\0").replace("&", "").replace("\0", "&").rstrip("…")
    keys = action.shortcut().toString(QKeySequence.SequenceFormat.NativeText)
    head = f"{plain} ({keys})" if keys else plain
    action.setToolTip(f"{head}\n{tip}" if tip else head)
