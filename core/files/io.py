"""Files: curve CSV and design JSON, written atomically, read defensively.

The last level of core: it formats results, it never computes them. The GUI
and the CLI both write through here, so their CSV files are identical.
"""
from __future__ import annotations

import json
import math
import os
import re
from pathlib import Path
from typing import Any, Iterable, Iterator

import numpy as np

from .atomic import atomic_write
# Design files are read in design_file; re-exported here, where they have always been.
from .design_file import (FILE_FORMAT, FILE_VERSION, load_design, masses_from_dict,  # noqa: F401
                          masses_to_dict, parse_design)
from core.linkage.kinematics import Motion
from core.linkage.spec import Spec

CURVE_COLUMNS = ("rpm", "crank_deg", "time_s", "ram_x_mm", "ram_v_m_s", "ram_a_m_s2",
                 "lever_deg", "lever_omega_rad_s", "lever_alpha_rad_s2")
EXTRA_COLUMNS = ("slide_v_m_s", "coriolis_m_s2")
ROD_COLUMNS = ("rod_deg", "rod_omega_rad_s", "rod_alpha_rad_s2", "pressure_angle_deg")


def curve_table(motion: Motion) -> tuple[tuple[str, ...], np.ndarray]:
    """Long-form table, one row per (rpm, angle): column names and a 2-D array."""
    m, n = motion.ram_v.shape
    tile = lambda a: np.broadcast_to(a, (m, n))  # noqa: E731
    columns: list[tuple[str, np.ndarray]] = [
        ("rpm", tile(motion.rpm[:, None])),
        ("crank_deg", tile(np.degrees(motion.crank_angle))),
        ("time_s", motion.time),
        ("ram_x_mm", tile(motion.ram_x)),
        ("ram_v_m_s", motion.ram_v),
        ("ram_a_m_s2", motion.ram_a),
        ("lever_deg", tile(np.degrees(motion.lever_angle))),
        ("lever_omega_rad_s", motion.lever_omega),
        ("lever_alpha_rad_s2", motion.lever_alpha),
        ("slide_v_m_s", motion.slide_v),
        ("coriolis_m_s2", motion.coriolis),
    ]
    if motion.rod_angle is not None:
        columns += [
            ("rod_deg", tile(np.degrees(motion.rod_angle))),
            ("rod_omega_rad_s", motion.rod_omega),
            ("rod_alpha_rad_s2", motion.rod_alpha),
            ("pressure_angle_deg", tile(np.degrees(motion.pressure_angle))),
        ]
    names = tuple(name for name, _ in columns)
    data = np.stack([np.asarray(values, dtype=float).reshape(-1) for _, values in columns], axis=1)
    return names, data


# A cell of user text that starts like a formula is one to Excel, LibreOffice and Sheets
# (OWASP "CSV injection"): =, +, -, @, and tab or carriage return, which some of them skip.
FORMULA_LEADS = ("=", "+", "-", "@", "\t", "\r")
ZERO_ULPS = 64       # a value within this many ulps of its column's largest magnitude is 0


# Where a spreadsheet may split one cell into several when it imports (its separator
# option): a piece after one of these that starts like a formula is one, too (issue 42).
FIELD_SEPARATORS = re.compile(r"([;,|\t])")


def csv_text(text: str) -> str:
    """A cell of text (a design's name, a file name, a note) as every CSV writer here
    writes it: with a ``'`` before it when it would start a formula (:data:`FORMULA_LEADS`),
    so a spreadsheet shows it as text, as OWASP advises; and before every piece after a
    separator a spreadsheet may split on (:data:`FIELD_SEPARATORS`, ``a;=cmd`` is
    ``a;'=cmd``; spaces before the piece do not hide it), so the cell is guarded as a whole
    and per name. Numbers are never passed through this (−2 must stay a number); only
    text that a user may have typed is."""
    head = "'" if text.startswith(FORMULA_LEADS) else ""
    pieces = FIELD_SEPARATORS.split(text)
    for i in range(2 if head else 0, len(pieces), 2):     # the even items are the pieces
        body = pieces[i].lstrip(" ")
        if body.startswith(FORMULA_LEADS[:4]):    # = + - @ (a tab or CR is a separator here)
            pieces[i] = pieces[i][:len(pieces[i]) - len(body)] + "'" + body
    return head + "".join(pieces)


def zero_scale(data: np.ndarray) -> np.ndarray:
    """Per column, the magnitude under which a value is round-off of zero: ZERO_ULPS
    ulps (ZERO_ULPS · 2.2e-16) of the column's largest finite magnitude."""
    data = np.asarray(data, dtype=float)
    with np.errstate(invalid="ignore"):
        largest = np.nanmax(np.where(np.isfinite(data), np.abs(data), np.nan), axis=0,
                            initial=0.0) if data.size else np.zeros(data.shape[1:])
    return ZERO_ULPS * np.finfo(float).eps * largest


def snap_zeros(data: np.ndarray, scale: np.ndarray | None = None) -> np.ndarray:
    """``data`` (rows × columns) with round-off zeros written as 0: values within
    :func:`zero_scale` of their column (``scale`` when given, e.g. the whole table's
    when it is written in blocks), such as a ram velocity of −4.8e-17 m/s at a limit
    position, where the exact value is 0. −0 becomes 0 as well."""
    data = np.array(data, dtype=float)
    limit = zero_scale(data) if scale is None else np.asarray(scale, dtype=float)
    with np.errstate(invalid="ignore"):
        data[np.abs(data) <= limit] = 0.0
    return data


def table_csv(names: Iterable[str], data: np.ndarray) -> str:
    """CSV text with a header; numbers with 10 significant digits, NaN as an empty cell."""
    return "".join(table_chunks(names, data))


def table_chunks(names: Iterable[str] | None, data: np.ndarray,
                 rows: int = 20_000, scale: np.ndarray | None = None) -> Iterator[str]:
    """The CSV of :func:`table_csv` in pieces of ``rows`` rows (the header first, unless
    ``names`` is None), so a large table is never formatted in one piece.

    A NaN marks a value that is undefined at that angle (the guide's line of
    action when it carries no force) and becomes an empty cell. Round-off zeros
    are written as 0 (:func:`snap_zeros`, relative to ``scale``: by default
    :func:`zero_scale` of ``data``). Each number is ``"%.10g"`` of it, formatted a
    block at a time by :func:`core.files.numtext.g10_rows`.
    """
    from .numtext import g10_rows   # here: its tables (4-5 ms to build) wait for the first CSV
    data = snap_zeros(data, scale)
    if names is not None:
        yield ",".join(names) + "\n"
    if data.size == 0:
        return
    for start in range(0, data.shape[0], rows):
        yield g10_rows(data[start:start + rows])


def curves_csv(motion: Motion) -> str:
    return table_csv(*curve_table(motion))


def design_document(spec: Spec, rpms: Iterable[float], step_deg: float,
                    extra: dict[str, Any] | None = None) -> dict[str, Any]:
    doc: dict[str, Any] = {"format": FILE_FORMAT, "version": FILE_VERSION,
                           "spec": spec.to_dict(), "rpm": [float(r) for r in rpms],
                           "step_deg": float(step_deg)}
    if extra:
        doc.update(extra)
    return doc


def save_design(path: str | os.PathLike, spec: Spec, rpms: Iterable[float], step_deg: float,
                extra: dict[str, Any] | None = None) -> None:
    text = json.dumps(design_document(spec, rpms, step_deg, extra), indent=2, ensure_ascii=False)
    atomic_write(path, text + "\n")


def finite_or_none(value: float | None) -> float | None:
    return None if value is None or not math.isfinite(value) else float(value)
