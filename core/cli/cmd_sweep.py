"""``shaper sweep``: the figures of a whole family of designs, one row per design."""
from __future__ import annotations

import argparse
import json
import math
import sys
from typing import TYPE_CHECKING, Any, Callable, Iterator

from core.base.errors import DesignError
from core.space.names import PARAMETERS
from .common import (add_design_options, add_load_options, add_speed_options, design_error_text,
                     number, option_name, rpms_from_args, spec_from_args, spec_option)
from .loads import loads_given, masses_from_args
from .allocator import keep_freed_memory
from .output import write_output
from .streaming import Progress

if TYPE_CHECKING:
    import numpy as np

    from core.linkage.spec import Spec
    from core.space.sweep import Evaluation

HELP = "figures of many designs over varied parameters"
DESCRIPTION = ("Vary one or more design parameters over a range and report, for every combination, "
               "whether the design is valid (and why not), its measured K and stroke, maximum "
               "cutting and return speed and acceleration per crank speed, maximum pressure angle "
               "and, with loads, mean and peak crank torque and flywheel per speed. Every peak is "
               "an exact extremum of the closed-form motion. NAME is one of "
               + ", ".join(PARAMETERS) + " (guide: height above O4 in mm).")
EXAMPLES = ("shaper sweep --crank 100 --K 1.46 --stroke 312 --rod-ratio 0.3 "
            "--vary rod-ratio=0.2:1:9 --vary guide=450:700:6 --rpm 40 --csv -",
            "shaper sweep --dims 100,386.37,579.56 --vary crank=80:120:5 --json")


def configure(parser: argparse.ArgumentParser) -> None:
    add_design_options(parser)
    parser.add_argument("--vary", action="append", metavar="NAME=LO:HI:COUNT", required=True,
                        help="a parameter and its range (COUNT evenly spaced values); repeat to "
                             "vary several (every combination, the first varying slowest)")
    add_speed_options(parser)
    add_load_options(parser, required=False)
    out = parser.add_mutually_exclusive_group()
    out.add_argument("--csv", metavar="FILE|-", help="write CSV to FILE or stdout (the default)")
    out.add_argument("--json", action="store_true", help="print JSON, one object per design")
    parser.add_argument("--progress", action="store_true",
                        help="print a progress line on stderr at most every second, and one at the end "
                             "(without it: a line every 5 s when stderr is not a terminal)")


BLOCK = 50_000          # designs evaluated and formatted at a time, at most
BLOCK_CELLS = 400_000   # output cells (designs × columns) formatted at a time, at most
# Designs per block with loads (0.2 ms of CPU each at 1 speed, 0.9 ms at 16 speeds, rod
# variant): a progress line every few seconds.
LOADED_BLOCK = 2_000


def block_size(names: list[str], rpms, masses) -> int:
    """Designs per block: ``BLOCK``, fewer when many speeds make many columns, so that the
    text of a block (a Python string per cell while it is formatted) stays a few tens of MB."""
    per_speed = 3 + (3 if masses is not None else 0)
    columns = len(names) + 6 + per_speed * max(len(list(rpms)), 1)
    return min(BLOCK if masses is None else LOADED_BLOCK, max(1_000, BLOCK_CELLS // columns))


def parse_vary(texts: list[str], spec: Spec, with_count: bool) -> dict[str, tuple]:
    """``NAME=LO:HI[:COUNT]`` options → {typed name: (low, high[, count])}, in order."""
    from core.space.sweep import MAX_COUNT, check_vary
    out: dict[str, tuple] = {}
    shape = "NAME=LO:HI:COUNT" if with_count else "NAME=LO:HI"
    for text in texts:
        name, sep, rest = text.partition("=")
        parts = rest.split(":")
        if not sep or len(parts) != (3 if with_count else 2):
            raise DesignError("vary", text, f"must be {shape}")
        check_vary(name, spec)
        if name in out:
            raise DesignError("vary", text, f"varies {name} twice")
        low, high = number("vary", parts[0]), number("vary", parts[1])
        if high < low:
            raise DesignError("vary", text, "needs LO ≤ HI")
        if with_count:
            try:
                count = int(parts[2])
            except ValueError:
                raise DesignError("vary", text, "COUNT must be a whole number") from None
            if not 1 <= count <= MAX_COUNT or (count == 1) != (high == low):    # LO = HI: one row, not copies
                raise DesignError("vary", text, f"COUNT must be 2 to {MAX_COUNT} (1 when LO = HI)")
            out[name] = (low, high, count)
        else:
            out[name] = (low, high)
    if "rod" in out and "rod-ratio" in out:
        raise DesignError("vary", "rod", "vary either rod or rod-ratio, not both")
    return out


class _Variant:
    """Just enough of a design for ``masses_from_args`` (it only asks for the variant)."""

    def __init__(self, spec: Spec, varied: dict[str, tuple]) -> None:
        rod = spec.variant == "rod" or "rod" in varied or "rod-ratio" in varied
        self.rod = 1.0 if rod else None


def figure_columns(ev: Evaluation) -> list[tuple[str, np.ndarray]]:
    """(column, values) of every figure, per design; NaN where undefined."""
    import numpy as np
    several = ev.rpm.size > 1
    tag = (lambda rpm: f"@{rpm:g}") if several else (lambda rpm: "")
    with np.errstate(invalid="ignore"):     # an invalid crank ≥ frame has no θ (NaN, blank)
        theta = np.degrees(ev.designs.theta)
    cols: list[tuple[str, np.ndarray]] = [
        ("K", ev.peaks.time_ratio), ("stroke_mm", ev.peaks.stroke_mm),
        ("theta_deg", np.where(ev.valid.reshape(-1), theta, np.nan))]
    for key in ("v_work_max_m_s", "v_return_max_m_s", "a_max_m_s2"):
        cols += [(key + tag(r), ev.figures[key][:, j]) for j, r in enumerate(ev.rpm)]
    pressure = ev.peaks.pressure_max
    cols.append(("pressure_angle_max_deg",
                 np.degrees(pressure) if pressure is not None else np.full(ev.valid.size, np.nan)))
    if ev.dynamics is not None:
        for key in ("mean_torque_N_m", "max_torque_N_m", "flywheel_inertia_kg_m2"):
            cols += [(key + tag(r), ev.dynamics[key][:, j]) for j, r in enumerate(ev.rpm)]
    return cols


def varied_column(name: str) -> str:
    """The column of a varied parameter: its name as typed; K is ``K_nominal`` beside the
    measured ``K``."""
    return "K_nominal" if name == "K" else name


def reasons(ev: Evaluation, option: Callable[[str], str] = option_name) -> list[str]:
    """One line per design, "" when valid, else the CLI's message for that design alone,
    naming the option as ``option(parameter)`` does: as ``analyze`` of that design alone
    would (``--dims (L3)``, ``--guide``)."""
    import numpy as np
    out = [""] * ev.valid.size
    names: dict[str, str] = {}          # option(parameter), once per parameter
    for i in np.flatnonzero(~ev.valid.reshape(-1)).tolist():
        error = ev.error(i)
        name = names.get(error.parameter)  # type: ignore[union-attr]
        if name is None:
            name = names[error.parameter] = option(error.parameter)  # type: ignore[union-attr]
        out[i] = design_error_text(error, name)  # type: ignore[arg-type]
    return out


def csv_header(names: list[str], ev: Evaluation) -> str:
    figures = [c for c, _ in figure_columns(ev)]
    return ",".join([varied_column(n) for n in names] + ["valid", "reason"] + figures) + "\n"


def csv_rows(names: list[str], values: dict[str, np.ndarray], ev: Evaluation,
             option: Callable[[str], str] = option_name) -> str:
    """CSV lines (no header) of the designs in ``ev``; empty cells where undefined.

    The numbers of a row are formatted together, by the vectorized "%.10g" of
    ``core.files.numtext``; only the joins with the text columns are per row."""
    import numpy as np
    valid = np.where(ev.valid.reshape(-1), "true", "false")
    why = [_quote(r) if r else r for r in reasons(ev, option)]    # "" for a valid design
    if not valid.size:
        return ""
    varied = _format_rows([values[PARAMETERS[n]] for n in names], valid.size)
    figures = _format_rows([v for _, v in figure_columns(ev)], valid.size)
    if varied is None:
        lines = [f"{v},{w},{f}" for v, w, f in zip(valid.tolist(), why, figures)]
    else:
        lines = [f"{a},{v},{w},{f}" for a, v, w, f in zip(varied, valid.tolist(), why, figures)]
    return "\n".join(lines) + "\n"


def _format_rows(columns: list[np.ndarray], size: int) -> list[str] | None:
    """Per row, the columns' values with 10 significant digits joined by commas, an empty
    cell where a value is not finite; None without columns."""
    import numpy as np

    from core.files.numtext import g10_rows
    if not columns:
        return None
    data = np.column_stack([np.asarray(c, dtype=float).reshape(-1) for c in columns])
    data[~np.isfinite(data)] = np.nan
    return g10_rows(data).split("\n")[:size]


def json_rows(names: list[str], values: dict[str, np.ndarray], ev: Evaluation,
              option: Callable[[str], str] = option_name) -> list[str]:
    """One JSON object (text) per design, with the keys of the CSV columns."""
    cols = figure_columns(ev)
    why = reasons(ev, option)
    valid = ev.valid.reshape(-1)
    out = []
    for i in range(valid.size):
        row: dict[str, Any] = {varied_column(n): float(values[PARAMETERS[n]][i]) for n in names}
        row.update(valid=bool(valid[i]), reason=why[i])
        row.update({c: _number(v[i]) for c, v in cols})
        out.append(json.dumps(row, ensure_ascii=False, allow_nan=False))
    return out


def _number(value: float) -> float | None:
    value = float(value)
    return value if math.isfinite(value) else None


def _quote(text: str) -> str:
    return '"' + text.replace('"', '""') + '"' if any(c in text for c in ',"\n') else text


def inputs(args: argparse.Namespace, with_count: bool):
    """(spec, varied ranges by typed name, speeds, loads or None) from the options."""
    spec = spec_from_args(args)
    varied = parse_vary(args.vary, spec, with_count)
    rpms = rpms_from_args(args)
    masses = masses_from_args(args, _Variant(spec, varied), required=False) \
        if loads_given(args) else None  # type: ignore[arg-type]
    return spec, varied, rpms, masses


def run(args: argparse.Namespace) -> int:
    from core.space.sweep import grid
    keep_freed_memory()                     # its chunks' arrays are not faulted in anew
    spec, varied, rpms, masses = inputs(args, with_count=True)
    values = grid({PARAMETERS[n]: r for n, r in varied.items()})
    names = list(varied)
    option = lambda parameter: spec_option(parameter, spec, args)  # noqa: E731
    size = next(iter(values.values())).size
    with Progress(f"sweeping {size} designs", size, lines=args.progress, log=True) as progress:
        pieces = _pieces(spec, values, names, rpms, masses, as_json=args.json, option=option,
                         progress=progress.update)
        if args.json:                           # JSON goes to stdout block by block
            for piece in pieces:
                sys.stdout.write(piece)
        else:                                   # CSV: stdout, or a file written as it streams
            write_output("--csv", args.csv or "-", pieces)
    return 0


def _pieces(spec: Spec, values: dict[str, np.ndarray], names: list[str], rpms, masses,
            as_json: bool, option: Callable[[str], str] = option_name,
            progress: Callable[[int], None] | None = None) -> Iterator[str]:
    """The output text, one block of designs at a time (:func:`block_size`): memory is bounded
    by the block (its figures and its text), not by the number of designs or speeds.
    ``progress(designs done)`` is called after each block."""
    from core.space.sweep import evaluate
    size = next(iter(values.values())).size
    step = block_size(names, rpms, masses)
    for start in range(0, size, step):
        block = {k: v[start:start + step] for k, v in values.items()}
        ev = evaluate(spec, block, rpms, masses)
        if as_json:
            yield ("[\n" if start == 0 else ",\n") + ",\n".join(json_rows(names, block, ev, option))
        else:
            yield (csv_header(names, ev) if start == 0 else "") + csv_rows(names, block, ev, option)
        del ev
        if progress is not None:
            progress(min(start + step, size))
    if as_json:
        yield "\n]\n"
