"""One lettering of the joints' names (GB/T 14691: a drawing's letters all upright or all
sloped): the report's scheme figures (§3, the scheme's SVG export that the report paints)
slope O₂, O₄, A, B as the drawing sheets do. They were italic in the report and upright on
the sheets. Read from the SVGs each writes: a sheet's text painted by ``sheet_paint`` and
the report's limit-position schemes (whose names stay bold, the screen's weight)."""
from __future__ import annotations

import re

from PySide6.QtCore import QBuffer, QByteArray, QIODevice, QRectF, QSize
from PySide6.QtGui import QPainter
from PySide6.QtSvg import QSvgGenerator

import shaperapp.report.figures as figures
from core.drawing.sheet import Sheet, Text, paper
from core.linkage.metrics import analyze
from core.linkage.spec import Spec
from shaperapp.widgets.sheet_paint import paint_sheet

TEXT = re.compile(r'<text[^>]*font-style="([^"]*)"[^>]*>([^<]*)</text>')
JOINTS = {"O₂", "O₄", "A", "B"}


def lettering(svg: bytes) -> dict[str, set[str]]:
    """text → the font-styles (normal, italic, oblique) it is written in."""
    found: dict[str, set[str]] = {}
    for style, text in TEXT.findall(bytes(svg).decode("utf-8")):
        found.setdefault(text, set()).add(style)
    return found


def sheet_svg(sheet: Sheet) -> bytes:
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    generator = QSvgGenerator()
    generator.setOutputDevice(buffer)
    generator.setSize(QSize(420, 297))
    generator.setViewBox(QRectF(0, 0, 420, 297))
    painter = QPainter(generator)
    paint_sheet(sheet, painter, svg=True)
    painter.end()
    return bytes(data)


def test_the_reports_joint_names_are_lettered_as_the_sheets(qapp, monkeypatch):
    shots = []
    real = figures.scheme_paint
    monkeypatch.setattr(figures, "scheme_paint", lambda made, *rest: shots.extend(made) or real(made, *rest))
    rpms = [60.0]
    views = figures.ReportViews(Spec(), rpms, None, analyze(Spec().design(), rpms))
    try:
        views.limit_schemes()
    finally:
        views.close()
    sheet = lettering(sheet_svg(Sheet(paper("A3"), (Text("A", (100.0, 100.0), 5.0, "cm"),))))
    assert sheet["A"] == {"normal"}             # the sheets letter upright
    assert len(shots) == 2
    for shot in shots:
        report = lettering(shot.svg)
        assert JOINTS <= set(report), sorted(report)
        assert {text: report[text] for text in JOINTS} == {text: sheet["A"] for text in JOINTS}
