"""The gear pair's inputs and the last valid pair, beside the design model.

The pair that drives the crank (issue 35, item 4) depends on nothing of the linkage, so it
is designed at once from what the user typed in the Gear tab (``core.gear.design_pair``).
A typed value that cannot make a pair names its field (``error``) and the last valid pair
stays; every edit is an undoable step on the design model's undo stack, so Ctrl+Z undoes
gear, cam and design edits in the order they were made. The pair is a part of the design
file ("gear"), read all or nothing by ``core.gear.file`` when a file is opened.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from PySide6.QtCore import QCoreApplication, QObject

from core.gear.inputs import GearPairInputs
from core.gear.pair import GearPair, design_pair
from core.gear.file import gear_from_dict, gear_to_dict
from shaperapp.design.model import DesignModel
from shaperapp.parts.model import PartModel, Typed, number

MODES = ("auto", "shifts", "centre")
"""How the shifts are given: by the rule, as x1 and x2, or as the centre distance a′."""
NUMBERS = ("z1", "z2", "module", "x1", "x2", "centre", "pressure_angle", "addendum",
           "clearance", "tip_limit", "contact_limit")
MODE_FIELDS = {"auto": (), "shifts": ("x1", "x2"), "centre": ("centre",)}
DEFAULTS: dict[str, Any] = {"z1": 13.0, "z2": 40.0, "module": 6.0, "mode": "centre",
                            "x1": 0.0, "x2": 0.0, "centre": 162.0, "pressure_angle": 20.0,
                            "addendum": 1.0, "clearance": 0.25, "tip_limit": 0.25,
                            "contact_limit": 1.2}
"""The pair a design without a "gear" object gets: z1 = 13, z2 = 40, m = 6 mm at a′ = 162 mm,
the example of docs/cli.md and of tests/data/my.shaper.json. Why this pair: its pinion has
fewer teeth than zmin = 17 of the 20° rack, so it must be shifted to be cut without undercut,
which is what the course design's gear part is about; i = 40/13 ≈ 3.08 is a usual
single-stage reduction in front of the crank; and a′ = 162 mm, the standard a = 159 mm
rounded up to a machinable value, makes a positive pair whose checks all pass."""


@dataclass(frozen=True)
class GearTyped(Typed):
    """The gear's fields as typed: floats, or text that is not a number; ``mode`` one of
    MODES. One state of the undo history."""

    values: tuple[tuple[str, Any], ...] = tuple(sorted(DEFAULTS.items()))


def _number(name: str, value: Any) -> float:
    return number(name, value, not_finite="must be a number")


def _teeth(name: str, value: Any) -> int | float:
    """A whole float as the int the core and the file expect; else the float, which the
    core refuses naming the field."""
    number = _number(name, value)
    return int(number) if number == int(number) else number


def gear_inputs(typed: GearTyped) -> GearPairInputs:
    """The core inputs of the typed fields (the shift fields of the mode only);
    DesignError names a field that is not a number."""
    v = typed.dict
    mode = v["mode"]
    shifts = {name: _number(name, v[name]) for name in MODE_FIELDS[mode]}
    return GearPairInputs(z1=_teeth("z1", v["z1"]), z2=_teeth("z2", v["z2"]),
                          module_mm=_number("module", v["module"]),
                          x1=shifts.get("x1"), x2=shifts.get("x2"), centre_mm=shifts.get("centre"),
                          pressure_angle_deg=_number("pressure_angle", v["pressure_angle"]),
                          addendum=_number("addendum", v["addendum"]),
                          clearance=_number("clearance", v["clearance"]),
                          tip_limit=_number("tip_limit", v["tip_limit"]),
                          contact_limit=_number("contact_limit", v["contact_limit"]))


def typed_from(inputs: GearPairInputs, pair: GearPair) -> GearTyped:
    """The typed fields of ``inputs``; the shift fields its mode leaves unused show the
    designed ``pair``'s values, ready for a switch of mode."""
    mode = "shifts" if inputs.x1 is not None else "centre" if inputs.centre_mm is not None else "auto"
    return GearTyped().with_(z1=float(inputs.z1), z2=float(inputs.z2), module=float(inputs.module_mm),
                             mode=mode, x1=pair.gear1.shift, x2=pair.gear2.shift, centre=pair.centre_mm,
                             pressure_angle=float(inputs.pressure_angle_deg),
                             addendum=float(inputs.addendum), clearance=float(inputs.clearance),
                             tip_limit=float(inputs.tip_limit), contact_limit=float(inputs.contact_limit))


DEFAULT_PAIR = design_pair(gear_inputs(GearTyped()))


def check_part(data: Any) -> GearPair:
    """The pair of a file's "gear" object; DesignError (the file is refused, nothing
    changed) when the object is bad or its pair cannot be made (a centre distance that no
    shift fits), so an opened file never leaves the tab without a pair to show."""
    return design_pair(gear_from_dict(data))


class GearModel(PartModel):
    """Signals: ``pairChanged`` (a new valid pair), ``errorChanged``, ``typedChanged``."""

    pairChanged = PartModel.valueChanged     # one signal, the name the part's readers use
    PART = "gear"

    def __init__(self, model: DesignModel, parent: QObject | None = None) -> None:
        super().__init__(model, GearTyped(), DEFAULT_PAIR, check_part, parent)
        self._load()

    @property
    def pair(self) -> GearPair:
        """The last valid pair (the one on screen and in Save)."""
        return self._value

    def merge_key(self, names: tuple[str, ...]) -> tuple[str, tuple[str, ...]] | None:
        """A switch of mode is a step of its own; keystrokes in one field merge."""
        return None if "mode" in names else (self.PART, names)

    def edit_text(self) -> str:
        return QCoreApplication.translate("GearModel", "edit gear pair")

    def unmade_text(self) -> str:
        return QCoreApplication.translate("GearModel", "This design's gear pair cannot be made: no pair is shown.")

    def set_mode(self, mode: str) -> None:
        """Give the shifts another way; the fields of the new mode start from the pair on
        screen, so the switch alone changes no number."""
        if mode == self._typed.dict["mode"]:
            return
        pair = self._value
        self.set_fields(mode=mode, x1=pair.gear1.shift, x2=pair.gear2.shift, centre=pair.centre_mm)

    def document(self) -> dict[str, Any]:
        """The inputs of the pair on screen, as the design file keeps them."""
        return gear_to_dict(self._value.inputs)

    def crank_turn(self) -> float:
        """The crank angle (rad) of the animation bar: the gear z2 sits on the crank's shaft."""
        m = self.design_model
        return float(m.motion.crank_angle[m.angle_index])

    def typed_of(self, data: Any) -> GearTyped:
        """An opened file's pair (read all or nothing when the file was opened), or the
        default one; the shift fields its mode leaves unused show the pair's."""
        pair = DEFAULT_PAIR if data is None else check_part(data)
        return typed_from(pair.inputs, pair)

    def compute(self, typed: GearTyped) -> GearPair:
        return design_pair(gear_inputs(typed))
