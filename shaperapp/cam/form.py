"""The cam's inputs: the data sheet's numbers and laws, sent to the cam model after a pause.

As in the design form, the text goes to the model as typed; the model names the field
that cannot make a cam, and the form marks it (the last valid cam stays on screen).
"""
from __future__ import annotations

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QComboBox, QFormLayout, QLabel, QVBoxLayout, QWidget

from core.cam import LAWS
from core.cam.cam import RETURN_PRESSURE_DEG
from shaperapp.design.fields import DEBOUNCE_MS, ERROR_STYLE, NumberField, parse_number
from shaperapp.widgets.messages import ERROR_TEXT_STYLE, describe

from .model import CHOICES, NUMBERS, OPTIONAL, CamModel

UNITS = {"arm": "mm", "swing": "°", "pressure": "°", "return_pressure": "°", "rise": "°",
         "dwell": "°", "return": "°", "roller": "mm", "base": "mm", "distance": "mm", "phase": "°",
         "hub": "mm", "boss": "mm", "clearance": "mm"}


class CamForm(QWidget):
    """Number fields, the two laws, and the error line under them."""

    def __init__(self, cam_model: CamModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = cam_model
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(DEBOUNCE_MS)
        self._timer.timeout.connect(self.commit)
        self._pending: set[str] = set()
        self.fields = {name: NumberField(UNITS[name]) for name in NUMBERS + OPTIONAL}
        for field in self.fields.values():
            field.edit.setMinimumWidth(64)
            field.edit.setMaximumWidth(90)
        self.laws = {name: QComboBox(self) for name in CHOICES}
        self._labels = {name: QLabel(self) for name in NUMBERS + OPTIONAL + CHOICES}
        layout = QFormLayout()
        order = ("arm", "swing", "rise", "dwell", "return", "rise_law", "return_law", "pressure",
                 "return_pressure", "roller", "base", "distance", "hub", "boss", "clearance", "phase")
        for name in order:
            widget = self.laws[name] if name in CHOICES else self.fields[name]
            layout.addRow(self._labels[name], widget)
        for name, field in self.fields.items():
            field.edited.connect(lambda n=name: self._typed(n))
        for name, combo in self.laws.items():
            for law in LAWS:
                combo.addItem("", law)
            combo.activated.connect(lambda _i, n=name: self._choose(n))
        self.error_label = QLabel(self)
        self.error_label.setWordWrap(True)
        self.error_label.setStyleSheet(ERROR_TEXT_STYLE)
        column = QVBoxLayout(self)
        column.setContentsMargins(0, 0, 0, 0)
        column.addLayout(layout)
        column.addWidget(self.error_label)
        column.addStretch(1)
        cam_model.typedChanged.connect(self._show_typed)
        cam_model.errorChanged.connect(self._show_error)
        self.retranslate()
        self._show_typed()
        self._show_error()

    def retranslate(self) -> None:
        texts = {
            "arm": self.tr("Arm l"), "swing": self.tr("Swing ψmax"),
            "rise": self.tr("Rise"), "dwell": self.tr("Outer dwell"),
            "return": self.tr("Return"), "rise_law": self.tr("Rise law"),
            "return_law": self.tr("Return law"), "pressure": self.tr("[α] rise"),
            "return_pressure": self.tr("[α] return"),
            "roller": self.tr("Roller r"), "base": self.tr("Check base r0"),
            "distance": self.tr("Check distance a"), "phase": self.tr("Rise at crank φ"),
            "hub": self.tr("Hub radius"), "boss": self.tr("Pivot boss radius"),
            "clearance": self.tr("Least clearance"),
        }
        for name, label in self._labels.items():
            label.setText(texts[name])
        tip = self.tr("Allowed pressure angle on the return, °. The default %1° is said in the "
                      "textbooks: the follower returns unloaded, closed by its spring, so the return "
                      "may take 70°–80° against 30°–45° on the working rise.").replace(
            "%1", f"{RETURN_PRESSURE_DEG:g}")
        self._labels["return_pressure"].setToolTip(tip)
        self.fields["return_pressure"].edit.setToolTip(tip)
        names = {"parabolic": self.tr("parabolic"), "cosine": self.tr("cosine"),
                 "sine": self.tr("sine (cycloidal)"), "poly345": self.tr("3-4-5 polynomial")}
        for combo in self.laws.values():
            for i in range(combo.count()):
                combo.setItemText(i, names[combo.itemData(i)])
        for name in OPTIONAL:
            self.fields[name].edit.setPlaceholderText(self.tr("auto"))
        self._show_error()

    def commit(self) -> None:
        """Send the fields typed into since the last commit (the debounce timer's end)."""
        self._timer.stop()
        if not self._pending:
            return
        changes = {}
        for name in sorted(self._pending):
            text = self.fields[name].edit.text()
            changes[name] = "" if name in OPTIONAL and not text.strip() else parse_number(text)
        self._pending.clear()
        self._model.set_fields(**changes)

    def _typed(self, name: str) -> None:
        self._pending.add(name)
        self._timer.start()

    def _choose(self, name: str) -> None:
        self.commit()
        self._model.set_fields(**{name: self.laws[name].currentData()})

    def _show_typed(self) -> None:
        values = self._model.typed.dict
        for name, field in self.fields.items():
            if name not in self._pending:
                field.set_value(values[name])
        for name, combo in self.laws.items():
            combo.setCurrentIndex(combo.findData(values[name]))

    def _show_error(self) -> None:
        for field in self.fields.values():
            field.set_error(False)
        for combo in self.laws.values():
            combo.setStyleSheet("")
        error = self._model.error
        if error is None:
            self.error_label.hide()
            self.error_label.setText("")
            return
        name = {"rise_law": "rise_law", "return_law": "return_law"}.get(error.parameter, error.parameter)
        if name in self.fields:
            self.fields[name].set_error(True)
        elif name in self.laws:
            self.laws[name].setStyleSheet(ERROR_STYLE)
        self.error_label.setText("⚠ " + describe(error) + "\n" + self.tr("The last valid cam stays on screen."))
        self.error_label.show()

    def marked_fields(self) -> list[str]:
        return [name for name, f in self.fields.items() if f.edit.styleSheet()]
