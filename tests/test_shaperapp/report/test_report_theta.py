"""Issue 32: in the report's scheme figure θ's label sat on the L3 dimension line. Checked as
pixels: the figure is painted once whole and once without θ's mark (no dashed limit
lines, arc or label); where θ's text is written, the figure without it must be blank
paper, so nothing of the scheme (a line, a label) lies under the text.
"""
from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QRectF
from PySide6.QtGui import QColor, QImage

import shaperapp.report.figures as figures
from core.linkage.metrics import analyze
from core.linkage.spec import Spec
from paint_recorder import PaintRecorder

pytestmark = pytest.mark.slow      # about 3 s a design: the report's views are built and exported

SIZE = (1600, 700)           # device px: the figure's box, about 17 × 7.5 cm at 240 dpi
PX_PER_MM = SIZE[0] / 170.0


def painted(paint) -> tuple[np.ndarray, list]:
    """The figure painted on white paper: its darkest channel per pixel, and the texts drawn."""
    image = QImage(*SIZE, QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    painter = PaintRecorder(image)
    paint(painter, QRectF(0, 0, *SIZE), PX_PER_MM)
    texts = painter.texts
    painter.end()
    bits = np.frombuffer(image.constBits(), dtype=np.uint8).reshape(SIZE[1], image.bytesPerLine() // 4, 4)
    return bits[:, :SIZE[0], :3].min(axis=2), texts


@pytest.mark.parametrize("spec", [Spec(), Spec(time_ratio=1.6), Spec(crank=50.7),
                                  Spec(variant="rod", rod_input="ratio", rod_ratio=0.3)],
                         ids=["default", "K=1.6", "L1=50.7", "rod"])
def test_theta_is_written_on_blank_paper(qapp, monkeypatch, spec):
    rpms = [40.0, 60.0]
    views = figures.ReportViews(spec, rpms, None, analyze(spec.design(), rpms))
    try:
        paint = views.limit_schemes()
        _, texts = painted(paint)
        thetas = [box for text, box in texts if text.startswith("θ")]
        assert len(thetas) == 2
        monkeypatch.setattr(figures, "_mark_theta", lambda *args, **kwargs: None)
        bare, _ = painted(paint)
    finally:
        views.close()
    for box in thetas:
        x0, x1 = int(box.left()) - 1, int(np.ceil(box.right())) + 1
        y0, y1 = int(box.top()) - 1, int(np.ceil(box.bottom())) + 1
        under = bare[y0:y1, x0:x1]
        assert under.size and (under < 200).sum() == 0, (box, int((under < 200).sum()))
