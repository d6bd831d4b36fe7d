"""The gear pair's inputs and the last valid pair, beside the design model.

The pair that drives the crank (issue 35, item 4) depends on nothing of the linkage, so it
is designed at once from what the user typed in the Gear tab (``core.gear.design_pair``).
A typed value that cannot make a pair names its field (``error``) and the last valid pair
stays; every edit is an undoable step on the design model's undo stack, so Ctrl+Z undoes
gear, cam and design edits in the order they were made. The pair is a part of the design
file ("gear"), read all or nothing by ``core.gear.file`` when a file is opened.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from PySide6.QtCore import QCoreApplication, QObject, Signal

from core.errors import DesignError
from core.gear.inputs import GearPairInputs
from core.gear.pair import GearPair, design_pair
from core.gear.file import gear_from_dict, gear_to_dict
from shaperapp.design.model import DesignModel
from shaperapp.design.results import COMPUTE_ERRORS, compute_error
from shaperapp.design.undo import InputEdit, push_edit

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
class GearTyped:
    """The gear's fields as typed: floats, or text that is not a number; ``mode`` one of
    MODES. One state of the undo history."""

    values: tuple[tuple[str, Any], ...] = tuple(sorted(DEFAULTS.items()))

    @property
    def dict(self) -> dict[str, Any]:
        return dict(self.values)

    def with_(self, **changes: Any) -> "GearTyped":
        return GearTyped(tuple(sorted({**self.dict, **changes}.items())))


def _number(name: str, value: Any) -> float:
    if isinstance(value, str) or not math.isfinite(value):
        raise DesignError(name, value, "must be a number")
    return float(value)


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


class GearModel(QObject):
    """Signals: ``pairChanged`` (a new valid pair), ``errorChanged``, ``typedChanged``."""

    pairChanged = Signal()
    errorChanged = Signal()
    typedChanged = Signal()

    def __init__(self, model: DesignModel, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.design_model = model
        self._typed = GearTyped()
        self._valid_typed = self._typed
        self._pair = DEFAULT_PAIR
        self._error: DesignError | None = None
        model.parts.register("gear", self.document, check_part)
        model.loaded.connect(self._load)
        self._load()

    @property
    def pair(self) -> GearPair:
        """The last valid pair (the one on screen and in Save)."""
        return self._pair

    @property
    def typed(self) -> GearTyped:
        return self._typed

    @property
    def error(self) -> DesignError | None:
        """Why the typed pair is refused (None: the typed pair is the one on screen)."""
        return self._error

    def set_fields(self, **changes: Any) -> None:
        """Change some typed fields (one undoable step; keystrokes in one field merge)."""
        after = self._typed.with_(**changes)
        if after == self._typed:
            return
        names = tuple(sorted(changes))
        key = None if "mode" in changes else ("gear", names)
        push_edit(self.design_model.undo_stack,
                  InputEdit(self._apply, self._typed, after, key,
                            lambda: QCoreApplication.translate("GearModel", "edit gear pair")))

    def set_mode(self, mode: str) -> None:
        """Give the shifts another way; the fields of the new mode start from the pair on
        screen, so the switch alone changes no number."""
        if mode == self._typed.dict["mode"]:
            return
        pair = self._pair
        self.set_fields(mode=mode, x1=pair.gear1.shift, x2=pair.gear2.shift, centre=pair.centre_mm)

    def document(self) -> dict[str, Any]:
        """The inputs of the pair on screen, as the design file keeps them."""
        return gear_to_dict(self._pair.inputs)

    def crank_turn(self) -> float:
        """The crank angle (rad) of the animation bar: the gear z2 sits on the crank's shaft."""
        m = self.design_model
        return float(m.motion.crank_angle[m.angle_index])

    def _load(self) -> None:
        """A file was opened (or New): its pair (read all or nothing when the file was
        opened), or the default one."""
        data = self.design_model.parts.loaded("gear")
        if data is None:
            typed = typed_from(DEFAULT_PAIR.inputs, DEFAULT_PAIR)
        else:
            pair = check_part(data)
            typed = typed_from(pair.inputs, pair)
        self._apply(typed)

    def _apply(self, typed: GearTyped) -> None:
        self._typed = typed
        self.typedChanged.emit()
        try:
            pair = design_pair(gear_inputs(typed))
        except DesignError as exc:
            self._set_error(exc)
            return
        except COMPUTE_ERRORS as exc:       # a corner of the closed forms: said, never a traceback
            self._set_error(compute_error(exc))
            return
        self._set_error(None)
        self._valid_typed = typed
        if pair != self._pair:
            self._pair = pair
            self.pairChanged.emit()

    def _set_error(self, error: DesignError | None) -> None:
        if str(error) != str(self._error):
            self._error = error
            self.errorChanged.emit()
        self._error = error
