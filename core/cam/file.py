"""The cam's inputs in a design file: a flat JSON object, units in the keys.

Written by the GUI beside the design (``"cam"``); read back all or nothing. A file
without it (every file before issue 23) opens with the default cam.
"""
from __future__ import annotations

from typing import Any

from core.base.errors import DesignError
from .cam import CamInputs
from .laws import Program
from .timing import check_phase

NUMBER_KEYS = ("arm_mm", "swing_deg", "rise_deg", "dwell_deg", "return_deg", "pressure_deg",
               "return_pressure_deg", "hub_mm", "boss_mm", "clearance_mm")
"""Each may be missing (its default: files before issue 34 have no hub, boss or clearance)."""
OPTIONAL_KEYS = ("roller_mm", "base_mm", "distance_mm", "phase_deg")
TEXT_KEYS = ("rise_law", "return_law")


def cam_to_dict(inputs: CamInputs, phase_deg: float | None) -> dict[str, Any]:
    p = inputs.program
    return {"arm_mm": inputs.arm_mm, "swing_deg": p.swing_deg, "rise_deg": p.rise_deg,
            "dwell_deg": p.dwell_deg, "return_deg": p.return_deg, "rise_law": p.rise_law,
            "return_law": p.return_law, "pressure_deg": inputs.pressure_deg,
            "return_pressure_deg": inputs.return_pressure_deg, "roller_mm": inputs.roller_mm,
            "base_mm": inputs.base_mm, "distance_mm": inputs.distance_mm, "hub_mm": inputs.hub_mm,
            "boss_mm": inputs.boss_mm, "clearance_mm": inputs.clearance_mm, "phase_deg": phase_deg}


def default_values() -> dict[str, Any]:
    """What a file's ``"cam"`` object takes for each key it lacks."""
    return cam_to_dict(CamInputs(), None)


def cam_from_dict(data: Any) -> tuple[CamInputs, float | None]:
    """The inputs and phase of a file's ``"cam"`` object; DesignError names a bad key."""
    if not isinstance(data, dict):
        raise DesignError("cam", type(data).__name__, "must be an object of cam inputs")
    unknown = sorted(set(data) - set(NUMBER_KEYS + OPTIONAL_KEYS + TEXT_KEYS))
    if unknown:
        raise DesignError(unknown[0], data[unknown[0]], "is not a cam field")
    values: dict[str, Any] = {}
    for key in NUMBER_KEYS + OPTIONAL_KEYS:
        if key not in data or (key in OPTIONAL_KEYS and data[key] is None):
            continue
        value = data[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise DesignError(key, value, "must be a number")
        values[key] = float(value)
    for key in TEXT_KEYS:
        if key in data:
            if not isinstance(data[key], str):
                raise DesignError(key, data[key], "must be text")
            values[key] = data[key]
    base = CamInputs()
    p = base.program
    program = Program(values.get("swing_deg", p.swing_deg), values.get("rise_deg", p.rise_deg),
                      values.get("dwell_deg", p.dwell_deg), values.get("return_deg", p.return_deg),
                      values.get("rise_law", p.rise_law), values.get("return_law", p.return_law))
    inputs = CamInputs(arm_mm=values.get("arm_mm", base.arm_mm), program=program,
                       pressure_deg=values.get("pressure_deg", base.pressure_deg),
                       return_pressure_deg=values.get("return_pressure_deg", base.return_pressure_deg),
                       roller_mm=values.get("roller_mm"), base_mm=values.get("base_mm"),
                       distance_mm=values.get("distance_mm"),
                       **{key: values[key] for key in ("hub_mm", "boss_mm", "clearance_mm") if key in values})
    phase = values.get("phase_deg")
    return inputs, None if phase is None else check_phase(phase)
