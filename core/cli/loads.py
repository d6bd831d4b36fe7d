"""The masses and loads a command reads: the load options (``common.LOAD_OPTIONS``) over
the design file's loads over the defaults.

Split from common.py (which declares the options) so that the reading of loads, and the
one test of whether any were given, stands in one place for the commands that take them
(dynamics, table, sweep, library add).
"""
from __future__ import annotations

import argparse
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from core.base.errors import DesignError
from .common import LOAD_OPTIONS, UsageError, design_file, number, option_name

if TYPE_CHECKING:
    from core.forces.masses import MassProperties
    from core.linkage.geometry import Design

REQUIRED_LOADS = ("lever_mass_kg", "lever_inertia_kg_m2", "ram_mass_kg", "cut_force_N")
# an essential mass → the weight that may stand for it (the task book's G4, G6)
ALTERNATIVES = {"lever_mass_kg": "lever_weight_N", "ram_mass_kg": "ram_weight_N"}


def loads_given(args: argparse.Namespace) -> bool:
    """True when a load option was typed or the design file carries loads."""
    doc = design_file(args)
    if doc is not None and doc.get("masses") is not None:
        return True
    return (args.no_gravity or bool(getattr(args, "rotors", None))
            or any(getattr(args, dest) is not None for _, dest, _, _ in LOAD_OPTIONS))


def masses_or_none(args: argparse.Namespace, design: Design) -> MassProperties | None:
    """The loads, or None when none were given (kinematics only)."""
    return masses_from_args(args, design, required=False) if loads_given(args) else None


def masses_from_args(args: argparse.Namespace, design: Design, required: bool) -> MassProperties:
    """The load options over the design file's loads (if any) over the defaults.

    With ``required``, the four essential loads must come from the options or the file.
    A rod mass the file keeps from the rod variant is dropped for a block design; one
    given as an option is refused by the solver instead.
    """
    from core.forces.masses import MassProperties, masses_for_design  # only commands with loads
    doc = design_file(args)
    base = doc.get("masses") if doc is not None else None
    if base is not None:
        base = masses_for_design(design, base)
    changes: dict[str, Any] = {}
    for option, dest, _, _ in LOAD_OPTIONS:
        text = getattr(args, dest)
        if text is None:
            continue
        if dest == "ram_cg_mm":
            parts = text.split(",")
            if len(parts) != 2:
                raise DesignError(dest, text, "must be DX,DY in mm")
            changes[dest] = tuple(number(dest, p) for p in parts)
        else:
            changes[dest] = number(dest, text)
    for mass, weight in ALTERNATIVES.items():
        if mass in changes and weight in changes:
            raise UsageError(f"{option_name(mass)}: give either {option_name(mass)} or "
                             f"{option_name(weight)}, not both")
        if weight in changes:           # a weight typed here replaces the file's mass
            changes[mass] = 0.0
        elif mass in changes:           # and a mass the file's weight
            changes[weight] = None
    if getattr(args, "rotors", None):
        changes["rotors"] = tuple(rotor(text, doc, args) for text in args.rotors)
    if args.no_gravity:
        changes["gravity"] = False
    if base is None:
        if required:
            for dest in REQUIRED_LOADS:
                if dest not in changes:
                    other = ALTERNATIVES.get(dest)
                    also = f" (or {option_name(other)})" if other else ""   # one option names the line
                    raise UsageError(f"{option_name(dest)}: required{also}, or give --design with loads")
        base = MassProperties()
    return replace(base, **changes)


def rotor(text: str, doc: dict[str, Any] | None, args: argparse.Namespace | None = None
          ) -> tuple[float, float]:
    """One ``--rotor J:RATIO`` (or ``J:gear``, the pinion shaft of the gear pair, z2/z1) as
    (J kg·m², ω_i/ω2). The gear pair is the one the command designs where it takes gear
    options (``shaper design``'s --z1, --z2 … over the file's pair, as it writes it), else the
    design file's: J:gear took the file's pair, 40/13, under a file's --z1 15 --z2 41, and
    was refused without a file though --z1 and --z2 were given."""
    from core.forces.rotors import check_rotors, rotor_from_text
    if text.partition(":")[2].strip().lower() != "gear":
        return rotor_from_text(text)
    if args is not None and any(getattr(args, dest, None) is not None for dest in gear_dests()):
        from .cmd_gear import pair_from_args
        pair = pair_from_args(args).inputs
    elif doc is not None and doc.get("gear") is not None:
        from ..gear.file import gear_from_dict
        pair = gear_from_dict(doc["gear"])
    else:       # what to give, each of which works as said (test_cli_loads_task_book.py)
        check_rotors([rotor_from_text(text, 40 / 13)])  # a bad J first: 'nan:gear' was told to type 'nan:3.07692'
        options = "--z1, --z2 and --module, " if args is not None and hasattr(args, "z1") else ""
        which = "no --design file was given" if doc is None else "the --design file has no gear pair"
        raise UsageError(f"--rotor: {text!r} takes the ratio z2/z1 of the gear pair, and {which}: give "
                         f"the ratio itself as J:RATIO (for z1 = 13, z2 = 40: {text.partition(':')[0].strip()}:"
                         f"{40 / 13:.6g}), {options}or a --design file with a \"gear\" object (gear.z1, gear.z2, "
                         "gear.module_mm), which the GUI's File › Save writes with the Gear tab's pair and "
                         "'shaper design --design FILE --z1 Z1 --z2 Z2 --module M -o FILE' adds")
    return rotor_from_text(text, pair.z2 / pair.z1)


def gear_dests() -> tuple[str, ...]:
    """The gear options' names in the parsed arguments (z1, z2, module_mm …)."""
    from .cmd_gear import OPTIONS
    return tuple(row[1] for row in OPTIONS)
