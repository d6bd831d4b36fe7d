"""``shaper dynamics``: joint forces, crank torque, power and the flywheel."""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from core.base.figure_text import figure_text
from .cmd_synth import design_summary
from .common import (UsageError, add_angle_options, add_design_options, add_load_options, add_speed_options,
                     design_from_args, request_from_args)
from .loads import masses_from_args
from .output import print_json, print_table
from .streaming import write_table

if TYPE_CHECKING:
    import numpy as np

    from core.forces.dynamics import DynamicsSummary, SpeedSummary
    from core.forces.masses import MassProperties
    from core.linkage.geometry import Design

HELP = "joint forces, crank torque, power and flywheel"
DESCRIPTION = ("Kinetostatic analysis at constant crank speed: the crank's driving torque, power, "
               "every joint force and the guide reaction, and per speed the mean torque, motor "
               "power, energy fluctuation and flywheel inertia.")
EXAMPLES = ("shaper dynamics --crank 100 --K 1.4 --stroke 300 --rpm 40 60 --lever-mass 20 "
            "--lever-inertia 1.1 --ram-mass 70 --cut-force 7000 --cut-height 80",
            "shaper dynamics --design my.shaper.json --csv forces.csv")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser)
    add_speed_options(parser)
    add_angle_options(parser, "the CSV")
    add_load_options(parser, required=True)
    parser.add_argument("--csv", metavar="FILE|-", help="write the forces per angle as CSV to FILE or stdout")
    parser.add_argument("--json", action="store_true", help="print the per-speed summary as JSON")


def json_document(args: argparse.Namespace) -> dict:
    """What ``--json`` prints without ``--csv`` (``shaper class``'s answer key holds it)."""
    from core.forces.flywheel import summarize
    design = design_from_args(args)
    masses = masses_from_args(args, design, required=True)
    _, rpms = request_from_args(args)
    return summary_json(design, summarize(design, rpms, masses))


def summary_json(design: Design, summary: DynamicsSummary) -> dict:
    from core.files.dynamics_io import summary_document
    doc = design_summary(design)
    doc.update(summary_document(summary, design))
    return doc


def run(args: argparse.Namespace) -> int:
    from core.files.dynamics_io import dynamics_table
    from core.forces.dynamics import solve_dynamics
    from core.forces.flywheel import summarize
    if args.json and args.csv == "-":
        raise UsageError("--json: cannot share stdout with --csv -; write the CSV to a file")
    if args.json and args.csv is None:
        print_json(json_document(args))
        return 0
    design = design_from_args(args)
    masses = masses_from_args(args, design, required=True)
    angles, rpms = request_from_args(args)  # validated even when only the summary is printed
    if args.csv is not None:
        def block(phi: np.ndarray, rpm: float):
            return dynamics_table(solve_dynamics(design, phi, [rpm], masses))

        write_table("--csv", args.csv, "computing forces", block, angles, rpms)
        if not args.json:
            return 0
    summary = summarize(design, rpms, masses)
    if args.json:
        print_json(summary_json(design, summary))
        return 0
    print_table(summary_rows(design, masses, summary))
    for s in summary.speeds:
        print(f"\n{s.rpm:g} r/min")
        print_table(speed_rows(s, summary.rotor_inertia_kg_m2 if masses.rotors else None))
    return 0


def summary_rows(design: Design, masses: MassProperties,
                 summary: DynamicsSummary) -> list[tuple[str, str]]:
    """(label, value) of the loads and speed-independent results, as printed."""
    rows = [("variant", design.variant),
            ("lever weight G4", f"{masses.weight('lever_mass_kg'):g} N"),
            ("ram weight G6", f"{masses.weight('ram_mass_kg'):g} N"),
            ("cutting force", f"{masses.cut_force_N:g} N over {1 - 2 * masses.idle_fraction:.0%} of the stroke"),
            ("mean reduced inertia J_e", f"{figure_text('inertia', summary.equivalent_inertia_mean_kg_m2)} kg·m²")]
    if masses.rotors:
        parts = " + ".join(f"{j:g}·{r:g}²" for j, r in masses.rotors)
        rows.append(("rotating parts J_c = Σ J·(ω/ω2)²",
                     f"{parts} = {figure_text('inertia', summary.rotor_inertia_kg_m2)} kg·m²"))
    return rows + [("speed fluctuation δ", figure_text("coefficient", masses.delta))]


def speed_rows(s: SpeedSummary, rotors_kg_m2: float | None = None) -> list[tuple[str, str]]:
    """(label, value) of one crank speed's torque, power and flywheel, as printed (and in
    the report). With ``rotors_kg_m2`` (J_c, when rotating parts were given) also the
    flywheel the task book asks for, J_F − J_c, or that none is needed."""
    f = figure_text
    rows = [("mean / max crank torque", f"{f('torque', s.mean_torque_N_m)} N·m / {f('torque', s.max_torque_N_m)} N·m"),
            ("mean power", f"{f('power', s.mean_power_W)} W"),
            ("energy fluctuation ΔW_max", f"{f('energy', s.energy_fluctuation_J)} J"),
            ("flywheel J_F", f"{f('inertia', s.flywheel_inertia_kg_m2)} kg·m²")]
    if rotors_kg_m2 is None:
        return rows + [("flywheel J_F − J_e (net)", f"{f('inertia', s.flywheel_inertia_net_kg_m2)} kg·m²")]
    return rows + [("flywheel needed J_F − J_c", needed_text(s, rotors_kg_m2)),
                   ("flywheel J_F − J_c − J_e (net)", f"{f('inertia', s.flywheel_inertia_net_kg_m2)} kg·m²")]


def needed_text(s: SpeedSummary, rotors_kg_m2: float) -> str:
    """J_F − J_c, or that no flywheel is needed (never a negative inertia)."""
    if s.flywheel_needed:
        return f"{figure_text('inertia', s.flywheel_inertia_needed_kg_m2)} kg·m²"
    return f"none needed (J_c = {figure_text('inertia', rotors_kg_m2)} kg·m² ≥ J_F)"
