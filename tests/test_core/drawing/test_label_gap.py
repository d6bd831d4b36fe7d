"""A label keeps a readable gap from the texts round it (core.drawing.labels.LABEL_GAP),
not only clear of them: a joint name 1.1 text heights before a dimension on its line read
as one label with it ("O₂ H = 312.6", the report's scheme of 方案 I)."""
from __future__ import annotations

import numpy as np
import pytest

from core.drawing.labels import LABEL_GAP, place
from core.drawing.sheet import Text


def apart(a, b, height) -> bool:
    """Boxes (x0, y0, x1, y1) at least LABEL_GAP apart: beside on one line, or over each other."""
    beside = max(a[0] - b[2], b[0] - a[2])
    over = max(a[1] - b[3], b[1] - a[3])
    return beside >= LABEL_GAP[0] * height - 1e-9 or over >= LABEL_GAP[1] * height - 1e-9


@pytest.mark.parametrize("height", [2.5, 3.5, 5.0])
@pytest.mark.parametrize("offset", [0.2, 0.6, 1.0, 1.4])
def test_a_label_keeps_the_gap_from_a_text_on_its_line(height, offset):
    """A dimension's text stands on the label's preferred line, ``offset`` text heights past
    where the label would end at its first spot (touching it is free, but too close)."""
    first = Text("O2", (1.5, 0.0), height, "lm").box()
    other = Text("H = 312.6", (first[2] + offset * height, 0.0), height, "lm")
    taken = [other.box()]
    placed = place("O2", (0.0, 0.0), height, taken, np.zeros((0, 4)), preferred=(1.0, 0.0))
    assert placed, "left out"
    label = placed[0]
    assert label.text == "O2" and apart(label.box(), other.box(), label.height), (label.box(), other.box())
