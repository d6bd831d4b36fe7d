"""Each check's quantity, its limit and whether it passes, without advice: what the checks
report and what the search for an advice's amount (``amounts``) follows.

undercut (x ≥ x_min), tip thickness (sa ≥ limit · m), contact ratio (ε ≥ limit) and involute
interference at each root: the mating tip must meet the flank no lower than where the rack's
involute starts (the form point F, N F = r sin α − (h*a − x) m / sin α along the line of action;
an undercut flank is judged from N itself, and the undercut check fails anyway).
"""
from __future__ import annotations

from typing import Any, NamedTuple

GearPair = Any
"""A ``pair.GearPair``, not imported: ``pair`` asks ``amounts`` (which reads margins here) for
its refusals' values, and no module of core imports one that imports it back, even for types."""

CHECKS = ("undercut1", "undercut2", "tip1", "tip2", "contact", "interference1", "interference2")
INTERFERENCE_TOLERANCE_MM = 1e-9
"""The interference check passes this far short of its need (the two lengths' rounding)."""


class Margin(NamedTuple):
    """One check's ``ok``, ``value`` and ``limit`` (value ≥ limit passes)."""
    ok: bool
    value: float
    limit: float


def check_margins(pair: GearPair) -> dict[str, Margin]:
    """Every check of ``pair`` by name (CHECKS' order)."""
    p = pair.inputs
    gears = (pair.gear1, pair.gear2)
    limit = p.tip_limit * p.module_mm
    out: dict[str, Margin] = {}
    for k, gear in ((1, gears[0]), (2, gears[1])):
        out[f"undercut{k}"] = Margin(not gear.undercut, gear.shift, gear.least_shift)
    for k, gear in ((1, gears[0]), (2, gears[1])):
        out[f"tip{k}"] = Margin(gear.sa >= limit, gear.sa, limit)
    out["contact"] = Margin(pair.contact_ratio >= p.contact_limit, pair.contact_ratio, p.contact_limit)
    for k, gear in ((1, gears[0]), (2, gears[1])):
        reach = pair.n1b2 if k == 1 else pair.n1n2 - pair.n1b1
        need = max(gear.form_length, 0.0)
        out[f"interference{k}"] = Margin(reach >= need - INTERFERENCE_TOLERANCE_MM, reach, need)
    return out
