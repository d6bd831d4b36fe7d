"""Text in boxes on a sheet: the standard height that fits, an ellipsis where none does, a
cell's text and a ruled table of cells (GB/T 10609.1).

Split from :mod:`core.drawing.sheet`, which holds the items these build (texts, lines)
and how wide a text is: the sheet says what is drawn, this module fits words into room.
"""
from __future__ import annotations

from typing import Collection, Sequence

import numpy as np

from .dxf import OUTLINE, TEXT, THIN
from .sheet import TEXT_HEIGHTS, Box, Item, Pair, Text, clipped_spans, line, marked, rectangle, text_width


# ---- text that fits ----------------------------------------------------------------------

CELL_PAD = 1.0          # a cell's text keeps this clear of the rules either side, mm
LEAST_CELL_PAD = 0.5    # … or this, where it would otherwise be cut with "…"

def fitting_height(text: str, room: float, largest: float = 5.0) -> float:
    """The largest standard height ≤ ``largest`` at which ``text`` is ≤ ``room`` mm wide
    (the smallest, 2.5 mm, if none is)."""
    for h in sorted((h for h in TEXT_HEIGHTS if h <= largest), reverse=True):
        if text_width(text, h) <= room:
            return h
    return TEXT_HEIGHTS[0]


def cell_text(text: str, box: Box, largest: float = 5.0, align: str = "c",
              layer: str = TEXT, notation: bool = False) -> Text:
    """``text`` inside the cell ``box``, as large as fits (≤ ``largest``), centred
    vertically, aligned left (1 mm in), centre or right, 1 mm clear of the rules (0.5 mm
    where that keeps it whole: "202100123456" at 2.5 mm is 26.2 mm wide, its cell 28 mm);
    with ``notation``, in the index notation of :func:`marked` (the program's own words
    only, never a user's)."""
    x0, y0, x1, y1 = box
    pad = CELL_PAD
    plain, spans = marked(text) if notation else (text, ())
    h = min(fitting_height(plain, x1 - x0 - 2.0 * pad, largest), (y1 - y0) / 1.6)
    h = max((v for v in TEXT_HEIGHTS if v <= h), default=TEXT_HEIGHTS[0])
    if text_width(plain, h) > x1 - x0 - 2.0 * pad:
        pad = LEAST_CELL_PAD        # closer to the rules rather than cut (a 12-digit student number)
    room = x1 - x0 - 2.0 * pad
    x = {"l": x0 + pad, "c": (x0 + x1) / 2.0, "r": x1 - pad}[align]
    plain, spans = clipped_spans(plain, spans, room, h)
    text = Text(plain, (x, (y0 + y1) / 2.0), h, align + "m", layer=layer, subscripts=spans)
    low, high = text.box()[1], text.box()[3]
    lift = min(max(y0 - low, 0.0), max(y1 - high, 0.0))   # a subscript below: up, if it has room
    return text if not lift else Text(plain, (x, (y0 + y1) / 2.0 + lift), h, align + "m",
                                      layer=layer, subscripts=spans)


# ---- tables ------------------------------------------------------------------------------

def table(top_left: Pair, widths: Sequence[float], rows: Sequence[Sequence[str]],
          row_height: float = 8.0, text_height: float = 3.5, layer: str = TEXT,
          aligns: str | None = None, plain: Collection[int] = (), header_rows: int = 1,
          spans: bool = False) -> list[Item]:
    """Rows of texts in ruled cells: outline thick, inner rules thin (GB/T 10609.1). The
    texts are the program's own labels and numbers, in the index notation of :func:`marked`,
    but for the columns in ``plain`` (a user's words, a student's name: taken as they are)
    below the first ``header_rows`` rows. With ``spans``, a text after the first column that
    only empty cells follow fills them too, no rule between (the meshing table's values of
    the pair, one module or centre distance for both gears: "162.0000 (159.0000) mm" was set
    a size smaller in its one column beside an empty one)."""
    x0, y_top = top_left
    xs = np.concatenate([[x0], x0 + np.cumsum(widths)])
    height = row_height * len(rows)
    items: list[Item] = [rectangle((x0, y_top - height, float(xs[-1]), y_top), OUTLINE)]
    for k in range(1, len(rows)):
        y = y_top - k * row_height
        items.append(line([(x0, y), (xs[-1], y)], THIN))
    ends = [_span_end(row, len(widths)) if spans else 0 for row in rows]   # a spanning text's column
    for c in range(1, len(widths)):
        ruled = [r for r, end in enumerate(ends) if not 0 < end < c]       # rows this rule divides
        for first, last in _runs(ruled):
            low, high = y_top - (last + 1) * row_height, y_top - first * row_height
            items.append(line([(xs[c], low), (xs[c], high)], THIN))
    for r, row in enumerate(rows):
        y1 = y_top - r * row_height
        for c, text in enumerate(row):
            if text:
                align = aligns[c] if aligns else "c"
                notation = r < header_rows or c not in plain
                right = xs[-1] if 0 < ends[r] == c else xs[c + 1]     # 0: the row spans nothing
                items.append(cell_text(text, (float(xs[c]), y1 - row_height, float(right), y1),
                                       text_height, align, layer, notation=notation))
    return items


def _span_end(row: Sequence[str], columns: int) -> int:
    """The column of ``row``'s last text when it is after the first column and only empty
    cells follow it (it spans them), else 0."""
    filled = [c for c in range(columns) if c < len(row) and row[c]]
    last = filled[-1] if filled else 0
    return last if 0 < last < columns - 1 else 0


def _runs(indices: list[int]) -> list[tuple[int, int]]:
    """Consecutive runs of sorted ``indices`` as (first, last): one rule per run of rows."""
    runs: list[tuple[int, int]] = []
    for i in indices:
        if runs and runs[-1][1] == i - 1:
            runs[-1] = (runs[-1][0], i)
        else:
            runs.append((i, i))
    return runs
