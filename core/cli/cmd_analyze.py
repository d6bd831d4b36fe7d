"""``shaper analyze``: cycle metrics per crank speed, measured from the motion."""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from core.base.figure_text import figure_text
from .cmd_synth import design_summary
from .common import add_design_options, add_speed_options, design_from_args, rpms_from_args
from .output import print_json, print_table

if TYPE_CHECKING:
    from core.linkage.geometry import Design
    from core.linkage.metrics import CycleMetrics, SpeedMetrics

HELP = "cycle metrics per crank speed"
DESCRIPTION = ("Measured K and stroke, working and return angles and times, maximum cutting and "
               "return speeds, maximum acceleration and (rod variant) the maximum pressure angle, "
               "per crank speed.")
EXAMPLES = ("shaper analyze --crank 100 --K 1.4 --stroke 300 --rpm 40 60",
            "shaper analyze --design my.shaper.json --json")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser)
    add_speed_options(parser)
    parser.add_argument("--json", action="store_true", help="print JSON")


def metrics_summary(design: Design, metrics: CycleMetrics) -> dict[str, Any]:
    from core.files.io import finite_or_none
    out = design_summary(design)
    out.update({
        "K": metrics.time_ratio,
        "stroke_mm": metrics.stroke_mm,
        "K_nominal": design.time_ratio,
        "stroke_nominal_mm": design.stroke,
        "work_angle_deg": metrics.work_angle_deg,
        "return_angle_deg": metrics.return_angle_deg,
        "limit_positions": {"work_start_crank_deg": metrics.work_start_deg,
                            "work_end_crank_deg": metrics.work_end_deg,
                            "ram_min_mm": metrics.ram_min_mm, "ram_max_mm": metrics.ram_max_mm},
        "pressure_angle_max_deg": finite_or_none(metrics.pressure_angle_max_deg),
        "speeds": [
            {"rpm": s.rpm, "cycle_time_s": s.cycle_time_s, "work_time_s": s.work_time_s,
             "return_time_s": s.return_time_s, "v_work_max_m_s": s.v_work_max_m_s,
             "v_return_max_m_s": s.v_return_max_m_s, "v_work_mean_m_s": s.v_work_mean_m_s,
             "a_max_m_s2": s.a_max_m_s2, "lever_omega_max_rad_s": s.lever_omega_max_rad_s,
             "lever_alpha_max_rad_s2": s.lever_alpha_max_rad_s2}
            for s in metrics.speeds
        ],
    })
    return out


def cycle_rows(metrics: CycleMetrics) -> list[tuple[str, str]]:
    """(label, value) of the speed-independent figures, as printed (and in the report)."""
    f = figure_text
    rows = [("measured K", f("ratio", metrics.time_ratio)),
            ("measured stroke", f"{f('length', metrics.stroke_mm)} mm"),
            ("θ", f"{f('angle', metrics.theta_deg)}°"),
            ("working / return crank angle",
             f"{f('angle', metrics.work_angle_deg)}° / {f('angle', metrics.return_angle_deg)}°")]
    if metrics.pressure_angle_max_deg is not None:
        rows.append(("max pressure angle", f"{f('angle', metrics.pressure_angle_max_deg)}°"))
    return rows


def speed_rows(s: SpeedMetrics) -> list[tuple[str, str]]:
    """(label, value) of one crank speed's figures, as printed (and in the report)."""
    f = figure_text
    return [("working / return time", f"{f('time', s.work_time_s)} s / {f('time', s.return_time_s)} s"),
            ("max cutting speed", f"{f('speed', s.v_work_max_m_s)} m/s"),
            ("mean cutting speed", f"{f('speed', s.v_work_mean_m_s)} m/s"),
            ("max return speed", f"{f('speed', s.v_return_max_m_s)} m/s"),
            ("max |acceleration|", f"{f('acceleration', s.a_max_m_s2)} m/s²")]


def json_document(args: argparse.Namespace) -> dict[str, Any]:
    """What ``--json`` prints (``shaper class``'s answer key holds it for each student)."""
    from core.linkage.metrics import analyze
    design = design_from_args(args)
    return metrics_summary(design, analyze(design, rpms_from_args(args)))


def run(args: argparse.Namespace) -> int:
    if args.json:
        print_json(json_document(args))
        return 0
    from core.linkage.metrics import analyze
    design = design_from_args(args)
    metrics = analyze(design, rpms_from_args(args))
    print_table(cycle_rows(metrics))
    for s in metrics.speeds:
        print(f"\n{s.rpm:g} r/min")
        print_table(speed_rows(s))
    return 0
