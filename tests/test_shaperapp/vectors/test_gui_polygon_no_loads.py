"""A force polygon without forces (no loads, or none acting at that angle) is painted as
an empty diagram with its caption, not an error (issue 33, item 1)."""
import pytest
from PySide6.QtCore import QRectF
from PySide6.QtGui import QImage, QPainter

from core.forces.masses import MassProperties
from core.linkage.geometry import synthesize
from core.forces.polygons import force_polygon, lever_force_polygon
from shaperapp.vectors.paint import paint_polygon


@pytest.mark.parametrize("build", [force_polygon, lever_force_polygon], ids=["ram group", "lever"])
@pytest.mark.parametrize("masses", [MassProperties(), MassProperties(cut_force_N=7000.0, gravity=False)],
                         ids=["zero loads", "cut force on the return stroke"])
def test_a_polygon_without_forces_paints_nothing_but_its_caption(qtbot, build, masses):
    polygon = build(synthesize(100, 1.4, 300), 270.0, 40.0, masses)
    assert all(v.magnitude == 0.0 for v in polygon.vectors)
    image = QImage(600, 400, QImage.Format.Format_ARGB32)
    image.fill(0xFFFFFFFF)
    painter = QPainter(image)
    paint_polygon(painter, QRectF(10, 10, 580, 380), polygon, 1.0)
    painter.end()
    inked = [y for y in range(image.height()) if any(image.pixel(x, y) != 0xFFFFFFFF
                                                     for x in range(0, image.width(), 2))]
    assert inked and max(inked) < 60          # the caption's lines at the top, nothing below


def test_a_polygon_without_forces_is_scaled_1_per_mm(qtbot):
    """The report's scale for an empty force polygon: 1 N/mm, as nice_scale gives for
    nothing, not 1.5e-11 N/mm from the 1e-9 floor of an extent."""
    from PySide6.QtGui import QFont, QFontMetricsF

    from shaperapp.vectors.paint import auto_scale
    polygon = force_polygon(synthesize(100, 1.4, 300), 270.0, 40.0, MassProperties())
    metrics = QFontMetricsF(QFont())
    assert auto_scale(polygon, QRectF(0, 0, 400, 300), metrics, 96 / 25.4) == 1.0
