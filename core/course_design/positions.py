"""The course design's table of crank positions: numbered and special positions.

A classic shaper assignment (牛头刨床, 机械原理课程设计) asks for the kinematic and
kinetostatic analysis at 12 equally spaced crank positions and at the special
positions: both limit positions, the start and end of the cut, and where the
ram moves fastest. This module finds those crank angles exactly and tabulates
every quantity core computes there.

Level: beside ``io``. The special angles come from ``metrics`` and ``dynamics``
(exact roots of closed-form functions, no sampling error; the same code that
finds ``analyze``'s peaks and switches the cutting force); the table rows
come from ``io.curve_table`` and ``dynamics_io.dynamics_table`` unchanged, so
its columns are the curves and dynamics CSV columns.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np

from core.linkage.designs import Designs
from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties
from core.linkage.cut import cut_window
from core.files.dynamics_io import FLAG_COLUMNS, dynamics_table
from core.base.errors import DesignError, require_finite
from core.linkage.geometry import Design
from core.files.io import curve_table, finite_or_none, snap_zeros, table_csv
from core.linkage.kinematics import solve
from core.linkage.metrics import cycle_peaks
from .counts import DEFAULT_COUNT, MAX_COUNT  # noqa: F401  (imported from here too)

MAX_EXTRA = 1000
SPECIAL_NAMES = ("limit_work_start", "limit_work_end", "cut_start", "cut_end",
                 "v_work_max", "v_return_max")
LEAD_COLUMNS = ("position", "name")

# Column groups for printed tables (CLI text and the report); absent columns are skipped.
COLUMN_GROUPS = (
    ("ram", ("ram_x_mm", "ram_v_m_s", "ram_a_m_s2", "time_s")),
    ("lever", ("lever_deg", "lever_omega_rad_s", "lever_alpha_rad_s2", "slide_v_m_s",
               "coriolis_m_s2")),
    ("rod", ("rod_deg", "rod_omega_rad_s", "rod_alpha_rad_s2", "pressure_angle_deg")),
    ("torque", ("crank_torque_N_m", "power_W", "cut_force_N", "guide_normal_N",
                "guide_moment_N_m", "guide_offset_mm", "guide_rear_N", "guide_front_N")),
    ("joints_crank", ("O2_x_N", "O2_y_N", "pin_A_x_N", "pin_A_y_N", "A_x_N", "A_y_N",
                      "A_normal_N")),
    ("joints_lever", ("O4_x_N", "O4_y_N", "B_x_N", "B_y_N", "C_x_N", "C_y_N")),
)


@dataclass(frozen=True)
class Positions:
    """Crank positions to tabulate, in table order (numbered, special, extra)."""

    crank_deg: np.ndarray
    """φ of each position, (k,) degrees; numbered ones exactly (i − 1)·360/N."""
    number: np.ndarray
    """Position number 1 … N, (k,) int; 0 for special and extra positions."""
    name: tuple[str, ...]
    """'' for numbered and extra positions, else one of ``SPECIAL_NAMES``."""

    @property
    def crank_angle(self) -> np.ndarray:
        """φ, (k,) rad."""
        return np.radians(self.crank_deg)


@dataclass(frozen=True)
class PositionTable:
    """Every computed quantity at each position and speed.

    Rows are speed-major like the curves CSV: all positions at the first speed,
    then at the next. ``columns`` are the curves CSV columns followed by the
    dynamics CSV columns (without its repeated ``rpm``/``crank_deg``) when loads
    were given.
    """

    positions: Positions
    rpm: np.ndarray
    """Crank speeds, (m,) r/min."""
    columns: tuple[str, ...]
    data: np.ndarray
    """(m·k, len(columns)) in the units of the column names."""

    def row(self, speed: int, position: int) -> dict[str, float]:
        values = self.data[speed * self.positions.crank_deg.size + position]
        return dict(zip(self.columns, (float(v) for v in values)))


def special_angles(design: Design, idle_fraction: float = 0.05) -> dict[str, float]:
    """The six special positions as crank angles in degrees, keyed by ``SPECIAL_NAMES``.

    The limits and the speed peaks are those of :func:`metrics.cycle_peaks` (what
    ``analyze`` reports), the cut's ends those of :func:`flywheel.cut_window` (where the
    dynamics switch the cutting force). The start limit is reported as a signed angle
    near 0 (as ``metrics.analyze`` does), the others in [0, 360).
    """
    idle = require_finite("idle_fraction", idle_fraction)
    if not 0.0 <= idle < 0.5:
        raise DesignError("idle_fraction", idle, "must be ≥ 0 and < 0.5")
    one = Designs.of(design)
    peaks = cycle_peaks(one)
    if not np.isfinite(peaks.work_start[0]):
        raise RuntimeError("the ram does not have exactly two dead points")
    cut_start, cut_end = cut_window(one, idle)
    start_deg = math.degrees(float(peaks.work_start[0]))
    if start_deg > 180.0:
        start_deg -= 360.0
    angles = {"limit_work_end": peaks.work_end, "cut_start": cut_start, "cut_end": cut_end,
              "v_work_max": peaks.v_work_at, "v_return_max": peaks.v_return_at}
    return {"limit_work_start": start_deg,
            **{name: math.degrees(float(value[0])) for name, value in angles.items()}}


def check_count(count: object) -> int:
    """Number of equally spaced positions, a whole number in [1, MAX_COUNT]."""
    value = require_finite("positions", count)
    if value != int(value) or not 1 <= value <= MAX_COUNT:
        raise DesignError("positions", count, f"must be a whole number from 1 to {MAX_COUNT}")
    return int(value)


def check_extra(angles_deg: Sequence[float]) -> np.ndarray:
    """Extra crank angles (``--at``), degrees, finite and within ±36000°."""
    values = np.asarray([require_finite("at", v) for v in angles_deg], dtype=float)
    if values.size > MAX_EXTRA:
        raise DesignError("at", values.size, f"must list at most {MAX_EXTRA} crank angles")
    if values.size and np.abs(values).max() > 36000.0:
        raise DesignError("at", float(np.abs(values).max()), "must lie within ±36000°")
    return values


def positions(design: Design, count: int = DEFAULT_COUNT, extra_deg: Sequence[float] = (),
              idle_fraction: float = 0.05) -> Positions:
    """Positions 1 … N from the limit that starts the working stroke (φ = 0 by the
    angle convention), then the special positions, then ``extra_deg`` as given."""
    n = check_count(count)
    extra = check_extra(extra_deg)
    special = special_angles(design, idle_fraction)
    degrees = np.concatenate([np.arange(n) * (360.0 / n),
                              [special[name] for name in SPECIAL_NAMES], extra])
    number = np.concatenate([np.arange(1, n + 1), np.zeros(len(SPECIAL_NAMES) + extra.size)])
    names = ("",) * n + SPECIAL_NAMES + ("",) * extra.size
    return Positions(crank_deg=degrees, number=number.astype(int), name=names)


def position_table(design: Design, where: Positions, rpms,
                   masses: MassProperties | None = None) -> PositionTable:
    """Curves (and, with ``masses``, dynamics) columns at every position and speed."""
    phi = where.crank_angle
    motion = solve(design, phi, rpms)
    names, data = curve_table(motion)
    speeds = motion.rpm
    if masses is not None:
        dyn_names, dyn_data = dynamics_table(solve_dynamics(design, phi, speeds, masses))
        keep = [i for i, name in enumerate(dyn_names) if name not in names]
        names = names + tuple(dyn_names[i] for i in keep)
        data = np.hstack([data, dyn_data[:, keep]])
    data = np.array(data, dtype=float)
    data[:, names.index("crank_deg")] = np.tile(where.crank_deg, speeds.size)
    return PositionTable(positions=where, rpm=speeds, columns=names, data=data)


def table_rows(table: PositionTable) -> list[tuple[int | None, str]]:
    """(position number or None, name) of every row, in row order."""
    lead = [(int(n) if n else None, name)
            for n, name in zip(table.positions.number, table.positions.name)]
    return lead * table.rpm.size


def table_records(table: PositionTable) -> list[dict[str, Any]]:
    """One JSON-ready object per row: position, name, then every column (NaN → null),
    round-off zeros as 0 as in the CSV (:func:`core.files.io.snap_zeros`); a yes/no column
    (``FLAG_COLUMNS``, 1/0 in the CSV, whose header says so) as true/false: it was 0.0/1.0."""
    out = []
    for (number, name), values in zip(table_rows(table), snap_zeros(table.data)):
        record: dict[str, Any] = {"position": number, "name": name}
        record.update({c: _flag(v) if c in FLAG_COLUMNS else finite_or_none(float(v))
                       for c, v in zip(table.columns, values)})
        out.append(record)
    return out


def _flag(value: float) -> bool | None:
    """A yes/no column's value in JSON: true, false, or null where it is undefined."""
    return None if not math.isfinite(value) else bool(value)


def positions_csv(table: PositionTable) -> str:
    """CSV with ``position,name`` before the curves/dynamics columns (same number format)."""
    lines = table_csv(table.columns, table.data).split("\n")
    lead = [f"{'' if n is None else n},{name}" for n, name in table_rows(table)]
    body = [f"{a},{b}" for a, b in zip(lead, lines[1:])]
    return ",".join(LEAD_COLUMNS) + "," + lines[0] + "\n" + "".join(line + "\n" for line in body)


def display_values(data: np.ndarray, columns: tuple[str, ...] = ()) -> np.ndarray:
    """``data`` with round-off noise set to 0: entries within 1e-9 of their column's
    largest magnitude (e.g. a velocity of 4e-17 m/s at a limit position).

    With the table's ``columns``, the guide reaction shows where the ram bears: the
    resultant's offset where it falls on the guide, else (the ram tilts) the two forces
    at the guide's ends (``core.forces.guide``); the other is blank (NaN)."""
    data = np.array(data, dtype=float)
    with np.errstate(invalid="ignore"):
        scale = np.nanmax(np.abs(data), axis=0, initial=0.0)
        data[np.abs(data) <= 1e-9 * scale] = 0.0
    if "guide_tilted" in columns:
        tilted = data[:, columns.index("guide_tilted")] != 0.0
        for name in ("guide_rear_N", "guide_front_N"):
            data[~tilted, columns.index(name)] = np.nan
        data[tilted, columns.index("guide_offset_mm")] = np.nan
    return data


@dataclass(frozen=True)
class TextGroup:
    """One printed table: a speed and a column group, numbers as ``column_texts``."""

    rpm: float
    group: str
    """A ``COLUMN_GROUPS`` name."""
    columns: tuple[str, ...]
    """``crank_deg`` then the group's columns present in the table."""
    rows: tuple[tuple[int | None, str, tuple[str, ...]], ...]
    """(position number or None, special name or '', texts per column)."""


def text_groups(table: PositionTable) -> list[TextGroup]:
    """The table as printed by ``shaper table``: per speed, per column group, round-off
    cleaned (``display_values``) and each column of one speed written by ``column_texts``,
    as the Positions tab and the report write it, so the three print one text per figure."""
    shown = display_values(table.data, table.columns)
    lead = table_rows(table)
    k = table.positions.crank_deg.size
    out = []
    for s, rpm in enumerate(table.rpm):
        rows_of_speed = slice(s * k, (s + 1) * k)
        texts = {name: column_texts(shown[rows_of_speed, c]) for c, name in enumerate(table.columns)
                 if name == "crank_deg" or any(name in names for _, names in COLUMN_GROUPS)}
        for group, names in COLUMN_GROUPS:
            columns = ("crank_deg",) + tuple(n for n in names if n in table.columns)
            if len(columns) == 1:
                continue
            rows = tuple((lead[s * k + i][0], lead[s * k + i][1], tuple(texts[c][i] for c in columns))
                         for i in range(k))
            out.append(TextGroup(float(rpm), group, columns, rows))
    return out


COLUMN_DIGITS = 5
"""Significant digits of a positions column's largest value; the column's other values
share its decimals."""
MAX_DECIMALS = 6


def column_texts(values: np.ndarray, digits: int = COLUMN_DIGITS) -> list[str]:
    """One column's numbers with one number of decimals: ``digits`` significant digits
    of its largest value, so 0 reads "0.000" beside "30.000" (not "0") and the decimal
    points line up. The precision of a column is that of its quantity's scale: a ram
    position of 17.788 mm in a 300 mm stroke reads 17.79, as 282.21 beside it. One rule
    for ``shaper table``, the Positions tab and the report (the CLI wrote 5 significant
    digits of each value, 17.788 beside the window's 17.79). NaN is ''."""
    finite = np.abs(values[np.isfinite(values)])
    largest = float(finite.max()) if finite.size else 0.0
    decimals = (min(max(digits - 1 - math.floor(math.log10(largest)), 0), MAX_DECIMALS)
                if largest > 0.0 else digits - 2)
    out = []
    for value in values:
        if not math.isfinite(value):
            out.append("")
            continue
        text = f"{value:.{decimals}f}"
        out.append(text[1:] if text.startswith("-") and float(text) == 0.0 else text)   # no "-0.000"
    return out

