"""``shaper``: the whole computation without a screen.

Bad input never shows a traceback: it exits with status 2 and one line on
stderr that names the option.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from typing import Any, Sequence

import numpy as np

from .errors import DesignError
from .geometry import Design, from_dimensions, synthesize
from .dynamics import MassProperties, solve_dynamics, summarize
from .dynamics_io import dynamics_csv, summary_document
from .io import curves_csv, finite_or_none
from .kinematics import check_angles, crank_angles, solve
from .metrics import CycleMetrics, analyze

OPTION_NAMES = {
    "crank": "--crank", "time_ratio": "--K", "stroke": "--stroke", "frame": "--dims (L2)",
    "lever": "--dims (L3)", "guide": "--guide", "rod": "--rod", "rod_ratio": "--rod-ratio",
    "rod_side": "--rod-side", "rpm": "--rpm", "step": "--step", "angles": "--angles",
    "dims": "--dims",
    "lever_mass_kg": "--lever-mass", "lever_inertia_kg_m2": "--lever-inertia",
    "lever_cg_mm": "--lever-cg", "ram_mass_kg": "--ram-mass", "ram_cg_mm": "--ram-cg",
    "rod_mass_kg": "--rod-mass", "block_mass_kg": "--block-mass", "crank_mass_kg": "--crank-mass",
    "cut_force_N": "--cut-force", "cut_height_mm": "--cut-height", "idle_fraction": "--idle",
    "delta": "--delta",
}


class UsageError(Exception):
    """Bad command-line words; reported as one line with exit status 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, not usage + message
        raise UsageError(message)


def _design_options(parser: argparse.ArgumentParser, allow_dims: bool) -> None:
    group = parser.add_argument_group("design")
    group.add_argument("--crank", type=str, metavar="MM", help="crank length L1, mm")
    group.add_argument("--K", dest="time_ratio", type=str, metavar="K",
                       help="time ratio K = working time / return time (> 1)")
    group.add_argument("--stroke", type=str, metavar="MM", help="ram stroke H, mm")
    if allow_dims:
        group.add_argument("--dims", type=str, metavar="L1,L2,L3[,L4]",
                           help="direct dimensions in mm instead of --crank/--K/--stroke")
    group.add_argument("--guide", default="chord", metavar="chord|sagitta|MM",
                       help="ram guide line: a rule, or its height above the lever pivot O4 in mm")
    group.add_argument("--rod", type=str, metavar="MM", help="connecting-rod length L4, mm")
    group.add_argument("--rod-ratio", type=str, metavar="R", help="rod length as a ratio L4/L3")
    group.add_argument("--rod-side", default="trailing", choices=("trailing", "leading"),
                       help="ram joint behind (trailing) or ahead of (leading) the lever tip while cutting")


def _speed_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--rpm", nargs="+", type=str, default=["40", "60"], metavar="RPM",
                        help="crank speeds, r/min (default 40 60)")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="shaper", description="Shaper quick-return mechanism: synthesis and kinematics.")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    p = sub.add_parser("synth", help="synthesize dimensions from L1, K, H")
    _design_options(p, allow_dims=False)
    p.add_argument("--json", action="store_true", help="print JSON")
    p = sub.add_parser("curves", help="ram and lever motion over the cycle, as CSV")
    _design_options(p, allow_dims=True)
    _speed_options(p)
    angles = p.add_mutually_exclusive_group()
    angles.add_argument("--step", type=str, default="1", metavar="DEG", help="crank-angle step, degrees (default 1)")
    angles.add_argument("--angles", type=str, metavar="A,B,…", help="explicit crank angles, degrees")
    p.add_argument("--csv", default="-", metavar="FILE|-", help="output file, or - for stdout (default)")
    p = sub.add_parser("analyze", help="cycle metrics per crank speed")
    _design_options(p, allow_dims=True)
    _speed_options(p)
    p.add_argument("--json", action="store_true", help="print JSON")
    _dynamics_parser(sub)
    return parser


def _dynamics_parser(sub: Any) -> None:
    p = sub.add_parser("dynamics", help="joint forces, crank torque, power and flywheel")
    _design_options(p, allow_dims=True)
    _speed_options(p)
    angles = p.add_mutually_exclusive_group()
    angles.add_argument("--step", type=str, default="1", metavar="DEG",
                        help="crank-angle step of the CSV, degrees (default 1)")
    angles.add_argument("--angles", type=str, metavar="A,B,…", help="explicit crank angles of the CSV, degrees")
    group = p.add_argument_group("masses and loads")
    group.add_argument("--lever-mass", required=True, metavar="KG", help="slotted lever mass, kg")
    group.add_argument("--lever-inertia", required=True, metavar="KGM2",
                       help="lever moment of inertia about its centre of mass, kg·m²")
    group.add_argument("--lever-cg", metavar="MM", help="lever centre of mass from O4 along the lever, mm (default L3/2)")
    group.add_argument("--ram-mass", required=True, metavar="KG", help="ram plus tool mass, kg")
    group.add_argument("--ram-cg", metavar="DX,DY",
                       help="ram centre of mass from the ram joint C, mm (default 0,0; write --ram-cg=-5,3 for a leading minus)")
    group.add_argument("--rod-mass", default="0", metavar="KG", help="connecting rod mass, kg (rod variant; default 0)")
    group.add_argument("--block-mass", default="0", metavar="KG", help="sliding block at the crank pin, kg (default 0)")
    group.add_argument("--crank-mass", default="0", metavar="KG", help="balanced crank mass, kg (default 0)")
    group.add_argument("--cut-force", required=True, metavar="N", help="cutting force on the tool, N")
    group.add_argument("--cut-height", default="0", metavar="MM", help="tool point below the guide line, mm (default 0)")
    group.add_argument("--idle", default="0.05", metavar="FRACTION",
                       help="uncut run-in and run-out, each as a fraction of the stroke (default 0.05)")
    group.add_argument("--delta", default=str(1.0 / 30.0), metavar="D",
                       help="coefficient of speed fluctuation δ for the flywheel (default 1/30)")
    group.add_argument("--no-gravity", action="store_true", help="leave the links' weights out")
    p.add_argument("--csv", metavar="FILE|-", help="write the forces per angle as CSV to FILE or stdout")
    p.add_argument("--json", action="store_true", help="print the per-speed summary as JSON")


def _number(option: str, text: str) -> float:
    try:
        return float(text)
    except (TypeError, ValueError):
        raise DesignError(option, text, "must be a number") from None


def design_from_args(args: argparse.Namespace) -> Design:
    guide: Any = args.guide
    if guide not in ("chord", "sagitta"):
        guide = _number("guide", guide)
    rod = None if args.rod is None else _number("rod", args.rod)
    ratio = None if args.rod_ratio is None else _number("rod_ratio", args.rod_ratio)
    dims = getattr(args, "dims", None)
    synth = [args.crank, args.time_ratio, args.stroke]
    if dims is not None:
        if any(v is not None for v in synth):
            raise UsageError("--dims: give either --dims or --crank/--K/--stroke, not both")
        parts = [p.strip() for p in dims.split(",")]
        if len(parts) not in (3, 4):
            raise DesignError("dims", dims, "must be L1,L2,L3 or L1,L2,L3,L4 in mm")
        values = [_number("dims", p) for p in parts]
        if len(values) == 4:
            if rod is not None or ratio is not None:
                raise UsageError("--dims: give L4 either in --dims or with --rod/--rod-ratio")
            rod = values[3]
        return from_dimensions(values[0], values[1], values[2], guide=guide, rod=rod,
                               rod_ratio=ratio, rod_side=args.rod_side)
    for name, value in zip(("crank", "time_ratio", "stroke"), synth):
        if value is None:
            raise UsageError(f"{OPTION_NAMES[name]}: required (or use --dims)" if dims is None
                             and hasattr(args, "dims") else f"{OPTION_NAMES[name]}: required")
    return synthesize(_number("crank", args.crank), _number("time_ratio", args.time_ratio),
                      _number("stroke", args.stroke), guide=guide, rod=rod, rod_ratio=ratio,
                      rod_side=args.rod_side)


def design_summary(design: Design) -> dict[str, Any]:
    return {
        "variant": design.variant,
        "theta_deg": math.degrees(design.theta),
        "K": design.time_ratio,
        "stroke_mm": design.stroke,
        "crank_mm": design.crank,
        "frame_mm": design.frame,
        "lever_mm": design.lever,
        "guide_mm": design.guide,
        "h_mm": design.guide_above_crank,
        "rod_mm": design.rod,
        "rod_side": design.rod_side if design.rod is not None else None,
    }


def metrics_summary(design: Design, metrics: CycleMetrics) -> dict[str, Any]:
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


def _angles(args: argparse.Namespace) -> np.ndarray:
    if args.angles is not None:
        parts = [p for p in args.angles.split(",") if p.strip()]
        return check_angles(np.array([_number("angles", p) for p in parts]))
    return crank_angles(_number("step", args.step))


def _rpms(args: argparse.Namespace) -> list[float]:
    return [_number("rpm", r) for r in args.rpm]


def _write(target: str, text: str) -> None:
    if target == "-":
        sys.stdout.write(text)
    else:
        from .io import atomic_write
        atomic_write(target, text)


def _print_table(rows: list[tuple[str, str]]) -> None:
    width = max(len(k) for k, _ in rows)
    for key, value in rows:
        print(f"{key:<{width}}  {value}")


def run(argv: Sequence[str] | None) -> int:
    args = build_parser().parse_args(argv)
    if args.command == "synth":
        design = design_from_args(args)
        summary = design_summary(design)
        if args.json:
            print(json.dumps(summary, indent=2))
        else:
            rows = [("variant", design.variant),
                    ("extreme-position angle θ", f"{summary['theta_deg']:.4f} °"),
                    ("frame O2O4 L2", f"{design.frame:.3f} mm"),
                    ("lever O4B L3", f"{design.lever:.3f} mm"),
                    ("guide above lever pivot", f"{design.guide:.3f} mm"),
                    ("guide above crank centre h", f"{design.guide_above_crank:.3f} mm")]
            if design.rod is not None:
                rows.append(("rod BC L4", f"{design.rod:.3f} mm ({design.rod_side})"))
            rows += [("time ratio K", f"{design.time_ratio:.6g}"), ("stroke H", f"{design.stroke:.3f} mm")]
            _print_table(rows)
        return 0
    design = design_from_args(args)
    rpms = _rpms(args)
    if args.command == "curves":
        motion = solve(design, _angles(args), rpms)
        _write(args.csv, curves_csv(motion))
        return 0
    if args.command == "dynamics":
        return _run_dynamics(args, design, rpms)
    metrics = analyze(design, rpms)
    summary = metrics_summary(design, metrics)
    if args.json:
        print(json.dumps(summary, indent=2))
    else:
        _print_table([("measured K", f"{metrics.time_ratio:.6f}"),
                      ("measured stroke", f"{metrics.stroke_mm:.3f} mm"),
                      ("θ", f"{metrics.theta_deg:.4f} °"),
                      ("working / return crank angle",
                       f"{metrics.work_angle_deg:.3f} ° / {metrics.return_angle_deg:.3f} °")])
        for s in metrics.speeds:
            print(f"\n{s.rpm:g} r/min")
            _print_table([("working / return time", f"{s.work_time_s:.4f} s / {s.return_time_s:.4f} s"),
                          ("max cutting speed", f"{s.v_work_max_m_s:.4f} m/s"),
                          ("mean cutting speed", f"{s.v_work_mean_m_s:.4f} m/s"),
                          ("max return speed", f"{s.v_return_max_m_s:.4f} m/s"),
                          ("max |acceleration|", f"{s.a_max_m_s2:.4f} m/s²")])
    return 0


def masses_from_args(args: argparse.Namespace) -> MassProperties:
    """The ``dynamics`` options as a validated :class:`MassProperties`."""
    cg = None
    if args.ram_cg is not None:
        parts = args.ram_cg.split(",")
        if len(parts) != 2:
            raise DesignError("ram_cg_mm", args.ram_cg, "must be DX,DY in mm")
        cg = tuple(_number("ram_cg_mm", p) for p in parts)
    numbers = {name: _number(name, getattr(args, attr)) for name, attr in (
        ("lever_mass_kg", "lever_mass"), ("lever_inertia_kg_m2", "lever_inertia"),
        ("ram_mass_kg", "ram_mass"), ("rod_mass_kg", "rod_mass"), ("block_mass_kg", "block_mass"),
        ("crank_mass_kg", "crank_mass"), ("cut_force_N", "cut_force"),
        ("cut_height_mm", "cut_height"), ("idle_fraction", "idle"), ("delta", "delta"))}
    if args.lever_cg is not None:
        numbers["lever_cg_mm"] = _number("lever_cg_mm", args.lever_cg)
    if cg is not None:
        numbers["ram_cg_mm"] = cg
    return MassProperties(gravity=not args.no_gravity, **numbers)


def _run_dynamics(args: argparse.Namespace, design: Design, rpms: list[float]) -> int:
    if args.json and args.csv == "-":
        raise UsageError("--json: cannot share stdout with --csv -; write the CSV to a file")
    masses = masses_from_args(args)
    angles = _angles(args)   # validated even when only the summary is printed
    if args.csv is not None:
        _write(args.csv, dynamics_csv(solve_dynamics(design, angles, rpms, masses)))
        if not args.json:
            return 0
    summary = summarize(design, rpms, masses)
    if args.json:
        doc = design_summary(design)
        doc.update(summary_document(summary, design))
        print(json.dumps(doc, indent=2))
    else:
        _print_table([("variant", design.variant),
                       ("cutting force", f"{masses.cut_force_N:g} N over {1 - 2 * masses.idle_fraction:.0%} of the stroke"),
                       ("mean reduced inertia J_e", f"{summary.equivalent_inertia_mean_kg_m2:.5g} kg·m²"),
                       ("speed fluctuation δ", f"{masses.delta:.5g}")])
        for s in summary.speeds:
            print(f"\n{s.rpm:g} r/min")
            _print_table([("mean / max crank torque", f"{s.mean_torque_N_m:.4g} N·m / {s.max_torque_N_m:.4g} N·m"),
                          ("mean power", f"{s.mean_power_W:.4g} W"),
                          ("energy fluctuation ΔW_max", f"{s.energy_fluctuation_J:.4g} J"),
                          ("flywheel J_F", f"{s.flywheel_inertia_kg_m2:.4g} kg·m²"),
                          ("flywheel J_F − J_e (net)", f"{s.flywheel_inertia_net_kg_m2:.4g} kg·m²")])
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    try:
        code = run(argv)
    except UsageError as exc:
        print(f"shaper: error: {exc}", file=sys.stderr)
        return 2
    except DesignError as exc:
        option = OPTION_NAMES.get(exc.parameter, exc.parameter)
        print(f"shaper: error: {option}: {exc.allowed} (got {exc.value})", file=sys.stderr)
        return 2
    except BrokenPipeError:
        try:
            sys.stdout = None  # type: ignore[assignment]  # nothing more can be written
        finally:
            return 0
    except OSError as exc:
        print(f"shaper: error: --csv: cannot write {exc.filename}: {exc.strerror}", file=sys.stderr)
        return 2
    return code


if __name__ == "__main__":
    sys.exit(main())
