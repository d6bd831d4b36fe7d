"""The cam's inputs: the data sheet's numbers and laws, sent to the cam model after a pause.

As in the design form, the text goes to the model as typed; the model names the field
that cannot make a cam, and the form marks it (the last valid cam stays on screen).
"""
from __future__ import annotations

from typing import Any

from PySide6.QtWidgets import QComboBox, QWidget

from core.cam import LAWS
from core.cam.defaults import RETURN_PRESSURE_DEG
from shaperapp.design.fields import parse_number
from shaperapp.parts.form import PartForm
from shaperapp.widgets.messages import describe as describe_error

from .model import CHOICES, NUMBERS, OPTIONAL, CamModel

UNITS = {"arm": "mm", "swing": "°", "pressure": "°", "return_pressure": "°", "rise": "°",
         "dwell": "°", "return": "°", "roller": "mm", "base": "mm", "distance": "mm", "phase": "°",
         "hub": "mm", "boss": "mm", "clearance": "mm"}
ORDER = ("arm", "swing", "rise", "dwell", "return", "rise_law", "return_law", "pressure",
         "return_pressure", "roller", "base", "distance", "hub", "boss", "clearance", "phase")


class CamForm(PartForm):
    """Number fields, the two laws, and the error line under them."""

    def __init__(self, cam_model: CamModel, parent: QWidget | None = None) -> None:
        super().__init__(cam_model, {name: UNITS[name] for name in NUMBERS + OPTIONAL}, ORDER, 90, parent)
        self.laws = self.combos
        for name, combo in self.laws.items():
            for law in LAWS:
                combo.addItem("", law)
            combo.activated.connect(lambda _i, n=name: self._choose(n))
        self._finish()
        self.retranslate()
        self._show_typed()
        self._show_error()

    describe = staticmethod(describe_error)

    def make_combos(self) -> dict[str, QComboBox]:
        return {name: QComboBox(self) for name in CHOICES}

    def retranslate(self) -> None:
        self.set_labels({
            "arm": self.tr("Arm l"), "swing": self.tr("Swing ψmax"),
            "rise": self.tr("Rise"), "dwell": self.tr("Outer dwell"),
            "return": self.tr("Return"), "rise_law": self.tr("Rise law"),
            "return_law": self.tr("Return law"), "pressure": self.tr("[α] rise"),
            "return_pressure": self.tr("[α] return"),
            "roller": self.tr("Roller r"), "base": self.tr("Check base r0"),
            "distance": self.tr("Check distance a"), "phase": self.tr("Rise at crank φ"),
            "hub": self.tr("Hub radius"), "boss": self.tr("Pivot boss radius"),
            "clearance": self.tr("Least clearance"),
        })
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

    def read(self, name: str) -> Any:
        text = self.fields[name].edit.text()
        return "" if name in OPTIONAL and not text.strip() else parse_number(text)

    def kept(self) -> str:
        return self.tr("The last valid cam stays on screen.")

    def _choose(self, name: str) -> None:
        law = self.laws[name].currentData()      # before the commit shows the model's
        self.commit()
        self._model.set_fields(**{name: law})

    def _show_typed(self) -> None:
        super()._show_typed()
        values = self._model.typed.dict
        for name, combo in self.laws.items():
            combo.setCurrentIndex(combo.findData(values[name]))
