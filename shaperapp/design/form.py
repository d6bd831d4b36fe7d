"""The design form: what the designer types, sent to the model after a short pause.

Text goes to the model as typed; the model's validation names the offending
parameter, and the form marks that field. The form never computes anything.
"""
from __future__ import annotations

import math

from PySide6.QtCore import QEvent, Qt
from PySide6.QtWidgets import (QButtonGroup, QComboBox, QFormLayout, QGroupBox, QHBoxLayout,
                               QLabel, QLineEdit, QListWidget, QListWidgetItem, QRadioButton, QSizePolicy,
                               QToolButton, QVBoxLayout, QWidget)

from core.linkage.kinematics import MAX_RPM
from shaperapp.widgets.combos import fill_combo
from shaperapp.widgets.messages import describe

from .fields import (ERROR_STYLE, NumberField, PendingEdits, error_line, exact_number, parse_number,
                     show_error_line)
from .inputs import MAX_SPEEDS
from .model import DesignModel

CHOICES = ("variant", "guide_rule", "rod_input", "rod_side")


class DesignForm(QWidget):
    """Inputs of the design: mode, L1/K/H or L1/L2/L3, variant, guide, rod, speeds."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self.pending = PendingEdits(self._send, self)     # fields typed into, sent after a pause

        self._synth_radio = QRadioButton(self)
        self._dims_radio = QRadioButton(self)
        self._mode_group = QButtonGroup(self)
        self._mode_group.addButton(self._synth_radio)
        self._mode_group.addButton(self._dims_radio)
        self._fields = {
            "crank": NumberField("mm"), "time_ratio": NumberField("–"), "stroke": NumberField("mm"),
            "frame": NumberField("mm"), "lever": NumberField("mm"),
            "guide_height": NumberField("mm"), "rod_length": NumberField("mm"),
            "rod_ratio": NumberField("–"), "step": NumberField("°"),
        }
        self._variant = QComboBox(self)
        self._guide_rule = QComboBox(self)
        self._rod_input = QComboBox(self)
        self._rod_side = QComboBox(self)
        for combo in (self._variant, self._guide_rule, self._rod_input, self._rod_side):
            # Every choice readable in full: a long one moves the combo under its label
            # (the mechanism box wraps long rows) instead of being cut.
            combo.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToContents)
        self._speeds = QListWidget(self)
        self._speeds.setMaximumHeight(78)
        self._speeds.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Fixed)
        self._add_speed = QToolButton(self)
        self._add_speed.setText("+")
        self._remove_speed = QToolButton(self)
        self._remove_speed.setText("−")
        self._error_label = error_line(self)
        self._error_label.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Minimum)
        self._labels: dict[str, QLabel] = {}
        self._build_layout()

        for name, field in self._fields.items():
            field.edited.connect(lambda n=name: self.pending.typed(n))
            field.edit.editingFinished.connect(self._on_editing_finished)
        self._mode_group.buttonToggled.connect(self._on_mode_toggled)
        for name in CHOICES:
            combo = self._combo(name)
            combo.currentIndexChanged.connect(lambda _=0, n=name: self._on_choice(n))
        self._speeds.itemChanged.connect(self._commit_speeds)
        self._add_speed.clicked.connect(self._on_add_speed)
        self._remove_speed.clicked.connect(self._on_remove_speed)

        model.specChanged.connect(self._show_spec)
        model.errorChanged.connect(self._show_error)
        self._retranslate()
        self._show_spec()
        self._show_speeds()
        self._show_error()

    # ---- layout --------------------------------------------------------
    def _row(self, form: QFormLayout, key: str, widget: QWidget) -> None:
        label = QLabel(self)
        self._labels[key] = label
        form.addRow(label, widget)

    def _build_layout(self) -> None:
        f = self._fields
        self._mode_box = QGroupBox(self)
        mode = QHBoxLayout(self._mode_box)
        mode.addWidget(self._synth_radio)
        mode.addWidget(self._dims_radio)

        self._main_box = QGroupBox(self)
        main = QFormLayout(self._main_box)
        self._row(main, "crank", f["crank"])
        self._row(main, "time_ratio", f["time_ratio"])
        self._row(main, "stroke", f["stroke"])
        self._row(main, "frame", f["frame"])
        self._row(main, "lever", f["lever"])
        self._main_form = main

        self._mech_box = QGroupBox(self)
        mech = QFormLayout(self._mech_box)
        mech.setRowWrapPolicy(QFormLayout.RowWrapPolicy.WrapLongRows)
        self._row(mech, "variant", self._variant)
        self._row(mech, "guide_rule", self._guide_rule)
        self._row(mech, "guide_height", f["guide_height"])
        self._row(mech, "rod_input", self._rod_input)
        self._row(mech, "rod_length", f["rod_length"])
        self._row(mech, "rod_ratio", f["rod_ratio"])
        self._row(mech, "rod_side", self._rod_side)
        self._mech_form = mech

        self._speed_box = QGroupBox(self)
        speed = QFormLayout(self._speed_box)
        buttons = QVBoxLayout()
        buttons.addWidget(self._add_speed)
        buttons.addWidget(self._remove_speed)
        buttons.addStretch(1)
        speeds = QHBoxLayout()
        speeds.addWidget(self._speeds, 1)
        speeds.addLayout(buttons)
        holder = QWidget(self)
        holder.setLayout(speeds)
        self._row(speed, "rpm", holder)
        self._row(speed, "step", f["step"])

        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        for box in (self._mode_box, self._main_box, self._mech_box, self._speed_box):
            layout.addWidget(box)
        layout.addWidget(self._error_label)
        layout.addStretch(1)

    # ---- translation ---------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self._mode_box.setTitle(self.tr("Input"))
        self._synth_radio.setText(self.tr("Synthesis from L1, K, H"))
        self._dims_radio.setText(self.tr("Direct dimensions"))
        self._show_titles()
        self._mech_box.setTitle(self.tr("Mechanism"))
        self._speed_box.setTitle(self.tr("Crank speeds"))
        texts = {
            "crank": (self.tr("Crank length L1"), self.tr("Length of the crank O2A, mm")),
            "time_ratio": (self.tr("Time ratio K"),
                           self.tr("Working time / return time; greater than 1")),
            "stroke": (self.tr("Stroke H"), self.tr("Ram (tool) stroke, mm")),
            "frame": (self.tr("Frame distance L2"),
                      self.tr("Distance O2O4 between crank centre and lever pivot, mm")),
            "lever": (self.tr("Lever length L3"), self.tr("Length of the slotted lever O4B, mm")),
            "variant": (self.tr("Ram drive"), self.tr("How the lever tip drives the ram")),
            "guide_rule": (self.tr("Ram guide"), self.tr("Where the ram guide line lies")),
            "guide_height": (self.tr("Guide height"),
                             self.tr("Height of the ram guide line above the lever pivot O4, mm")),
            "rod_input": (self.tr("Rod given as"), self.tr("Give the rod as a length or as L4/L3")),
            "rod_length": (self.tr("Rod length L4"), self.tr("Length of the connecting rod BC, mm")),
            "rod_ratio": (self.tr("Rod ratio L4/L3"), self.tr("Rod length as a fraction of the lever")),
            "rod_side": (self.tr("Rod side"),
                         self.tr("Ram joint C behind (trailing) or ahead of (leading) the lever tip while cutting")),
            "rpm": (self.tr("Speeds, r/min"),
                    self.tr("Crank speeds in r/min; double-click to edit, + and − to add or remove")),
            "step": (self.tr("Angle step"), self.tr("Crank-angle step of the curves and the CSV export, degrees")),
        }
        for key, (label, tip) in texts.items():
            self._labels[key].setText(label)
            self._labels[key].setToolTip(tip)
            widget = self._fields.get(key)
            target = widget.edit if widget else self._speeds if key == "rpm" else self._combo(key)
            target.setToolTip(tip)
        fill_combo(self._variant, {"block": self.tr("Block in ram slot"), "rod": self.tr("Connecting rod")})
        fill_combo(self._guide_rule, {"chord": self.tr("Through the tip's extreme positions (chord)"),
                                      "sagitta": self.tr("Mid-sagitta of the tip's arc"),
                                      "height": self.tr("Explicit height")})
        fill_combo(self._rod_input, {"ratio": self.tr("Ratio L4/L3"), "length": self.tr("Length")})
        fill_combo(self._rod_side, {"trailing": self.tr("Trailing the tip"),
                                    "leading": self.tr("Leading the tip")})
        self._add_speed.setToolTip(self.tr("Add a crank speed (at most %1)").replace("%1", str(MAX_SPEEDS)))
        self._remove_speed.setToolTip(self.tr("Remove the selected crank speed"))
        self._show_error()

    def _show_titles(self) -> None:
        synth = self._model.spec.mode == "synthesis"
        self._main_box.setTitle(self.tr("Synthesis inputs") if synth else self.tr("Link lengths"))

    def _combo(self, name: str) -> QComboBox:
        return {"variant": self._variant, "guide_rule": self._guide_rule,
                "rod_input": self._rod_input, "rod_side": self._rod_side}[name]

    # ---- model → form ---------------------------------------------------
    def _show_spec(self) -> None:
        """Mirror the typed inputs, leaving alone what is being typed."""
        spec = self._model.spec
        widgets = [self._synth_radio, self._dims_radio] + [self._combo(n) for n in CHOICES]
        for w in widgets:
            w.blockSignals(True)
        self._mode_group.blockSignals(True)
        (self._synth_radio if spec.mode == "synthesis" else self._dims_radio).setChecked(True)
        for name in CHOICES:
            combo = self._combo(name)
            combo.setCurrentIndex(max(combo.findData(getattr(spec, name)), 0))
        for w in widgets:
            w.blockSignals(False)
        self._mode_group.blockSignals(False)
        for name, field in self._fields.items():
            if name not in self.pending:
                field.set_value(self._model.step_input if name == "step" else getattr(spec, name))
        self._show_speeds()
        self._show_titles()
        self._update_visibility()

    def _show_speeds(self) -> None:
        values = [self._speed_value(i) for i in range(self._speeds.count())]
        typed = list(self._model.rpm_inputs)
        if values != typed:
            row = self._speeds.currentRow()
            self._speeds.blockSignals(True)
            self._speeds.clear()
            for rpm in typed:
                item = QListWidgetItem(rpm if isinstance(rpm, str) else exact_number(float(rpm)))
                item.setFlags(item.flags() | Qt.ItemFlag.ItemIsEditable)
                self._speeds.addItem(item)
            self._speeds.setCurrentRow(min(row, self._speeds.count() - 1))
            self._speeds.blockSignals(False)
        self._add_speed.setEnabled(self._speeds.count() < MAX_SPEEDS)
        self._remove_speed.setEnabled(self._speeds.count() > 1)

    def _update_visibility(self) -> None:
        spec = self._model.spec
        synth = spec.mode == "synthesis"
        rod = spec.variant == "rod"
        shown = {"time_ratio": synth, "stroke": synth, "frame": not synth, "lever": not synth,
                 "guide_height": spec.guide_rule == "height", "rod_input": rod,
                 "rod_length": rod and spec.rod_input == "length",
                 "rod_ratio": rod and spec.rod_input == "ratio", "rod_side": rod}
        for key, visible in shown.items():
            form = self._main_form if key in ("time_ratio", "stroke", "frame", "lever") else self._mech_form
            form.setRowVisible(self._labels[key], visible)

    def _error_widgets(self, parameter: str) -> list[QWidget]:
        spec = self._model.spec
        if parameter == "guide":
            return [self._fields["guide_height"].edit if spec.guide_rule == "height" else self._guide_rule]
        if parameter in ("rod", "rod_ratio"):
            return [self._fields["rod_length" if spec.rod_input == "length" else "rod_ratio"].edit]
        if parameter == "rpm":
            return [self._speeds]
        if parameter == "rod_side":
            return [self._rod_side]
        if parameter == "lever" and spec.mode == "synthesis":
            return [self._fields["stroke"].edit]
        field = self._fields.get(parameter)
        return [field.edit] if field else []

    def _show_error(self) -> None:
        for field in self._fields.values():
            field.set_error(False)
        for widget in (self._guide_rule, self._speeds, self._rod_side):
            widget.setStyleSheet("")
        error = self._model.error
        if error is not None:
            for widget in self._error_widgets(error.parameter):
                widget.setStyleSheet(ERROR_STYLE)
        show_error_line(self._error_label, None if error is None else describe(error),
                        self.tr("The last valid design stays on screen."))

    def error_text(self) -> str:
        """The message shown under the form ('' when the input is valid)."""
        return self._error_label.text() if self._model.error else ""

    def marked_fields(self) -> list[str]:
        """Names of the fields currently marked as invalid."""
        marked = [name for name, f in self._fields.items() if f.edit.styleSheet()]
        if self._guide_rule.styleSheet():
            marked.append("guide_rule")
        if self._speeds.styleSheet():
            marked.append("rpm")
        return marked

    # ---- form → model ---------------------------------------------------
    def field(self, name: str) -> QLineEdit:
        """The line edit of a numeric field (for shortcuts and tests)."""
        return self._fields[name].edit

    def _on_editing_finished(self) -> None:
        self._commit()
        self._model.end_typing()

    def _on_mode_toggled(self, _button=None, checked: bool = True) -> None:
        if checked:
            mode = "synthesis" if self._synth_radio.isChecked() else "dimensions"
            self._commit()
            self._model.set_spec(mode=mode)

    def _on_choice(self, name: str) -> None:
        """A choice sends the fields typed before it first. It is read before that commit:
        the form then shows the model, which still holds the old choice."""
        value = self._combo(name).currentData()
        self._commit()
        self._model.set_spec(**{name: value})

    def _commit(self) -> None:
        """Send the fields typed into since the last commit (the shared path, ``PendingEdits``)."""
        self.pending.commit()

    def _send(self, pending: set[str]) -> None:
        """The typed fields, as typed: the model validates and names the one to mark.
        Untouched fields are not re-read, so their display rounding never changes the design."""
        changes = {name: self._fields[name].value() for name in pending if name != "step"}
        if changes:
            self._model.set_spec(**changes)
        if "step" in pending:
            self._model.set_step(self._fields["step"].value())

    def _speed_value(self, row: int) -> float | str:
        return parse_number(self._speeds.item(row).text())

    def _commit_speeds(self) -> None:
        values = [self._speed_value(i) for i in range(self._speeds.count())]
        self._model.set_rpms(values)

    def _on_add_speed(self) -> None:
        values = [self._speed_value(i) for i in range(self._speeds.count())]
        if len(values) >= MAX_SPEEDS:
            return
        numbers = [v for v in values if isinstance(v, float) and math.isfinite(v)]
        new = min(max(numbers) + 20.0, MAX_RPM) if numbers else 40.0
        self._model.set_rpms(values + [new])

    def _on_remove_speed(self) -> None:
        values = [self._speed_value(i) for i in range(self._speeds.count())]
        if len(values) <= 1:
            return
        row = self._speeds.currentRow()
        del values[row if 0 <= row < len(values) else -1]
        self._model.set_rpms(values)
