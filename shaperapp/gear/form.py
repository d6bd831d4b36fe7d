"""The gear pair's inputs: teeth, module, how the shifts are given, the rack and the limits,
sent to the gear model after a pause.

As in the design and cam forms, text goes to the model as typed; the model names the field
that cannot make a pair and the form marks it, while the last valid pair stays on screen.
The module is an editable list of GB/T 1357's first series: any positive value is taken,
with the core's note under the form when it is not of that series.
"""
from __future__ import annotations

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QComboBox, QFormLayout, QLabel, QVBoxLayout, QWidget

from core.gear.involute import FIRST_SERIES_MM
from shaperapp.design.fields import (DEBOUNCE_MS, ERROR_STYLE, NumberField, exact_number,
                                     parse_number)
from shaperapp.widgets.messages import ERROR_TEXT_STYLE

from shaperapp.widgets.gear_messages import describe_gear_error, field_names, module_note
from .model import MODE_FIELDS, MODES, GearModel

UNITS = {"z1": "", "z2": "", "x1": "", "x2": "", "centre": "mm", "pressure_angle": "°",
         "addendum": "", "clearance": "", "tip_limit": "× m", "contact_limit": ""}
ORDER = ("z1", "z2", "module", "mode", "x1", "x2", "centre", "pressure_angle", "addendum",
         "clearance", "tip_limit", "contact_limit")


class GearForm(QWidget):
    """Number fields, the module and mode lists, the note and the error line under them."""

    def __init__(self, gear_model: GearModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = gear_model
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(DEBOUNCE_MS)
        self._timer.timeout.connect(self.commit)
        self._pending: set[str] = set()
        self.fields = {name: NumberField(unit) for name, unit in UNITS.items()}
        for field in self.fields.values():
            field.edit.setMinimumWidth(64)
            field.edit.setMaximumWidth(90)
        self.module = QComboBox(self)
        self.module.setEditable(True)
        self.module.setInsertPolicy(QComboBox.InsertPolicy.NoInsert)
        for m in FIRST_SERIES_MM:
            self.module.addItem(exact_number(m))
        self.module.setMaximumWidth(90)
        self.mode = QComboBox(self)
        self.mode.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon)
        self.mode.setMinimumContentsLength(12)      # the longest choice is shown when the list opens
        for mode in MODES:
            self.mode.addItem("", mode)
        self._labels = {name: QLabel(self) for name in ORDER}
        layout = QFormLayout()
        for name in ORDER:
            widget = {"module": self.module, "mode": self.mode}.get(name) or self.fields[name]
            layout.addRow(self._labels[name], widget)
        for name, field in self.fields.items():
            field.edited.connect(lambda n=name: self._typed(n))
        self.module.lineEdit().textEdited.connect(lambda _t: self._typed("module"))
        self.module.activated.connect(lambda _i: self._typed("module", at_once=True))
        self.mode.activated.connect(self._choose_mode)
        self.note = QLabel(self)
        self.note.setWordWrap(True)
        self.error_label = QLabel(self)
        self.error_label.setWordWrap(True)
        self.error_label.setStyleSheet(ERROR_TEXT_STYLE)
        column = QVBoxLayout(self)
        column.setContentsMargins(0, 0, 0, 0)
        column.addLayout(layout)
        column.addWidget(self.note)
        column.addWidget(self.error_label)
        column.addStretch(1)
        gear_model.typedChanged.connect(self._show_typed)
        gear_model.errorChanged.connect(self._show_error)
        gear_model.pairChanged.connect(self._show_note)
        self.retranslate()
        self._show_typed()

    def retranslate(self) -> None:
        names = field_names()
        for name, label in self._labels.items():
            label.setText(names[name])
        texts = {"auto": self.tr("automatic (the rule)"), "shifts": self.tr("shift factors x1, x2"),
                 "centre": self.tr("centre distance a′")}
        for i in range(self.mode.count()):
            self.mode.setItemText(i, texts[self.mode.itemData(i)])
        self.fields["z1"].edit.setToolTip(self.tr("The pinion, on the motor side"))
        self.fields["z2"].edit.setToolTip(self.tr("The gear, on the crank's shaft"))
        self._show_note()
        self._show_error()

    def commit(self) -> None:
        """Send the fields typed into since the last commit (the debounce timer's end)."""
        self._timer.stop()
        if not self._pending:
            return
        changes = {}
        for name in sorted(self._pending):
            text = self.module.currentText() if name == "module" else self.fields[name].edit.text()
            changes[name] = parse_number(text)
        self._pending.clear()
        self._model.set_fields(**changes)

    def _typed(self, name: str, at_once: bool = False) -> None:
        self._pending.add(name)
        self._timer.start()
        if at_once:
            self.commit()

    def _choose_mode(self, _index: int) -> None:
        self.commit()
        self._model.set_mode(self.mode.currentData())

    def _show_typed(self) -> None:
        values = self._model.typed.dict
        for name, field in self.fields.items():
            if name not in self._pending:
                field.set_value(values[name])
        if "module" not in self._pending:
            value = values["module"]
            if isinstance(value, str) or parse_number(self.module.currentText()) != value:
                self.module.setEditText(value if isinstance(value, str) else exact_number(value))
        mode = values["mode"]
        self.mode.setCurrentIndex(self.mode.findData(mode))
        for name in ("x1", "x2", "centre"):
            self.fields[name].setEnabled(name in MODE_FIELDS[mode])
            self.fields[name].edit.setCursorPosition(0)     # a long carried-over value from its start

    def _show_note(self) -> None:
        """The core's note when the module of the pair on screen is not of the first series."""
        inputs = self._model.pair.inputs
        text = module_note(inputs.module_mm) if inputs.module_note else ""
        self.note.setText(text)
        self.note.setVisible(bool(text))

    def _show_error(self) -> None:
        for field in self.fields.values():
            field.set_error(False)
        self.module.setStyleSheet("")
        error = self._model.error
        if error is None:
            self.error_label.hide()
            self.error_label.setText("")
            return
        if error.parameter in self.fields:
            self.fields[error.parameter].set_error(True)
        elif error.parameter == "module":
            self.module.setStyleSheet(ERROR_STYLE)
        self.error_label.setText("⚠ " + describe_gear_error(error) + "\n"
                                 + self.tr("The last valid gear pair stays on screen."))
        self.error_label.show()

    def marked_fields(self) -> list[str]:
        marked = [name for name, f in self.fields.items() if f.edit.styleSheet()]
        return (["module"] if self.module.styleSheet() else []) + marked
