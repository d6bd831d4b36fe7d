"""What a refused cam says, with the value it names: the sentences of the refusals whose
advice is a search (``advice``), each value designed before it is named.

Why apart from ``cam``: each takes the whole design it probes (``probe``, ``cam._probe``)
as an argument, as ``advice``'s searches do, so that ``cam`` only decides which refusal
gets which advice, and when (``cam.NOW``; ``cam.LATER`` leaves it to
``pending.PendingAdvice.seek``, which runs the same functions).
"""
from __future__ import annotations

from dataclasses import replace

from core.base.errors import DesignError
from .advice import (Design, arm_for_roller, largest_swing, largest_typed_roller, least_allowance,
                     least_checked, longer_arm, swing_below, top_allowance)
from .build import MIN_ROLLER_MM, FitError
from .defaults import MAX_ARM_MM
from .extremes import min_convex_radius
from .laws import MIN_SWING_DEG
from .roller_range import too_large_text
from .synthesis import largest_roller, synthesize


def allowance_advice(probe: Design, inputs, error: DesignError, most_deg: float) -> DesignError:
    """An allowance too small for any cam within reach: the least rise allowance that gives
    a whole cam, else the least return allowance (the rise's kept), else the least for
    both, each designed (``advice.least_allowance``) below ``most_deg``; else, when even the
    largest allowance is refused (by the hub or the pivot boss: 36 of 791 random sheets), a
    smaller swing that gives one at these allowances (``advice.swing_below``); else the
    fields left to change."""
    for names, what in ((("pressure_deg",), "an allowance of {}° gives one"),
                        (("return_pressure_deg",), "a return allowance of {}° gives one"),
                        (("pressure_deg", "return_pressure_deg"), "{}° on the rise and the return give one")):
        least = least_allowance(probe, inputs, names, most_deg)
        if least is not None:
            name = names[0] if len(names) == 1 else "pressure_deg"
            return DesignError(name.removesuffix("_deg"), getattr(inputs, name),
                               f"{error.allowed}; {what.format(f'{least:.1f}')}")
    top = f"{top_allowance(most_deg):g}"
    swing = swing_below(probe, inputs)
    if swing is not None:
        return DesignError(error.parameter, error.value,       # its statement is the allowance's
                           f"{error.allowed}; a swing of {swing:.1f}° gives one (no allowance up to {top}° does)")
    return DesignError(error.parameter, error.value,
                       f"{error.allowed}; no allowance up to {top}° gives one, nor a smaller swing: change the "
                       "arm, the program, the hub, the pivot boss or the clearance")


def checked_advice(probe: Design, inputs, error: DesignError) -> DesignError:
    """A checked cam that does not clear its hub (or the pivot boss), with the least base
    radius (centre distance) at the same centre distance (base radius) that gives a whole
    cam, designed (``advice.least_checked``); else the refusal as it was."""
    field, what = (("base_mm", "a base radius") if error.parameter == "base"
                   else ("distance_mm", "a centre distance"))
    most = inputs.distance_mm + inputs.arm_mm if field == "base_mm" else 4.0 * MAX_ARM_MM
    least = least_checked(probe, inputs, field, most)
    if least is None:
        return error
    return FitError(error.parameter, error.value, f"{error.allowed}; {what} of {least:.2f} mm gives one")


def swing_advice(probe: Design, inputs, error: DesignError) -> DesignError:
    """A synthesized cam that no raise clears of the pivot boss (or the hub), with the largest
    swing that gives a whole cam (``advice.largest_swing``), else, when even the least swing
    does not, the shortest arm that does (``advice.longer_arm``), each designed; else the
    refusal as it was. The swing first: the refusal names it, and it is the input that
    pushes the roller's outer position toward the pivot."""
    swing = largest_swing(probe, inputs)
    if swing is not None:
        return FitError("swing", inputs.program.swing_deg, f"{error.allowed}; a swing of {swing:.1f}° gives one")
    arm = longer_arm(probe, inputs)
    if arm is None:
        return error
    return FitError("arm", inputs.arm_mm, f"{error.allowed}; an arm of {arm:.1f} mm gives one "
                    f"(no swing down to {MIN_SWING_DEG:g}° does)")


def typed_advice(probe: Design, inputs) -> DesignError:
    """What to change when a synthesized cam refuses its typed roller, the first of these
    that designs: a smaller roller (the largest that works), a blank one (the automatic
    choice raises the base radius for one), a longer arm; each value designed before it is
    named (``advice``)."""
    f = synthesize(inputs.arm_mm, inputs.program, inputs.allowance)
    rho = min_convex_radius(f, inputs.program)
    if largest_roller(rho) >= MIN_ROLLER_MM:
        most = largest_typed_roller(probe, inputs, largest_roller(rho))
        if most is not None:
            taken = probe(replace(inputs, roller_mm=float(most)))
            return DesignError("roller", inputs.roller_mm, too_large_text(most, taken.min_curvature_radius_mm))
    try:
        cam = probe(replace(inputs, roller_mm=None))
    except DesignError:
        cam = None
    blank = None if cam is None else \
        f"left blank, the roller is {cam.roller_mm:.4g} mm on a base radius raised to {cam.base_radius_mm:.4g} mm"
    if blank is not None and largest_roller(rho) < MIN_ROLLER_MM:
        return DesignError("roller", inputs.roller_mm,
                           f"the smallest cam for the allowances takes no roller of {MIN_ROLLER_MM:g} mm or "
                           f"more (ρmin = {rho:.4g} mm); {blank}")
    if blank is not None:
        return DesignError("roller", inputs.roller_mm, "no roller up to the smallest cam's largest gives a cam "
                           f"within the allowances that clears the hub and the pivot boss; {blank}")
    none = f"no cam within the allowances takes a roller of {inputs.roller_mm:.4g} mm and clears the hub and the pivot boss"
    arm = longer_arm(probe, inputs)
    if arm is not None:
        return FitError("arm", inputs.arm_mm, f"{none}; an arm of {arm:.1f} mm gives one")
    return FitError("swing", inputs.program.swing_deg,
                    f"{none}, with any arm up to {MAX_ARM_MM:g} mm; {_swing_for_roller(probe, inputs)}")


def _swing_for_roller(probe: Design, inputs) -> str:
    """When no arm takes the typed roller: a smaller swing that does (``advice.swing_below``),
    else, with the roller left blank, the largest swing that gives a cam, else the shortest
    longer arm (as the blank roller's own refusal names them), each designed; else which
    fields are left to change."""
    swing = swing_below(probe, inputs)
    if swing is not None:
        return f"a swing of {swing:.1f}° gives one"
    blank = replace(inputs, roller_mm=None)
    swing = largest_swing(probe, blank)
    if swing is not None:
        return f"leave the roller blank, and a swing of {swing:.1f}° gives one"
    arm = longer_arm(probe, blank)
    if arm is not None:
        return f"leave the roller blank, and an arm of {arm:.1f} mm gives one"
    return ("no smaller swing gives one either, nor, with the roller left blank, a swing or an arm: change the hub, "
            "the pivot boss, the clearance, the allowances or the program")


def synthesis_advice(probe: Design, inputs) -> str:
    """Advice for a checked cam that takes no roller: what the synthesis gives with its base
    radius and centre distance left out (with the typed roller, else with none too), each
    designed before it is named."""
    tries = [inputs.roller_mm, None] if inputs.roller_mm is not None else [None]
    for roller in tries:
        try:
            cam = probe(replace(inputs, base_mm=None, distance_mm=None, roller_mm=roller))
        except DesignError:
            continue
        if roller is not None:
            return (f"leave out the base radius and the centre distance, and the synthesis gives "
                    f"r0 = {cam.base_radius_mm:.4g} mm for this roller")
        what = "the base radius and the centre distance" if inputs.roller_mm is None else \
            "the base radius, the centre distance and the roller"
        return (f"leave out {what}, and the synthesis gives r0 = {cam.base_radius_mm:.4g} mm with a "
                f"roller of {cam.roller_mm:.4g} mm")
    blank = replace(inputs, base_mm=None, distance_mm=None, roller_mm=None)
    arm = arm_for_roller(probe, blank, synthesize(blank.arm_mm, blank.program, blank.allowance))
    if arm is None:
        return f"no synthesized cam takes one either, with any arm up to {MAX_ARM_MM:g} mm"
    what = "the base radius and the centre distance" if inputs.roller_mm is None else \
        "the base radius, the centre distance and the roller"
    return f"leave out {what}, and an arm of {arm:.1f} mm gives one"
