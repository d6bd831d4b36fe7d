"""Which typed roller a checked cam takes, and the one refusal that says so.

A checked cam (its base radius and centre distance given) is fixed, so a typed roller r
must meet three conditions at once:

* r ≤ the largest for the pitch curve's ρmin (r ≤ 0.8·ρmin and ρmin − r ≥ 3 mm,
  ``synthesis.largest_roller``): the profile neither undercut nor pointed;
* r ≤ r0 − hub − clearance: the profile's smallest radius clears the hub (``build``);
* r ≥ R1 − (a − boss − clearance): the profile's largest radius clears the pivot boss.

Why one refusal for all three: refused for one, a roller made to fit it was refused for the
next (30 November: "must be ≤ 0.2928 mm", and 0.2928 mm then left the profile 0.27 mm in
the hub's clearance). The bounds a refusal states are rounded inward, so that typing one
as printed passes.
"""
from __future__ import annotations

from dataclasses import dataclass

from core.linkage.verdict import round_text
from .build import Room, pitch_max_radius
from .follower import Follower
from .laws import Program
from .synthesis import largest_roller

DIGITS = 4
"""Significant digits of a stated bound (more when the range is narrower than that)."""
TOLERANCE = 1e-12
"""Share of a bound by which a roller may pass it (the checks' rounding)."""


@dataclass(frozen=True)
class RollerRange:
    """The rollers a checked cam takes (mm): at least ``least_mm`` (the boss; ≤ 0: any),
    at most ``round_mm`` (the curvature) and ``hub_mm`` (the hub)."""

    least_mm: float
    round_mm: float
    hub_mm: float
    rho_mm: float
    hub_limit_mm: float
    """hub + clearance, the profile's least smallest radius."""
    boss_limit_mm: float
    """a − boss − clearance, the profile's greatest largest radius."""

    @property
    def most_mm(self) -> float:
        return min(self.round_mm, self.hub_mm)

    def takes(self, roller_mm: float) -> bool:
        return (roller_mm <= self.most_mm * (1.0 + TOLERANCE)
                and roller_mm >= self.least_mm - TOLERANCE * abs(self.least_mm))

    def stated(self) -> tuple[str, str] | None:
        """The least and the most as printed (rounded up and down), or None when the
        range is empty at 12 digits (or holds no positive roller)."""
        for digits in range(DIGITS, 13):
            most = round_text(self.most_mm, digits, down=True) if self.most_mm > 0.0 else None
            if most is None:
                return None
            least = round_text(self.least_mm, digits) if self.least_mm > 0.0 else "0"
            if float(least) <= float(most) and self.takes(float(least)) and self.takes(float(most)):
                return least, most
        return None


def roller_range(f: Follower, program: Program, rho_mm: float, room: Room) -> RollerRange:
    """The :class:`RollerRange` of the checked cam ``f`` with ρmin ``rho_mm``."""
    hub = room.hub_mm + room.clearance_mm
    boss = f.distance_mm - room.boss_mm - room.clearance_mm
    return RollerRange(least_mm=pitch_max_radius(f, program) - boss, round_mm=largest_roller(rho_mm),
                       hub_mm=f.base_radius_mm - hub, rho_mm=rho_mm, hub_limit_mm=hub, boss_limit_mm=boss)


def too_large_text(most: str, rho_mm: float) -> str:
    """The refusal of a roller the pitch curve's curvature bounds."""
    return (f"too large: must be ≤ {most} mm (r ≤ 0.8·ρmin and ρmin − r ≥ 3 mm); the pitch curve's "
            f"smallest convex radius ρmin is {rho_mm:.4g} mm, and a roller that large undercuts the "
            "profile or leaves it pointed")


def refusal_text(span: RollerRange, stated: tuple[str, str]) -> str:
    """Why a checked cam refuses a typed roller, with the range it takes (``stated``)."""
    least, most = stated
    if span.least_mm > 0.0:
        return (f"must be between {least} and {most} mm on this cam: at least {least} mm for the "
                f"profile's largest radius R1 − r to stay within a − boss − clearance = "
                f"{span.boss_limit_mm:.4g} mm, at most {most} mm for it to clear the hub and stay round "
                f"(ρmin = {span.rho_mm:.4g} mm)")
    if span.round_mm <= span.hub_mm:
        return too_large_text(most, span.rho_mm)
    return (f"too large for the hub: must be ≤ {most} mm, so that the profile's smallest radius r0 − r "
            f"stays ≥ hub + clearance = {span.hub_limit_mm:.4g} mm")


def no_roller_text(span: RollerRange) -> str:
    """Why a checked cam takes no roller at all (the advice is the caller's)."""
    if span.most_mm <= 0.0:
        return (f"this cam takes no roller: its pitch curve's smallest convex radius ρmin = "
                f"{span.rho_mm:.4g} mm and r0 − hub − clearance = {span.hub_mm:.4g} mm leave no room for one")
    return (f"this cam takes no roller: the hub and ρmin = {span.rho_mm:.4g} mm allow one of at most "
            f"{span.most_mm:.4g} mm, the pivot boss needs one of at least {span.least_mm:.4g} mm")
