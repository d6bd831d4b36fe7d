"""The design as the user states it: synthesis inputs or direct dimensions.

A :class:`Spec` is what a form edits and what a design file stores; it keeps
the inactive fields too, so switching mode or variant loses nothing. It turns
into a :class:`~core.geometry.Design` with :meth:`Spec.design`.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass, fields, replace
from typing import Any

from .errors import DesignError, require_range
from .geometry import MAX_ROD_RATIO, MAX_TIME_RATIO, Design, from_dimensions, require_length, synthesize

MODES = ("synthesis", "dimensions")
VARIANTS = ("block", "rod")
GUIDE_RULES = ("chord", "sagitta", "height")
ROD_INPUTS = ("ratio", "length")
ROD_SIDES = ("trailing", "leading")
LENGTH_FIELDS = ("crank", "stroke", "frame", "lever", "guide_height", "rod_length")


@dataclass(frozen=True)
class Spec:
    """All form inputs; lengths in mm."""

    mode: str = "synthesis"
    crank: float = 100.0
    time_ratio: float = 1.4
    stroke: float = 300.0
    frame: float = 386.37
    lever: float = 579.56
    variant: str = "block"
    guide_rule: str = "chord"
    guide_height: float = 560.0     # above the lever pivot O4, used when guide_rule == "height"
    rod_input: str = "ratio"
    rod_length: float = 170.0
    rod_ratio: float = 0.3
    rod_side: str = "trailing"

    def check_fields(self) -> None:
        """Check every field on its own, the inactive ones too (K and H in dimensions
        mode, the rod in the block variant …), with the same bounds as when active.

        :meth:`design` checks only what the current mode uses; this makes sure a
        spec that is saved holds no value that would be refused after a switch."""
        self._check_choices()
        for name in LENGTH_FIELDS:
            require_length(name, getattr(self, name))
        require_range("time_ratio", self.time_ratio, 1.0, MAX_TIME_RATIO)
        require_range("rod_ratio", self.rod_ratio, 0.0, MAX_ROD_RATIO)

    def _check_choices(self) -> None:
        for name, allowed in (("mode", MODES), ("variant", VARIANTS),
                              ("guide_rule", GUIDE_RULES), ("rod_input", ROD_INPUTS),
                              ("rod_side", ROD_SIDES)):
            if getattr(self, name) not in allowed:
                raise DesignError(name, getattr(self, name), "must be one of " + ", ".join(allowed))

    def design(self) -> Design:
        """Synthesize or assemble the design; raises DesignError on bad input."""
        self._check_choices()
        guide = self.guide_height if self.guide_rule == "height" else self.guide_rule
        rod = ratio = None
        if self.variant == "rod":
            if self.rod_input == "length":
                rod = self.rod_length
            else:
                ratio = self.rod_ratio
        if self.mode == "synthesis":
            return synthesize(self.crank, self.time_ratio, self.stroke, guide=guide,
                              rod=rod, rod_ratio=ratio, rod_side=self.rod_side)
        return from_dimensions(self.crank, self.frame, self.lever, guide=guide,
                               rod=rod, rod_ratio=ratio, rod_side=self.rod_side)

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> "Spec":
        """Build from a mapping; unknown keys are refused, missing ones defaulted."""
        names = {f.name: f for f in fields(cls)}
        unknown = set(data) - set(names)
        if unknown:
            raise DesignError(sorted(unknown)[0], data[sorted(unknown)[0]], "is not a design field")
        values: dict[str, Any] = {}
        for key, value in data.items():
            if names[key].type == "str":
                if not isinstance(value, str):
                    raise DesignError(key, value, "must be text")
                values[key] = value
            else:
                if isinstance(value, bool) or not isinstance(value, (int, float)):
                    raise DesignError(key, value, "must be a number")
                values[key] = float(value)
        return replace(cls(), **values)
