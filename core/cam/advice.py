"""The values a cam's refusal names, each one designed before it is named.

Why designed and not read off one cam: the conditions a cam meets (the allowances, the
pitch curve's curvature, the hub, the pivot boss) interact through the synthesis's raise, so
a bound read off the refused cam need not hold for the cam its value gives (30 November: a
typed roller refused "must be ≤ 12.74 mm", and 12.74 mm then raised the cam to one that took
only 12.01 mm). Each search here calls ``design`` (a whole design that raises DesignError
when refused) on the values it tries, and names only one that passed.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Callable

from core.base.errors import DesignError
from core.linkage.verdict import round_text
from .build import MIN_ROLLER_MM, pitch_max_radius
from .defaults import MAX_ARM_MM
from .extremes import min_convex_radius
from .follower import Follower
from .laws import MIN_SWING_DEG
from .synthesis import largest_roller

ARM_STEP_MM = 0.1
"""The resolution of the arm a refusal names."""
ALLOWANCE_STEP_DEG = 0.1
"""The resolution of an allowed pressure angle a refusal names."""
ROLLER_DIGITS = 4
"""Significant digits of a roller a refusal names (rounded down, and designed so)."""
CHECKED_STEP_MM = 0.01
"""The resolution of a checked cam's base radius or centre distance a refusal names."""
CHECKED_GROWTH = 1.25
"""Successive values tried, each this times the last, until the checked cam designs."""
SWING_STEP_DEG = 0.1
"""The resolution of the swing a refusal names."""
ROLLER_HALVINGS = 12
"""Bisection steps for the largest typed roller that works (a share 2⁻¹² ≈ 2.4e-4 of it)."""

Design = Callable[[object], object]
"""A whole design of cam inputs (``cam._solved`` without its own advice): raises DesignError."""


def works(design: Design, inputs) -> bool:
    """Whether ``inputs`` give a cam."""
    try:
        design(inputs)
    except DesignError:
        return False
    return True


def least_on_grid(fine: Callable[[float], bool], lo: float, hi: float, step: float) -> float:
    """A multiple of ``step`` in (lo, hi] that is ``fine``, found by bisection between ``lo``
    (not fine) and ``hi`` (fine): the least if the fine values are an interval; a smaller
    one is not known to fail otherwise."""
    while hi - lo > step * (1.0 + 1e-9):
        mid = float(f"{math.ceil(0.5 * (lo + hi) / step - 1e-9) * step:.10g}")    # as it prints
        if mid >= hi:       # the midpoint rounds up to hi: the grid value below hi, if above lo
            mid = float(f"{(round(hi / step) - 1) * step:.10g}")      # (r0 18.4934 -> 18.50, not 18.51)
            if mid <= lo:
                break
        lo, hi = (lo, mid) if fine(mid) else (mid, hi)
    return hi


def shortest_arm(design: Design, inputs, top: float) -> float:
    """A multiple of ARM_STEP_MM between the arm of ``inputs`` (refused) and ``top`` (which
    works) whose cam works (:func:`least_on_grid`)."""
    return least_on_grid(lambda arm: works(design, replace(inputs, arm_mm=arm)), inputs.arm_mm, top,
                         ARM_STEP_MM)


def least_allowance(design: Design, inputs, names: tuple[str, ...], most_deg: float) -> float | None:
    """The least allowed pressure angle, set for each of ``names`` (``pressure_deg``,
    ``return_pressure_deg``), a multiple of ALLOWANCE_STEP_DEG below ``most_deg``, with which
    ``inputs`` design; None if the largest does not. Why designs and not the synthesis
    alone: a larger allowance gives a smaller, sharper cam, which the roller's least size
    or the room may then refuse."""
    def fine(deg: float) -> bool:
        return works(design, replace(inputs, **{name: deg for name in names}))
    top = top_allowance(most_deg)
    if not fine(top):
        return None
    return least_on_grid(fine, max(getattr(inputs, name) for name in names), top, ALLOWANCE_STEP_DEG)


def top_allowance(most_deg: float) -> float:
    """The largest allowance a refusal may name: the multiple of ALLOWANCE_STEP_DEG below ``most_deg``."""
    return float(f"{math.floor(most_deg / ALLOWANCE_STEP_DEG - 1e-9) * ALLOWANCE_STEP_DEG:.10g}")


def arm_for_roller(design: Design, inputs, smallest: Follower) -> float | None:
    """An arm whose cam takes an automatic roller of at least MIN_ROLLER_MM, between this
    arm and one whose smallest cam does (:func:`scaled_arm`); None if none up to MAX_ARM_MM
    does.

    Why a search of real designs: the scaled smallest cam fits everything from some arm on,
    but a raised cam of a much shorter arm often does too (a 21.25 mm arm whose smallest cam
    fits from 80.2 mm gave one from 32.3 mm)."""
    top = scaled_arm(inputs, smallest)
    if top is None or not works(design, replace(inputs, arm_mm=top)):
        return None
    return shortest_arm(design, inputs, top)


def longer_arm(design: Design, inputs) -> float | None:
    """An arm whose cam works where that of ``inputs`` is refused (a typed roller too large
    for it, a pivot boss it cannot clear): the first of arms doubling from this one that
    works, then :func:`shortest_arm` below it; None if none up to MAX_ARM_MM does. (The
    smallest cam scales with the arm, the roller, the hub and the boss do not: a longer
    arm's pitch curve is rounder and its cam reaches farther from the boss.)"""
    top = inputs.arm_mm
    while top < MAX_ARM_MM:
        top = min(2.0 * top, MAX_ARM_MM)
        top = float(f"{math.ceil(top / ARM_STEP_MM - 1e-9) * ARM_STEP_MM:.10g}")
        if top <= MAX_ARM_MM and works(design, replace(inputs, arm_mm=top)):
            return shortest_arm(design, inputs, top)
    return None


def largest_swing(design: Design, inputs) -> float | None:
    """The largest swing ψmax below the refused one of ``inputs``, a multiple of
    SWING_STEP_DEG, with which the cam designs: :func:`least_on_grid` on the negated swing
    between the refused one and MIN_SWING_DEG; None if MIN_SWING_DEG does not design.

    Why designs and not a closed form: a smaller swing shrinks the smallest cam and its R1
    together, and the raise that clears the hub and the boss finds other centres; the
    swings that work were an interval from MIN_SWING_DEG up in every refused cam tried
    (25 random ones, every 0.5°), which the bisection assumes."""
    def fine(swing: float) -> bool:
        return works(design, replace(inputs, program=replace(inputs.program, swing_deg=swing)))
    if not fine(MIN_SWING_DEG):
        return None
    return -least_on_grid(lambda negated: fine(-negated), -inputs.program.swing_deg, -MIN_SWING_DEG,
                          SWING_STEP_DEG)


SWING_SCAN_DEG = 1.0
"""The steps of :func:`swing_below`'s scan down from the refused swing."""


def swing_below(design: Design, inputs) -> float | None:
    """A swing below the refused one of ``inputs``, a multiple of SWING_STEP_DEG, with which
    the cam designs: the first of the swings SWING_SCAN_DEG apart down from the refused one
    that does, then the largest to SWING_STEP_DEG between it and the last that did not
    (:func:`least_on_grid` on the negated swing); None if none down to MIN_SWING_DEG does.

    Why a scan and not :func:`largest_swing`'s bisection from MIN_SWING_DEG: with a typed
    roller the swings that work need not reach down to it (a smaller swing gives a smaller,
    sharper cam, which the roller undercuts): for a cam of arm 97.3 mm refused for its
    12.75 mm roller at 58.4° with any arm, they were 32°–46°."""
    def fine(swing: float) -> bool:
        return works(design, replace(inputs, program=replace(inputs.program, swing_deg=swing)))
    failed = inputs.program.swing_deg
    swing = float(f"{math.ceil(failed / SWING_SCAN_DEG - 1.0 - 1e-9) * SWING_SCAN_DEG:.10g}")
    while swing >= MIN_SWING_DEG:
        if fine(swing):
            return -least_on_grid(lambda negated: fine(-negated), -failed, -swing, SWING_STEP_DEG)
        failed, swing = swing, float(f"{swing - SWING_SCAN_DEG:.10g}")
    return None


def largest_typed_roller(design: Design, inputs, bound_mm: float) -> str | None:
    """The largest roller (as printed, ROLLER_DIGITS significant digits rounded down) up to
    ``bound_mm`` with which ``inputs`` give a cam, by halving and then bisection; None if
    none down to 1e-3 of the bound does."""
    def fine(text: str) -> bool:
        return works(design, replace(inputs, roller_mm=float(text)))
    top = round_text(bound_mm, ROLLER_DIGITS, down=True)
    if fine(top):
        return top
    hi, lo = bound_mm, 0.5 * bound_mm
    while not works(design, replace(inputs, roller_mm=lo)):
        hi, lo = lo, 0.5 * lo
        if lo < 1e-3 * bound_mm:
            return None
    for _ in range(ROLLER_HALVINGS):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if works(design, replace(inputs, roller_mm=mid)) else (lo, mid)
    text = round_text(lo, ROLLER_DIGITS, down=True)
    return text if fine(text) else repr(lo)


def scaled_arm(inputs, smallest: Follower) -> float | None:
    """The shortest arm (mm, rounded up to ARM_STEP_MM) whose smallest cam takes its largest
    roller, at least MIN_ROLLER_MM, and with it clears the hub and the pivot boss; None if
    no arm up to MAX_ARM_MM does.

    Why a closed form and not a search: the pressure-angle conditions do not change with
    the scale, so the smallest cam of an arm s times as long is this one scaled by s (its
    base radius, centre distance, R1 and ρmin all s times theirs), while the roller's least
    size, the hub, the boss and the clearance stay; each condition then holds from some s
    on, and the least s for all is found by bisection on these few numbers."""
    rho = min_convex_radius(smallest, inputs.program)
    r0, a, r1 = smallest.base_radius_mm, smallest.distance_mm, pitch_max_radius(smallest, inputs.program)
    room = inputs.room

    def fits(s: float) -> bool:
        r = largest_roller(rho * s)
        return (r >= MIN_ROLLER_MM and r0 * s - r >= room.hub_mm + room.clearance_mm
                and r1 * s - r <= a * s - room.boss_mm - room.clearance_mm)
    lo, hi = 1.0, MAX_ARM_MM / inputs.arm_mm
    if not fits(hi):
        return None
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if fits(mid) else (mid, hi)
    arm = math.ceil(inputs.arm_mm * hi * (1.0 + 1e-9) / ARM_STEP_MM) * ARM_STEP_MM
    return arm if fits(arm / inputs.arm_mm) and arm <= MAX_ARM_MM else None


def least_checked(design: Design, inputs, field: str, most: float) -> float | None:
    """The least ``field`` (``base_mm`` or ``distance_mm``) above the refused one, a multiple
    of CHECKED_STEP_MM up to ``most``, with which the checked cam of ``inputs`` designs: values
    growing by CHECKED_GROWTH until one does, then :func:`least_on_grid` between it and the
    last that did not; None if none up to ``most`` does.

    Why the whole design and not the shortfall added: a larger r0 (or a) at the same a (or
    r0) turns the arm's start ψ0, so R1, the curvature and the automatic roller all change."""
    lo = getattr(inputs, field)

    def fine(value: float) -> bool:
        return works(design, replace(inputs, **{field: value}))
    hi = lo
    while hi < most:
        hi = min(float(f"{math.ceil(hi * CHECKED_GROWTH / CHECKED_STEP_MM - 1e-9) * CHECKED_STEP_MM:.10g}"), most)
        if fine(hi):
            return least_on_grid(fine, lo, hi, CHECKED_STEP_MM)
        lo = hi
    return None
