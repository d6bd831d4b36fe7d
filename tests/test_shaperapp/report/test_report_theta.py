"""Issue 32: in the report's scheme figure θ's label sat on the L3 dimension line. Checked as
pixels: the figure is painted once whole and once without θ's mark (no dashed limit
lines, arc or label); where θ's text is written, the figure without it must be blank
paper, so nothing of the scheme (a line, a label) lies under the text.
"""
from __future__ import annotations

import re
from dataclasses import replace

import numpy as np
import pytest
from PySide6.QtCore import QRectF
from PySide6.QtGui import QColor, QFont, QFontInfo, QImage

import shaperapp.report.figures as figures
from core.linkage.metrics import analyze
from core.linkage.spec import Spec
from paint_recorder import PaintRecorder
from shaperapp.widgets.fonts import report_font

pytestmark = pytest.mark.slow      # about 3 s a design: the report's views are built and exported

SIZE = (1600, 700)           # device px: the figure's box, about 17 × 7.5 cm at 240 dpi
PX_PER_MM = SIZE[0] / 170.0


def painted(paint, font: QFont | None = None, recorder=PaintRecorder) -> tuple[np.ndarray, list, list]:
    """The figure painted on white paper (in ``font``, as the report sets its painter): its
    darkest channel per pixel, the texts drawn and the pixel size of each (a
    ``SizeRecorder``'s; else empty)."""
    image = QImage(*SIZE, QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    painter = recorder(image)
    if font is not None:
        painter.setFont(font)
    paint(painter, QRectF(0, 0, *SIZE), PX_PER_MM)
    texts, sizes = painter.texts, getattr(painter, "sizes", [])
    painter.end()
    bits = np.frombuffer(image.constBits(), dtype=np.uint8).reshape(SIZE[1], image.bytesPerLine() // 4, 4)
    return bits[:, :SIZE[0], :3].min(axis=2), texts, sizes


@pytest.mark.parametrize("spec", [Spec(), Spec(time_ratio=1.6), Spec(crank=50.7),
                                  Spec(variant="rod", rod_input="ratio", rod_ratio=0.3)],
                         ids=["default", "K=1.6", "L1=50.7", "rod"])
def test_theta_is_written_on_blank_paper(qapp, monkeypatch, spec):
    rpms = [40.0, 60.0]
    views = figures.ReportViews(spec, rpms, None, analyze(spec.design(), rpms))
    try:
        paint = views.limit_schemes()
        _, texts, _ = painted(paint)
        thetas = [box for text, box in texts if text.startswith("θ")]
        assert len(thetas) == 2
        monkeypatch.setattr(figures, "mark_theta", lambda *args, **kwargs: None)
        bare, _, _ = painted(paint)
    finally:
        views.close()
    for box in thetas:
        x0, x1 = int(box.left()) - 1, int(np.ceil(box.right())) + 1
        y0, y1 = int(box.top()) - 1, int(np.ceil(box.bottom())) + 1
        under = bare[y0:y1, x0:x1]
        assert under.size and (under < 200).sum() == 0, (box, int((under < 200).sum()))


SCHEMES = [Spec(mode="dimensions", crank=110.0, frame=380.0, lever=540.0, variant="rod", rod_ratio=0.25),
           Spec(mode="dimensions", crank=90.0, frame=350.0, lever=580.0, variant="rod", rod_ratio=0.3),
           Spec(mode="dimensions", crank=110.0, frame=430.0, lever=810.0, variant="rod", rod_ratio=0.36),
           Spec()]


class SizeRecorder(PaintRecorder):
    """Also records the font's pixel size each text is written at."""

    def __init__(self, device) -> None:
        super().__init__(device)
        self.sizes: list[float] = []

    def drawText(self, *args):
        self.sizes.append(QFontInfo(self.font()).pixelSize())
        return super().drawText(*args)


def textless(svg: bytes) -> bytes:
    """The SVG without its texts (Qt's generator writes each as one <text> element)."""
    return re.sub(rb"<text\b.*?</text>", b"", svg, flags=re.DOTALL)


@pytest.mark.parametrize("language", ["en", "zh_CN"])
@pytest.mark.parametrize("spec", SCHEMES, ids=["scheme-I", "scheme-II", "scheme-III", "default"])
def test_theta_keeps_the_labels_gap_from_every_text(qapp, monkeypatch, spec, language):
    """θ's text keeps LABEL_GAP (1.5 of its heights beside, 0.5 over or under) from every text
    of the scheme, read as ink: the scheme's texts are what its picture loses when its <text>
    elements are taken out. 方案 I's θ stood a third of a line under "L3 = 540.0"."""
    rpms = [60.0]
    views = figures.ReportViews(spec, rpms, None, analyze(spec.design(), rpms))
    made = []
    real = figures.scheme_paint
    monkeypatch.setattr(figures, "scheme_paint", lambda *args: made.append(args) or real(*args))
    try:
        paint = views.limit_schemes()
    finally:
        views.close()
    shots, captions, theta = made[0]
    font = report_font(language, 9.0)
    whole, texts, sizes = painted(paint, font, SizeRecorder)
    thetas = [(box, size) for (text, box), size in zip(texts, sizes) if text.startswith("θ")]
    assert len(thetas) == 2
    monkeypatch.setattr(figures, "mark_theta", lambda *args, **kwargs: None)
    bare, _, _ = painted(paint, font)
    plain = [replace(s, svg=textless(s.svg)) for s in shots]
    lines_only, _, _ = painted(real(plain, captions, theta), font)
    ink = (bare < 200) & (lines_only >= 200)        # the scheme's texts, and nothing else
    assert ink.sum() > 500                          # ten labels' ink in each of two schemes
    for box, h in thetas:
        gx, gy = 1.5 * h, 0.5 * h
        x0, x1 = int(np.floor(box.left() - gx)) + 1, int(np.ceil(box.right() + gx)) - 1
        y0, y1 = int(np.floor(box.top() - gy)) + 1, int(np.ceil(box.bottom() + gy)) - 1
        near = ink[max(y0, 0):y1, max(x0, 0):x1]
        assert not near.any(), (language, box, h, int(near.sum()))
