"""The checks every sheet must pass, as the tests measure its description: every item
inside the border, no two texts overlapping (``tests/sheet_checks.py`` adds no text
crossed by a line).

Split from sheet.py, which describes a sheet; these only read one.
"""
from __future__ import annotations

import numpy as np

from .sheet import Item, Sheet, Text, item_box


def outside_border(sheet: Sheet) -> list[Item]:
    """Items not wholly inside the border (the frame's own trimmed edge excepted)."""
    x0, y0, x1, y1 = sheet.paper.border
    trim = (0.0, 0.0, sheet.paper.width, sheet.paper.height)
    tol = 1e-6
    out = []
    for item in sheet.items:
        b = item_box(item)
        if np.allclose(b, trim):
            continue
        if b[0] < x0 - tol or b[1] < y0 - tol or b[2] > x1 + tol or b[3] > y1 + tol:
            out.append(item)
    return out


def overlapping_texts(sheet: Sheet) -> list[tuple[Text, Text]]:
    """Pairs of texts whose boxes intersect."""
    texts = [it for it in sheet.items if isinstance(it, Text)]
    boxes = np.array([t.box() for t in texts]).reshape(-1, 4)
    pairs = []
    for i in range(len(texts)):
        b = boxes[i]
        hit = ((boxes[i + 1:, 0] < b[2]) & (boxes[i + 1:, 2] > b[0])
               & (boxes[i + 1:, 1] < b[3]) & (boxes[i + 1:, 3] > b[1]))
        pairs += [(texts[i], texts[i + 1 + j]) for j in np.flatnonzero(hit)]
    return pairs
