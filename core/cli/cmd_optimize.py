"""``shaper optimize``: the best design within bounds for one objective."""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from core.base.errors import DesignError
from core.base.figure_text import figure_name, key_figure_text
from core.space.names import OBJECTIVES, PARAMETERS, UNITLESS
from .cmd_sweep import _number, figure_columns, inputs
from .cmd_synth import design_summary
from .common import add_design_options, add_load_options, add_speed_options, given_text
from .output import print_json, print_table

if TYPE_CHECKING:
    from core.linkage.geometry import Design
    from core.space.optimize import Optimum
    from core.space.sweep import Evaluation

HELP = "find the design that minimizes an objective"
DESCRIPTION = ("Search the varied parameters within their bounds for the design with the smallest "
               "objective: pressure-angle (largest pressure angle, rod variant), accel (largest "
               "|a| at the highest speed), peak-torque or flywheel (J_F at the slowest speed; both "
               "need loads). K and H stay fixed unless varied. A dense sweep of the box, then "
               "differential evolution and a Nelder–Mead polish (scipy); the result is never "
               "worse than the sweep's best point. NAME is one of " + ", ".join(PARAMETERS) + ".")
EXAMPLES = ("shaper optimize --crank 100 --K 1.46 --stroke 312 --rod-ratio 0.3 "
            "--objective pressure-angle --vary rod-ratio=0.2:1 --vary guide=450:700",
            "shaper optimize --design my.shaper.json --objective flywheel --vary crank=80:120 --json")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser)
    parser.add_argument("--objective", required=True, choices=tuple(OBJECTIVES),
                        help="what to minimize")
    parser.add_argument("--vary", action="append", metavar="NAME=LO:HI", required=True,
                        help="a free parameter and its bounds; repeat for several")
    add_speed_options(parser)
    add_load_options(parser, required=False)
    parser.add_argument("--json", action="store_true", help="print JSON")


def optimum_document(best: Optimum, typed: list[str],
                     ends: dict[str, str] | None = None) -> dict[str, Any]:
    """Objective, the optimal design (keys of ``shaper synth --json``) and its figures;
    ``on_bound``: the varied parameters (as typed) whose optimum is an end of its range."""
    from core.space.optimize import no_gain_text
    ev = best.evaluation
    doc: dict[str, Any] = {
        "objective": best.objective,
        "objective_unit": OBJECTIVES[best.objective][1],
        "objective_value": _number(best.value),
        "start_value": best.start_value,
        "vary": {name: float(best.x[i]) for i, name in enumerate(typed)},
        "evaluations": best.evaluations,
        "on_bound": {typed[i]: ends[name] for i, name in enumerate(best.names) if name in (ends or {})},
        "improves": best.improves,
        "no_gain": None if best.improves else no_gain_text(best, dict(zip(best.names, typed))),
    }
    doc["design"] = design_summary(_design(ev))
    doc["figures"] = {name: _number(values[0]) for name, values in figure_columns(ev)}
    return doc


def _design(ev: Evaluation) -> Design:
    from core.linkage.geometry import Design
    d = ev.designs
    return Design(crank=float(d.crank[0]), frame=float(d.frame[0]), lever=float(d.lever[0]),
                  guide=float(d.guide[0]), rod=None if d.rod is None else float(d.rod[0]),
                  rod_side=d.rod_side)  # type: ignore[arg-type]


def run(args: argparse.Namespace) -> int:
    from core.space.optimize import on_bounds, optimize, tidy_optimum
    spec, varied, rpms, masses = inputs(args, with_count=False)
    bounds = {PARAMETERS[n]: b for n, b in varied.items()}
    best = optimize(spec, bounds, args.objective, rpms, masses)
    typed = list(varied)
    if not best.evaluation.valid.all():
        raise DesignError("vary", ", ".join(args.vary), "contains no valid design")
    doc = optimum_document(best, typed, on_bounds(best, bounds))
    if args.json:
        print_json(doc)
        return 0
    objective = OBJECTIVE_KEYS[best.objective]         # its figure: one precision per kind
    start = "invalid" if best.start_value is None else key_figure_text(objective, best.start_value)
    rows = [("objective", f"{best.objective} ({OBJECTIVES[best.objective][0]})"),
            ("optimum", key_figure_text(objective, best.value)), ("design as given", start)]
    if not best.improves:       # no proposal: the design as given stands
        flat = [typed[i] for i, name in enumerate(best.names) if name in best.insensitive]
        rows = rows[:1] + rows[2:] + [("result", doc["no_gain"])]
        rows += [(name, f"best at the {end} bound: a better design may lie beyond it; widen the range")
                 for name, end in doc["on_bound"].items() if name not in flat]
        print_table(rows)
        return 0
    # each value as a person would type it, and as the Explore tab loads it: rounded where
    # that stays valid and as good (tidy_optimum), else in full. A rounding of its own
    # ("%.6g") put an optimum on the edge of validity outside it: K 1.00199 for 1.0019921,
    # which shaper analyze then refused ("must be ≥ 1.002").
    values, _ = tidy_optimum(spec, best, bounds, rpms, masses)
    rows += [(f"{name} (input)", given_text(values[best.names[i]]) + ("" if name in UNITLESS else " mm")
              + (f"  (at the {doc['on_bound'][name]} bound: the best design may lie beyond it; "
                 "widen the range)" if name in doc["on_bound"] else ""))
             for i, name in enumerate(typed)]
    design = doc["design"]
    rows += [("frame O2O4 L2", f"{design['frame_mm']:.3f} mm"),
             ("lever O4B L3", f"{design['lever_mm']:.3f} mm"),
             ("guide above lever pivot", f"{design['guide_mm']:.3f} mm")]
    if design["rod_mm"] is not None:
        rows.append(("rod BC L4", f"{design['rod_mm']:.3f} mm ({design['rod_side']})"))
    rows += [figure_row(key, value) for key, value in doc["figures"].items()]
    print_table(rows)
    return 0


# the figure each objective minimises (figure_columns' key: its kind and unit)
OBJECTIVE_KEYS = {"pressure-angle": "pressure_angle_max_deg", "accel": "a_max_m_s2",
                  "peak-torque": "max_torque_N_m", "flywheel": "flywheel_inertia_kg_m2"}
# figure_columns' keys named as ``shaper analyze`` names them, where an input has the same name
MEASURED = {"K": "measured K", "stroke_mm": "measured stroke", "theta_deg": "θ"}


def figure_row(key: str, value: float | None) -> tuple[str, str]:
    """(label, text) of one figure of the optimum as the table prints it: at its kind's
    precision with its unit (``core.base.figure_text``, as ``analyze`` and the GUI write
    it), K and the stroke marked measured, apart from the inputs above them ("K (input)")."""
    return MEASURED.get(key) or figure_name(key), "" if value is None else key_figure_text(key, value)
