"""How far to go along an advised change: the value of the input to type at which a failing
check passes, the least one, and printed so that typing it passes.

Why a search of designed pairs and not the margin's derivative (``advice``): the derivative
gives the direction, but the margins are far from linear over a useful step (a′ moves α′, Δy
and both tips at once), and a step may run into a refusal (a pointed tip, a split that
undercuts) before the check passes. Along one change, the pair typed as a user types it is
designed (``design``: ``pair.design_pair``, passed in so that ``pair`` may ask for amounts
too) and the check's sign bracketed: steps growing by GROWTH from STEP_START until it passes, then
bisection between the last that fails and the first that passes, to BISECT_TOLERANCE of the
change. The printed value is rounded away from the start (enough decimals that the rounding
adds at most PRINT_SHARE of the change) and designed again before it is named.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from typing import Callable

from core.base.errors import DesignError
from .inputs import GearPairInputs, MAX_SHIFT, MAX_TEETH
from .margins import GearPair, check_margins


STEP_START = 1e-3
"""The first step tried, in shift factor (for a′: times m, mm)."""
GROWTH = 1.25
"""Each step tried is this times the last, until one passes: a window where the check passes
before a refusal begins (a 6-tooth pinion's x1 from 0.29 down to −0.22, then x1 + x2 too
negative) is narrower than the doubling that skipped it (steps 1.024 to 2.048)."""
STEP_MOST = 2.0 * MAX_SHIFT
"""The largest step tried, in shift factor (for a′: times m, mm, or a′ itself if more, so
that a′ may go down to a cos α): beyond it the shifts leave their range."""
EDGE_HALVINGS = 50
"""Halvings that find where a refusal begins along a change (to 2⁻⁵⁰ of the bracket)."""
BISECT_TOLERANCE = 1e-8
"""The bracket is closed to this share of the change: well inside the last printed decimal
(PRINT_SHARE), so that the printed value is the first beyond the least change."""
PRINT_SHARE = 2e-3
"""The rounding of a printed value adds at most this share of the change, so that 1 % less
of the printed change fails again."""
LEAST_DECIMALS, MOST_DECIMALS = 4, 12
"""Decimals of a printed shift factor or a′ (mm): 4 as every bound of the gear, more for a
small change."""
BUMPS = 3
"""Further steps of the last decimal tried when the rounded value does not pass."""

Design = Callable[[GearPairInputs], GearPair]
"""A whole design of a pair's inputs (``pair.design_pair``): raises DesignError when refused."""


@dataclass(frozen=True)
class Start:
    """Where a change starts: the pair's inputs and the shifts and a′ it had (x1, x2, mm)."""
    inputs: GearPairInputs
    x1: float
    x2: float
    centre_mm: float


def start_of(pair: GearPair) -> Start:
    """The :class:`Start` of a designed pair."""
    return Start(pair.inputs, pair.gear1.shift, pair.gear2.shift, pair.centre_mm)


def unit(start: Start, name: str) -> float:
    """A unit of change ``name`` in the typed input's own unit: 1 of x, m mm of a′."""
    return start.inputs.module_mm if name == "centre" else 1.0


def typed(start: Start, name: str, step: float) -> GearPairInputs:
    """The inputs a user types after ``step`` of change ``name`` (``advice.MOVES``' names,
    signed): x1 or x2 alone (both typed), x1 + step and x2 − step (both typed), or a′ (mm,
    typed, the rule sharing it out)."""
    p = start.inputs
    if name == "x1":
        return replace(p, x1=start.x1 + step, x2=start.x2, centre_mm=None)
    if name == "x2":
        return replace(p, x1=start.x1, x2=start.x2 + step, centre_mm=None)
    if name == "transfer":
        return replace(p, x1=start.x1 + step, x2=start.x2 - step, centre_mm=None)
    return replace(p, x1=None, x2=None, centre_mm=start.centre_mm + step)


def passing(design: Design, inputs: GearPairInputs, check: str) -> GearPair | None:
    """The pair of ``inputs`` when it is designed and ``check`` passes, else None."""
    try:
        pair = design(inputs)
    except DesignError:
        return None
    return pair if check_margins(pair)[check].ok else None


def least_step(design: Design, start: Start, check: str, name: str, sign: int) -> float | None:
    """The least step (> 0, in the typed input's unit) of change ``name`` in direction
    ``sign`` at which ``check`` passes, to BISECT_TOLERANCE; None if none up to STEP_MOST.

    Where the state changes between two steps (failing to refused, one refusal to another,
    refused to failing), both edges of the change are found (EDGE_HALVINGS) and the step just
    past each tried: the check may pass only in a narrow window there (a′ of a 10/5 pair
    between where the split undercuts and where gear 2's tip comes to a point, 1 % wide).
    A window narrower than a step inside one state is not seen (a′ of a 24/7 pair at m = 1
    from 15.997 to 16.049 mm, gear 2 pointed on both sides): the refusal then says what it
    found, no value (``pair._pointed``)."""
    scale = unit(start, name)
    most = max(STEP_MOST * scale, start.centre_mm if name == "centre" else 0.0)     # a′ down to a cos α

    def state(step: float) -> str:
        try:
            pair = design(typed(start, name, sign * step))
        except DesignError as exc:
            return f"refused: {exc.parameter} {re.sub(r'[-+0-9.]+', '#', exc.allowed)}"     # its kind
        return PASSES if check_margins(pair)[check].ok else "fails"
    lo, hi, last = 0.0, STEP_START * scale, state(0.0)
    while (now := state(hi)) != PASSES:
        if now != last:
            found = _window(state, lo, hi, last, now)
            if found is not None:
                lo, hi = found
                break
        if hi >= most:
            return None
        lo, hi, last = hi, min(GROWTH * hi, most), now
    while hi - lo > BISECT_TOLERANCE * hi:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if state(mid) == PASSES else (mid, hi)
    return hi


PASSES = "passes"


def _window(state: Callable[[float], str], lo: float, hi: float, first: str,
            second: str) -> tuple[float, float] | None:
    """Between ``lo`` (state ``first``) and ``hi`` (``second``): a bracket (fails, passes) at
    the edge of either state, or None when the step just past both edges fails too."""
    a, b = _edge(state, lo, hi, first)          # the end of ``first``
    if state(b) == PASSES:
        return a, b
    c, d = _edge(state, lo, hi, second, at_low=False)      # the start of ``second``
    if state(c) == PASSES:
        return a, c
    return None


def _edge(state: Callable[[float], str], lo: float, hi: float, kind: str,
          at_low: bool = True) -> tuple[float, float]:
    """(last, first): the edge of the steps of state ``kind`` at ``lo`` (``at_low``) or at
    ``hi``, found by EDGE_HALVINGS halvings; ``last`` and ``first`` straddle it."""
    for _ in range(EDGE_HALVINGS):
        mid = 0.5 * (lo + hi)
        if (state(mid) == kind) == at_low:
            lo = mid
        else:
            hi = mid
    return lo, hi


def decimals(step: float) -> int:
    """Decimals that round a value by at most PRINT_SHARE of ``step``."""
    need = math.ceil(-math.log10(PRINT_SHARE * step)) if step > 0.0 else MOST_DECIMALS
    return min(max(LEAST_DECIMALS, need), MOST_DECIMALS)


def rounded(value: float, digits: int, up: bool, bump: int = 0) -> float:
    """``value`` rounded up (or down) to ``digits`` decimals, ``bump`` units further."""
    scale = 10.0 ** digits
    units = math.ceil(value * scale - 1e-6) if up else math.floor(value * scale + 1e-6)
    units += bump if up else -bump
    return units / scale


def printed(design: Design, start: Start, check: str, name: str, sign: int,
            step: float) -> tuple[tuple[str, ...], GearPair] | None:
    """The values to type (as text) for a step of ``step`` of change ``name``, rounded away
    from the start, and the pair they give; the rounding is stepped on (BUMPS) while the
    check fails there. x1 or x2: its value; a′: its value, mm; a transfer: x1 and x2 (x2
    keeping x1 + x2 to the decimals printed). None if no rounding passes."""
    digits = decimals(step)
    for bump in range(BUMPS + 1):
        if name == "transfer":
            x1 = rounded(start.x1 + sign * step, digits, sign > 0, bump)
            x2 = round(start.x2 - (x1 - start.x1), digits)
            values, inputs = (x1, x2), replace(start.inputs, x1=x1, x2=x2, centre_mm=None)
        else:
            field = {"x1": "x1", "x2": "x2", "centre": "centre_mm"}[name]
            value = rounded(getattr(start, field) + sign * step, digits, sign > 0, bump)
            values, inputs = (value,), replace(typed(start, name, 0.0), **{field: value})     # as printed
        pair = passing(design, inputs, check)
        if pair is not None:
            return tuple(f"{v + 0.0:.{digits}f}" for v in values), pair     # no "-0.0000"
    return None


def least_teeth(design: Design, inputs: GearPairInputs, k: int, check: str) -> int | None:
    """The fewest teeth z_k (more than now) with which ``inputs`` design and ``check`` passes,
    by doubling and then bisection on whole numbers; None if none up to MAX_TEETH does."""
    name = f"z{k}"

    def fine(z: int) -> bool:
        return passing(design, replace(inputs, **{name: z}), check) is not None
    lo = int(getattr(inputs, name))
    hi = lo + 1
    while not fine(hi):
        if hi >= MAX_TEETH:
            return None
        lo, hi = hi, min(2 * hi, MAX_TEETH)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (lo, mid) if fine(mid) else (mid, hi)
    return hi


def tip_bound(design: Design, start: Start, k: int, name: str) -> str | None:
    """The value to type of ``name`` (x1, x2 or a′, lowered) at which gear k's tip, pointed
    at ``start``, is at least the least tip thickness; None if no value in range is."""
    check = f"tip{k}"
    step = least_step(design, start, check, name, -1)
    done = None if step is None else printed(design, start, check, name, -1, step)
    return None if done is None else done[0][0]
