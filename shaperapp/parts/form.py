"""What every part's form does, written once: number fields from a table of units, laid out
with their labels in one order, typing sent to the part model after the shared pause
(``PendingEdits``), the model's typed fields shown back, and the field the model refuses
marked with the reason under the form while the last valid part stays on screen.

A part's form subclasses :class:`PartForm` and fills in its choices (``make_combos``), how a
field's text reads (``read``), its labels and how an error is worded (``describe``, ``kept``).
"""
from __future__ import annotations

from typing import Any

from PySide6.QtWidgets import QComboBox, QFormLayout, QLabel, QVBoxLayout, QWidget

from core.base.errors import DesignError
from shaperapp.design.fields import (ERROR_STYLE, NumberField, PendingEdits, error_line, parse_number,
                                     show_error_line)

from .model import PartModel


class PartForm(QWidget):
    """Number fields and choices in ``order``, then ``extras`` (e.g. a note), then the error line."""

    def __init__(self, part_model: PartModel, units: dict[str, str], order: tuple[str, ...],
                 field_width: int, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = part_model
        self.pending = PendingEdits(self._send, self)
        self.fields = {name: NumberField(units[name]) for name in units}
        for field in self.fields.values():
            field.edit.setMinimumWidth(64)
            field.edit.setMaximumWidth(field_width)
        self.combos: dict[str, QComboBox] = self.make_combos()
        self._labels = {name: QLabel(self) for name in order}
        layout = QFormLayout()
        for name in order:
            layout.addRow(self._labels[name], self.combos.get(name) or self.fields[name])
        for name, field in self.fields.items():
            field.edited.connect(lambda n=name: self.pending.typed(n))
        self.error_label = error_line(self)
        self.column = QVBoxLayout(self)
        self.column.setContentsMargins(0, 0, 0, 0)
        self.column.addLayout(layout)
        part_model.typedChanged.connect(self._show_typed)
        part_model.errorChanged.connect(self._show_error)

    def _finish(self, *extras: QWidget) -> None:
        """Place ``extras`` and the error line under the fields (the subclass's last step)."""
        for widget in (*extras, self.error_label):
            self.column.addWidget(widget)
        self.column.addStretch(1)

    # ---- what a part fills in ----------------------------------------------
    def make_combos(self) -> dict[str, QComboBox]:
        """The part's choices by field name (none by default)."""
        return {}

    def read(self, name: str) -> Any:
        """What the text of field ``name`` means, as the model takes it."""
        return parse_number(self.fields[name].edit.text())

    @staticmethod
    def describe(error: DesignError) -> str:
        """The reason in the current language (a subclass names its messages' function)."""
        raise NotImplementedError

    def kept(self) -> str:
        """What stays on screen while the typed fields are refused, in the current language."""
        raise NotImplementedError

    # ---- the shared path ---------------------------------------------------
    def set_labels(self, texts: dict[str, str]) -> None:
        for name, label in self._labels.items():
            label.setText(texts[name])

    def commit(self) -> None:
        """Send the fields typed into since the last commit (the debounce timer's end)."""
        self.pending.commit()

    def _send(self, names: set[str]) -> None:
        self._model.set_fields(**{name: self.read(name) for name in sorted(names)})

    def _show_typed(self) -> None:
        """The model's typed fields, leaving alone what is being typed."""
        values = self._model.typed.dict
        for name, field in self.fields.items():
            if name not in self.pending:
                field.set_value(values[name])

    def _show_error(self) -> None:
        for field in self.fields.values():
            field.set_error(False)
        for combo in self.combos.values():
            combo.setStyleSheet("")
        error = self._model.error
        if error is not None:
            if error.parameter in self.fields:
                self.fields[error.parameter].set_error(True)
            elif error.parameter in self.combos:
                self.combos[error.parameter].setStyleSheet(ERROR_STYLE)
        kept = self.kept() if self._model.own_value else self._model.unmade_text()
        show_error_line(self.error_label, None if error is None else self.describe(error), kept)

    def marked_fields(self) -> list[str]:
        """Names of the inputs marked invalid: a marked choice first, then the fields."""
        marked = [name for name, combo in self.combos.items() if combo.styleSheet()]
        return marked + [name for name, f in self.fields.items() if f.edit.styleSheet()]
