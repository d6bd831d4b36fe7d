"""The scheme's labels keep a readable gap from each other, on screen and in the report.

In the report's §3 of the task book's 方案 I (`--dims 110,380,540 --rod-ratio 0.25`, the
φ = 0 limit) the joint name O₂ stood on the line of the stroke's dimension, about one text
height before it, and read as one label: "O₂ H = 312.6". The label search now keeps
core.base.lettering.LABEL_GAP between texts: 1.5 text heights beside each other on one
line, 0.5 over each other (and 0.5 from a turned text, the L2 and h chain's, which no
upright text continues).

Checked on pixels, independently of the boxes the search uses: the scheme is exported as
SVG and rendered, once whole and once without each label; a label's ink is what its text
adds. Two labels' ink must keep the gap, in the larger label's font size (em, px).
"""
from __future__ import annotations

import itertools

import numpy as np
import pytest
from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QFontInfo

from core.base.lettering import LABEL_GAP
from core.linkage.spec import Spec
from gui_helpers import shown
from scheme_shots import darkest, limit_frames
from shaperapp.design.model import DesignModel
from shaperapp.scheme.view import SchemeWidget

pytestmark = pytest.mark.slow

SCALE = 2                # rendered at 2 px per exported px
INK = 200
# the task book's 方案 I–III (tests/test_shaperapp/course/test_class_command.py, CLASSIC)
TASK_BOOK = {name: Spec(mode="dimensions", crank=l1, frame=l2, lever=l3, variant="rod", rod_ratio=rod,
                        guide_rule="sagitta")
             for name, (l1, l2, l3, rod) in {"I": (110.0, 380.0, 540.0, 0.25), "II": (90.0, 350.0, 580.0, 0.3),
                                             "III": (110.0, 430.0, 810.0, 0.36)}.items()}


def labels(scheme) -> dict[str, object]:
    """The joint names and dimension texts shown."""
    items = {f"joint {k}": v for k, v in scheme._mechanism.labels.items()}
    items.update({f"dim {k}": v for k, v in scheme._dimensions.texts().items()})
    return {name: item for name, item in items.items() if item.isVisible()}


def ink_boxes(scheme) -> dict[str, tuple[np.ndarray, float, bool]]:
    """Each label's ink (x0, x1, y0, y1) in rendered px, its font size (em) in those px and
    whether it is turned: what its text adds to the exported picture."""
    whole = darkest(scheme.svg_bytes(), SCALE)
    out = {}
    for name, item in labels(scheme).items():
        item.setVisible(False)
        try:
            bare = darkest(scheme.svg_bytes(), SCALE)
        finally:
            item.setVisible(True)
        ys, xs = np.nonzero((whole < INK) & (bare >= INK))
        assert len(xs), name
        em = QFontInfo(item.textItem.font()).pixelSize() * SCALE
        out[name] = (np.array([xs.min(), xs.max() + 1, ys.min(), ys.max() + 1]), em, bool(item.angle))
    return out


def too_close(boxes) -> list[tuple]:
    """(a, b, gap beside, gap over, em) for every two labels nearer than LABEL_GAP: beside
    each other at least LABEL_GAP[0] em, or over each other LABEL_GAP[1] em; a turned
    text LABEL_GAP[1] em from anything (two turned ones, the L2 and h chain, are
    test_report_chain_labels.py's)."""
    out = []
    for (a, (p, em_a, turned_a)), (b, (q, em_b, turned_b)) in itertools.combinations(boxes.items(), 2):
        if turned_a and turned_b:
            continue
        em = max(em_a, em_b)
        beside = max(p[0] - q[1], q[0] - p[1])
        over = max(p[2] - q[3], q[2] - p[3])
        need = LABEL_GAP[1] if turned_a or turned_b else LABEL_GAP[0]
        if beside < need * em and over < LABEL_GAP[1] * em:
            out.append((a, b, round(beside / em, 2), round(over / em, 2)))
    return out


@pytest.mark.parametrize("name", TASK_BOOK)
def test_the_reports_limit_schemes_keep_the_labels_apart(qapp, name):
    found = []
    for scheme, index in limit_frames(TASK_BOOK[name]):
        found += [(index, *pair) for pair in too_close(ink_boxes(scheme))]
    assert found == []


@pytest.mark.parametrize("name", TASK_BOOK)
def test_the_screens_scheme_keeps_the_labels_apart(qtbot, name):
    model = DesignModel()
    model.load_state(TASK_BOOK[name], [60.0], 5.0)
    scheme = shown(qtbot, SchemeWidget(model), 640, 520)
    scheme.fit()
    found = []
    for index in range(0, model.angle_count, model.angle_count // 6):
        model.set_angle_index(index)
        QCoreApplication.processEvents()
        found += [(index, *pair) for pair in too_close(ink_boxes(scheme))]
    assert found == []
