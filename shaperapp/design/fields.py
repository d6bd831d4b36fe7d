"""What every input form is built from (the design's, the loads', the cam's): a number
field with its unit, how a value shows as text and how text reads back, the pause
before typing is sent to a model, and the mark of an invalid field.

Kept apart from the design form so that the three forms share one behaviour: a field
shows exactly what Save writes, accepts a decimal comma, and hands text that is no
number to the model as typed, which names the field to mark.
"""
from __future__ import annotations

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import QHBoxLayout, QLabel, QLineEdit, QWidget

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
