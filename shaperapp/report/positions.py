"""Section 5 of the report: the positions tables, and what they are for many speeds.

Up to ``FULL_SPEEDS`` crank speeds (a course design gives one to three) every speed
gets the whole table, one table per column group. With more, the whole table is
printed for the first speed only (the speed of the polygons in section 6), and the
quantities a student compares between speeds (the ram's velocity and acceleration,
the crank torque and the power) follow in one table each, a column per speed, split
into blocks of columns where they are wider than the page. Why: the kinematic
columns at another speed are those of the first scaled by n/n₁ (velocities) and
(n/n₁)² (accelerations), and 16 full tables were 30 of the report's 38 pages (and at
3600 positions most of its memory); every number stays in ``shaper table``.

Numbers have one number of decimals per column, as the Positions tab and ``shaper table``
show them (``core.course_design.positions.column_texts``: φ reads 0.000, 30.000 … 330.00 is not mixed with 0 and 30.000).
"""
from __future__ import annotations

import numpy as np
from PySide6.QtCore import QCoreApplication

from core.course_design.positions import COLUMN_GROUPS, PositionTable, column_texts, display_values
from shaperapp.widgets.column_titles import column_titles, group_titles, special_titles
from shaperapp.widgets.i18n import join_sentences

from .blocks import Table

translate = QCoreApplication.translate   # lupdate extracts translate("Report", "…")
FULL_SPEEDS = 3
ACROSS_SPEEDS = ("ram_v_m_s", "ram_a_m_s2", "crank_torque_N_m", "power_W")


def full_speeds(count: int) -> int:
    """How many of ``count`` speeds get the whole table (the first ones)."""
    return count if count <= FULL_SPEEDS else 1


def positions_note(table: PositionTable) -> str:
    """For more than ``FULL_SPEEDS`` speeds, the sentences that say what is printed, else ''."""
    if full_speeds(table.rpm.size) == table.rpm.size:
        return ""
    first = translate("Report", "The whole table is given at the first crank speed, n₁ = %1 r/min; "
                      "at a speed n the velocities are n/n₁ times and the accelerations (n/n₁)² "
                      "times those.").replace("%1", f"{table.rpm[0]:g}")
    then = (translate("Report", "The ram's velocity and acceleration, the crank torque and the power "
                      "follow at every speed.") if "crank_torque_N_m" in table.columns else
            translate("Report", "The ram's velocity and acceleration follow at every speed."))
    return join_sentences(first, then, translate("Report", "Every column at every speed: shaper table."))


def position_tables(table: PositionTable) -> list[Table]:
    """The whole table for each of the first ``full_speeds`` speeds, then (for more
    speeds) the ``ACROSS_SPEEDS`` columns at every speed."""
    shown = display_values(table.data, table.columns)
    k = table.positions.crank_deg.size
    lead = _lead(table)
    titles, groups = column_titles(), group_titles()
    out = []
    for s in range(full_speeds(table.rpm.size)):
        part = shown[s * k:(s + 1) * k]
        for group, names in COLUMN_GROUPS:
            columns = ["crank_deg"] + [n for n in names if n in table.columns]
            if len(columns) == 1:
                continue
            texts = [column_texts(part[:, table.columns.index(c)]) for c in columns]
            out.append(_table(lead, [titles[c] for c in columns], texts,
                              f"{table.rpm[s]:g} r/min — {groups[group]}"))
    if full_speeds(table.rpm.size) < table.rpm.size:
        out += _across_speeds(table, shown, lead)
    return out


def _across_speeds(table: PositionTable, shown: np.ndarray, lead: list[list[str]]) -> list[Table]:
    k = table.positions.crank_deg.size
    titles = column_titles()
    phi = column_texts(shown[:k, table.columns.index("crank_deg")])
    caption = translate("Report", "At every crank speed: %1")
    out = []
    for name in ACROSS_SPEEDS:
        if name not in table.columns:
            continue
        c = table.columns.index(name)
        texts = [phi] + [column_texts(shown[s * k:(s + 1) * k, c]) for s in range(table.rpm.size)]
        header = [titles["crank_deg"]] + [f"{rpm:g} r/min" for rpm in table.rpm]
        out.append(_table(lead, header, texts, caption.replace("%1", titles[name])))
    return out


def _lead(table: PositionTable) -> list[list[str]]:
    """Each row's number and special position's name."""
    specials = special_titles()
    return [[str(n or ""), specials.get(name, "")]
            for n, name in zip(table.positions.number, table.positions.name)]


def _table(lead: list[list[str]], header: list[str], columns: list[list[str]], caption: str) -> Table:
    rows = [first + [column[r] for column in columns] for r, first in enumerate(lead)]
    return Table([translate("Report", "No."), translate("Report", "Position")] + header, rows, caption,
                 [bool(first[1]) for first in lead], left_columns=2, key_columns=3)   # No., name, φ
