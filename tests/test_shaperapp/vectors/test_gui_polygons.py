"""The polygon painter draws every vector at its value/μ; the view follows the animation."""
import math
import xml.etree.ElementTree as ET

import pytest
from PySide6.QtCore import QLineF, QRectF
from PySide6.QtGui import QImage, QPainter

from core.forces.masses import MassProperties
from core.linkage.geometry import synthesize
from core.forces.polygons import nice_scale, paper, polygons
from shaperapp.vectors.export import export_polygon
from shaperapp.vectors.paint import paint_polygon
from shaperapp.vectors.view import PolygonView

from gui_helpers import shown

LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70,
                       cut_force_N=7000, cut_height_mm=80)


class RecordingPainter(QPainter):
    """Records the lines drawn under a y-up (drawing-mm) transform: the vectors."""

    def __init__(self, device):
        super().__init__(device)
        self.vector_lines = []

    def drawLine(self, *args):
        line = args[0] if len(args) == 1 else QLineF(*args)
        if self.transform().m22() < 0:
            self.vector_lines.append(((line.x1(), line.y1()), (line.x2(), line.y2()),
                                      self.transform().m11()))
        return super().drawLine(*args)


@pytest.mark.parametrize("kw", [{}, {"rod_ratio": 0.3}])
@pytest.mark.parametrize("phi", [40.0, 250.0])
@pytest.mark.parametrize("px_per_mm", [None, 96 / 25.4])
def test_every_drawn_vector_is_value_over_scale(qtbot, kw, phi, px_per_mm):
    design = synthesize(100, 1.4, 300, **kw)
    image = QImage(900, 700, QImage.Format.Format_ARGB32)
    for polygon in polygons(design, phi, 40, LOADS).values():
        mu = nice_scale(polygon.largest(), 80)
        painter = RecordingPainter(image)
        used = paint_polygon(painter, QRectF(10, 10, 880, 680), polygon, mu, px_per_mm=px_per_mm)
        painter.end()
        drawn = painter.vector_lines
        shown = [v for v in polygon.vectors if v.magnitude > 0]
        assert len(drawn) == len(shown)
        pts = paper(polygon, mu)
        for (tail, head, m11), vec in zip(drawn, shown):
            assert tail == pytest.approx(pts[vec.tail], abs=1e-9)
            assert head == pytest.approx(pts[vec.head], abs=1e-9)
            assert math.dist(tail, head) == pytest.approx(vec.magnitude / mu, rel=1e-12)
            assert m11 == pytest.approx(used)               # one drawing mm = used device units
        if px_per_mm is not None:
            assert used == pytest.approx(px_per_mm)


def test_svg_export_is_true_scale(qtbot, tmp_path):
    design = synthesize(100, 1.4, 300)
    polygon = polygons(design, 100, 40)["velocity"]
    target = tmp_path / "v.svg"
    export_polygon(str(target), polygon, 0.01)
    root = ET.parse(target).getroot()
    assert root.get("width").endswith("mm")
    text = target.read_text()
    assert "v = 0.01 (m/s)/mm" in text          # μ is a separate run in the fallback font
    png = tmp_path / "v.png"
    export_polygon(str(png), polygon, 0.01)
    image = QImage(str(png))
    assert image.width() > 500 and image.dotsPerMeterX() == 8000
    with pytest.raises(ValueError):
        export_polygon(str(tmp_path / "v.txt"), polygon, 0.01)


@pytest.fixture
def view(qtbot, model):
    return shown(qtbot, PolygonView(model), 760, 620)


def test_view_follows_the_animation_and_speed(view, model):
    model.set_angle_deg(100)
    expected = polygons(model.design, model.crank_deg, model.rpms[0])["velocity"]
    assert view.polygon().points == expected.points
    model.set_angle_deg(250)
    assert view.polygon().crank_deg == pytest.approx(250.0)
    view.speed_box.setCurrentIndex(1)
    assert view.polygon().rpm == model.rpms[1]


def test_scale_auto_and_typed(view, model, qtbot):
    view.set_kind("acceleration")
    auto = view.scale()
    mantissa = auto / 10 ** math.floor(math.log10(auto) + 1e-12)
    assert any(abs(mantissa - m) < 1e-9 for m in (1, 2, 2.5, 5))
    view.auto_box.setChecked(False)
    view.scale_edit.setText("0.05")
    view.scale_edit.editingFinished.emit()
    assert view.scale() == 0.05 and view.scale("velocity") != 0.05
    view.scale_edit.setText("-3")
    view.scale_edit.editingFinished.emit()
    assert view.scale() == 0.05 and view.scale_edit.text() == "0.05"
    view.auto_box.setChecked(True)
    assert view.scale() == auto


def test_view_export_and_force_kind(view, model, tmp_path):
    view.set_kind("force")
    model.set_angle_deg(60)
    assert {v.key for v in view.polygon().vectors} >= {"P", "R_B", "N"}
    view.export_image(str(tmp_path / "f.svg"))
    assert f"F = {view.scale():g} N/mm" in (tmp_path / "f.svg").read_text()
    grab = view.grab().toImage()
    colours = {grab.pixelColor(x, y).name() for x in range(0, grab.width(), 7)
               for y in range(60, grab.height(), 7)}
    assert len(colours) > 3                     # something was drawn besides the background


def test_shown_scale_is_the_drawn_scale_after_resizes(view, model, qtbot):
    view.resize(1200, 900)
    model.set_angle_deg(250)
    view.canvas.repaint()
    assert view.scale_edit.text() == f"{view.scale():g}"


def test_a_hidden_view_computes_nothing_until_shown(qtbot, model, monkeypatch):
    """Another tab in front: an edit must not pay for the polygons and their scale."""
    widget = PolygonView(model)
    qtbot.addWidget(widget)
    calls = []
    monkeypatch.setattr(widget, "_auto_scale", lambda kind: calls.append(kind) or 0.01)
    model.set_spec(time_ratio=1.5)
    assert calls == []
    widget.resize(760, 620)
    widget.show()
    qtbot.waitExposed(widget)
    assert calls                      # shown: the scale box is brought up to date
