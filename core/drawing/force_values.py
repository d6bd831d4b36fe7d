"""The values of forces drawn longer than their scale makes them (issue 40 item 2).

A force under MIN_ARROW at μF is drawn MIN_ARROW long on the kinetostatic sheet, so that
its shaft and head show; its length then says nothing of its size, and its value has to
be read beside it: after its name where that is free, else in a small table in the
drawing's free room.
"""
from __future__ import annotations

import numpy as np

from core.base.lettering import word_gap

from .labels import Room
from .sheet import Item, Text, marked_text, number_text


def values_table(room: Room, note: str, forces: list[tuple[str, tuple, float]], near: np.ndarray) -> list[Item]:
    """The values of the lengthened forces that found no room after their names, as a
    small table (``note`` over one line per force) in the free room nearest ``near``:
    drawn 7 mm long, such a force's length says nothing of its size."""
    if not forces:
        return []
    h = 3.5
    lines = [marked_text(note, (0.0, 0.0), h, "lt")]
    for i, (text, spans, value) in enumerate(forces, start=1):
        name = Text(text, (0.0, -1.6 * h * i), h, "lt", subscripts=spans)
        lines += [name, after(name, f"= {newtons(value)} N")]     # as a value after its name is written
    return list(room.block(lines, (float(near[0]), float(near[1]))))


def newtons(value: float) -> str:
    """A force's value to four significant digits without an exponent (1870, not 1.87e+03):
    the digits the report's polygons and this sheet's guide rows give the same force, so a
    force reads alike on the sheet and in the report (R_O4 = 1335 N, not 1330 N beside it)."""
    return f"{value:.4g}" if abs(value) >= 1e6 else number_text(float(f"{value:.4g}"))


def value_after(room: Room, name: Text, value: str) -> list[Item]:
    """``value`` on the line of the label ``name``, after it, if free there (else left out)."""
    found = room.first_free([after(name, value)])
    return [] if found is None else [found]


def after(name: Text, value: str) -> Text:
    """``value`` on the line of ``name``, a word space after it (GB/T 14691: ``core.base.lettering.WORD_GAP``)."""
    box = name.box()
    return Text(value, (box[2] + word_gap(name.height), (box[1] + box[3]) / 2.0), name.height, "lm")
