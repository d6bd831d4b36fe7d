"""The loads form: masses, centres of mass, cutting force and flywheel requirement.

A compact form for ``MassProperties``. Like the design form, text goes to the
model as typed after a short pause, so the model's validation names the field
to mark; a bad value keeps the last valid loads (and their results) on screen.
The form draws nothing: the force plots (forces.py) and the scheme's force
arrows follow the model.
"""
from __future__ import annotations

import math

from PySide6.QtCore import QEvent
from PySide6.QtWidgets import (QCheckBox, QComboBox, QFormLayout, QGroupBox, QLabel, QLineEdit,
                               QVBoxLayout, QWidget)

from core.forces.masses import GRAVITY
from core.base.errors import DesignError
from core.forces.rotors import rotors_from_text, rotors_text

from shaperapp.widgets.messages import describe

from .errors import as_typed
from .fields import NumberField, PendingEdits, error_line, format_number, parse_number, show_error_line
from .model import DesignModel

# Input fields in form order: MassProperties names, except the two ram offsets
# (one pair in the model) and the idle margin (typed in %, stored as a fraction).
FIELD_UNITS = {
    "lever_mass_kg": "kg", "lever_cg_mm": "mm", "lever_inertia_kg_m2": "kg·m²",
    "ram_mass_kg": "kg", "ram_cg_dx": "mm", "ram_cg_dy": "mm",
    "rod_mass_kg": "kg", "block_mass_kg": "kg",
    "cut_force_N": "N", "cut_height_mm": "mm", "idle_percent": "%",
    "delta": "–", "lever_weight_N": "N", "ram_weight_N": "N", "guide_length_mm": "mm",
    "rotors": "J:ω/ω2",
}
GROUPS = (("lever", ("lever_given", "lever_mass_kg", "lever_weight_N", "lever_cg_mm",
                     "lever_inertia_kg_m2")),
          ("ram", ("ram_given", "ram_mass_kg", "ram_weight_N", "ram_cg_dx", "ram_cg_dy",
                   "guide_length_mm")),
          ("links", ("rod_mass_kg", "block_mass_kg")),
          ("cutting", ("cut_force_N", "cut_height_mm", "idle_percent")),
          ("flywheel", ("gravity", "delta", "rotors")))
# A link whose load is typed as a mass (kg) or, as the task book states it, a weight (N):
# link → (mass field, weight field); the choice shows one of the two.
GIVEN = {"lever": ("lever_mass_kg", "lever_weight_N"), "ram": ("ram_mass_kg", "ram_weight_N")}
EMPTY_IS_NONE = ("lever_cg_mm", "guide_length_mm")     # empty: the default (L3/2, the stroke H)
DELTA_DIGITS = 4                         # δ = 1/30 shows as 0.03333


def parse_ratio(text: str) -> float | str:
    """δ is usually quoted as a fraction (1/30): accept ``a/b`` as well as a decimal.

    Returns the float, or the text itself when it is not a number, so that the
    model's validation reports it like any other bad input."""
    if "/" not in text:
        return parse_number(text)
    top, _, bottom = text.partition("/")
    a, b = parse_number(top), parse_number(bottom)
    if isinstance(a, float) and isinstance(b, float) and b != 0.0:
        return a / b
    return text


class LoadsForm(QWidget):
    """Load inputs of the forces view, grouped by link; marks the field the model rejects."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self.pending = PendingEdits(self._send, self)     # fields typed into, sent after a pause

        self._fields = {name: NumberField(unit) for name, unit in FIELD_UNITS.items()}
        self._gravity = QCheckBox(self)
        self._given = {link: QComboBox(self) for link in GIVEN}
        for combo in self._given.values():
            combo.addItem("", "mass")
            combo.addItem("", "weight")
        self._forms: dict[str, QFormLayout] = {}
        self._labels: dict[str, QLabel] = {}
        self._boxes: dict[str, QGroupBox] = {}
        self._error_label = error_line(self)
        column = QVBoxLayout(self)
        column.setContentsMargins(4, 4, 4, 4)
        for key, names in GROUPS:
            box = QGroupBox(self)
            form = QFormLayout(box)
            form.setFieldGrowthPolicy(QFormLayout.FieldGrowthPolicy.AllNonFixedFieldsGrow)
            for name in names:
                label = QLabel(box)
                self._labels[name] = label
                form.addRow(label, self._widget(name))
            self._boxes[key] = box
            self._forms[key] = form
            column.addWidget(box)
        column.addWidget(self._error_label)
        column.addStretch(1)

        for name, number in self._fields.items():
            number.edited.connect(lambda n=name: self.pending.typed(n))
            number.edit.editingFinished.connect(self._commit)
        self._gravity.toggled.connect(lambda on: self._model.set_masses(gravity=on))
        for link, combo in self._given.items():
            combo.activated.connect(lambda _i, k=link: self._on_given(k))
        model.forcesChanged.connect(self._on_forces)
        model.forcesErrorChanged.connect(self._show_error)
        self._retranslate()
        self._on_forces()

    # ---- public API ----------------------------------------------------
    def field(self, name: str) -> QLineEdit:
        """The line edit of an input: a MassProperties name, ``ram_cg_dx``/``ram_cg_dy``
        or ``idle_percent``."""
        return self._fields[name].edit

    def gravity_box(self) -> QCheckBox:
        return self._gravity

    def given_box(self, link: str) -> QComboBox:
        """The mass/weight choice of ``link`` ("lever" or "ram")."""
        return self._given[link]

    def _widget(self, name: str) -> QWidget:
        if name == "gravity":
            return self._gravity
        if name.endswith("_given"):
            return self._given[name.removesuffix("_given")]
        return self._fields[name]

    def marked_fields(self) -> list[str]:
        """Names (as for :meth:`field`) of the inputs marked invalid."""
        return [name for name, number in self._fields.items() if number.edit.styleSheet()]

    def error_text(self) -> str:
        """The message under the form ('' while the loads are valid)."""
        return self._error_label.text() if self._model.forces_error is not None else ""

    # ---- model → form --------------------------------------------------
    def _on_forces(self) -> None:
        self._fields["rod_mass_kg"].setEnabled(self._model.design.rod is not None)
        self._show_inputs()
        self._show_placeholder()

    def _show_placeholder(self) -> None:
        half = format_number(self._model.design.lever / 2.0)
        self._fields["lever_cg_mm"].edit.setPlaceholderText(self.tr("L3/2 = {0}").format(half))
        stroke = format_number(self._model.design.stroke)
        self._fields["guide_length_mm"].edit.setPlaceholderText(self.tr("H = {0}").format(stroke))
        self._fields["rotors"].edit.setPlaceholderText(self.tr("none"))

    # ---- text ----------------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _field_texts(self) -> dict[str, tuple[str, str]]:
        """(label, tooltip) of every input."""
        return {
            "lever_mass_kg": (self.tr("Mass m4"), self.tr("Mass of the slotted lever O4B, kg")),
            "lever_cg_mm": (self.tr("Centre of mass c"),
                            self.tr("Distance of the lever's centre of mass from O4 along O4B, mm; "
                                    "leave empty for L3/2")),
            "lever_inertia_kg_m2": (self.tr("Inertia J_S4"),
                                    self.tr("Moment of inertia of the lever about its centre of "
                                            "mass, kg·m²")),
            "ram_mass_kg": (self.tr("Mass m6"), self.tr("Mass of the ram with the tool, kg")),
            "ram_cg_dx": (self.tr("Centre of mass dx"),
                          self.tr("Horizontal offset of the ram's centre of mass from the ram "
                                  "joint C, mm (+ in the cutting direction)")),
            "ram_cg_dy": (self.tr("Centre of mass dy"),
                          self.tr("Vertical offset of the ram's centre of mass from the ram "
                                  "joint C, mm (+ up)")),
            "rod_mass_kg": (self.tr("Rod mass m5"),
                            self.tr("Mass of the connecting rod BC, a uniform bar, kg (rod "
                                    "variant only)")),
            "block_mass_kg": (self.tr("Block mass"),
                              self.tr("Mass of the sliding block at the crank pin A, kg")),
            "cut_force_N": (self.tr("Cutting force P"),
                            self.tr("Cutting resistance on the tool, against the cut, N")),
            "cut_height_mm": (self.tr("Tool below guide yP"),
                              self.tr("Height of the tool point below the ram guide line, mm "
                                      "(negative = above)")),
            "idle_percent": (self.tr("Idle margin"),
                             self.tr("Uncut run-in and run-out at each end of the working "
                                     "stroke, % of the stroke H (0 to under 50)")),
            "lever_given": (self.tr("Load given as"),
                            self.tr("The lever's load as a mass in kg, or as the task book states "
                                    "it, a weight G4 in N (mass = G4/9.81)")),
            "lever_weight_N": (self.tr("Weight G4"),
                               self.tr("Weight of the slotted lever O4B, N, as the task book states it")),
            "ram_given": (self.tr("Load given as"),
                          self.tr("The ram's load as a mass in kg, or as the task book states it, "
                                  "a weight G6 in N (mass = G6/9.81)")),
            "ram_weight_N": (self.tr("Weight G6"),
                             self.tr("Weight of the ram with the tool, N, as the task book states it")),
            "guide_length_mm": (self.tr("Guide length"),
                                self.tr("Length of the ram's guide (the column's ways), centred on "
                                        "the ram's mid-travel, mm; leave empty for the stroke H. "
                                        "Where the guide's reaction falls outside it, the ram tilts "
                                        "and bears on the guide's two ends")),
            "rotors": (self.tr("Rotating parts"),
                       self.tr("Other rotating parts (crank shaft, gears, motor) for the flywheel, "
                               "each J:ratio, J in kg·m² and its speed over the crank's, separated "
                               "by ';' (e.g. 0.5:1; 0.02:15); J:gear takes z2/z1 of the Gear tab's "
                               "pair, for the pinion shaft. The flywheel needed is "
                               "J_F − Σ J·ratio²")),
            "gravity": (self.tr("Gravity"),
                        self.tr("Include the weights of the links (g = 9.81 m/s²)")),
            "delta": (self.tr("Speed fluctuation δ"),
                      self.tr("Coefficient of speed fluctuation (ωmax − ωmin)/ωmean the "
                              "flywheel must hold, between 0 and 1; a fraction such as 1/30 "
                              "is accepted")),
        }

    def _retranslate(self) -> None:
        titles = {"lever": self.tr("Slotted lever"), "ram": self.tr("Ram and tool"),
                  "links": self.tr("Rod and block"), "cutting": self.tr("Cutting"),
                  "flywheel": self.tr("Flywheel")}
        for key, box in self._boxes.items():
            box.setTitle(titles[key])
        for name, (text, tip) in self._field_texts().items():
            self._labels[name].setText(text)
            self._labels[name].setToolTip(tip)
            widget = self._widget(name)
            (widget.edit if isinstance(widget, NumberField) else widget).setToolTip(tip)
        for combo in self._given.values():
            combo.setItemText(0, self.tr("mass, kg"))
            combo.setItemText(1, self.tr("weight, N"))
        self._gravity.setText(self.tr("include weights"))
        self._show_placeholder()
        self._show_error()
        # One label width in every group box, so the fields line up down the form: the widest
        # label's in this language (a label's size hint keeps its minimum width, so that is
        # cleared first: after a switch to Chinese the English width stayed).
        for label in self._labels.values():
            label.setMinimumWidth(0)
        width = max(label.sizeHint().width() for label in self._labels.values())
        for label in self._labels.values():
            label.setMinimumWidth(width)

    # ---- inputs --------------------------------------------------------
    def _value(self, name: str) -> object:
        """What the field means in model units: float, None (empty centre of mass) or the
        text itself when it is not a number."""
        text = self._fields[name].edit.text()
        if name in EMPTY_IS_NONE and not text.strip():
            return None
        if name == "rotors":
            try:
                return rotors_from_text(text, self._gear_ratio())
            except DesignError:
                return text                     # the model names the part that is wrong
        if name == "delta":
            return parse_ratio(text)
        value = parse_number(text)
        if name == "idle_percent" and isinstance(value, float):
            return value / 100.0
        return value

    @staticmethod
    def _text(name: str, value: object) -> str:
        if value is None:
            return ""
        if isinstance(value, str):
            return value
        if name == "rotors":
            return rotors_text(value)  # type: ignore[arg-type]
        if name == "idle_percent":
            return format_number(float(value) * 100.0)
        if name == "delta":
            return f"{float(value):.{DELTA_DIGITS}g}"
        return format_number(float(value))

    def _model_values(self) -> dict[str, object]:
        """The model's inputs (as last typed, valid or not) keyed like the fields."""
        inputs = self._model.mass_inputs
        pair = inputs["ram_cg_mm"]
        dx, dy = pair if isinstance(pair, tuple) and len(pair) == 2 else (pair, pair)
        values = {name: inputs.get(name) for name in self._fields}
        values.update(ram_cg_dx=dx, ram_cg_dy=dy, idle_percent=inputs["idle_fraction"])
        values["gravity"] = inputs["gravity"]
        return values

    def _show_inputs(self) -> None:
        """Mirror the model into the fields, leaving alone what is being typed."""
        values = self._model_values()
        for name, number in self._fields.items():
            if name in self.pending:
                continue
            wanted = values[name]
            text = self._text(name, wanted)
            if number.edit.text() != text and self._value(name) != wanted:
                number.edit.setText(text)
        self._gravity.blockSignals(True)
        self._gravity.setChecked(bool(values["gravity"]))
        self._gravity.blockSignals(False)
        for link, (mass, weight) in GIVEN.items():
            as_weight = values[weight] is not None
            self._given[link].setCurrentIndex(1 if as_weight else 0)
            form = self._forms[link]
            form.setRowVisible(self._fields[mass], not as_weight)
            form.setRowVisible(self._fields[weight], as_weight)

    def _gear_ratio(self) -> float | None:
        """z2/z1 of the design's gear pair (the Gear tab's, as Save writes it): the speed of
        the pinion shaft over the crank's, for a rotating part typed as ``J:gear``."""
        from core.gear.file import gear_from_dict
        try:
            pair = gear_from_dict(self._model.saved_parts().get("gear"))
        except DesignError:
            return None
        return pair.z2 / pair.z1

    def _on_given(self, link: str) -> None:
        """Switch a link between mass and weight, carrying the value over (m·g or G/g)."""
        as_weight = self._given[link].currentData() == "weight"    # before the commit shows the model
        self._commit()
        mass, weight = GIVEN[link]
        inputs = self._model.mass_inputs
        if as_weight:
            if inputs.get(weight) is not None:
                return
            value = inputs.get(mass)
            carried = float(f"{value * GRAVITY:.12g}") if isinstance(value, float) else value
            self._model.set_masses(**{weight: carried, mass: 0.0})
        else:
            if inputs.get(weight) is None:
                return
            value = inputs.get(weight)
            carried = float(f"{value / GRAVITY:.12g}") if isinstance(value, float) else value
            self._model.set_masses(**{mass: carried, weight: None})

    def _commit(self) -> None:
        """Send the fields typed into since the last commit (the shared path, ``PendingEdits``)."""
        self.pending.commit()

    def _send(self, pending: set[str]) -> None:
        """The typed fields; the model validates and says which one is wrong."""
        changes: dict[str, object] = {}
        for name in pending:
            if name in ("ram_cg_dx", "ram_cg_dy"):
                changes["ram_cg_mm"] = (self._value("ram_cg_dx"), self._value("ram_cg_dy"))
            elif name == "idle_percent":
                changes["idle_fraction"] = self._value(name)
            else:
                changes[name] = self._value(name)
        for mass, weight in GIVEN.values():      # the one typed stands, the other is unset
            if weight in changes:
                changes[mass] = 0.0
            elif mass in changes:
                changes[weight] = None
        current = self._model.mass_inputs
        changes = {key: value for key, value in changes.items() if current.get(key) != value}
        if changes:
            self._model.set_masses(**changes)

    def _error_fields(self, error: DesignError) -> list[str]:
        """Fields to mark for ``error``: the ram offset names its component by value."""
        if error.parameter == "idle_fraction":
            return ["idle_percent"]
        if error.parameter in ("rotor_inertia_kg_m2", "rotor_ratio"):
            return ["rotors"]
        if error.parameter == "ram_cg_mm":
            values = self._model_values()
            for name in ("ram_cg_dx", "ram_cg_dy"):
                if values[name] == error.value or (
                        isinstance(values[name], float) and isinstance(error.value, float)
                        and math.isnan(values[name]) and math.isnan(error.value)):
                    return [name]
            return ["ram_cg_dx", "ram_cg_dy"]
        return [error.parameter] if error.parameter in self._fields else []

    def _show_error(self) -> None:
        for number in self._fields.values():
            number.set_error(False)
        self._show_inputs()      # an invalid value set from elsewhere shows as typed
        error = self._model.forces_error
        for name in [] if error is None else self._error_fields(error):
            self._fields[name].set_error(True)
        show_error_line(self._error_label, None if error is None else describe(as_typed(error)),
                        self.tr("The last valid results stay on screen."))
