"""The gear pair's inputs in a design file: a flat JSON object, units in the keys.

``"gear": {"z1", "z2", "module_mm", "x1", "x2", "centre_mm", "pressure_angle_deg", "addendum",
"clearance", "tip_limit", "contact_limit"}``; z1, z2 and module_mm are required, the rest
optional (null or absent: the default, or the rule for the shifts). Read all or nothing: a
bad key, type or range is a DesignError naming it, and nothing of the object is used.
"""
from __future__ import annotations

from typing import Any

from core.base.errors import DesignError
from .inputs import GearPairInputs

REQUIRED_KEYS = ("z1", "z2", "module_mm")
OPTIONAL_KEYS = ("x1", "x2", "centre_mm", "pressure_angle_deg", "addendum", "clearance",
                 "tip_limit", "contact_limit")
# a key of the object → the field of GearPairInputs it sets
_FIELDS = {"z1": "z1", "z2": "z2", "module_mm": "module_mm", "x1": "x1", "x2": "x2",
           "centre_mm": "centre_mm", "pressure_angle_deg": "pressure_angle_deg",
           "addendum": "addendum", "clearance": "clearance", "tip_limit": "tip_limit",
           "contact_limit": "contact_limit"}


def gear_to_dict(inputs: GearPairInputs) -> dict[str, Any]:
    """The object a design file keeps under ``"gear"``."""
    return {key: getattr(inputs, field) for key, field in _FIELDS.items()}


def gear_from_dict(data: Any) -> GearPairInputs:
    """The checked inputs of a file's ``"gear"`` object; DesignError names a bad key."""
    if not isinstance(data, dict):
        raise DesignError("gear", type(data).__name__, "must be an object of gear inputs")
    unknown = sorted(set(data) - set(REQUIRED_KEYS + OPTIONAL_KEYS), key=str)
    if unknown:
        raise DesignError(unknown[0], data[unknown[0]], "is not a gear field")
    values: dict[str, Any] = {}
    for key in REQUIRED_KEYS + OPTIONAL_KEYS:
        if key not in data or (key in OPTIONAL_KEYS and data[key] is None):
            if key in REQUIRED_KEYS:
                raise DesignError(key, None, "is required in a gear object")
            continue
        value = data[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise DesignError(key, value, "must be a number")
        values[_FIELDS[key]] = value
    for key in ("z1", "z2"):
        if values[key] != int(values[key]):
            raise DesignError(key, values[key], "must be a whole number of teeth")
        values[key] = int(values[key])
    return GearPairInputs(**values).check()
