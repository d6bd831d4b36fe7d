"""The inputs of a gear pair, checked at the boundary: teeth, module, basic rack, and the shift
given as x1 and x2, or as the centre distance a′, or left to the rule (``shift.py``)."""
from __future__ import annotations

import math
from dataclasses import dataclass

from core.base.errors import DesignError
from .involute import FIRST_SERIES_MM

MIN_TEETH = 5
MAX_TEETH = 1000
MIN_MODULE_MM = 0.01
MAX_MODULE_MM = 100.0
MAX_SHIFT = 5.0


@dataclass(frozen=True)
class GearPairInputs:
    """An external spur pair on the GB/T 1356 basic rack.

    ``z1`` teeth of the pinion (the motor side), ``z2`` of the gear; ``module_mm`` m, mm;
    ``x1``, ``x2`` shift factors (both or neither); ``centre_mm`` the centre distance a′, mm
    (instead of x1 and x2); neither: the rule of :func:`core.gear.shift.auto_shifts`.
    ``pressure_angle_deg`` α, °; ``addendum`` h*a and ``clearance`` c* of the rack;
    ``tip_limit`` the least tip thickness as a multiple of m; ``contact_limit`` the least ε.
    """
    z1: int
    z2: int
    module_mm: float
    x1: float | None = None
    x2: float | None = None
    centre_mm: float | None = None
    pressure_angle_deg: float = 20.0
    addendum: float = 1.0
    clearance: float = 0.25
    tip_limit: float = 0.25
    contact_limit: float = 1.2

    @property
    def alpha(self) -> float:
        """α in radians."""
        return math.radians(self.pressure_angle_deg)

    @property
    def module_note(self) -> str | None:
        """Why the module is unusual (not of GB/T 1357's first series), or None."""
        if any(math.isclose(self.module_mm, m, rel_tol=1e-12) for m in FIRST_SERIES_MM):
            return None
        return f"m = {self.module_mm:g} mm is not a GB/T 1357 first-series module"

    def check(self) -> GearPairInputs:
        """Self, or a DesignError naming the first field out of range."""
        for name in ("z1", "z2"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) \
                    or not math.isfinite(value) or value != int(value):
                raise DesignError(name, value, "must be a whole number of teeth")
            if not MIN_TEETH <= value <= MAX_TEETH:
                raise DesignError(name, value, f"must be ≥ {MIN_TEETH} and ≤ {MAX_TEETH} teeth")
        if isinstance(self.module_mm, (int, float)) and not isinstance(self.module_mm, bool) \
                and 0.0 < self.module_mm < MIN_MODULE_MM:      # a subnormal m: lengths of 0/0
            raise DesignError("module", self.module_mm, f"must be ≥ {MIN_MODULE_MM:g} and ≤ "
                              f"{MAX_MODULE_MM:g} mm")
        _within("module", self.module_mm, 0.0, MAX_MODULE_MM, "mm", open_low=True)
        _within("pressure_angle", self.pressure_angle_deg, 10.0, 35.0, "°")
        _within("addendum", self.addendum, 0.5, 2.0, "")
        _within("clearance", self.clearance, 0.0, 1.0, "")
        most = most_clearance(self.alpha, self.addendum)
        if self.clearance > most:
            raise DesignError("clearance", self.clearance, f"must be ≤ {math.floor(most * 1e4) / 1e4:.4f} "
                              f"at α = {self.pressure_angle_deg:g}° and h*a = {self.addendum:g}: the "
                              "rack's tip rounding would not fit its tooth")
        _within("tip_limit", self.tip_limit, 0.0, 1.0, "× m")
        _within("contact_limit", self.contact_limit, 1.0, 3.0, "")
        if (self.x1 is None) != (self.x2 is None):
            missing = "x2" if self.x2 is None else "x1"
            raise DesignError(missing, None, "must be given with the other shift factor")
        if self.x1 is not None and self.centre_mm is not None:
            raise DesignError("centre", self.centre_mm, "give either the shift factors or the "
                              "centre distance, not both")
        if self.x1 is not None:
            _within("x1", self.x1, -MAX_SHIFT, MAX_SHIFT, "")
            _within("x2", self.x2, -MAX_SHIFT, MAX_SHIFT, "")
        if self.centre_mm is not None:
            _within("centre", self.centre_mm, 0.0, 1e6, "mm", open_low=True)
        return self


def most_clearance(alpha: float, addendum: float) -> float:
    """The largest c* whose tip rounding ρ = c* m / (1 − sin α) fits the rack's tooth:
    (π/4 − h*a tan α) / (tan α + sec α), where the two roundings of the tooth's tip meet on
    its axis (0.295 at 20°, 0.203 at 25°). A larger one cut a tooth space folded on itself
    and a root the rack cannot cut (issue 42), so it is refused by name."""
    return (math.pi / 4.0 - addendum * math.tan(alpha)) / (math.tan(alpha) + 1.0 / math.cos(alpha))


def _within(name: str, value: object, low: float, high: float, unit: str,
            open_low: bool = False) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise DesignError(name, value, "must be a finite number")
    if (value <= low if open_low else value < low) or value > high:
        sign = ">" if open_low else "≥"
        raise DesignError(name, value, f"must be {sign} {low:g} and ≤ {high:g} {unit}".rstrip())
