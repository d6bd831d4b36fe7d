"""Dimensional synthesis: from what a designer knows (L1, K, H) to link lengths.

This is the first level of core: it only knows lengths and angles, never
time. A :class:`Design` is a value; everything else is derived from it.

Frame of reference (used by every level): the lever pivot O4 is the origin,
the crank centre O2 lies straight above it at (0, L2), the ram guide is the
horizontal line y = ``guide``, and the ram cuts toward +x. With cutting to the
right the crank turns clockwise in this y-up frame.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from .designs import (GUIDE_RULES, MAX_CRANK_RATIO, MAX_LENGTH_MM, MAX_ROD_RATIO, MAX_TIME_RATIO,  # noqa: F401
                      MIN_LENGTH_MM, ROD_SIDES, Designs, check_designs, dimensions_many,
                      ratio_error, synthesize_many)
from .drive import ROD_MARGIN, drive_margin  # noqa: F401
from .designs import _guide, _guide_number, check_length
from core.base.errors import DesignError, require_range
from .verdict import Verdict

GuideRule = Literal["chord", "sagitta"]
RodSide = Literal["trailing", "leading"]


@dataclass(frozen=True)
class Design:
    """Link lengths of one shaper mechanism, all in mm.

    ``rod`` is None for the block variant (a block on the lever tip slides in
    a vertical slot of the ram) and the connecting-rod length L4 otherwise.
    ``guide`` is the height of the ram guide line above the lever pivot O4.
    ``rod_side`` says whether the ram joint C trails the lever tip B while
    cutting (classic layout) or leads it (seed 000's layout).
    """

    crank: float
    frame: float
    lever: float
    guide: float
    rod: float | None = None
    rod_side: RodSide = "trailing"

    def __post_init__(self) -> None:
        validate(self)

    @property
    def variant(self) -> str:
        return "block" if self.rod is None else "rod"

    @property
    def theta(self) -> float:
        """Extreme-position angle θ in rad; equal to the lever swing."""
        return 2.0 * math.asin(self.crank / self.frame)

    @property
    def time_ratio(self) -> float:
        """K implied by the dimensions: (π + θ) / (π − θ)."""
        return (math.pi + self.theta) / (math.pi - self.theta)

    @property
    def stroke(self) -> float:
        """Ram stroke H implied by the dimensions, mm: 2·L3·sin(θ/2)."""
        return 2.0 * self.lever * math.sin(self.theta / 2.0)

    @property
    def guide_above_crank(self) -> float:
        """Seed 003's h: height of the guide line above the crank centre O2, mm."""
        return self.guide - self.frame

    @property
    def rod_sign(self) -> float:
        """+1 when C leads B in the cutting direction (+x), −1 when it trails."""
        return 1.0 if self.rod_side == "leading" else -1.0


def theta_from_time_ratio(time_ratio: float) -> float:
    """θ = π (K − 1)/(K + 1), rad."""
    return math.pi * (time_ratio - 1.0) / (time_ratio + 1.0)


def guide_height(rule: GuideRule | float, lever: float, theta: float) -> float:
    """Guide-line height above the lever pivot for a named rule or an explicit value.

    ``chord``: through both extreme positions of the lever tip, L3·cos(θ/2).
    ``sagitta``: midway along the arc's sagitta, L3·(1 + cos(θ/2))/2, which
    halves the rod's worst inclination.
    """
    value = _guide_argument(rule)
    if not isinstance(value, str):
        verdict = Verdict(np.zeros(1, dtype=np.int16))
        check_length(verdict, "guide", np.asarray(value, dtype=float).reshape(1))
        verdict.raise_first()
    height = _guide(value, np.array([float(lever)]), np.array([float(theta)]))
    return float(height[0])


def require_length(name: str, value: object) -> float:
    """A link length in [MIN_LENGTH_MM, MAX_LENGTH_MM] mm."""
    return require_range(name, value, MIN_LENGTH_MM, MAX_LENGTH_MM, "mm", low_open=False)


def synthesize(crank: float, time_ratio: float, stroke: float, *,
               guide: GuideRule | float = "chord", rod: float | None = None,
               rod_ratio: float | None = None, rod_side: RodSide = "trailing") -> Design:
    """Seed 003's synthesis: L2 = L1/sin(θ/2), L3 = H/(2 sin(θ/2)).

    Give ``rod`` (mm) or ``rod_ratio`` (L4/L3) for the connecting-rod variant;
    give neither for the block variant. The rules are those of
    :func:`core.linkage.designs.synthesize_many` on one design.
    """
    return _one_design(synthesize_many, (("crank", crank), ("time_ratio", time_ratio),
                                         ("stroke", stroke)), guide, rod, rod_ratio, rod_side)


def from_dimensions(crank: float, frame: float, lever: float, *,
                    guide: GuideRule | float = "chord", rod: float | None = None,
                    rod_ratio: float | None = None,
                    rod_side: RodSide = "trailing") -> Design:
    """A design from measured link lengths; K, H and θ are then implied."""
    return _one_design(dimensions_many, (("crank", crank), ("frame", frame), ("lever", lever)),
                       guide, rod, rod_ratio, rod_side)


def _one_design(many, lengths, guide, rod, rod_ratio, rod_side) -> Design:
    """``many`` (synthesize_many or dimensions_many) on one design; its first error raised."""
    designs, verdict = many(*(_one(name, value) for name, value in lengths),
                            guide=_guide_argument(guide), rod=_optional("rod", rod),
                            rod_ratio=_optional("rod_ratio", rod_ratio), rod_side=rod_side,
                            validate=False)
    verdict.raise_first()
    try:
        return _design(designs)         # validated as a Design: the rules of check_designs
    except DesignError as exc:
        if rod_ratio is None:
            raise
        raise ratio_error(exc, float(rod_ratio)) from None


def _one(name: str, value: object) -> np.ndarray:
    """A scalar input as a one-design array; text that is no number is refused here."""
    try:
        return np.array([float(value)])  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise DesignError(name, value, "must be a number") from None


def _optional(name: str, value: object) -> np.ndarray | None:
    return None if value is None else _one(name, value)


def _guide_argument(guide: object):
    if isinstance(guide, str) and guide in GUIDE_RULES:
        return guide
    number = _guide_number(guide)
    return _one("guide", number)


def _design(designs: Designs) -> Design:
    rod = None if designs.rod is None else float(designs.rod[0])
    return Design(crank=float(designs.crank[0]), frame=float(designs.frame[0]),
                  lever=float(designs.lever[0]), guide=float(designs.guide[0]), rod=rod,
                  rod_side=designs.rod_side)  # type: ignore[arg-type]


def validate(design: Design) -> None:
    """Refuse a design that cannot be assembled or would jam somewhere in the cycle.

    The rules are :func:`core.linkage.designs.check_designs` on this one design.
    """
    one = {name: _one(name, getattr(design, name)) for name in ("crank", "frame", "lever", "guide")}
    rod = None if design.rod is None else _one("rod", design.rod)
    verdict = Verdict(np.zeros(1, dtype=np.int16))
    check_designs(verdict, Designs(rod=rod, rod_side=design.rod_side, **one))
    verdict.raise_first()


def rod_drive_margin(design: Design) -> float:
    """min over the swing of r·cos ψ − s·d·sin ψ, mm: zero where the rod lies in line
    with the lever, which then has no arm to drive it (a dead centre). See :func:`core.linkage.drive.drive_margin`.
    """
    return float(drive_margin(Designs.of(design))[0])
