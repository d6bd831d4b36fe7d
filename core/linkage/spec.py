"""The design as the user states it: synthesis inputs or direct dimensions.

A :class:`Spec` is what a form edits and what a design file stores; it keeps
the inactive fields too, so switching mode or variant loses nothing. It turns
into a :class:`~core.linkage.geometry.Design` with :meth:`Spec.design`.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass, fields, replace
from typing import Any

from core.base.errors import DesignError, require_range
from .geometry import MAX_ROD_RATIO, MAX_TIME_RATIO, Design, from_dimensions, require_length, synthesize

MODES = ("synthesis", "dimensions")
VARIANTS = ("block", "rod")
GUIDE_RULES = ("chord", "sagitta", "height")
ROD_INPUTS = ("ratio", "length")
ROD_SIDES = ("trailing", "leading")
NUMBER_FIELDS = ("crank", "time_ratio", "stroke", "frame", "lever", "guide_height",
                 "rod_length", "rod_ratio")


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
        for name in NUMBER_FIELDS:
            self.check_field(name)

    def check_field(self, name: str) -> None:
        """Check one number field on its own bounds (DesignError names it)."""
        value = getattr(self, name)
        if name == "time_ratio":
            require_range(name, value, 1.0, MAX_TIME_RATIO)
        elif name == "rod_ratio":
            require_range(name, value, 0.0, MAX_ROD_RATIO)
        else:
            require_length(name, value)

    def active_fields(self) -> frozenset[str]:
        """The number fields the current mode, variant, guide rule and rod input use."""
        names = {"crank"} | ({"time_ratio", "stroke"} if self.mode == "synthesis" else {"frame", "lever"})
        if self.guide_rule == "height":
            names.add("guide_height")
        if self.variant == "rod":
            names.add("rod_length" if self.rod_input == "length" else "rod_ratio")
        return frozenset(names)

    def switch_mode(self, mode: str, design: Design) -> "Spec":
        """This spec in ``mode``, carrying ``design`` over: its L2 and L3 into direct
        dimensions, or the K and H it implies into synthesis.

        The fields of ``mode`` are kept when they already give ``design`` (to 1e-9), so
        K and H come back as typed after a switch there and back. Otherwise the carried
        values are rounded to 12 significant digits where that keeps the design valid,
        else nudged by a few parts in 10¹² (a design on a bound, K = 5 or L3 = L2 + L1,
        may fall just outside it after a round trip through sin and asin)."""
        if mode == self.mode or mode not in MODES:
            return replace(self, mode=mode)
        kept = replace(self, mode=mode)
        if _gives(kept, design):
            return kept
        if mode == "dimensions":
            carried = {"frame": design.frame, "lever": design.lever}
        else:
            carried = {"time_ratio": design.time_ratio, "stroke": design.stroke}
        base = replace(self, mode=mode, **carried)
        for candidate in _nudged(base, carried):
            try:
                candidate.design()
            except DesignError:
                continue
            return candidate
        return base

    def _check_choices(self) -> None:
        for name, allowed in (("mode", MODES), ("variant", VARIANTS),
                              ("guide_rule", GUIDE_RULES), ("rod_input", ROD_INPUTS),
                              ("rod_side", ROD_SIDES)):
            if getattr(self, name) not in allowed:
                raise DesignError(name, getattr(self, name), "must be one of " + ", ".join(allowed))

    def design(self) -> Design:
        """Synthesize or assemble the design; raises DesignError on bad input, naming the
        input as it was given (a rod given as L4/L3 in L4/L3: ``designs.ratio_error``)."""
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


def _gives(spec: Spec, design: Design, rel: float = 1e-9) -> bool:
    """Whether ``spec`` is valid and gives ``design`` to ``rel``."""
    try:
        other = spec.design()
    except DesignError:
        return False
    if (other.rod is None) != (design.rod is None):
        return False
    pairs = [(getattr(other, n), getattr(design, n)) for n in ("crank", "frame", "lever", "guide")]
    if design.rod is not None:
        pairs.append((other.rod, design.rod))
    return all(abs(a - b) <= rel * abs(b) for a, b in pairs)


def _nudged(base: Spec, carried: dict[str, float]):
    """Candidates near the carried values: rounded first, then exact, then nudged."""
    names = list(carried)
    yield replace(base, **{n: float(f"{v:.12g}") for n, v in carried.items()})
    yield base
    factors = (1.0, 1.0 + 1e-12, 1.0 - 1e-12, 1.0 + 1e-10, 1.0 - 1e-10, 1.0 + 1e-9, 1.0 - 1e-9)
    for f0 in factors:
        for f1 in factors:
            yield replace(base, **{names[0]: carried[names[0]] * f0, names[1]: carried[names[1]] * f1})

