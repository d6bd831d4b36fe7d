"""The report's force polygons: every force's name is read as its own (issue 40, item 2).

方案 I of the task book at φ = 120°: F_I6 (49 N) and N (470 N) beside P (7000 N) are
under 8 mm on the report's page at μF = 60 N/mm, and their names stood side by side at
the one corner, "F_I6 N", each as near the other's arrow as its own. What is painted
is recorded (paint_recorder); a name is read as its force's when the force's middle is
nearer its letters than every other vertex and middle by half a text line, or a leader
line runs from the force's line to the name. Written from the recorded geometry, not
with the placer's code."""
from __future__ import annotations

import math

import pytest
from PySide6.QtCore import QLineF, QPointF, QRectF
from PySide6.QtGui import QFontMetricsF, QImage

from core.forces.masses import MassProperties, masses_for_design
from core.linkage.geometry import from_dimensions
from core.forces.polygons import force_polygon, lever_force_polygon
from shaperapp.report.figures import report_font
from shaperapp.vectors.paint import auto_scale, paint_polygon

from paint_recorder import PaintRecorder

SCHEME_I = from_dimensions(110.0, 380.0, 540.0, rod=135.0)
LOADS_I = masses_for_design(SCHEME_I, MassProperties(
    lever_mass_kg=200.0 / 9.81, lever_inertia_kg_m2=1.1, lever_cg_mm=270.0, ram_mass_kg=700.0 / 9.81,
    ram_cg_mm=(240.0, 50.0), cut_force_N=7000.0, cut_height_mm=80.0))
PX = 300 / 25.4


class Recorder(PaintRecorder):
    """Also the lines drawn on the page itself (the leaders), not under the drawing's transform."""

    def __init__(self, device) -> None:
        super().__init__(device)
        self.page_lines: list[QLineF] = []

    def drawLine(self, *args):
        if self.transform().m22() > 0:
            self.page_lines.append(self.transform().map(args[0] if len(args) == 1 else QLineF(*args)))
        return super().drawLine(*args)


def distance(box: QRectF, p: QPointF) -> float:
    return math.hypot(max(box.left() - p.x(), 0.0, p.x() - box.right()),
                      max(box.top() - p.y(), 0.0, p.y() - box.bottom()))


def on_segment(p: QPointF, seg: QLineF, tol: float) -> bool:
    d = seg.p2() - seg.p1()
    length2 = d.x() ** 2 + d.y() ** 2
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p - seg.p1()).x() * d.x() + (p - seg.p1()).y() * d.y()) / length2))
    q = seg.p1() + d * t
    return math.hypot(p.x() - q.x(), p.y() - q.y()) <= tol


@pytest.mark.parametrize("lang", ["en", "zh"])
@pytest.mark.parametrize("build", [force_polygon, lever_force_polygon], ids=["ram", "lever"])
def test_scheme_i_force_names_are_each_read_as_their_own(qtbot, build, lang):
    polygon = build(SCHEME_I, 120.0, 60.0, LOADS_I)
    image = QImage(round(172 * PX), round(107 * PX), QImage.Format.Format_ARGB32)
    image.setDotsPerMeterX(round(PX * 1000))
    image.setDotsPerMeterY(round(PX * 1000))
    rect = QRectF(0, 0, 170 * PX, 105 * PX)
    font = report_font(lang, 8.0)
    painter = Recorder(image)
    line = QFontMetricsF(font, image).height()
    scale = auto_scale(polygon, rect, QFontMetricsF(font, image), PX)
    paint_polygon(painter, rect, polygon, scale, px_per_mm=PX, font=font, legend=False)
    painter.end()
    drawn = [v for v in polygon.vectors if v.magnitude > 0.0]
    assert len(painter.lines) == len(drawn)
    middles = {v.key: seg.center() for v, seg in zip(drawn, painter.lines)}
    named = [seg.p1() for seg in painter.lines] + [seg.p2() for seg in painter.lines] + list(middles.values())
    # after the two caption lines, each force's name in the vectors' order: its letter, then
    # its index as a second run
    runs = painter.texts[2:]
    texts = []
    for v in drawn:
        (letter, box), runs = runs[0], runs[1:]
        assert letter == v.key.split("_")[0]
        if "_" in v.key:
            (index, sub), runs = runs[0], runs[1:]
            assert index == v.key.split("_")[1]
            box = box.united(sub)
        texts.append((v.key, box))
    assert runs == []
    unread = []
    for key, box in texts:
        seg = painter.lines[[v.key for v in drawn].index(key)]
        tied = any(on_segment(lead.p1(), seg, 0.1 * line) and distance(box, lead.p2()) <= 0.3 * line
                   for lead in painter.page_lines)
        own = distance(box, middles[key])
        others = [p for p in named if math.hypot(p.x() - middles[key].x(), p.y() - middles[key].y()) > 1.0
                  and not on_segment(p, seg, 1.0)]
        if not tied and any(distance(box, p) < own + 0.5 * line for p in others):
            unread.append(key)
    assert unread == []
