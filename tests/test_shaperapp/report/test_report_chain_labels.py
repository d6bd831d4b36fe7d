"""The report's scheme figure: the L2 and h labels of the vertical dimension chain keep a
clear gap. At K = 1.6 (`shaper report --crank 100 --K 1.6 --stroke 300`) they stood end
to end, 0.96 em apart, and read as one text "L2 = 282.0 h = 113.5".

Checked as pixels of the SVG the report paints: the scheme is exported at the report's
size and rendered, once whole and once without each label; a label's ink is what its
text adds. Two labels in one column (their ink's x ranges overlap) must be at least
GAP_EM apart along it, a clear gap against the 0.3 em word spaces inside each label;
side by side (the chain's line between them) they must not touch.
"""
from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QFontInfo

import shaperapp.report.figures as figures
from core.linkage.metrics import analyze
from core.linkage.spec import Spec
from scheme_shots import darkest
from shaperapp.scheme.view import SchemeWidget

SCALE = 2                # rendered at 2 px per exported px
GAP_EM = 1.5
INK = 200


def rendered(scheme, path) -> np.ndarray:
    """The exported scheme painted on white paper: its darkest channel per pixel."""
    scheme.export_image(str(path))
    return darkest(str(path), SCALE)


def ink_box(scheme, name, whole, path) -> tuple[int, int, int, int]:
    """(x0, x1, y0, y1) of the pixels the label ``name`` darkens."""
    item = scheme._dimensions.texts()[name]
    item.setVisible(False)
    try:
        bare = rendered(scheme, path)
    finally:
        item.setVisible(True)
    ys, xs = np.nonzero((whole < INK) & (bare >= INK))
    assert len(xs), name
    return xs.min(), xs.max(), ys.min(), ys.max()


def chain_gaps(spec, tmp_path) -> list[tuple[str, float]]:
    """At both limit positions, as the report draws them: ("column", gap in em) or
    ("side", gap in em) between the L2 and h labels' ink."""
    rpms = [40.0, 60.0]
    views = figures.ReportViews(spec, rpms, None, analyze(spec.design(), rpms))
    out = []
    try:
        scheme = views._show(SchemeWidget(views.model), *figures.SCHEME_PX)
        em = QFontInfo(scheme._dimensions.texts()["L2"].textItem.font()).pixelSize() * SCALE
        for index in (0, views._end_index):
            views.model.set_angle_index(index)
            scheme.fit()
            QCoreApplication.processEvents()
            whole = rendered(scheme, tmp_path / "whole.svg")
            a, b = (ink_box(scheme, name, whole, tmp_path / "bare.svg") for name in ("L2", "h"))
            across = max(a[0] - b[1], b[0] - a[1])
            along = max(a[2] - b[3], b[2] - a[3])
            out.append(("column", along / em) if across < 0 else ("side", across / em))
    finally:
        views.close()
    return out


# the design, then a sweep of K (slow: about 1.5 s a design, the report's scheme
# built, exported and rendered)
@pytest.mark.parametrize("spec", [Spec(crank=100.0, time_ratio=1.6, stroke=300.0)]
                         + [pytest.param(Spec(crank=50.0, time_ratio=k, stroke=300.0), marks=pytest.mark.slow)
                            for k in np.arange(1.1, 3.0, 0.3)],
                         ids=lambda spec: f"L1={spec.crank:g},K={spec.time_ratio:.1f}")
def test_l2_and_h_keep_a_clear_gap(qapp, tmp_path, spec):
    for kind, gap in chain_gaps(spec, tmp_path):
        assert gap >= (GAP_EM if kind == "column" else 0.25), (kind, gap)
