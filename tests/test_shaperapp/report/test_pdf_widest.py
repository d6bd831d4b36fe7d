"""The report's table widths measure each text once per font (``Layout.widest``): the
width it gives must be Qt's own largest advance, in the font asked for, whatever was
measured before in another font."""
from __future__ import annotations

from PySide6.QtCore import QBuffer, QByteArray, QIODevice
from PySide6.QtGui import QFontMetricsF, QPdfWriter

from shaperapp.report.pdf_base import Layout, RESOLUTION


def _layout() -> tuple[Layout, QPdfWriter, QBuffer]:
    buffer = QBuffer(QByteArray())
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    writer = QPdfWriter(buffer)
    writer.setResolution(RESOLUTION)
    return Layout(writer, "en"), writer, buffer


def test_widest_is_qts_largest_advance_in_each_font(qapp):
    lay, writer, _buffer = _layout()
    texts = ["1", "-123.456", "ω2 (rad/s)", "-123.456", "W", "φ1 = 359.9°", "1"]
    for _ in range(2):                       # the second pass answers from what was measured
        for font in (lay.small, lay.tiny, lay.small, lay.bold):
            m = QFontMetricsF(font, writer)
            assert lay.widest(font, texts) == max(m.horizontalAdvance(t) for t in texts)
            assert lay.widest(font, texts[2:3]) == m.horizontalAdvance(texts[2])
    assert lay.widest(lay.small, texts) > lay.widest(lay.tiny, texts) > 0.0   # fonts kept apart
    assert lay.widest(lay.small, []) == 0.0
    assert lay.widest(lay.small, iter(["", ""])) == 0.0
