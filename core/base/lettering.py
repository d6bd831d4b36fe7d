"""The room between texts, after GB/T 14691 (type B lettering): a word space beside a text,
and the wider gap a label keeps so that it reads as its own text. Plain numbers, for the
sheets (core.drawing) and the screen's scheme (shaperapp.scheme) alike: the first screen
reads them without importing the drawings."""
from __future__ import annotations

# GB/T 14691 (type B lettering): a word's letters stand a = 2/10 h apart, words e = 6/10 h.
# A text's box holds its letters' side bearings (some 0.1 h each side), so two texts side by
# side keep WORD_GAP·h between their boxes, about e between their inks: "105 120", never
# "105120" (boxes that only touch stand a letter space apart and read as one number).
WORD_GAP = 0.4

LABEL_GAP = (1.5, 0.5)
"""The room a label looks for first between itself and another text, in the label's text
heights: beside it on one line (x), and over or under it (y). Not touching is not enough:
GB/T 14691 (ISO 3098) spaces the words of one text 0.6 h apart and its lines 0.4 h, so two
labels closer than that read as one text. The report's scheme of 方案 I put the joint name
O₂ 1.1 h before the dimension "H = 312.6" on its line, and a reader read "O₂ H = 312.6"; at
1.5 h, two and a half word spaces, they read apart. Over each other, 0.5 h is more than a
line gap of one note."""


def word_gap(height: float) -> float:
    """The room, mm, a text ``height`` high keeps between its box and a text beside it
    (WORD_GAP)."""
    return WORD_GAP * height


def label_gap(height: float) -> tuple[float, float]:
    """:data:`LABEL_GAP` for a label ``height`` high, mm (x, y)."""
    return LABEL_GAP[0] * height, LABEL_GAP[1] * height
