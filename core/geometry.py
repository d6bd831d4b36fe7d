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

from .errors import DesignError, require_range

MIN_LENGTH_MM = 0.001
MAX_LENGTH_MM = 100_000.0
MAX_TIME_RATIO = 5.0
MAX_ROD_RATIO = 10.0      # L4/L3
# L1/L2 = sin(θ/2) at K = 5 (θ = 120°): the largest crank a frame allows.
MAX_CRANK_RATIO = math.sin(math.pi * (MAX_TIME_RATIO - 1.0) / (MAX_TIME_RATIO + 1.0) / 2.0)
# The rod must keep a horizontal reach |Cx − Bx| and a drive margin of this fraction of
# L4 (a pressure angle below 89.94°), so forces and accelerations stay finite and exact.
ROD_MARGIN = 1e-3
GuideRule = Literal["chord", "sagitta"]
RodSide = Literal["trailing", "leading"]
ROD_SIDES: tuple[str, ...] = ("trailing", "leading")
GUIDE_RULES: tuple[str, ...] = ("chord", "sagitta")


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
    if rule == "chord":
        return lever * math.cos(theta / 2.0)
    if rule == "sagitta":
        return lever * (1.0 + math.cos(theta / 2.0)) / 2.0
    if isinstance(rule, str):
        try:
            rule = float(rule)
        except ValueError:
            raise DesignError("guide", rule,
                              "must be 'chord', 'sagitta' or a height in mm") from None
    return require_length("guide", rule)


def require_length(name: str, value: object) -> float:
    """A link length in [MIN_LENGTH_MM, MAX_LENGTH_MM] mm."""
    return require_range(name, value, MIN_LENGTH_MM, MAX_LENGTH_MM, "mm", low_open=False)


def synthesize(crank: float, time_ratio: float, stroke: float, *,
               guide: GuideRule | float = "chord", rod: float | None = None,
               rod_ratio: float | None = None, rod_side: RodSide = "trailing") -> Design:
    """Seed 003's synthesis: L2 = L1/sin(θ/2), L3 = H/(2 sin(θ/2)).

    Give ``rod`` (mm) or ``rod_ratio`` (L4/L3) for the connecting-rod variant;
    give neither for the block variant.
    """
    crank = require_length("crank", crank)
    time_ratio = require_range("time_ratio", time_ratio, 1.0, MAX_TIME_RATIO)
    stroke = require_length("stroke", stroke)
    theta = theta_from_time_ratio(time_ratio)
    half = math.sin(theta / 2.0)
    # L2 = L1/sin(θ/2) and L3 = H/(2 sin(θ/2)) grow without bound as K → 1.
    smallest_half = max(crank, stroke / 2.0) / MAX_LENGTH_MM
    if half < smallest_half:
        k_min = (math.pi + 2.0 * math.asin(smallest_half)) / (math.pi - 2.0 * math.asin(smallest_half))
        raise DesignError("time_ratio", time_ratio,
                          f"must be ≥ {_round_up(k_min)} for this crank and stroke, so that "
                          f"the frame and the lever stay ≤ {MAX_LENGTH_MM:g} mm")
    frame = crank / half
    lever = stroke / (2.0 * half)
    shortest = crank + frame
    if lever < shortest:
        need = 2.0 * shortest * half
        raise DesignError("stroke", stroke,
                          f"must be ≥ {need:.1f} mm for this crank and K, "
                          "so that the crank pin stays on the lever")
    rod_length = _rod_length(rod, rod_ratio, lever)
    return Design(crank=crank, frame=frame, lever=lever,
                  guide=guide_height(guide, lever, theta), rod=rod_length,
                  rod_side=rod_side)


def from_dimensions(crank: float, frame: float, lever: float, *,
                    guide: GuideRule | float = "chord", rod: float | None = None,
                    rod_ratio: float | None = None,
                    rod_side: RodSide = "trailing") -> Design:
    """A design from measured link lengths; K, H and θ are then implied."""
    crank = require_length("crank", crank)
    frame = require_length("frame", frame)
    lever = require_length("lever", lever)
    _check_crank_ratio(crank, frame)
    theta = 2.0 * math.asin(crank / frame)
    rod_length = _rod_length(rod, rod_ratio, lever)
    return Design(crank=crank, frame=frame, lever=lever,
                  guide=guide_height(guide, lever, theta), rod=rod_length,
                  rod_side=rod_side)


def _rod_length(rod: float | None, rod_ratio: float | None, lever: float) -> float | None:
    if rod is not None and rod_ratio is not None:
        raise DesignError("rod", rod, "must be given either as a length or as a ratio L4/L3, not both")
    if rod_ratio is not None:
        ratio = require_range("rod_ratio", rod_ratio, 0.0, MAX_ROD_RATIO)
        return ratio * lever
    if rod is not None:
        return require_length("rod", rod)
    return None


def _round_up(value: float, digits: int = 6, down: bool = False) -> str:
    """``value`` rounded up (or down) to ``digits`` significant digits, so that a stated
    minimum (or maximum) is itself allowed."""
    scale = 10.0 ** (digits - 1 - math.floor(math.log10(abs(value))))
    rounded = (math.floor if down else math.ceil)(value * scale) / scale
    return f"{rounded:.{digits}g}"


def _check_crank_ratio(crank: float, frame: float) -> None:
    """K = (π + θ)/(π − θ) with sin(θ/2) = L1/L2 must stay ≤ 5, like a synthesized K."""
    if crank >= frame:
        raise DesignError("crank", crank,
                          f"must be shorter than the frame O2O4 ({frame:.6g} mm)")
    if crank > MAX_CRANK_RATIO * frame * (1.0 + 1e-12):
        raise DesignError("crank", crank,
                          f"must be ≤ {_round_up(MAX_CRANK_RATIO * frame, down=True)} mm (0.866·L2), so that the "
                          f"time ratio K stays ≤ {MAX_TIME_RATIO:g}")


def validate(design: Design) -> None:
    """Refuse a design that cannot be assembled or would jam somewhere in the cycle."""
    for name in ("crank", "frame", "lever", "guide"):
        require_length(name, getattr(design, name))
    _check_crank_ratio(design.crank, design.frame)
    if design.rod_side not in ROD_SIDES:
        raise DesignError("rod_side", design.rod_side, "must be 'trailing' or 'leading'")
    reach = design.frame + design.crank
    if design.lever < reach:
        raise DesignError("lever", design.lever,
                          f"must be ≥ L2 + L1 = {reach:.6g} mm, "
                          "so that the crank pin stays on the lever")
    if design.guide <= reach:
        raise DesignError("guide", design.guide,
                          f"must be > L2 + L1 = {reach:.6g} mm above the lever pivot, "
                          "so that the ram clears the crank")
    half = design.theta / 2.0
    tip_low = design.lever * math.cos(half)
    if design.rod is None:
        if design.guide > design.lever:
            raise DesignError("guide", design.guide,
                              f"must be ≤ the lever length {design.lever:.6g} mm: "
                              "the block on the lever tip cannot reach a higher guide")
        return
    require_length("rod", design.rod)
    # The rod's rise |d| = |guide − By| is largest at a limit position (By lowest) or at
    # ψ = 0 (By = L3); its horizontal reach sqrt(L4² − d²) must stay ≥ ROD_MARGIN·L4.
    rise = max(design.guide - tip_low, design.lever - design.guide)
    need = rise / math.sqrt(1.0 - ROD_MARGIN ** 2)
    if design.rod <= need:
        raise DesignError("rod", design.rod,
                          f"must be > {need:.6g} mm to reach the guide line "
                          "over the whole cycle")
    if rod_drive_margin(design) <= ROD_MARGIN * design.rod:
        raise DesignError("rod", design.rod,
                          "the rod passes a dead-centre position against the lever; "
                          "lengthen the rod or move the guide line")


def rod_drive_margin(design: Design) -> float:
    """min over the swing of r·cos ψ − s·d·sin ψ, mm: zero where the rod stands square
    to the lever and the ram would stall (a dead centre).

    The minimum is bracketed on a grid over ψ ∈ [−θ/2, θ/2] and polished with Brent's
    method, so a narrow dip between grid points is not missed.
    """
    from scipy.optimize import minimize_scalar

    half = design.theta / 2.0
    rod, sign = float(design.rod), design.rod_sign  # type: ignore[arg-type]

    def drive(psi):
        d = design.guide - design.lever * np.cos(psi)
        r = np.sqrt(np.maximum(rod ** 2 - d ** 2, 0.0))
        return r * np.cos(psi) - sign * d * np.sin(psi)

    psi = np.linspace(-half, half, 721)
    values = drive(psi)
    i = int(np.argmin(values))
    lo, hi = psi[max(i - 1, 0)], psi[min(i + 1, psi.size - 1)]
    if hi - lo <= 0.0:
        return float(values[i])
    best = minimize_scalar(lambda p: float(drive(p)), bounds=(lo, hi), method="bounded",
                           options={"xatol": 1e-12 * max(half, 1e-300)})
    return float(min(values[i], best.fun))
