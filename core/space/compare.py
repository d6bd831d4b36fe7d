"""Comparing 2 to 6 designs at one crank speed: overlay curves and a figure table.

Every number comes from the same core functions as ``shaper analyze`` and
``shaper dynamics`` (through :func:`core.space.figures.figures`), evaluated at the
common speed. The table has one row per figure: each design's value, its
difference from the first design (the reference) and which design is best.

"Best" per figure (``better`` in :mod:`core.space.figures`):
- lower is better: max |a| (inertia loads), max pressure angle (transmission),
  mean and max crank torque (drive size) and flywheel J_F;
- no best: K, H, θ, the dimensions and the speeds. They are requirements or
  trade-offs, not merits.
No design is marked when all values in a row are equal, or fewer than two designs
have a value (torques need loads; the pressure angle exists for the rod variant only).
"""
from __future__ import annotations

import csv
import io as _io
import json
import math
from dataclasses import dataclass
from typing import Any, Iterator, Sequence

import numpy as np

from core.base.figure_text import figure_kind, figure_text, value_text  # noqa: F401 (compare's text)
from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties, masses_for_design
from core.base.errors import DesignError
from core.files.io import csv_text, snap_zeros, zero_scale
from .figures import DESIGN_FIGURES, SPEED_FIGURES, TEXT_FIGURES, Figures, figures
from core.linkage.kinematics import angle_count, crank_angles, solve
from core.files.numtext import g10_rows
from core.linkage.spec import Spec

MIN_DESIGNS, MAX_DESIGNS = 2, 6
CURVE_COLUMNS = ("design", "crank_deg", "ram_x_mm", "ram_v_m_s", "ram_a_m_s2", "crank_torque_N_m")


@dataclass(frozen=True)
class Candidate:
    """A design to compare: its label (library name or file name), inputs and loads."""

    label: str
    spec: Spec
    masses: MassProperties | None = None


# The inputs that name a design in a label, in order: (Spec field, symbol, unit).
LABEL_INPUTS = (("time_ratio", "K", ""), ("stroke", "H", " mm"), ("crank", "L1", " mm"),
                ("frame", "L2", " mm"), ("lever", "L3", " mm"), ("guide_height", "guide", " mm"),
                ("rod_ratio", "L4/L3", ""), ("rod_length", "L4", " mm"))


def distinguishing_inputs(spec: Spec, others: Sequence[Spec]) -> str:
    """The inputs that tell ``spec`` from ``others`` in a label, e.g. "K 1.4" or
    "K 1.4, L1 120 mm": the mode's first input (K in synthesis, L1 with direct
    dimensions) always, then every other input ``spec`` uses whose value differs from an
    other design's (one that does not use it counts as differing). Numbers as typed (:g)."""
    active = spec.active_fields()
    first = "time_ratio" if spec.mode == "synthesis" else "crank"
    parts = []
    for field, symbol, unit in LABEL_INPUTS:
        if field not in active:
            continue
        value = getattr(spec, field)
        if field == first or any(field not in o.active_fields() or getattr(o, field) != value
                                 for o in others):
            parts.append(f"{symbol} {value:g}{unit}")
    return ", ".join(parts)


def distinguishing_choices(candidate: Candidate, others: Sequence[Candidate]) -> tuple[str, ...]:
    """The choices, besides the numbers of :func:`distinguishing_inputs`, that tell
    ``candidate`` from ``others``, as codes a GUI puts in words: its guide rule ("chord" or
    "sagitta") and rod side ("trailing" or "leading") where an other design has another,
    and "loads" where an other design has the same inputs and other loads."""
    spec = candidate.spec
    out = []
    if spec.guide_rule != "height" and any(o.spec.guide_rule != spec.guide_rule for o in others):
        out.append(spec.guide_rule)
    if spec.variant == "rod" and any(o.spec.variant == "rod" and o.spec.rod_side != spec.rod_side
                                     for o in others):
        out.append(spec.rod_side)
    if any(o.spec == spec and o.masses != candidate.masses for o in others):
        out.append("loads")
    return tuple(out)


@dataclass(frozen=True)
class Row:
    """One figure across the designs."""

    key: str                                   # JSON key, e.g. ``a_max_m_s2``
    unit: str
    better: str | None                         # "lower", "higher" or None
    values: tuple[Any, ...]                    # one per design; None where it has none
    differences: tuple[float | None, ...]      # value − the first design's value
    best: tuple[int, ...]                      # indices of the best designs (may be empty)


@dataclass(frozen=True)
class Comparison:
    labels: tuple[str, ...]
    rpm: float                                 # the common crank speed, r/min
    crank_deg: np.ndarray                      # (n,) crank angles, degrees
    ram_x_mm: np.ndarray                       # (k, n) ram displacement per design, mm
    ram_v_m_s: np.ndarray                      # (k, n) ram velocity, m/s
    ram_a_m_s2: np.ndarray                     # (k, n) ram acceleration, m/s²
    crank_torque_N_m: tuple[np.ndarray | None, ...]   # (n,) per design; None without loads
    figures: tuple[Figures, ...]
    rows: tuple[Row, ...]


CURVE_CHUNK = 1 << 14      # crank angles solved at a time for the curves


def compare(candidates: Sequence[Candidate], rpm: float, step_deg: float = 1.0,
            curves: bool = True) -> Comparison:
    """Curves and figure table of 2 to 6 designs at ``rpm``; DesignError for bad input.

    Without ``curves`` (a table only: the figures do not depend on the step) the curve
    arrays are empty, and the step is only checked. The curves are solved
    ``CURVE_CHUNK`` angles at a time into arrays made once, so the memory is the
    curves themselves (4 values a design an angle), not every intermediate of the
    mechanism at the finest step (1.5 GB for two designs at 0.0002°).
    """
    if not MIN_DESIGNS <= len(candidates) <= MAX_DESIGNS:
        raise DesignError("designs", len(candidates), f"compare {MIN_DESIGNS} to {MAX_DESIGNS} designs")
    labels = [c.label for c in candidates]
    for label in labels:
        if labels.count(label) > 1:
            raise DesignError("designs", label, "each design may appear only once")
    phi = crank_angles(step_deg) if curves else np.zeros(angle_count(step_deg))[:0]
    shape = (len(candidates), phi.size)
    xs, vs, accs = np.empty(shape), np.empty(shape), np.empty(shape)
    torques: list[np.ndarray | None] = []
    figs = []
    for k, c in enumerate(candidates):
        design = c.spec.design()
        masses = masses_for_design(design, c.masses) if c.masses is not None else None
        torque = np.empty(phi.size) if masses is not None else None
        for start in range(0, phi.size, CURVE_CHUNK):
            part = slice(start, start + CURVE_CHUNK)
            # each chunk starts with φ = 0, so the ram's zero is taken as for the whole cycle
            angles = np.concatenate(([0.0], phi[part]))
            motion = solve(design, angles, [rpm])
            xs[k, part], vs[k, part], accs[k, part] = motion.ram_x[1:], motion.ram_v[0, 1:], motion.ram_a[0, 1:]
            if torque is not None:
                torque[part] = solve_dynamics(design, angles, [rpm], masses).crank_torque[0, 1:]
        torques.append(torque)
        figs.append(figures(c.spec, [rpm], c.masses))
    return Comparison(labels=tuple(labels), rpm=float(rpm), crank_deg=np.degrees(phi), ram_x_mm=xs,
                      ram_v_m_s=vs, ram_a_m_s2=accs, crank_torque_N_m=tuple(torques),
                      figures=tuple(figs), rows=table_rows(figs))


def table_rows(figs: Sequence[Figures]) -> tuple[Row, ...]:
    """The side-by-side rows: text figures, design figures, then the first speed's figures."""
    rows = [Row(key, "", None, tuple(getattr(f, key) for f in figs), (None,) * len(figs), ())
            for key in TEXT_FIGURES]
    for key, unit, _, better in DESIGN_FIGURES:
        rows.append(_row(key, unit, better, [getattr(f, key) for f in figs]))
    for key, unit, _, better in SPEED_FIGURES:
        rows.append(_row(key, unit, better, [getattr(f.speeds[0], key) for f in figs]))
    return tuple(rows)


def _row(key: str, unit: str, better: str | None, values: list[float | None]) -> Row:
    ref = values[0]
    diffs = tuple(None if v is None or ref is None else v - ref for v in values)
    return Row(key, unit, better, tuple(values), diffs, best_indices(values, better))


def best_indices(values: Sequence[float | None], better: str | None) -> tuple[int, ...]:
    """Indices of the best values (ties within 1e-9 relative), or () if there is no best."""
    present = [(i, v) for i, v in enumerate(values) if v is not None and math.isfinite(v)]
    if better is None or len(present) < 2:
        return ()
    numbers = [v for _, v in present]
    target = min(numbers) if better == "lower" else max(numbers)
    tol = 1e-9 * max(1.0, abs(target))
    if max(numbers) - min(numbers) <= tol:
        return ()
    return tuple(i for i, v in present if abs(v - target) <= tol)


# ---- text ----------------------------------------------------------------------
def difference_text(row: Row, index: int) -> str:
    """What follows design ``index``'s value: its difference from the first design in
    brackets at the row's precision (``+62.763``), `` (=)`` within round-off, ``''`` for
    the first design or no difference."""
    diff = row.differences[index]
    if index == 0 or diff is None or isinstance(row.values[index], str):
        return ""
    tiny = abs(diff) <= 1e-9 * max(1.0, abs(row.values[0]))
    return " (=)" if tiny else f" ({'+' if diff > 0 else ''}{figure_text(figure_kind(row.key), diff)})"


# ---- export --------------------------------------------------------------------
def _number(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, str):
        return csv_text(value)
    return "%.10g" % value


def table_csv(comparison: Comparison) -> str:
    """The figure table as CSV: figure, unit, better, one column per design, the
    differences from the first design, and the best design(s) separated by ``;``. The
    designs' names are user text (:func:`core.files.io.csv_text`)."""
    labels = comparison.labels
    names = [csv_text(label) for label in labels]
    out = _io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["figure", "unit", "better", *names,
                     *(csv_text(f"{label} - {labels[0]}") for label in labels[1:]), "best"])
    writer.writerow(["rpm", "r/min", "", *(_number(comparison.rpm) for _ in labels),
                     *("" for _ in labels[1:]), ""])
    for row in comparison.rows:
        writer.writerow([row.key, row.unit, row.better or "", *(_number(v) for v in row.values),
                         *(_number(d) for d in row.differences[1:]),
                         csv_text(";".join(labels[i] for i in row.best))])
    return out.getvalue()


def curves_csv(comparison: Comparison) -> str:
    """The overlay curves in long form, one row per (design, crank angle); round-off
    zeros as 0 (:func:`core.files.io.snap_zeros`, over all designs of a column)."""
    return "".join(curves_csv_chunks(comparison))


def curves_csv_chunks(comparison: Comparison, rows: int = 20_000) -> Iterator[str]:
    """:func:`curves_csv` in pieces of at most ``rows`` rows, so a fine step is written
    without its whole text (650 MB for six designs at 0.0002°) in memory at once."""
    yield ",".join(CURVE_COLUMNS) + "\n"
    nan = np.full(comparison.crank_deg.shape, np.nan)
    torques = [nan if t is None else t for t in comparison.crank_torque_N_m]
    scale = np.array([0.0, *(_column_scale(a) for a in (comparison.ram_x_mm, comparison.ram_v_m_s,
                                                         comparison.ram_a_m_s2, torques))])
    for k, label in enumerate(comparison.labels):
        cell = _csv_cell(csv_text(label)) + ","
        for start in range(0, comparison.crank_deg.size, rows):
            part = slice(start, start + rows)
            block = np.column_stack([comparison.crank_deg[part], comparison.ram_x_mm[k, part],
                                     comparison.ram_v_m_s[k, part], comparison.ram_a_m_s2[k, part],
                                     torques[k][part]])
            text = g10_rows(snap_zeros(block, scale))
            yield cell + text[:-1].replace("\n", "\n" + cell) + "\n"


def _column_scale(curves: Sequence[np.ndarray]) -> float:
    """:func:`core.files.io.zero_scale` of one column over all designs' curves (one at a time)."""
    return max((float(zero_scale(np.reshape(c, (-1, 1)))[0]) for c in curves), default=0.0)


def _csv_cell(text: str) -> str:
    """``text`` as one CSV cell, quoted as :mod:`csv` quotes it (a comma, a quote, a newline)."""
    out = _io.StringIO()
    csv.writer(out, lineterminator="\n").writerow([text])
    return out.getvalue()[:-1]


def comparison_document(comparison: Comparison, curves: bool = False) -> dict[str, Any]:
    """JSON-ready: the speed, the designs, one object per figure (and the curves if asked)."""
    labels = comparison.labels
    doc: dict[str, Any] = {
        "rpm": comparison.rpm, "designs": list(labels), "reference": labels[0],
        "figures": [{"figure": r.key, "unit": r.unit, "better": r.better,
                     "values": dict(zip(labels, r.values)),
                     "differences": dict(zip(labels, r.differences)),
                     "best": [labels[i] for i in r.best]} for r in comparison.rows],
    }
    if curves:
        doc["curves"] = {"crank_deg": comparison.crank_deg.tolist(), "designs": [
            {"design": label, "ram_x_mm": comparison.ram_x_mm[k].tolist(),
             "ram_v_m_s": comparison.ram_v_m_s[k].tolist(),
             "ram_a_m_s2": comparison.ram_a_m_s2[k].tolist(),
             "crank_torque_N_m": None if comparison.crank_torque_N_m[k] is None
             else comparison.crank_torque_N_m[k].tolist()}
            for k, label in enumerate(labels)]}
    return doc


def comparison_json(comparison: Comparison, curves: bool = False) -> str:
    return json.dumps(comparison_document(comparison, curves), indent=2, allow_nan=False,
                      ensure_ascii=False) + "\n"
