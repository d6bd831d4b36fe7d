"""A polygon's label search passes by the lines whose extent stays off a candidate box
(``LabelPlacer._meets_a_line``); the answer must be Qt's own test of every line
(``crosses``), box by box: lines through, along, touching and just off a box's edges,
points (zero length), upright and flat lines, and lines added after the first test."""
from __future__ import annotations

import numpy as np
from PySide6.QtCore import QLineF, QPointF, QRectF

from shaperapp.vectors.labels import LabelPlacer, crosses


def _lines(rng: np.random.Generator, box: QRectF) -> list[QLineF]:
    """Random lines, and lines ending on, running along or lying a hair off the box's edges."""
    out = [QLineF(*rng.uniform(-50.0, 150.0, 4)) for _ in range(40)]
    l, t, r, b = box.left(), box.top(), box.right(), box.bottom()
    for hair in (0.0, 1e-9, 1e-3, 0.02):
        out += [QLineF(l - 5.0, t - hair, r + 5.0, t - hair), QLineF(r + hair, t - 5.0, r + hair, b + 5.0),
                QLineF(l - hair, b + hair, l - 20.0, b + 20.0), QLineF(r + hair, b + hair, r + hair, b + hair),
                QLineF(l - 10.0, t, l - hair, t), QLineF((l + r) / 2, b + hair, (l + r) / 2, b + 9.0)]
    return out


def test_the_lines_met_are_qts_crossings_box_by_box(qapp):
    rng = np.random.default_rng(7)
    for _ in range(60):
        x, y = rng.uniform(0.0, 100.0, 2)
        box = QRectF(x, y, rng.uniform(0.5, 30.0), rng.uniform(0.5, 12.0))
        lines = _lines(rng, box)
        rng.shuffle(lines)
        placer = LabelPlacer(QRectF(-100.0, -100.0, 400.0, 400.0), 10.0, lines=lines[:1])
        for k in range(1, len(lines)):
            placer.add_line(lines[k])
            expected = any(crosses(box, line) for line in lines[:k + 1])
            assert placer._meets_a_line(box) == expected, k
            given = LabelPlacer(QRectF(-100.0, -100.0, 400.0, 400.0), 10.0, lines=lines[:k + 1])
            assert given._meets_a_line(box) == expected, k
