"""The rows one library entry is stored as, written inside the caller's transaction.

An entry is one ``entries`` row (its name, notes, tags, times, design figures and the
version of their computation), its ``documents`` row, a ``speeds`` row per distinct
speed and a ``tags`` row per tag. Split from the package's ``Library`` so that the
columns and the SQL that writes them stand in one place: adding an entry, and rewriting
the figures of one whose computation changed (``Library.refresh_figures``).
"""
from __future__ import annotations

import sqlite3
from typing import Sequence

from core.space.figures import DESIGN_KEYS, SPEED_KEYS, TEXT_FIGURES, Figures, SpeedFigures

from .entry import Entry, distinct_speeds

ENTRY_COLUMNS = ("name", "notes", "tags", "created", "modified") + TEXT_FIGURES + DESIGN_KEYS \
    + ("figures_version",)
SPEED_COLUMNS = ("rpm",) + SPEED_KEYS


def insert_entry(c: sqlite3.Connection, entry: Entry) -> None:
    """All of ``entry``'s rows (the name must be free)."""
    values = {"name": entry.name, "notes": entry.notes, "tags": ",".join(entry.tags),
              "created": entry.created, "modified": entry.modified,
              "figures_version": entry.figures_version, **entry.figures.design_values()}
    cursor = c.execute(f"INSERT INTO entries ({', '.join(ENTRY_COLUMNS)}) VALUES "
                       f"({', '.join('?' * len(ENTRY_COLUMNS))})",
                       [values[k] for k in ENTRY_COLUMNS])
    entry_id = cursor.lastrowid
    c.execute("INSERT INTO documents (entry_id, text) VALUES (?, ?)", (entry_id, entry.text))
    insert_speeds(c, entry_id, entry.figures.speeds)
    c.executemany("INSERT INTO tags (entry_id, tag) VALUES (?, ?)",
                  [(entry_id, tag) for tag in entry.tags])


def insert_speeds(c: sqlite3.Connection, entry_id: int, speeds: Sequence[SpeedFigures]) -> None:
    """A ``speeds`` row per distinct speed, in order."""
    c.executemany(f"INSERT INTO speeds (entry_id, pos, {', '.join(SPEED_COLUMNS)}) VALUES "
                  f"(?, ?, {', '.join('?' * len(SPEED_COLUMNS))})",
                  [(entry_id, pos, *(getattr(s, k) for k in SPEED_COLUMNS))
                   for pos, s in enumerate(distinct_speeds(speeds))])


def rewrite_figures(c: sqlite3.Connection, entry: Entry, figs: Figures, version: int) -> bool:
    """``figs`` stored as ``entry``'s figures of computation ``version``; False (nothing
    written) when the library no longer holds ``entry`` as it was read (removed, or
    re-saved by another program meanwhile)."""
    row = c.execute("SELECT e.id FROM entries e JOIN documents d ON d.entry_id = e.id "
                    "WHERE e.name = ? AND d.text = ?", (entry.name, entry.text)).fetchone()
    if row is None:
        return False
    values = {"figures_version": version, **figs.design_values()}
    keys = [k for k in ENTRY_COLUMNS if k in values]
    c.execute(f"UPDATE entries SET {', '.join(f'{k} = ?' for k in keys)} WHERE id = ?",
              [values[k] for k in keys] + [row[0]])
    c.execute("DELETE FROM speeds WHERE entry_id = ?", (row[0],))
    insert_speeds(c, row[0], figs.speeds)
    return True
