"""One feed cam from the data sheet: synthesized (or checked), its roller chosen, timed.

:class:`CamInputs` is what the data sheet gives (and what a form or a file holds);
:func:`design_cam` turns it into a :class:`Cam`, whose figures are the extremes of each phase
(the rise and the return, where the pressure angle and the curvature change), solved on the
closed forms (``extremes``), not read off a grid.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from core.base.errors import DesignError, require_range
from core.linkage.verdict import round_text
from . import advice, advised
from .defaults import BOSS_MM, CLEARANCE_MM, HUB_MM, MAX_ARM_MM, MIN_ARM_MM, RETURN_PRESSURE_DEG
from .extremes import min_convex_radius, pressure_peaks
from .follower import Follower, check_follower
from .laws import Program
from .pending import PendingAdvice, check_stop
from .build import (MIN_ROLLER_MM, FitError, Room, pitch_max_radius, raised, require_buildable,
                    roller_for_hub, shortfalls)
from .roller_range import no_roller_text, refusal_text, roller_range, too_large_text
from .synthesis import Allowance, convex_radius_for, largest_roller, synthesize
from .timing import Timing, timing

MIN_PRESSURE_DEG, MAX_PRESSURE_DEG = 5.0, 85.0
"""Allowances, degrees: at a right angle the cam pushes across the arm and jams; below 5°
the cam would be many times the arm's size."""


@dataclass(frozen=True)
class CamInputs:
    """The data sheet: arm length l (mm), the program, the allowances (degrees), and
    optionally the roller (mm) and a base radius with its centre distance (mm) to check;
    and what the cam must clear (mm): the camshaft's hub, the follower pivot's boss and the
    least clearance between them and the profile (see :mod:`build`)."""

    arm_mm: float = 150.0
    program: Program = field(default_factory=Program)
    pressure_deg: float = 40.0
    return_pressure_deg: float = RETURN_PRESSURE_DEG
    roller_mm: float | None = None
    base_mm: float | None = None
    distance_mm: float | None = None
    hub_mm: float = HUB_MM
    boss_mm: float = BOSS_MM
    clearance_mm: float = CLEARANCE_MM

    def __post_init__(self) -> None:
        require_range("arm", self.arm_mm, MIN_ARM_MM, MAX_ARM_MM, "mm", low_open=False)
        for name in ("pressure", "return_pressure"):
            require_range(name, getattr(self, name + "_deg"), MIN_PRESSURE_DEG, MAX_PRESSURE_DEG, "°",
                          low_open=False, high_open=True)
        if self.roller_mm is not None:
            require_range("roller", self.roller_mm, 0.0, MAX_ARM_MM, "mm")
        if (self.base_mm is None) != (self.distance_mm is None):
            missing = "distance" if self.distance_mm is None else "base"
            raise DesignError(missing, None, "give --base and --distance together to check a cam")
        if self.base_mm is not None:
            require_range("base", self.base_mm, 0.0, MAX_ARM_MM * 4, "mm")
            require_range("distance", self.distance_mm, 0.0, MAX_ARM_MM * 4, "mm")
        for name in ("hub", "boss", "clearance"):
            require_range(name, getattr(self, name + "_mm"), 0.0, MAX_ARM_MM, "mm", low_open=False)

    @property
    def allowance(self) -> Allowance:
        return Allowance(self.pressure_deg, self.return_pressure_deg)

    @property
    def room(self) -> Room:
        return Room(self.hub_mm, self.boss_mm, self.clearance_mm)


@dataclass(frozen=True)
class Cam:
    """A cam and its figures (mm, degrees); ``timing`` is None without a linkage."""

    inputs: CamInputs
    follower: Follower
    roller_mm: float
    largest_roller_mm: float
    min_curvature_radius_mm: float        # smallest convex radius of the pitch curve
    max_pressure_rise_deg: float
    max_pressure_return_deg: float
    timing: Timing | None = None
    base_raised_from_mm: float | None = None
    """The smallest base radius for the allowances alone, when the synthesis raised it to
    clear the hub or the pivot boss (None: not raised)."""

    @property
    def program(self) -> Program:
        return self.inputs.program

    @property
    def base_radius_mm(self) -> float:
        return self.follower.base_radius_mm

    @property
    def profile_min_radius_mm(self) -> float:
        """The profile's smallest radius r0 − r (exact, see :mod:`build`)."""
        return self.follower.base_radius_mm - self.roller_mm

    @property
    def pitch_max_radius_mm(self) -> float:
        """The pitch curve's largest radius R1: the roller's centre at ψmax."""
        return pitch_max_radius(self.follower, self.program)

    @property
    def profile_max_radius_mm(self) -> float:
        """The profile's largest radius R1 − r (exact, see :mod:`build`)."""
        return self.pitch_max_radius_mm - self.roller_mm

    @property
    def within_allowance(self) -> bool:
        return (self.max_pressure_rise_deg <= self.inputs.pressure_deg + 1e-6
                and self.max_pressure_return_deg <= self.inputs.return_pressure_deg + 1e-6)


def figures(f: Follower, program: Program) -> tuple[float, float, float]:
    """Max pressure angle on the rise and on the return (°) and the pitch curve's smallest
    convex radius of curvature (mm; the dwells are arcs of radius ≥ the base radius), each
    solved, not sampled (``extremes``)."""
    peaks = pressure_peaks(f, program)
    return peaks.rise_deg, peaks.return_deg, min_convex_radius(f, program)


def checked_follower(inputs: CamInputs) -> Follower:
    """The follower of a given base radius and centre distance, on the side whose worst
    pressure angle (as a share of its allowance) is smaller."""
    a, r0, l = inputs.distance_mm, inputs.base_mm, inputs.arm_mm
    c = (a * a + l * l - r0 * r0) / (2.0 * a * l)
    if not abs(a - l) < r0 < a + l:         # on r0 itself: near an end c rounds to ±1
        raise DesignError("base", r0, f"must be between |a − l| = {round_text(abs(a - l), 4)} mm and "
                          f"a + l = {round_text(a + l, 4, down=True)} mm for the arm to reach the cam")
    psi0 = math.degrees(math.acos(min(max(c, -1.0), 1.0)))
    candidates = [Follower(l, a, psi0, s) for s in (-1, 1)]
    check_follower(candidates[0], inputs.program)

    def worst(f: Follower) -> float:
        peaks = pressure_peaks(f, inputs.program)
        return max(peaks.rise_deg / inputs.pressure_deg, peaks.return_deg / inputs.return_pressure_deg)
    return min(candidates, key=worst)


def design_cam(inputs: CamInputs, design=None, idle_fraction: float = 0.05,
               phase_deg: float | None = None, advice_later: bool = False) -> Cam:
    """Synthesize (or check) the cam, choose or check its roller, and time it against the
    linkage ``design`` when one is given.

    An automatic roller is never below MIN_ROLLER_MM: a synthesized cam too sharp for one
    is raised until it takes one (``_fitted``) or refused naming an arm that gives one
    (``_require_roller``), a checked cam refused. ``advice_later``: a refusal whose advice
    is a search of many designs raises :class:`~core.cam.pending.PendingAdvice` at once,
    whose ``seek()`` gives the refusal raised without it (the GUI, which must not wait)."""
    when = None if design is None else timing(inputs.program, design, idle_fraction, phase_deg)
    return replace(_solved(inputs, LATER if advice_later else NOW), timing=when)


NOW, LATER, NEVER = "now", "later", "never"
"""How a refusal's advice is found: searched before it is raised; left to
``PendingAdvice.seek`` (a search of many designs only: a checked cam's hub or boss, a few
tens of ms, is searched at once); or not at all, for a probe of a search, whose refusal
no one reads (:func:`_probe`)."""


def _solved(inputs: CamInputs, advise: str) -> Cam:
    """:func:`design_cam` without the timing; ``advise`` NOW, LATER or NEVER."""
    try:
        return _designed(inputs, advise)
    except PendingAdvice:
        raise
    except (RollerError, FitError) as exc:
        if advise != NEVER and inputs.base_mm is not None and exc.allowed.startswith(ROOM_REFUSALS):
            raise advised.checked_advice(_probe, inputs, exc) from None
        if advise != NEVER and inputs.roller_mm is None and inputs.base_mm is None and \
                exc.allowed.startswith(SYNTHESIZED_ROOM_REFUSALS):
            raise (_pending(inputs, exc, exc.allowed, "swing") if advise == LATER
                   else advised.swing_advice(_probe, inputs, exc)) from None
        if advise == NEVER or inputs.roller_mm is None or inputs.base_mm is not None:
            raise
        raise (_pending(inputs, exc, ROLLER_STATEMENT.format(inputs.roller_mm), "roller") if advise == LATER
               else advised.typed_advice(_probe, inputs)) from None
    except DesignError as exc:
        if advise == NEVER or exc.parameter != "pressure" or inputs.base_mm is not None:
            raise
        raise (_pending(inputs, exc, exc.allowed, "allowance") if advise == LATER
               else advised.allowance_advice(_probe, inputs, exc, MAX_PRESSURE_DEG)) from None


ROLLER_STATEMENT = "no whole cam takes a roller of {:.4g} mm with these inputs"
"""A typed roller's refusal while its advice is searched (the curvature's bound the first
refusal states need not hold: see ``advice``)."""


def _pending(inputs: CamInputs, refusal: DesignError, statement: str, seeking: str) -> PendingAdvice:
    """``refusal`` said as ``statement``, its advice left to a search (``pending.SEEKING``)
    that designs ``inputs`` as :func:`design_cam` does."""
    def find() -> DesignError:
        try:
            _solved(inputs, NOW)
        except DesignError as exc:
            return exc
        raise AssertionError(f"{inputs} refused, then designed")     # the same code, the same inputs
    return PendingAdvice(refusal, statement, seeking, find)


ROOM_REFUSALS = ("the profile's smallest radius r0 − r = ", "the profile's largest radius ")
"""How ``build.require_buildable``'s refusals of a checked cam begin: the hub (its base
radius named) and the pivot boss (its centre distance)."""


SYNTHESIZED_ROOM_REFUSALS = ("no cam within the allowances clears the pivot boss;", ROOM_REFUSALS[0])
"""How ``build.require_buildable``'s refusals of a synthesized cam begin: no raise clears the
pivot boss (the swing named), or the hub while the smallest cam clears the boss (the hub)."""


def _probe(inputs: CamInputs) -> Cam:
    """A whole design, refused without advice: what ``advice``'s searches try (each asks
    first whether its search is to stop, ``pending.check_stop``)."""
    check_stop()
    return _solved(inputs, NEVER)


def _designed(inputs: CamInputs, advise: str) -> Cam:
    synthesized, typed = inputs.base_mm is None, inputs.roller_mm is not None
    if synthesized:
        f = synthesize(inputs.arm_mm, inputs.program, inputs.allowance)
    else:
        f = checked_follower(inputs)
    smallest = f
    up, back, rho = figures(f, inputs.program)
    if typed and not synthesized:
        biggest, roller = largest_roller(rho), inputs.roller_mm
        _require_typed_fits(inputs, f, rho, advise)
    elif typed:
        biggest, roller = largest_roller(rho), inputs.roller_mm
        _check_roller(roller, biggest, rho)
    else:
        biggest = largest_roller(rho)
        roller = max(biggest, MIN_ROLLER_MM) if synthesized else roller_for_hub(biggest, f, inputs.room)
    if synthesized and (roller > biggest or max(shortfalls(f, inputs.program, roller, inputs.room).values()) > 0.0):
        f, roller, (up, back, rho, biggest) = _fitted(inputs, f, roller)
    if not typed:
        _require_roller(inputs, smallest, roller, biggest, rho, advise)
    require_buildable(f, inputs.program, roller, inputs.room, checked=not synthesized)
    raised_from = smallest.base_radius_mm if f.base_radius_mm > smallest.base_radius_mm else None
    return Cam(inputs, f, roller, biggest, rho, up, back, None, raised_from)


class RollerError(DesignError):
    """A synthesized cam refusing its typed roller for its curvature: :func:`_typed_advice`
    says instead what works (as for a FitError, a raise that found no room for it)."""


def _check_roller(roller: float, biggest: float, rho: float) -> None:
    """A synthesized cam's typed roller, against its curvature (the raise sees to the hub
    and the boss); the bound stated rounded down, so that typing it passes."""
    if roller > biggest * (1.0 + 1e-12):
        raise RollerError("roller", roller, too_large_text(f"{biggest:.4g}", rho))


def _require_typed_fits(inputs: CamInputs, f: Follower, rho: float, advise: str) -> None:
    """A checked cam's typed roller against all three of its bounds at once (see
    :mod:`roller_range`): refused naming the range it takes, or, if it takes none, the base
    radius with what leaving the cam to the synthesis gives."""
    span = roller_range(f, inputs.program, rho, inputs.room)
    if span.takes(inputs.roller_mm):
        return
    stated = span.stated()
    if stated is not None:
        raise DesignError("roller", inputs.roller_mm, refusal_text(span, stated))
    raise _left_to_synthesis(inputs, no_roller_text(span), advise)


def _left_to_synthesis(inputs: CamInputs, statement: str, advise: str) -> DesignError:
    """A checked cam that takes no roller, refused naming its base radius: ``statement``,
    then (NOW) :func:`_synthesis_advice`; LATER, pending; NEVER, the statement alone."""
    refusal = FitError("base", inputs.base_mm, statement)
    if advise == NEVER:
        return refusal
    if advise == LATER:
        return _pending(inputs, refusal, statement, "synthesis")
    return FitError("base", inputs.base_mm, f"{statement}; {advised.synthesis_advice(_probe, inputs)}")


FIT_ROUNDS = 4
"""Raises tried while the automatic roller of the raised cam comes out smaller."""
SCREEN_MARGIN = 1e-3
"""How much rounder than a roller needs (share of ρmin) the raise screens centres for, past
the grid's error (at most 6e-4, see ``build.CURVATURE_SAMPLES``); ten times more on each
try whose polished radius still falls short."""


def _fitted(inputs: CamInputs, f: Follower, roller: float
            ) -> tuple[Follower, float, tuple[float, float, float, float]]:
    """The synthesized cam raised to clear the hub and the pivot boss with this roller, and
    to take it (an automatic roller of MIN_ROLLER_MM, which the smallest cam's pitch curve
    may be too sharp for: centres are then screened for its ρmin).

    An automatic roller is never made larger than the one the raise assumed (a larger one
    would eat the hub's clearance again); when the raised cam's largest roller is smaller,
    the raise is redone with it, down to MIN_ROLLER_MM. When no raise fits, the smallest cam
    comes back as it was (``_require_roller`` and require_buildable then say why)."""
    fixed = inputs.roller_mm is not None
    least, best, margin = f.base_radius_mm, None, SCREEN_MARGIN
    for _ in range(FIT_ROUNDS):
        need = None if fixed or roller > MIN_ROLLER_MM else convex_radius_for(roller) * (1.0 + margin)
        g = raised(inputs.arm_mm, inputs.program, inputs.allowance, roller, inputs.room, least, need)
        if g is None:
            break
        up, back, rho = figures(g, inputs.program)
        biggest = largest_roller(rho)
        if fixed:
            _check_roller(roller, biggest, rho)
        fits = biggest >= roller * (1.0 - 1e-12)
        best = (g, roller if fits or fixed else biggest, (up, back, rho, biggest))
        if fits or fixed:
            break
        if need is not None:
            margin *= 10.0
        roller = max(biggest, MIN_ROLLER_MM)
    if best is None:
        up, back, rho = figures(f, inputs.program)
        return f, roller, (up, back, rho, largest_roller(rho))
    return best


def _require_roller(inputs: CamInputs, smallest: Follower, roller: float, biggest: float,
                    rho: float, advise: str) -> None:
    """FitError when the automatic roller is below MIN_ROLLER_MM or more than the cam takes:
    for a checked cam naming its base radius, for a synthesized one an arm that gives one
    (``advice.arm_for_roller``, when ``advise`` is NOW; LATER, pending)."""
    if MIN_ROLLER_MM * (1.0 - 1e-12) <= roller <= biggest * (1.0 + 1e-12):
        return
    need = convex_radius_for(MIN_ROLLER_MM)
    if inputs.base_mm is not None:
        raise _left_to_synthesis(inputs, f"the pitch curve's smallest convex radius ρmin = {rho:.4g} mm takes "
                                 f"no roller of {MIN_ROLLER_MM:g} mm or more (that needs ρmin ≥ {need:g} mm)",
                                 advise)
    none = (f"no cam within the allowances takes a roller of {MIN_ROLLER_MM:g} mm or more and clears "
            "the hub and the pivot boss")
    if advise == LATER:
        raise _pending(inputs, FitError("arm", inputs.arm_mm, none), none, "arm")
    arm = advice.arm_for_roller(_probe, inputs, smallest) if advise == NOW else inputs.arm_mm
    if arm is None:             # no arm does: the smallest cam's path runs past the pivot boss
        require_buildable(smallest, inputs.program, MIN_ROLLER_MM, inputs.room, checked=False)
        raise FitError("swing", inputs.program.swing_deg, f"{none}, with any arm up to {MAX_ARM_MM:g} mm")
    raise FitError("arm", inputs.arm_mm, f"{none}; an arm of {arm:.1f} mm gives one")
