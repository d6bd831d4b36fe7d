"""What every ``shaper`` subcommand shares: options and parsing (output: ``output``).

The design can come from options (``--crank/--K/--stroke`` or ``--dims``) or
from a design file (``--design``), never both. Numbers are parsed here so a
bad one is reported as a ``DesignError`` naming the core parameter, which
``option_name`` turns into the option the user typed.
"""
from __future__ import annotations

import argparse
import math
import re
import sys
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.base.errors import DesignError, long_integer_text
from ..version import version_text

if TYPE_CHECKING:
    import numpy as np

    from core.linkage.geometry import Design
    from core.linkage.spec import Spec

# numpy and the engine are imported by the functions that use them, not with this module:
# every command imports it, and ``shaper COMMAND --help`` prints only its parser's texts
# (``shaper gear --help`` took numpy and the linkage, about 0.2 s, to print them; issue 43
# item 5).

DEFAULT_RPMS = ("40", "60")

# core parameter → the option that sets it (used for every error message)
OPTION_NAMES = {
    "crank": "--crank", "time_ratio": "--K", "stroke": "--stroke", "frame": "--dims",
    "lever": "--dims", "guide": "--guide", "guide_height": "--guide", "rod": "--rod",
    "rod_length": "--rod", "rod_ratio": "--rod-ratio", "rod_side": "--rod-side", "rpm": "--rpm",
    "step": "--step", "angles": "--angles", "dims": "--dims", "design": "--design",
    "lever_mass_kg": "--lever-mass", "lever_inertia_kg_m2": "--lever-inertia",
    "lever_cg_mm": "--lever-cg", "ram_mass_kg": "--ram-mass", "ram_cg_mm": "--ram-cg",
    "rod_mass_kg": "--rod-mass", "block_mass_kg": "--block-mass", "crank_mass_kg": "--crank-mass",
    "cut_force_N": "--cut-force", "cut_height_mm": "--cut-height", "idle_fraction": "--idle",
    "delta": "--delta", "gravity": "--no-gravity", "lever_weight_N": "--lever-weight",
    "ram_weight_N": "--ram-weight", "guide_length_mm": "--guide-length", "rotors": "--rotor",
    "rotor_inertia_kg_m2": "--rotor", "rotor_ratio": "--rotor",
}

# (option, dest, metavar, help) of the load inputs; dest is the MassProperties field
# (read by loads.masses_from_args).
LOAD_OPTIONS = (
    ("--lever-mass", "lever_mass_kg", "KG", "slotted lever mass, kg (or --lever-weight)"),
    ("--lever-weight", "lever_weight_N", "N",
     "slotted lever weight G4, N, as the task book states it (instead of --lever-mass; mass = G4/9.81)"),
    ("--lever-inertia", "lever_inertia_kg_m2", "KGM2", "lever moment of inertia about its centre of mass, kg·m²"),
    ("--lever-cg", "lever_cg_mm", "MM",
     "lever centre of mass from O4 along the lever (the task book's l_O4S4), mm (default L3/2)"),
    ("--ram-mass", "ram_mass_kg", "KG", "ram plus tool mass, kg (or --ram-weight)"),
    ("--ram-weight", "ram_weight_N", "N",
     "ram plus tool weight G6, N, as the task book states it (instead of --ram-mass; mass = G6/9.81)"),
    ("--ram-cg", "ram_cg_mm", "DX,DY",
     "ram centre of mass S6 from the ram joint C, mm: DX in the cutting direction, DY up (give the "
     "task book's x_S6, y_S6 in this frame; default 0,0; write --ram-cg=-5,3 for a leading minus)"),
    ("--rod-mass", "rod_mass_kg", "KG", "connecting rod mass, kg (rod variant; default 0)"),
    ("--block-mass", "block_mass_kg", "KG", "sliding block at the crank pin, kg (default 0)"),
    ("--crank-mass", "crank_mass_kg", "KG", "balanced crank mass, kg (default 0)"),
    ("--cut-force", "cut_force_N", "N", "cutting force on the tool, N"),
    ("--cut-height", "cut_height_mm", "MM", "tool point below the guide line, mm (default 0)"),
    ("--idle", "idle_fraction", "FRACTION",
     "uncut run-in and run-out, each as a fraction of the stroke (default 0.05)"),
    ("--delta", "delta", "D", "coefficient of speed fluctuation δ for the flywheel (default 1/30)"),
    ("--guide-length", "guide_length_mm", "MM",
     "length of the ram's guide (the column's ways), centred on the ram's mid-travel, mm "
     "(at least 1, default the stroke H); a guide reaction outside it is carried by its two ends"),
)
ROTOR_HELP = ("another rotating part reduced to the crank for the flywheel: its inertia J in kg·m² "
              "and its speed over the crank's, J:RATIO (e.g. 0.02:15 for a motor rotor at 15 times "
              "the crank speed), or J:gear for the pinion shaft of the gear pair (ratio z2/z1: the "
              "design file's, or the one --z1, --z2 … give where the command takes them); repeat for each part. J_F needed = ΔW_max/(ω²δ) − Σ J·RATIO²")

# argparse reads "-1e5" as an unknown option; accept every float spelling as a value.
_NEGATIVE_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$", re.I)


class UsageError(Exception):
    """Bad command-line words; reported as one line with exit status 2."""


class Parser(argparse.ArgumentParser):
    """One-line errors instead of usage + message; negative numbers are values."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = _NEGATIVE_NUMBER

    def error(self, message: str) -> None:  # type: ignore[override]
        missing = re.match(r"the following arguments are required: (.+)$", message)
        if missing:     # name the option first, like every other message
            first, *rest = missing.group(1).split(", ")
            message = f"{first}: required" + (f" (also {', '.join(rest)})" if rest else "")
        raise UsageError(message)


class VersionAction(argparse._VersionAction):
    """``--version``, which looks the installed version up only when asked: reading
    the package metadata (``importlib.metadata``) costs every other command 15 ms."""

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace,
                 values: Any, option_string: str | None = None) -> None:
        self.version = version_text(parser.prog)
        super().__call__(parser, namespace, values, option_string)


def option_name(parameter: str) -> str:
    return OPTION_NAMES.get(parameter, "--" + parameter.replace("_", "-"))


# Every character str.splitlines() breaks at: shown escaped, so an error stays one line
# whatever the user typed (an argument or a file name may hold a newline).
_LINE_BREAKS = "\n\r\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029"


def one_line(text: str) -> str:
    return "".join(repr(ch)[1:-1] if ch in _LINE_BREAKS else ch for ch in text)


def fail(message: str, status: int = 2) -> int:
    try:
        print(f"shaper: error: {one_line(message)}", file=sys.stderr)
    except (OSError, ValueError):
        pass
    return status


# ---- numbers ---------------------------------------------------------------
def number(parameter: str, text: str) -> float:
    """``text`` as a float; a bad one is a DesignError naming ``parameter``."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        raise DesignError(parameter, text, "must be a number") from None
    if not math.isfinite(value):
        raise DesignError(parameter, text, "must be a finite number")
    return value


def number_list(parameter: str, text: str) -> list[float]:
    parts = [p for p in text.split(",") if p.strip()]
    if not parts:
        raise DesignError(parameter, text, "must be a comma-separated list of numbers")
    return [number(parameter, p) for p in parts]


# ---- design ----------------------------------------------------------------
def add_design_options(parser: argparse.ArgumentParser, allow_dims: bool = True,
                       allow_file: bool = True) -> None:
    group = parser.add_argument_group("design (give --crank, --K and --stroke"
                                      + (", or --dims" if allow_dims else "")
                                      + (", or --design FILE" if allow_file else "") + ")")
    group.add_argument("--crank", metavar="MM", help="crank length L1, mm")
    group.add_argument("--K", dest="time_ratio", metavar="K",
                       help="time ratio K = working time / return time (> 1)")
    group.add_argument("--stroke", metavar="MM", help="ram stroke H, mm")
    if allow_dims:
        group.add_argument("--dims", metavar="L1,L2,L3[,L4]",
                           help="direct dimensions in mm instead of --crank/--K/--stroke")
    if allow_file:
        group.add_argument("--design", metavar="FILE",
                           help="a design file as the GUI saves it (its speeds, step and loads are "
                                "used unless given here)")
    group.add_argument("--guide", metavar="chord|sagitta|MM",
                       help="ram guide line: a rule, or its height above the lever pivot O4 in mm "
                            "(default chord)")
    group.add_argument("--rod", metavar="MM", help="connecting-rod length L4, mm (rod variant)")
    group.add_argument("--rod-ratio", metavar="R", help="rod length as a ratio L4/L3 (rod variant)")
    group.add_argument("--rod-side", choices=("trailing", "leading"),
                       help="ram joint behind (trailing, default) or ahead of (leading) the lever "
                            "tip while cutting")


def add_speed_options(parser: argparse.ArgumentParser) -> None:
    from core.linkage.limits import MAX_RPM, MAX_SPEEDS, MIN_RPM
    parser.add_argument("--rpm", nargs="+", metavar="RPM",
                        help=f"1 to {MAX_SPEEDS} crank speeds, {MIN_RPM:g} to {MAX_RPM:g} r/min "
                             "(default 40 60, or the design file's)")


def add_angle_options(parser: argparse.ArgumentParser, what: str) -> None:
    from core.linkage.limits import MAX_SAMPLES, MAX_STEP_DEG, MIN_STEP_DEG
    angles = parser.add_mutually_exclusive_group()
    angles.add_argument("--step", metavar="DEG",
                        help=f"crank-angle step of {what}, {MIN_STEP_DEG:g} to {MAX_STEP_DEG:g} degrees "
                             f"(default 1, or the design file's); at most {MAX_SAMPLES} angles × speeds")
    angles.add_argument("--angles", metavar="A,B,…", help=f"explicit crank angles of {what}, degrees")


def add_load_options(parser: argparse.ArgumentParser, required: bool) -> None:
    note = " (required unless --design has loads)" if required else ""
    group = parser.add_argument_group("masses and loads" + note)
    for option, dest, metavar, text in LOAD_OPTIONS:
        group.add_argument(option, dest=dest, metavar=metavar, help=text)
    group.add_argument("--rotor", dest="rotors", action="append", metavar="J:RATIO", help=ROTOR_HELP)
    group.add_argument("--no-gravity", action="store_true", help="leave the links' weights out")


def design_file(args: argparse.Namespace) -> dict[str, Any] | None:
    """The loaded ``--design`` file (read once and cached on ``args``), or None."""
    path = getattr(args, "design", None)
    if path is None:
        return None
    cached = getattr(args, "_design_doc", None)
    if cached is None:
        from core.files.io import load_design
        cached = load_design(path)
        args._design_doc = cached
        if not getattr(args, "defaults_said", False):       # else said by the caller (shaper class's --base)
            from .notes import say_defaulted
            say_defaulted("--design", path, cached)     # once, as the file is read
    return cached


def spec_from_args(args: argparse.Namespace) -> Spec:
    """The inputs as a :class:`Spec`, from the options or from ``--design``."""
    from core.linkage.spec import Spec
    synth_given = [v is not None for v in (args.crank, args.time_ratio, args.stroke)]
    dims = getattr(args, "dims", None)
    doc = design_file(args)
    if doc is not None:
        clash = [name for name, given in zip(("--crank", "--K", "--stroke"), synth_given) if given]
        clash += ["--dims"] if dims is not None else []
        if clash:
            raise UsageError(f"--design: give either a design file or {clash[0]}, not both")
        spec: Spec = doc["spec"]
    elif dims is not None:
        if any(synth_given):
            raise UsageError("--dims: give either --dims or --crank/--K/--stroke, not both")
        values = number_list("dims", dims)
        if len(values) not in (3, 4):
            raise DesignError("dims", dims, "must be L1,L2,L3 or L1,L2,L3,L4 in mm")
        spec = Spec(mode="dimensions", crank=values[0], frame=values[1], lever=values[2])
        if len(values) == 4:
            if args.rod is not None or args.rod_ratio is not None:
                raise UsageError("--dims: give L4 either in --dims or with --rod/--rod-ratio, not both")
            spec = replace(spec, variant="rod", rod_input="length", rod_length=values[3])
    else:
        for option, given in zip(("--crank", "--K", "--stroke"), synth_given):
            if not given:
                alternatives = "--dims or --design" if dims is None and hasattr(args, "dims") else "--design"
                raise UsageError(f"{option}: required (or use {alternatives})")
        spec = Spec(crank=number("crank", args.crank), time_ratio=number("time_ratio", args.time_ratio),
                    stroke=number("stroke", args.stroke))
    return _apply_mechanism_options(spec, args)


def _apply_mechanism_options(spec: Spec, args: argparse.Namespace) -> Spec:
    changes: dict[str, Any] = {}
    if args.guide is not None:
        if args.guide in ("chord", "sagitta"):
            changes["guide_rule"] = args.guide
        else:
            changes.update(guide_rule="height", guide_height=number("guide", args.guide))
    if args.rod is not None and args.rod_ratio is not None:
        raise UsageError("--rod: give either --rod or --rod-ratio, not both")
    if args.rod is not None:
        changes.update(variant="rod", rod_input="length", rod_length=number("rod", args.rod))
    if args.rod_ratio is not None:
        changes.update(variant="rod", rod_input="ratio", rod_ratio=number("rod_ratio", args.rod_ratio))
    if args.rod_side is not None:
        changes["rod_side"] = args.rod_side
    spec = replace(spec, **changes)
    if args.rod_side is not None and spec.variant != "rod":
        raise UsageError("--rod-side: only for the rod variant; give --rod or --rod-ratio too")
    return spec


def design_from_args(args: argparse.Namespace) -> Design:
    """The design the options describe; a DesignError is re-raised as a UsageError naming
    the option of *this* subcommand that holds the bad value (``--dims (L2)`` …)."""
    spec = spec_from_args(args)
    try:
        return spec.design()
    except DesignError as exc:
        raise UsageError(design_error_text(exc, spec_option(exc.parameter, spec, args))) from None


def given_text(value: object) -> str:
    """A value as the user would have typed it: 0 for 0.0, 1000000000 for 1e9 (the shortest
    text that reads back as the same float, without a trailing ".0")."""
    if isinstance(value, float):
        text = repr(value)
        return text[:-2] if text.endswith(".0") else text
    if type(value) is int:
        return long_integer_text(value) or str(value)
    return str(value)


def design_error_text(exc: DesignError, option: str | None = None) -> str:
    """The one-line message for a DesignError: option, what is allowed, the value given."""
    text = given_text(exc.value)
    value = text if len(text) <= 60 else text[:57] + "..."
    return f"{option or option_name(exc.parameter)}: {exc.allowed} (got {value})"


# Direct dimensions: which value of --dims a core parameter is.
_DIMS_POSITION = {"crank": "L1", "frame": "L2", "lever": "L3"}
# Synthesis: the derived lengths come from these inputs.
_SYNTH_SOURCE = {"frame": "--K", "lever": "--stroke"}


def spec_option(parameter: str, spec: Spec, args: argparse.Namespace) -> str:
    """The option that set ``parameter`` of ``spec`` in this command line (``--dims (L3)``
    for a value of --dims, as every subcommand names it)."""
    from_dims = getattr(args, "dims", None) is not None
    if from_dims and parameter in _DIMS_POSITION:
        return f"--dims ({_DIMS_POSITION[parameter]})"
    if from_dims and parameter in ("time_ratio", "stroke"):
        return "--dims"           # K and H are implied by L1, L2, L3
    if from_dims and parameter in ("rod", "rod_length") and args.rod is None \
            and getattr(args, "rod_ratio", None) is None and spec.variant == "rod":
        return "--dims (L4)"
    if design_file(args) is not None and parameter in ("crank", "time_ratio", "stroke", "frame",
                                                        "lever", "mode", "variant"):
        return "--design"         # a value of the file, not of an option
    if spec.mode == "synthesis" and parameter in _SYNTH_SOURCE:
        return _SYNTH_SOURCE[parameter]
    return option_name(parameter)


def request_from_args(args: argparse.Namespace) -> tuple[np.ndarray, list[float]]:
    """The crank angles (rad) and speeds of a table, refused with the angle option if it
    would hold more than ``core.linkage.kinematics.MAX_SAMPLES`` samples."""
    from core.linkage.kinematics import check_request
    rpms = rpms_from_args(args)
    angles = angles_from_args(args)
    if args.angles is not None:
        check_request(angles.size, len(rpms), "angles", angles.size)
    else:
        check_request(angles.size, len(rpms), "step", _step_value(args))
    return angles, rpms


def _step_value(args: argparse.Namespace) -> float:
    """``--step``, else the design file's step, else 1°."""
    if args.step is not None:
        return number("step", args.step)
    doc = design_file(args)
    return doc["step_deg"] if doc is not None else 1.0


def rpms_from_args(args: argparse.Namespace) -> list[float]:
    if args.rpm is not None:
        return [number("rpm", r) for r in args.rpm]
    doc = design_file(args)
    if doc is not None:
        return list(doc["rpm"])
    return [float(r) for r in DEFAULT_RPMS]


def angles_from_args(args: argparse.Namespace) -> np.ndarray:
    """Crank angles in rad from ``--angles`` or ``--step`` (or the design file's step)."""
    import numpy as np

    from core.linkage.kinematics import check_angles, crank_angles
    if args.angles is not None:
        return check_angles(np.array(number_list("angles", args.angles)))
    return crank_angles(_step_value(args))


def library_path(library: str | None) -> Path:
    """The library ``--library`` names (see ``resolve_path``); an empty one is refused
    rather than taken for the default library."""
    from core.library.store import resolve_path      # sqlite3 and platformdirs: only when needed
    if library is not None and not library.strip():
        raise UsageError("--library: the path is empty")
    return resolve_path(library)


NOTES: list[str] = []      # notes printed on stderr once a command has succeeded


def note_read_only(library) -> None:
    """A note for when a library (``core.library.Library``) could only be opened for
    reading, printed if the command succeeds (a failure stays one line); a write to it
    is refused in one line saying why."""
    if library.read_only is not None:
        NOTES.append(f"shaper: note: {library.path} is opened read-only: {library.read_only}")


def whole_number(option: str, text: str, low: int = 0, high: int = 10 ** 12) -> int:
    """An integer option from ``low`` to ``high`` (a run of 5000 digits is refused as one
    short line, not echoed, and never reaches SQLite or numpy as an overflow)."""
    shown = text if len(text) <= 40 else text[:37] + "..."
    try:
        value = int(text.strip()) if len(text) <= 40 else None
    except ValueError:
        value = None
    if value is None or not low <= value <= high:
        raise UsageError(f"{option}: must be a whole number from {low} to {high:g} (got {shown!r})")
    return value
