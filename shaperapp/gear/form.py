"""The gear pair's inputs: teeth, module, how the shifts are given, the rack and the limits,
sent to the gear model after a pause.

As in the design and cam forms, text goes to the model as typed; the model names the field
that cannot make a pair and the form marks it, while the last valid pair stays on screen.
The module is an editable list of GB/T 1357's first series: any positive value is taken,
with the core's note under the form when it is not of that series.
"""
from __future__ import annotations

from typing import Any

from PySide6.QtWidgets import QComboBox, QLabel, QWidget

from core.base.figure_text import figure_text
from core.gear.involute import FIRST_SERIES_MM
from shaperapp.design.fields import exact_number, parse_number
from shaperapp.parts.form import PartForm
from shaperapp.widgets.gear_messages import describe_gear_error, field_names, module_note

from .model import MODE_FIELDS, MODES, GearModel

UNITS = {"z1": "", "z2": "", "x1": "", "x2": "", "centre": "mm", "pressure_angle": "°",
         "addendum": "", "clearance": "", "tip_limit": "× m", "contact_limit": ""}
FIELD_WIDTH = 80
"""px of a number field: the shown text is rounded to fit (``shown_number``), the value kept."""
LABEL_WIDTH = 100
"""px of a field's name at most (longer ones wrap): with FIELD_WIDTH, the form leaves both
gears' columns room beside it at 1280 × 720 in English."""
SHIFT_FIELDS = ("x1", "x2", "centre")
SHOWN_KINDS = {"x1": "gear_factor", "x2": "gear_factor", "centre": "gear_length"}
"""How a greyed shift field (the pair's value, derived by the mode) writes it: as the Gear
tab's table and ``shaper gear`` write that figure (``core.base.figure_text``), 0.239644 and
162.1049 (it showed 7 significant digits, 0.2396444 beside the table's 0.239644)."""
SHOWN_DIGITS = 7
"""Significant digits a shift field of the mode shows of a value it did not get typed (carried
over from the pair when the mode changed): 0.4151111 fits FIELD_WIDTH, and a value from a
file reads as it was typed (0.3, not 0.300000). The exact value is the tooltip either way,
and the model keeps it."""
ORDER = ("z1", "z2", "module", "mode", "x1", "x2", "centre", "pressure_angle", "addendum",
         "clearance", "tip_limit", "contact_limit")


class GearForm(PartForm):
    """Number fields, the module and mode lists, the note and the error line under them."""

    def __init__(self, gear_model: GearModel, parent: QWidget | None = None) -> None:
        super().__init__(gear_model, UNITS, ORDER, FIELD_WIDTH, parent)
        for field in self.fields.values():
            field.unit.setMinimumWidth(0)       # "mm", "°", "× m": the form narrow enough that
            # both gears' columns fit beside it at 1280 × 720
        for label in self._labels.values():     # a long name on two lines, not a wider form
            label.setWordWrap(True)
            label.setMaximumWidth(LABEL_WIDTH)
        self.module.lineEdit().textEdited.connect(lambda _t: self.pending.typed("module"))
        self.module.activated.connect(lambda _i: self.pending.typed("module", at_once=True))
        self.mode.activated.connect(self._choose_mode)
        self.note = QLabel(self)
        self.note.setWordWrap(True)
        self._finish(self.note)
        gear_model.pairChanged.connect(self._show_note)
        gear_model.pairChanged.connect(self._show_typed)     # the greyed fields follow the pair
        self.retranslate()
        self._show_typed()

    describe = staticmethod(describe_gear_error)

    def make_combos(self) -> dict[str, QComboBox]:
        self.module = QComboBox(self)
        self.module.setEditable(True)
        self.module.setInsertPolicy(QComboBox.InsertPolicy.NoInsert)
        for m in FIRST_SERIES_MM:
            self.module.addItem(exact_number(m))
        self.module.setMaximumWidth(FIELD_WIDTH)
        self.mode = QComboBox(self)
        self.mode.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon)
        self.mode.setMinimumContentsLength(11)      # the longest choice is shown when the list opens
        for mode in MODES:
            self.mode.addItem("", mode)
        return {"module": self.module, "mode": self.mode}

    def retranslate(self) -> None:
        names = field_names()
        self.set_labels(names)
        for name, label in self._labels.items():
            label.setMinimumWidth(min(label.fontMetrics().horizontalAdvance(names[name]) + 2, LABEL_WIDTH))
        texts = {"auto": self.tr("automatic (the rule)"), "shifts": self.tr("shift factors x1, x2"),
                 "centre": self.tr("centre distance a′")}
        for i in range(self.mode.count()):
            self.mode.setItemText(i, texts[self.mode.itemData(i)])
        self.fields["z1"].edit.setToolTip(self.tr("The pinion, on the motor side"))
        self.fields["z2"].edit.setToolTip(self.tr("The gear, on the crank's shaft"))
        self._show_note()
        self._show_error()

    def read(self, name: str) -> Any:
        return parse_number(self.module.currentText()) if name == "module" else super().read(name)

    def kept(self) -> str:
        return self.tr("The last valid gear pair stays on screen.")

    def _choose_mode(self, _index: int) -> None:
        mode = self.mode.currentData()          # before the commit shows the model's
        self.commit()
        self._model.set_mode(mode)

    def shown_values(self) -> dict:
        """What each number field stands for: the typed value, and for the shift fields its
        mode does not use (greyed) the pair on screen's, the pair the tables show (when the
        typed pair is refused, the last valid one)."""
        values = self._model.typed.dict
        pair = self._model.pair
        derived = {"x1": pair.gear1.shift, "x2": pair.gear2.shift, "centre": pair.centre_mm}
        return {name: derived[name] if name in derived and name not in MODE_FIELDS[values["mode"]]
                else values[name] for name in self.fields}

    def _show_typed(self) -> None:
        values = self._model.typed.dict
        for name, value in self.shown_values().items():
            if name in self.pending:
                continue
            if name in SHIFT_FIELDS and not isinstance(value, str):
                self._show_rounded(name, value, greyed=name not in MODE_FIELDS[values["mode"]])
            else:
                self.fields[name].set_value(value)
        if "module" not in self.pending:
            value = values["module"]
            if isinstance(value, str) or parse_number(self.module.currentText()) != value:
                self.module.setEditText(value if isinstance(value, str) else exact_number(value))
        mode = values["mode"]
        self.mode.setCurrentIndex(self.mode.findData(mode))
        for name in SHIFT_FIELDS:
            self.fields[name].setEnabled(name in MODE_FIELDS[mode])
            self.fields[name].edit.setCursorPosition(0)     # a long carried-over value from its start

    def _show_rounded(self, name: str, value: float, greyed: bool) -> None:
        """``value`` in shift field ``name``: greyed, as its figure is written (SHOWN_KINDS);
        else rounded to SHOWN_DIGITS unless its text already means it (a value as typed stays
        as typed). The exact value is the tooltip. A field's text is sent to the model only
        when typed into, so the rounding never replaces the value."""
        edit = self.fields[name].edit
        edit.setToolTip(exact_number(value))
        if greyed:
            rounded = figure_text(SHOWN_KINDS[name], value)
            if edit.text() != rounded:
                edit.setText(rounded)
            return
        rounded = f"{value:.{SHOWN_DIGITS}g}"
        if parse_number(edit.text()) != value and edit.text() != rounded:
            edit.setText(rounded)

    def _show_note(self) -> None:
        """The core's note when the module of the pair on screen is not of the first series."""
        inputs = self._model.pair.inputs
        text = module_note(inputs.module_mm) if inputs.module_note else ""
        self.note.setText(text)
        self.note.setVisible(bool(text))
