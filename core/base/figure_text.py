"""How a figure is written in a table: one precision per kind of quantity (issue 40).

The CLI's text tables, the report (which prints the CLI's rows), the Results pane,
the library and Compare tables and the drawing sheets all write a figure through
``figure_text``, so that one figure reads the same everywhere: θ = 33.653° in every
place, not 33.6529° in one and 33.653° in another, K = 1.4599, not 1.45991 beside
1.459905. CSV and JSON keep the full precision (``core.files.numtext``); the positions
table has its own rule (five significant digits of a column's largest value,
``core.course_design.positions.column_texts``: ``shaper table``, the Positions tab and the
report), since a column of one quantity shares its decimals.

A dimension's text on a drawing (the scheme's L1, L2, L3, h, H and θ in the window and the
report, the sheets' dimensions, the DXF's DIMENSION texts) is another kind, written as CAD
writes a measurement: :func:`dimension_text`.

Fixed decimals where a course design quotes a quantity that way (lengths to the
micrometre, angles to a thousandth of a degree, speeds and accelerations to 0.1 mm/s
and 0.1 mm/s²); four significant digits for the loads, whose size spans decades.
"""
from __future__ import annotations

import math

# kind → ("f", decimals) or ("s", significant digits, written in fixed notation)
PRECISION: dict[str, tuple[str, int]] = {
    "length": ("f", 3),          # mm
    "angle": ("f", 3),           # °
    "ratio": ("f", 4),           # K, the nominal and the measured one
    "time": ("f", 4),            # s
    "speed": ("f", 4),           # m/s
    "acceleration": ("f", 4),    # m/s²
    "angular_speed": ("f", 4),   # rad/s, rad/s²
    "torque": ("s", 4),          # N·m
    "power": ("s", 4),           # W, kW
    "energy": ("s", 4),          # J
    "inertia": ("s", 4),         # kg·m²
    "coefficient": ("s", 5),     # δ
    # the gear pair's figures as ``shaper gear`` prints them: a meshing is checked to 0.1 µm
    # and its shift factors, α′ and ε to six decimals (core.gear.table)
    "gear_length": ("f", 4),     # mm: a′, the diameters, the thicknesses
    "gear_angle": ("f", 6),      # °: α′
    "gear_factor": ("f", 6),     # x1, x2, y, Δy, ε
}


def figure_text(kind: str, value: float) -> str:
    """``value`` as a table writes a figure of ``kind`` (see ``PRECISION``), without a
    negative zero; '—' for a value that is not finite (a figure the design has not)."""
    style, digits = PRECISION[kind]
    if not math.isfinite(value):
        return "—"
    if style == "s":
        if value == 0.0:
            return "0"
        digits = min(max(digits - 1 - math.floor(math.log10(abs(value))), 0), 12)
    text = f"{value:.{digits}f}"
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text


# A figure's key names its unit (``core.space.figures``, the CSV and JSON keys): suffix →
# (kind of PRECISION, unit as a table writes it). K has no unit.
KEY_SUFFIXES = (("_kg_m2", "inertia", "kg·m²"), ("_N_m", "torque", "N·m"), ("_m_s2", "acceleration", "m/s²"),
                ("_m_s", "speed", "m/s"), ("_deg", "angle", "°"), ("_mm", "length", "mm"))


def _key_parts(key: str) -> tuple[str, str, str]:
    """(name without its unit suffix and speed tag, kind, unit) of a figure key such as
    ``a_max_m_s2`` or a sweep's ``a_max_m_s2@40``."""
    base = key.split("@", 1)[0]
    for suffix, kind, unit in KEY_SUFFIXES:
        if base.endswith(suffix):
            return base[:-len(suffix)], kind, unit
    return base, "ratio" if base == "K" else "length", ""


def figure_kind(key: str) -> str:
    """The kind (``PRECISION``) a figure of ``key`` is written as: one precision per kind in
    every table, the GUI's and the CLI's (``shaper library compare``, ``shaper optimize``)."""
    return _key_parts(key)[1]


def figure_name(key: str) -> str:
    """A figure key without its unit, which its text then carries (``a_max`` for
    ``a_max_m_s2``; ``a_max at 40 r/min`` for a sweep's ``a_max_m_s2@40``)."""
    name, speed = _key_parts(key)[0], key.partition("@")[2]
    return f"{name} at {speed} r/min" if speed else name


def key_figure_text(key: str, value: float) -> str:
    """A figure of ``key`` with its unit: ``0.4295 m/s``, ``1.4000`` for K."""
    _, kind, unit = _key_parts(key)
    text = figure_text(kind, value)
    return f"{text} {unit}" if unit and text != "—" else text


def value_text(value: float | str | None, key: str) -> str:
    """A figure of ``key`` as ``shaper library compare``, ``list`` and ``show`` print it (and
    the report's comparison): at the precision of its kind, as the GUI's tables write it (it
    was 6 significant digits, 0.479993 m/s beside the Compare tab's 0.4800), a speed in
    r/min as typed, a text figure as it is, ``—`` where a design has none."""
    if value is None or isinstance(value, str):
        return "—" if value is None else value
    return f"{value:g}" if key == "rpm" else figure_text(figure_kind(key), value)


DIMENSION_DECIMALS = 2
"""Places of a dimension's text on a drawing: CAD's DIMDEC in the GB style of
``core.drawing.dimensions``, trailing zeros dropped as it drops them (L1 = 100, h = 148.44)."""


def dimension_text(value: float) -> str:
    """``value`` (mm or °) as a drawing's dimension writes it: ``DIMENSION_DECIMALS`` places,
    trailing zeros dropped, no negative zero. One rule for the scheme on screen, in the report
    and on the sheets: the scheme's h read 148.4 beside the sheet's 148.44."""
    text = f"{value:.{DIMENSION_DECIMALS}f}"
    text = text.rstrip("0").rstrip(".") if "." in text else text
    return "0" if text == "-0" else text
