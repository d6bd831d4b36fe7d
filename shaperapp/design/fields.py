"""What every input form is built from (the design's, the loads', the cam's, the gear's):
a number field with its unit, how a value shows as text and how text reads back, the
pause before typing is sent to a model (:class:`PendingEdits`), and the mark of an
invalid field with the line under the form that says why (:func:`show_error_line`).

Kept apart from the design form so that the three forms share one behaviour: a field
shows exactly what Save writes, accepts a decimal comma, and hands text that is no
number to the model as typed, which names the field to mark.
"""
from __future__ import annotations

from typing import Callable

from PySide6.QtCore import QObject, Qt, QTimer, Signal
from PySide6.QtWidgets import QHBoxLayout, QLabel, QLineEdit, QWidget

from shaperapp.widgets.messages import ERROR_TEXT_STYLE

DEBOUNCE_MS = 200        # typing is sent after this pause: one recompute per pause, not per key
ERROR_STYLE = "QLineEdit, QComboBox, QListWidget { border: 2px solid #c62828; background: #ffebee; }"


def format_number(value: float) -> str:
    """Six significant digits: a value a form shows about an input (a hint), not in one."""
    return f"{value:.6g}"


def exact_number(value: float) -> str:
    """The shortest text that reads back as exactly ``value``: an input field shows
    what Save will write, not a rounding of it (386.3703305, not 386.37)."""
    for digits in range(6, 18):
        text = f"{value:.{digits}g}"
        if float(text) == value:
            return text
    return repr(value)


def parse_number(text: str) -> float | str:
    """A float if the text is one (a decimal comma is accepted), else the text itself."""
    cleaned = text.strip().replace(",", ".")
    try:
        return float(cleaned)
    except ValueError:
        return text


class NumberField(QWidget):
    """A line edit with its unit beside it; emits ``edited`` on every keystroke."""

    edited = Signal()

    def __init__(self, unit: str, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.edit = QLineEdit(self)
        self.edit.setAlignment(Qt.AlignmentFlag.AlignRight)
        self.edit.setMinimumWidth(90)
        self.unit = QLabel(unit, self)
        self.unit.setMinimumWidth(34)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.edit, 1)
        layout.addWidget(self.unit)
        self.edit.textEdited.connect(self.edited)

    def set_value(self, value: float | str) -> None:
        """Show ``value`` unless the text already means it (so "1.60" stays as typed);
        text that is not a number (an invalid input, e.g. after undo) shows as it is."""
        if isinstance(value, str):
            if self.edit.text() != value:
                self.edit.setText(value)
        elif parse_number(self.edit.text()) != value:
            self.edit.setText(exact_number(value))

    def value(self) -> float | str:
        return parse_number(self.edit.text())

    def set_error(self, on: bool) -> None:
        self.edit.setStyleSheet(ERROR_STYLE if on else "")


class PendingEdits(QObject):
    """The fields typed into since the last commit, sent together after a pause.

    Every form's one path from keystrokes to its model: ``typed(name)`` restarts the
    DEBOUNCE_MS timer, and its end (or ``commit()``, before a choice, an export or the end
    of editing) hands the names to ``send`` once, so a pause costs one recompute and the
    fields not typed into are never re-read (their display rounding never changes a value).
    A form mirroring its model skips the names still pending (``name in pending``)."""

    def __init__(self, send: Callable[[set[str]], None], parent: QObject) -> None:
        super().__init__(parent)
        self._send = send
        self._names: set[str] = set()
        self.timer = QTimer(self)
        self.timer.setSingleShot(True)
        self.timer.setInterval(DEBOUNCE_MS)
        self.timer.timeout.connect(self.commit)

    def __contains__(self, name: object) -> bool:
        return name in self._names

    def typed(self, name: str, at_once: bool = False) -> None:
        """Field ``name`` was typed into: send after the pause (or now, ``at_once``)."""
        self._names.add(name)
        self.timer.start()
        if at_once:
            self.commit()

    def commit(self) -> None:
        """Send the pending names now (nothing when none is pending)."""
        self.timer.stop()
        if not self._names:
            return
        names, self._names = self._names, set()
        self._send(names)


def error_line(parent: QWidget) -> QLabel:
    """The hidden, wrapping red line under a form that says why its input is refused."""
    label = QLabel(parent)
    label.setWordWrap(True)
    label.setStyleSheet(ERROR_TEXT_STYLE)
    label.hide()
    return label


def show_error_line(label: QLabel, message: str | None, kept: str) -> None:
    """Show "⚠ message" and what stays on screen (``kept``), or hide the line (None)."""
    if message is None:
        label.setText("")
        label.hide()
        return
    label.setText("⚠ " + message + "\n" + kept)
    label.show()
