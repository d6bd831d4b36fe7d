"""Which shift factors: given, from the centre distance, or by the rule.

The no-backlash condition ties them to the working pressure angle α′ and the centre
distance a′:  inv α′ = 2 tan α (x1 + x2)/(z1 + z2) + inv α,  a′ cos α′ = a cos α.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from core.base.errors import DesignError
from .inputs import GearPairInputs
from .involute import inv, inv_inverse, least_shift, least_teeth

CENTRE_STEPS_MM = (1.0, 2.0, 5.0)
"""The rule's centre distance is rounded up to a multiple of 1, 2 or 5 × 10^k mm, the largest
not above m/10 (:func:`centre_step`): 0.5 mm at m = 5 or 6, 0.2 mm at m = 2, 0.01 mm at
m = 0.1. A fixed 0.5 mm made a 1.70 mm pair of m = 0.1 a 2.0 mm one, x2 = 4.27, refused as
pointed (issue 42): the step adds at most about 0.1 to x1 + x2 whatever the module."""


def centre_step(module_mm: float) -> float:
    """The largest 1, 2 or 5 × 10^k mm not above m/10: the rule's rounding of a′, mm."""
    decade = 10.0 ** math.floor(math.log10(module_mm / 10.0))
    return max(k * decade for k in CENTRE_STEPS_MM if k * decade <= module_mm / 10.0 * (1 + 1e-12))


def bound_text(value: float, up: bool, strict: bool = False) -> str:
    """``value`` to 4 decimals rounded towards the allowed side (up for a least value, down
    for a greatest), one step further when the bound is strict and the rounding is exact:
    the hinted number is itself accepted (49.1049 for a least 49.104929944 was refused)."""
    scaled = value * 1e4
    shown = math.ceil(scaled - 1e-9) if up else math.floor(scaled + 1e-9)
    if strict and shown / 1e4 == value:
        shown += 1 if up else -1
    if up and shown / 1e4 < value:
        shown += 1
    if not up and shown / 1e4 > value:
        shown -= 1
    return f"{shown / 1e4:.4f}"

MODES = ("given", "centre", "balanced", "positive")
"""How the shifts were found: x1, x2 given; from a′; the rule with x2 = −x1 (z1 + z2 ≥ 2 z_min);
the rule with a positive pair at a′ rounded up (z1 + z2 < 2 z_min)."""


@dataclass(frozen=True)
class Shifts:
    """The pair's shift factors and the meshing they give: ``x1``, ``x2``; ``alpha_w`` α′ in
    radians; ``centre_mm`` a′, mm; ``mode`` one of MODES."""
    x1: float
    x2: float
    alpha_w: float
    centre_mm: float
    mode: str


def reference_centre(p: GearPairInputs) -> float:
    """a = m (z1 + z2) / 2, mm: the centre distance of the standard pair."""
    return p.module_mm * (p.z1 + p.z2) / 2.0


def mesh_of_sum(p: GearPairInputs, total: float) -> tuple[float, float]:
    """(α′, a′) of a pair whose shifts add to ``total``, from the no-backlash condition."""
    if total == 0.0:            # the standard centre exactly, not Newton's last ulp
        return p.alpha, reference_centre(p)
    value = 2.0 * math.tan(p.alpha) * total / (p.z1 + p.z2) + inv(p.alpha)
    if not value > 0.0:
        least = -inv(p.alpha) * (p.z1 + p.z2) / (2.0 * math.tan(p.alpha))       # where α′ = 0
        raise DesignError("x1", total, "x1 + x2 is too negative: the gears would not mesh "
                          f"(α′ ≤ 0); raise x1 + x2 above {bound_text(float(least), True, True)}")
    alpha_w = inv_inverse(float(value))
    return alpha_w, reference_centre(p) * math.cos(p.alpha) / math.cos(alpha_w)


def sum_of_centre(p: GearPairInputs, centre: float) -> tuple[float, float]:
    """(x1 + x2, α′) that mesh without backlash at the centre distance ``centre``."""
    cos_w = reference_centre(p) * math.cos(p.alpha) / centre
    if not cos_w < 1.0:
        least = reference_centre(p) * math.cos(p.alpha)
        raise DesignError("centre", centre, f"must be > a cos α = {bound_text(least, True, True)} "
                          "mm (the working pressure angle would be 0)")
    alpha_w = math.acos(cos_w)
    return (float(inv(alpha_w) - inv(p.alpha)) * (p.z1 + p.z2) / (2.0 * math.tan(p.alpha)),
            alpha_w)


def split(p: GearPairInputs, total: float) -> tuple[float, float]:
    """x1 + x2 = ``total`` shared out: the pinion gets the least shift that keeps it uncut
    (never below 0: a pinion that is uncut as standard stays standard), the gear the rest;
    if that leaves the gear undercut, the pinion gives up what the gear needs. Why this rule:
    the pinion, with fewer teeth, is the one that undercuts; a gear shifted more than it
    needs only thins its tips. DesignError when no split keeps both uncut."""
    need1 = least_shift(p.z1, p.alpha, p.addendum)
    need2 = least_shift(p.z2, p.alpha, p.addendum)
    if total < need1 + need2 - 1e-12:
        least = mesh_of_sum(p, need1 + need2)[1]
        digits = 4              # enough to tell them apart ("-1.0414, below the -1.0414")
        while f"{total:.{digits}f}" == f"{need1 + need2:.{digits}f}" and digits < 12:
            digits += 1
        raise DesignError("centre", None, "needs x1 + x2 = "
                          f"{total:.{digits}f}, below the {need1 + need2:.{digits}f} that keeps both "
                          f"gears uncut; give ≥ {bound_text(least, True)} mm")
    x1 = min(max(need1, 0.0), total - need2)
    return x1, total - x1


def auto_shifts(p: GearPairInputs) -> Shifts:
    """Neither shifts nor a′ given: with z1 + z2 ≥ 2 z_min the least uncut x1 (≥ 0) and
    x2 = −x1 (a′ = a, a height-modified pair), shared as :func:`split` shares x1 + x2 = 0
    (so a gear 2 below z_min beside a larger pinion gets its least shift, x1 = −x2);
    otherwise the least positive pair, its a′
    rounded up to :func:`centre_step` and the shifts solved back from it and split as
    :func:`split`."""
    if p.z1 + p.z2 >= 2.0 * least_teeth(p.alpha, p.addendum):
        x1, x2 = split(p, 0.0)      # x1 = −x2: a pinion larger than an undercut gear gives way
        return Shifts(x1, x2, p.alpha, reference_centre(p), "balanced")
    need1 = max(least_shift(p.z1, p.alpha, p.addendum), 0.0)
    need2 = max(least_shift(p.z2, p.alpha, p.addendum), 0.0)
    step = centre_step(p.module_mm)
    centre = round(math.ceil(mesh_of_sum(p, need1 + need2)[1] / step - 1e-9) * step, 12)
    total, alpha_w = sum_of_centre(p, centre)
    x1, x2 = split(p, total)
    return Shifts(x1, x2, alpha_w, centre, "positive")


def find_shifts(p: GearPairInputs) -> Shifts:
    """The shifts and the meshing of checked inputs, in whichever mode they ask for."""
    if p.x1 is not None and p.x2 is not None:
        alpha_w, centre = mesh_of_sum(p, p.x1 + p.x2)
        return Shifts(float(p.x1), float(p.x2), alpha_w, centre, "given")
    if p.centre_mm is not None:
        total, alpha_w = sum_of_centre(p, p.centre_mm)
        try:
            x1, x2 = split(p, total)
        except DesignError as exc:
            raise DesignError("centre", p.centre_mm, exc.allowed) from None
        return Shifts(x1, x2, alpha_w, float(p.centre_mm), "centre")
    return auto_shifts(p)
