"""``shaper cam``: the feed cam with an oscillating roller follower, synthesized or checked."""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from ..cam.defaults import LAWS, RETURN_PRESSURE_DEG
from core.base.errors import DesignError
from core.linkage.limits import MAX_RPM, MIN_RPM
from .common import (UsageError, add_design_options, design_error_text, design_file,
                     design_from_args, number)
from .output import (OutputError, add_cad_font_option, add_lang_option, cad_font_from_args, print_json,
                     print_table, sheet_labels)

if TYPE_CHECKING:
    from ..cam import Cam, CamInputs

HELP = "the feed cam: base radius, centre distance, profile"
DESCRIPTION = ("The table's feed cam, a disc cam with an oscillating roller follower on the crank's "
               "shaft: the smallest base radius and its centre distance for the allowed pressure "
               "angles (or, with --base and --distance, a check of a given cam), the largest roller, "
               "and the profile in the cam's own frame (cam centre at the origin, the follower "
               "pivot on +x at cam angle 0, the cam turning clockwise). With a design, the feed "
               "is placed outside the cut.")
EXAMPLES = ("shaper cam --arm 120 --swing 15 --pressure 40 --rise 60 --dwell 10 --return 60 "
            "--law cosine --return-law parabolic",
            "shaper cam --arm 120 --swing 15 --pressure 40 --rise 60 --dwell 10 --return 60 "
            "--crank 100 --K 1.4 --stroke 300 --csv cam.csv --dxf cam.dxf --json")

# DesignError parameter → the option that sets it.
CAM_PARAMETERS = {"--arm": "arm", "--swing": "swing", "--pressure": "pressure",
                  "--return-pressure": "return_pressure", "--rise": "rise", "--dwell": "dwell",
                  "--return": "return", "--roller": "roller", "--base": "base", "--distance": "distance",
                  "--hub": "hub", "--boss": "boss", "--least-clearance": "clearance"}
CAM_OPTIONS = {"arm": "--arm", "swing": "--swing", "pressure": "--pressure",
               "return_pressure": "--return-pressure", "rise": "--rise", "dwell": "--dwell",
               "return": "--return", "rise_law": "--law", "return_law": "--return-law",
               "roller": "--roller", "base": "--base", "distance": "--distance",
               "hub": "--hub", "boss": "--boss", "clearance": "--least-clearance",
               "phase": "--phase", "idle_fraction": "--idle", "rpm": "--rpm", "step": "--step"}
DESIGN_DESTS = ("crank", "time_ratio", "stroke", "dims", "design", "guide", "rod", "rod_ratio",
                "rod_side")


def configure(parser: argparse.ArgumentParser) -> None:
    add_cam_options(parser)
    add_design_options(parser)
    timing = parser.add_argument_group("timing against the linkage (with a design)")
    timing.add_argument("--idle", metavar="FRACTION",
                        help="uncut run-in and run-out as a fraction of the stroke (default 0.05)")
    add_phase_option(timing)
    out = parser.add_argument_group("output")
    out.add_argument("--rpm", metavar="RPM", help="crank (and cam) speed for the follower's ω and α, "
                     "r/min (default 60, or the design file's first)")
    out.add_argument("--step", metavar="DEG", help="cam-angle step of the CSV, ° (default 1)")
    out.add_argument("--json", action="store_true", help="print the figures as JSON")
    out.add_argument("--csv", metavar="FILE|-", help="write one row per cam angle as CSV")
    out.add_argument("--dxf", metavar="FILE", help="write the profile at 1:1 in mm as DXF")
    add_cad_font_option(out)
    add_lang_option(out, "the --dxf notes")


def add_cam_options(parser: argparse.ArgumentParser,
                    title: str = "the cam (the data sheet; required unless --design has a cam)"
                    ) -> argparse._ArgumentGroup:
    """The data sheet's options (shared with ``shaper drawing --content cam``); the group."""
    cam = parser.add_argument_group(title)
    cam.add_argument("--arm", metavar="MM", help="follower arm length l, mm")
    cam.add_argument("--swing", metavar="DEG", help="the follower's swing ψmax, °")
    cam.add_argument("--pressure", metavar="DEG",
                     help="allowed pressure angle [α] on the rise, °")
    cam.add_argument("--return-pressure", metavar="DEG",
                     help=f"allowed pressure angle on the return, ° (default {RETURN_PRESSURE_DEG:g}: the "
                          "follower returns unloaded, closed by its spring, so textbooks allow 70–80° "
                          "there against 30–45° on the working rise)")
    cam.add_argument("--rise", metavar="DEG", help="cam angle of the rise, °")
    cam.add_argument("--dwell", metavar="DEG", help="cam angle of the outer dwell, °")
    cam.add_argument("--return", dest="back", metavar="DEG",
                     help="cam angle of the return, ° (the inner dwell is the rest of the turn)")
    cam.add_argument("--law", choices=LAWS, help="motion law of the rise (default sine)")
    cam.add_argument("--return-law", choices=LAWS, help="motion law of the return (default: --law)")
    cam.add_argument("--roller", metavar="MM", help="roller radius, mm (default: the largest that "
                     "keeps the profile smooth, at least 3 mm: the cam is raised for one)")
    cam.add_argument("--base", metavar="MM", help="base-circle radius of the pitch curve, mm, to check "
                     "a cam instead of synthesizing one (with --distance)")
    cam.add_argument("--distance", metavar="MM", help="centre distance cam–pivot, mm (with --base)")
    cam.add_argument("--hub", metavar="MM", help="radius of the camshaft's hub, which the profile must "
                     "clear, mm (default 12.5)")
    cam.add_argument("--boss", metavar="MM", help="radius of the boss around the follower's pivot, "
                     "which the cam must clear, mm (default 12.5)")
    # not --clearance: shaper drawing takes the gear's options too, and c* is --clearance there
    cam.add_argument("--least-clearance", dest="least_clearance", metavar="MM",
                     help="least gap between the profile and the hub or the boss, mm (default 3); "
                     "a synthesized cam is enlarged to keep it")
    return cam


def add_phase_option(group) -> None:
    group.add_argument("--phase", metavar="DEG", help="crank angle at which the rise starts, ° "
                       "(default: the feed centred outside the cut)")


# option → (its dest, the key of a design file's cam object)
SHEET = (("--arm", "arm", "arm_mm"), ("--swing", "swing", "swing_deg"), ("--pressure", "pressure", "pressure_deg"),
         ("--rise", "rise", "rise_deg"), ("--dwell", "dwell", "dwell_deg"), ("--return", "back", "return_deg"))
OPTIONAL = (("--return-pressure", "return_pressure", "return_pressure_deg"), ("--roller", "roller", "roller_mm"),
            ("--base", "base", "base_mm"), ("--distance", "distance", "distance_mm"),
            ("--hub", "hub", "hub_mm"), ("--boss", "boss", "boss_mm"),
            ("--least-clearance", "least_clearance", "clearance_mm"))


def _inputs(args: argparse.Namespace) -> tuple[CamInputs, float | None]:
    """The cam's inputs and phase: the options over the ``--design`` file's cam (if any)."""
    from ..cam import CamInputs, Program
    from ..cam.file import cam_from_dict, cam_to_dict
    doc = design_file(args)
    saved = cam_to_dict(*cam_from_dict(doc["cam"])) if doc is not None and doc.get("cam") else {}
    values = {}
    for option, dest, key in SHEET + OPTIONAL:
        text = getattr(args, dest)
        if text is not None:
            values[key] = number(CAM_PARAMETERS[option], text)
        elif saved.get(key) is not None:
            values[key] = saved[key]
        elif (option, dest, key) in SHEET:
            raise UsageError(f"{option}: required (or give --design with a cam)")
    rise_law = args.law or saved.get("rise_law", "sine")
    program = Program(swing_deg=values["swing_deg"], rise_deg=values["rise_deg"],
                      dwell_deg=values["dwell_deg"], return_deg=values["return_deg"], rise_law=rise_law,
                      return_law=args.return_law or (saved.get("return_law", rise_law) if not args.law
                                                      else args.law))
    inputs = CamInputs(arm_mm=values["arm_mm"], program=program, pressure_deg=values["pressure_deg"],
                       return_pressure_deg=values.get("return_pressure_deg", RETURN_PRESSURE_DEG),
                       roller_mm=values.get("roller_mm"), base_mm=values.get("base_mm"),
                       distance_mm=values.get("distance_mm"),
                       **{key: values[key] for key in ("hub_mm", "boss_mm", "clearance_mm") if key in values})
    phase = number("phase", args.phase) if args.phase is not None else saved.get("phase_deg")
    return inputs, phase


# a cam parameter → (its option's dest, its key in a design file's cam object)
_SOURCES = {**{CAM_PARAMETERS[option]: (dest, key) for option, dest, key in SHEET + OPTIONAL},
            "rise_law": ("law", "rise_law"), "return_law": ("return_law", "return_law"),
            "phase": ("phase", "phase_deg")}


def cam_option(parameter: str, args: argparse.Namespace | None = None) -> str | None:
    """The option that set the cam's ``parameter`` on this command line, or, when the value
    came from the ``--design`` file's cam, that file ("--design (cam.phase_deg)")."""
    option = CAM_OPTIONS.get(parameter)
    source = _SOURCES.get(parameter)
    if args is None or source is None or getattr(args, source[0], None) is not None:
        return option
    doc = design_file(args)
    if doc is not None and isinstance(doc.get("cam"), dict) and doc["cam"].get(source[1]) is not None:
        return f"--design (cam.{source[1]})"
    return option


def cam_usage_error(exc: DesignError, args: argparse.Namespace | None = None) -> UsageError:
    """A cam's DesignError as the one line naming its option (or the design file)."""
    return UsageError(design_error_text(exc, cam_option(exc.parameter, args)))


def cam_inputs_from_args(args: argparse.Namespace) -> tuple[CamInputs, float | None]:
    """The cam's inputs and phase from the options and ``--design`` (UsageError naming one)."""
    try:
        return _inputs(args)
    except DesignError as exc:
        raise cam_usage_error(exc, args) from None


def cam_from_inputs(given: tuple[CamInputs, float | None], design, idle: float,
                    args: argparse.Namespace | None = None) -> Cam:
    """The cam synthesized (or checked) and timed against ``design`` (UsageError naming the
    option, or the design file for a value of its cam, when ``args`` are given)."""
    from ..cam import design_cam
    try:
        return design_cam(given[0], design, idle, given[1])
    except DesignError as exc:
        raise cam_usage_error(exc, args) from None


def _rpm(args: argparse.Namespace) -> float:
    if args.rpm is not None:
        value = number("rpm", args.rpm)
    else:
        doc = design_file(args)
        value = float(doc["rpm"][0]) if doc is not None else 60.0
    if not MIN_RPM <= value <= MAX_RPM:
        raise DesignError("rpm", value, f"must be ≥ {MIN_RPM:g} and ≤ {MAX_RPM:g} r/min")
    return value


def _idle(args: argparse.Namespace) -> float:
    if args.idle is not None:
        value = number("idle_fraction", args.idle)
    else:
        doc = design_file(args)
        masses = doc.get("masses") if doc is not None else None
        value = masses.idle_fraction if masses is not None else 0.05
    if not 0.0 <= value < 0.5:
        raise DesignError("idle_fraction", value, "must be ≥ 0 and < 0.5")
    return value


def json_document(args: argparse.Namespace) -> dict:
    """What ``--json`` prints (``shaper class``'s answer key holds it for each student)."""
    cam, rpm, _ = _cam_at(args)
    return _summary(cam, rpm)


def _summary(cam: Cam, rpm: float) -> dict:
    from ..cam.table import cam_summary, follower_peaks
    summary = cam_summary(cam)
    summary.update(follower_peaks(cam, rpm))
    return summary


def _cam_at(args: argparse.Namespace):
    """The cam of the options, its speed and the CSV's cam angles (UsageError naming one)."""
    from core.linkage.kinematics import crank_angles
    linked = any(getattr(args, d, None) is not None for d in DESIGN_DESTS)
    if args.phase is not None and not linked:
        raise UsageError("--phase: give a design (--crank/--K/--stroke, --dims or --design) to time the cam")
    design = design_from_args(args) if linked else None
    cam_inputs = cam_inputs_from_args(args)
    try:
        rpm = _rpm(args)
        step = 1.0 if args.step is None else number("step", args.step)
        angles = crank_angles(step)
        idle = _idle(args) if linked else 0.05
    except DesignError as exc:
        raise cam_usage_error(exc) from None
    return cam_from_inputs(cam_inputs, design, idle, args), rpm, angles


def run(args: argparse.Namespace) -> int:
    if args.json and args.csv == "-":
        raise UsageError("--json: cannot share stdout with --csv -; write the CSV to a file")
    cad_font = cad_font_from_args(args, args.dxf is not None)
    if args.lang is not None and args.dxf is None:
        raise UsageError("--lang: only with --dxf")
    labels = sheet_labels(args.lang or "en", "cam") if args.dxf is not None else None
    cam, rpm, angles = _cam_at(args)
    if args.csv is not None:          # block by block: 1.8 million rows at the finest step
        from ..cam.table import cam_table
        from .streaming import write_table
        write_table("--csv", args.csv, "computing the cam", lambda delta, n: cam_table(cam, delta, n),
                    angles, [rpm])
    if args.dxf is not None:
        from core.drawing.cam_dxf import write_cam_dxf     # ezdxf: only when a drawing is asked for
        try:
            write_cam_dxf(cam, args.dxf, cad_font, labels)
        except OSError as exc:          # a WriteError: names the user's path and a plain reason
            raise OutputError(f"--dxf: {exc}") from None
    summary = _summary(cam, rpm)
    if args.json:
        print_json(summary)
    elif args.csv != "-":
        print_table(summary_rows(summary))
    return 0


def summary_rows(s: dict) -> list[tuple[str, str]]:
    """(label, value) of the cam's figures, as printed."""
    rows = [("base radius r0 (pitch curve)", f"{s['base_radius_mm']:.3f} mm"),
            ("centre distance a", f"{s['center_distance_mm']:.3f} mm"),
            ("arm l", f"{s['arm_mm']:.3f} mm"),
            ("initial arm angle ψ0", f"{s['initial_angle_deg']:.3f}°"),
            ("arrangement", f"roller {s['arm_side']} the line of centres, cam turning clockwise"),
            ("max pressure angle rise / return",
             f"{s['max_pressure_angle_rise_deg']:.3f}° / {s['max_pressure_angle_return_deg']:.3f}° "
             f"(allowed {s['allowed_pressure_angle_rise_deg']:g}° / "
             f"{s['allowed_pressure_angle_return_deg']:g}°)"),
            ("min convex radius ρmin (pitch curve)", f"{s['min_curvature_radius_mm']:.3f} mm"),
            ("roller r", f"{s['roller_mm']:.3f} mm (largest {s['largest_roller_mm']:.3f} mm)"),
            ("profile base radius r0 − r", f"{s['profile_base_radius_mm']:.3f} mm (at least hub + "
             f"clearance = {s['hub_mm'] + s['clearance_mm']:g} mm)"),
            ("profile's largest radius R1 − r", f"{s['profile_max_radius_mm']:.3f} mm (at most a − boss − "
             f"clearance = {s['center_distance_mm'] - s['boss_mm'] - s['clearance_mm']:.3f} mm)"),
            (f"follower max ω / α at {s['rpm']:g} r/min",
             f"{s['follower_omega_max_rad_s']:.4g} rad/s / {s['follower_alpha_max_rad_s2']:.4g} rad/s²")]
    if s["base_raised_from_mm"] is not None:
        rows.append(("note", f"base radius raised from {s['base_raised_from_mm']:.3f} mm to take the "
                     "roller and clear the hub and the pivot boss"))
    if not s["within_allowance"]:
        rows.append(("allowance", "EXCEEDED"))
    if "phase_deg" in s:
        rows.append(("rise starts at crank angle", f"{s['phase_deg']:.3f}° (cut ends at "
                     f"{s['cut_end_deg']:.3f}°, the next starts {s['clear_span_deg']:.3f}° later)"))
    return rows
