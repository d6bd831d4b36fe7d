"""``shaper design``: a design file written from the command line's options (issue 41).

A design is made without the GUI: the linkage, speeds, step, loads, feed cam and gear
pair are the options every other subcommand takes, read by those subcommands' own
parsers and checks (``common``, ``loads``, ``cmd_cam``, ``cmd_gear``), laid over
``--design`` (a file whose values the options change), and the file is checked by the
design file's own reader before it is written, atomically. ``shaper class`` reads each
row of its task table through :func:`configure` and :func:`document_from_args`, so an
option added to any of those parsers is a column of the table without more code.
"""
from __future__ import annotations

import argparse
import json
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from core.base.errors import DesignError
from .common import (UsageError, add_design_options, add_load_options, add_speed_options,
                     design_error_text, design_file, given_text, number, rpms_from_args,
                     spec_from_args, spec_option)
from .common import _apply_mechanism_options  # the mechanism options laid over a spec

if TYPE_CHECKING:
    from core.linkage.spec import Spec

HELP = "write a design file from the options (no GUI needed)"
DESCRIPTION = ("Write a design file (the GUI opens it; every --design option reads it) from the "
               "options the other subcommands take: the linkage (--crank/--K/--stroke or --dims, "
               "--guide, --rod …), the speeds (--rpm), the step, the loads, the feed cam (--arm, "
               "--swing …) and the gear pair (--z1, --z2, --module …). With --design FILE the "
               "options change that file's values and keep the rest. Every value is checked as the "
               "subcommand that uses it checks it, and the file as the GUI reads it, before it is "
               "written (atomically).")
EXAMPLES = ("shaper design --dims 110,380,540 --rod-ratio 0.25 --guide sagitta --rpm 60 "
            "--lever-mass 20.39 --lever-inertia 1.1 --ram-mass 71.36 --cut-force 7000 "
            "--cut-height 80 -o 方案I.shaper.json",
            "shaper design --design base.shaper.json --crank 110 --K 1.5 --stroke 320 -o s01.shaper.json")

LINKAGE = ("crank", "time_ratio", "stroke", "dims")


def configure(parser: argparse.ArgumentParser, output: bool = True) -> None:
    """The options of a design (``output``: and -o, which ``shaper class``'s rows lack)."""
    from .cmd_cam import add_cam_options, add_phase_option
    from .cmd_gear import add_gear_options
    add_design_options(parser)
    add_speed_options(parser)
    from core.linkage.limits import MAX_FILE_SAMPLES
    parser.add_argument("--step", metavar="DEG", help="crank-angle step the GUI shows, ° (default 1, "
                        f"or the design file's); at most {MAX_FILE_SAMPLES} angles × speeds, a design "
                        "file's limit")
    add_load_options(parser, required=False)
    add_phase_option(add_cam_options(parser, "the feed cam (optional)"))
    add_gear_options(parser, "the gear pair (optional; z1, z2 and the module together)")
    if output:
        parser.add_argument("-o", "--output", required=True, metavar="FILE.shaper.json",
                            help="the design file to write (replaced atomically)")


def run(args: argparse.Namespace) -> int:
    from core.files.io import atomic_write
    from .output import OutputError, check_target
    check_target("--output", args.output)
    text = design_text(document_from_args(args))
    try:
        atomic_write(args.output, text)
    except OSError as exc:          # a WriteError: names the path and a plain reason
        raise OutputError(f"--output: {exc}") from None
    print(args.output)
    return 0


def design_text(doc: dict[str, Any]) -> str:
    """A design document as the GUI's Save writes it (``core.files.io.save_design``)."""
    return json.dumps(doc, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def document_from_args(args: argparse.Namespace) -> dict[str, Any]:
    """The design file the options describe over ``--design``: every value checked as the
    subcommand that uses it checks it (UsageError or DesignError naming the option), and
    the whole read back by the design file's reader."""
    from core.files.design_file import OWN_KEYS, PART_KEYS, masses_to_dict, parse_design
    from core.files.io import design_document
    from core.linkage.kinematics import check_file_samples, check_rpms
    base = design_file(args) or {}
    spec = layered_spec(args)
    design = _design(spec, args)
    rpms = [float(r) for r in check_rpms(rpms_from_args(args))]
    step = number("step", args.step) if args.step is not None else float(base.get("step_deg", 1.0))
    check_file_samples(step, len(rpms))     # before the loads and parts: --step names the fault
    # the design file's own keys are written here; any other key of --design is kept
    extra: dict[str, Any] = {k: v for k, v in base.items() if k not in OWN_KEYS + PART_KEYS}
    from .loads import gear_dests, loads_given, masses_from_args
    idle = 0.05
    if loads_given(args):
        masses = masses_from_args(args, design, required=False)
        extra["forces"] = masses_to_dict(masses)
        idle = masses.idle_fraction
    if _given(args, _cam_dests()) or base.get("cam"):
        extra["cam"] = _cam(args, design, idle)
    if _given(args, gear_dests()) or base.get("gear"):
        from ..gear.file import gear_to_dict
        from .cmd_gear import pair_from_args
        extra["gear"] = gear_to_dict(pair_from_args(args).inputs)
    doc = design_document(spec, rpms, step, extra)
    parse_design(design_text(doc).encode("utf-8"), "the design")    # as the GUI will read it
    return doc


def layered_spec(args: argparse.Namespace) -> Spec:
    """The linkage: the options over ``--design``'s. Unlike the analysis commands, which
    take the linkage from the file or from the options, a design made from a file may
    change its linkage: --crank, --K, --stroke (the others of the three from the file when
    it is synthesized) or --dims replace the file's, and --guide, --rod … apply on top."""
    doc = design_file(args)
    if doc is None or all(getattr(args, d, None) is None for d in LINKAGE):
        return spec_from_args(args)
    base: Spec = doc["spec"]
    own = {d: getattr(args, d, None) for d in LINKAGE}
    if own["dims"] is None and base.mode == "dimensions" and None in (own["crank"], own["time_ratio"],
                                                                      own["stroke"]):
        first = next(o for o, d in (("--crank", "crank"), ("--K", "time_ratio"), ("--stroke", "stroke"))
                     if own[d] is not None)
        raise UsageError(f"{first}: the design file gives its linkage by dimensions; give --dims, "
                         "or --crank, --K and --stroke together")
    if own["dims"] is None and base.mode == "synthesis":
        for dest, value in (("crank", base.crank), ("time_ratio", base.time_ratio), ("stroke", base.stroke)):
            own[dest] = own[dest] if own[dest] is not None else given_text(value)
    bare = argparse.Namespace(**{**vars(args), **own, "design": None, "_design_doc": None,
                                 "guide": None, "rod": None, "rod_ratio": None, "rod_side": None})
    given = spec_from_args(bare)
    fields = ["mode", "crank", "time_ratio", "stroke", "frame", "lever"]
    if own["dims"] is not None and given.variant == "rod":     # L4 in --dims
        fields += ["variant", "rod_input", "rod_length"]
    return _apply_mechanism_options(replace(base, **{f: getattr(given, f) for f in fields}), args)


def _design(spec: Spec, args: argparse.Namespace):
    """The linkage's design; a DesignError as the one line naming the option (or --design)."""
    try:
        spec.check_fields()
        return spec.design()
    except DesignError as exc:
        linkage_given = any(getattr(args, d, None) is not None for d in LINKAGE)
        shown = argparse.Namespace(**{**vars(args), "design": None}) if linkage_given else args
        raise UsageError(design_error_text(exc, spec_option(exc.parameter, spec, shown))) from None


def _cam_dests() -> tuple[str, ...]:
    from .cmd_cam import OPTIONAL, SHEET
    return tuple(dest for _, dest, _ in SHEET + OPTIONAL) + ("law", "return_law", "phase")


def _given(args: argparse.Namespace, dests: tuple[str, ...]) -> bool:
    return any(getattr(args, d, None) is not None for d in dests)


def _cam(args: argparse.Namespace, design, idle: float) -> dict[str, Any]:
    """The cam's inputs as the file keeps them, checked by designing the cam against the
    linkage as ``shaper cam`` does."""
    from ..cam.file import cam_to_dict
    from .cmd_cam import cam_from_inputs, cam_inputs_from_args
    given = cam_inputs_from_args(args)
    cam_from_inputs(given, design, idle, args)
    return cam_to_dict(*given)
