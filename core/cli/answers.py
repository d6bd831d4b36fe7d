"""The answer key of a class (``shaper class``, issue 41): per student what ``shaper synth``,
``analyze``, ``dynamics``, ``cam`` and ``gear`` print with ``--json`` for the student's
design file, and the row of figures a teacher grades by.

The JSON is made by each subcommand's own ``json_document`` from its own parser's reading
of ``--design FILE --json``, the very path ``shaper COMMAND --design FILE --json`` takes,
so the key and a student's own run of the command cannot disagree.
"""
from __future__ import annotations

import csv
import io
from importlib import import_module
from typing import Any, Mapping, Sequence

from core.base.figure_text import figure_text
from core.files.io import csv_text

COMMANDS = ("synth", "analyze", "dynamics", "cam", "gear")


def command_json(command: str, design_path: str) -> dict[str, Any]:
    """What ``shaper COMMAND --design design_path --json`` prints, as a dict."""
    from . import build_parser
    module = import_module(f"{__package__}.cmd_{command}")
    args = build_parser({command: module}).parse_args([command, "--design", design_path, "--json"])
    return module.json_document(args)


def answer_entry(student: str, number: str, folder: str, design_path: str) -> dict[str, Any]:
    """One student's object of answer-key.json."""
    entry: dict[str, Any] = {"student": student, "student_number": number, "folder": folder}
    for command in COMMANDS:
        entry[command] = command_json(command, design_path)
    return entry


def failed_checks(entry: Mapping[str, Any]) -> list[str]:
    """The checks a student's design fails: the gear's by name, the cam's allowance."""
    failed = [c["name"] for c in entry["gear"]["checks"] if not c["ok"]]
    if not entry["cam"]["within_allowance"]:
        failed.insert(0, "cam_pressure_angle")
    return failed


def speed_count(entries: Sequence[Mapping[str, Any]]) -> int:
    return max((len(e["analyze"]["speeds"]) for e in entries), default=0)


# (column, unit) of the figures common to every student, from the JSON: (command, path)
FIGURES = (
    ("theta", "deg", ("synth", "theta_deg")), ("L1", "mm", ("synth", "crank_mm")),
    ("L2", "mm", ("synth", "frame_mm")), ("L3", "mm", ("synth", "lever_mm")),
    ("L4", "mm", ("synth", "rod_mm")), ("h", "mm", ("synth", "h_mm")),
    ("K", "", ("analyze", "K")), ("H", "mm", ("analyze", "stroke_mm")),
    ("r0", "mm", ("cam", "base_radius_mm")), ("a_cam", "mm", ("cam", "center_distance_mm")),
    ("r_roller", "mm", ("cam", "roller_mm")),
    ("x1", "", ("gear", "gear1", "shift_factor")), ("x2", "", ("gear", "gear2", "shift_factor")),
    ("a'", "mm", ("gear", "pair", "centre_mm")),
    ("alpha'", "deg", ("gear", "pair", "working_pressure_angle_deg")),
    ("epsilon", "", ("gear", "pair", "contact_ratio")),
)
# per speed: (column, unit, (command, key in that speed's object))
PER_SPEED = (("v_work_max", "m/s", ("analyze", "v_work_max_m_s")),
             ("v_return_max", "m/s", ("analyze", "v_return_max_m_s")),
             ("a_max", "m/s²", ("analyze", "a_max_m_s2")),
             ("M_max", "N·m", ("dynamics", "max_torque_N_m")),
             ("M_mean", "N·m", ("dynamics", "mean_torque_N_m")),
             ("dW_max", "J", ("dynamics", "energy_fluctuation_J")),
             ("J_F", "kg·m²", ("dynamics", "flywheel_inertia_kg_m2")),
             # the flywheel to add beside the other rotating parts (equal to J_F without them):
             # a student who counted a motor's rotor answers this one
             ("J_F_needed", "kg·m²", ("dynamics", "flywheel_inertia_needed_kg_m2")))


# each column's kind of figure (``core.base.figure_text``): the answer key's PDF writes a figure
# exactly as the report and ``shaper synth/analyze/dynamics/cam/gear`` print it
KINDS = {"theta": "angle", "L1": "length", "L2": "length", "L3": "length", "L4": "length",
         "h": "length", "K": "ratio", "H": "length", "r0": "length", "a_cam": "length",
         "r_roller": "length", "x1": "gear_factor", "x2": "gear_factor", "a'": "gear_length",
         "alpha'": "gear_angle", "epsilon": "gear_factor", "v_work_max": "speed",
         "v_return_max": "speed", "a_max": "acceleration", "M_max": "torque", "M_mean": "torque",
         "dW_max": "energy", "J_F": "inertia", "J_F_needed": "inertia"}


def cell_text(name: str, value: float | None) -> str:
    """A figure of column ``name`` as a table writes it: its kind's precision; the speed
    as given (72, not 72.0000); '—' for a figure the design has not (no rod)."""
    if value is None:
        return "—"
    if name == "n":
        return f"{value:g}"
    return figure_text(KINDS[name], value)


def _heading(name: str, unit: str) -> str:
    return f"{name} ({unit})" if unit else name


def key_header(speeds: int) -> list[str]:
    """answer-key.csv's header: who, the figures, per speed its own, the failed checks."""
    header = ["student", "student_number", "class", "folder"]
    header += [_heading(name, unit) for name, unit, _ in FIGURES]
    for i in range(1, speeds + 1):
        header.append(f"n{i} (r/min)")
        header += [_heading(f"{name}_{i}", unit) for name, unit, _ in PER_SPEED]
    return header + ["failed_checks"]


def key_values(entry: Mapping[str, Any], group: str, speeds: int) -> list[Any]:
    """A student's row of answer-key.csv as values (numbers stay numbers; None: none)."""
    row: list[Any] = [entry["student"], entry["student_number"], group, entry["folder"]]
    for _, _, path in FIGURES:
        value: Any = entry
        for key in path:
            value = value[key]
        row.append(value)
    motion, forces = entry["analyze"]["speeds"], entry["dynamics"]["speeds"]
    for i in range(speeds):
        if i < len(motion):
            row.append(motion[i]["rpm"])
            row += [(motion if command == "analyze" else forces)[i][key] for _, _, (command, key) in PER_SPEED]
        else:
            row += [None] * (1 + len(PER_SPEED))
    return row + [" ".join(failed_checks(entry))]


def key_csv(entries: Sequence[Mapping[str, Any]], groups: Sequence[str]) -> str:
    """answer-key.csv: one row per student, numbers at full precision, text guarded as
    every CSV of the tool guards it (``core.files.io.csv_text``: as a whole and per name)."""
    speeds = speed_count(entries)
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(key_header(speeds))
    for entry, group in zip(entries, groups):
        writer.writerow(["" if v is None else csv_text(v) if isinstance(v, str) else repr(float(v))
                         for v in key_values(entry, group, speeds)])
    return out.getvalue()
