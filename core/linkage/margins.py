"""How far a valid design is from each validation rule (for the design report).

``geometry.validate`` refuses a design that breaks a rule; this module says
by how much an accepted one clears each rule, so a report can show that the
design is not on the edge. Level: beside ``metrics``; imports ``geometry`` only.
"""
from __future__ import annotations

from dataclasses import dataclass

import math

from .geometry import MAX_TIME_RATIO, ROD_MARGIN, Design, rod_drive_margin


@dataclass(frozen=True)
class Margin:
    """One rule: ``value`` must stay on the right side of ``limit``; ``margin`` ≥ 0 if it does."""

    rule: str          # key: time_ratio, lever_reach, guide_clears_crank, guide_below_tip,
                       # rod_reach, rod_dead_centre
    value: float
    limit: float
    margin: float
    unit: str


def margins(design: Design) -> tuple[Margin, ...]:
    """Every rule that applies to ``design`` (see docs/methods.md, Validation), in order."""
    reach = design.frame + design.crank
    out = [Margin("time_ratio", design.time_ratio, MAX_TIME_RATIO,
                  MAX_TIME_RATIO - design.time_ratio, ""),
           Margin("lever_reach", design.lever, reach, design.lever - reach, "mm"),
           Margin("guide_clears_crank", design.guide, reach, design.guide - reach, "mm")]
    if design.rod is None:
        out.append(Margin("guide_below_tip", design.guide, design.lever,
                          design.lever - design.guide, "mm"))
        return tuple(out)
    tip_low = design.lever * math.cos(design.theta / 2.0)
    rise = max(design.guide - tip_low, design.lever - design.guide)
    need = rise / math.sqrt(1.0 - ROD_MARGIN ** 2)
    out.append(Margin("rod_reach", design.rod, need, design.rod - need, "mm"))
    drive = rod_drive_margin(design)
    out.append(Margin("rod_dead_centre", drive, ROD_MARGIN * design.rod,
                      drive - ROD_MARGIN * design.rod, "mm"))
    return tuple(out)
