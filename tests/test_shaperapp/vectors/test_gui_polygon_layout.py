"""Vector diagrams readable on a laptop and in the report (issue 20 item 2, issue 19 item 2).

What is drawn is recorded by ``paint_recorder.PaintRecorder``: every text run's ink box
from the font's metrics, the arrowheads' boxes and the vectors. On the report's page
(170 × 105 mm at 300 dpi) and in the pane of the real window at 1366 × 768 and
1280 × 720: no two texts overlap (P, G₅, F_I5 and N merged into one blob; a legend row's
superscript k touched the subscript above), no text lies on an arrowhead, the
polygon uses a good part of its pane, the whole legend can be scrolled to, and a limit
position says why the polygon degenerates.
"""
from __future__ import annotations

import pytest
from PySide6.QtCore import QRectF, QSettings
from PySide6.QtGui import QFontMetricsF, QImage
from PySide6.QtWidgets import QApplication

from core.forces.masses import MassProperties
from core.linkage.geometry import synthesize
from core.forces.polygons import polygons
from shaperapp.design.model import DesignModel
from shaperapp.report.figures import report_font
from shaperapp.vectors.paint import auto_scale, paint_polygon
from shaperapp.window.main_window import MainWindow

from paint_recorder import PaintRecorder, overlapping
from layout_checks import SharedProbes

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70,
                       cut_force_N=7000, cut_height_mm=80)
ANGLES = (0.0, 30.0, 90.0, 120.0, 210.0, 250.0, 300.0)      # 0 and 210: the limit positions (K 1.4)
PX = 300 / 25.4


def on_heads(texts, heads) -> list[str]:
    return [t for t, b in texts for h in heads if b.adjusted(0.5, 0.5, -0.5, -0.5).intersects(h)]


@pytest.mark.parametrize("lang", ["en", "zh"])
@pytest.mark.parametrize("kw", [{}, {"rod_ratio": 0.3}])
def test_report_polygons_keep_their_labels_apart(qtbot, kw, lang):
    design = synthesize(100, 1.4, 300, **kw)
    image = QImage(round(172 * PX), round(107 * PX), QImage.Format.Format_ARGB32)
    image.setDotsPerMeterX(round(PX * 1000))
    image.setDotsPerMeterY(round(PX * 1000))
    rect = QRectF(0, 0, 170 * PX, 105 * PX)
    font = report_font(lang, 8.0)
    for phi in ANGLES:
        for kind, polygon in polygons(design, phi, 40, LOADS).items():
            painter = PaintRecorder(image)
            scale = auto_scale(polygon, rect, QFontMetricsF(font, image), PX)
            paint_polygon(painter, rect, polygon, scale, px_per_mm=PX, font=font)
            painter.end()
            where = (phi, kind)
            assert overlapping(painter.texts) == [], where
            assert on_heads(painter.texts, painter.heads) == [], where
            outside = [t for t, b in painter.texts if not rect.contains(b)]
            assert outside == [], where
            names = [t for t, _ in painter.texts]
            if kind == "force":          # every force named on the drawing and in the legend
                for vec in polygon.vectors:
                    base = vec.key.partition("_")[0]
                    assert names.count(base) >= 2, (where, vec.key, names)
            limit = phi in (0.0, 210.0) and kind != "force"
            assert any("Limit position" in t for t in names) == limit, where


def pane(lang: str) -> tuple[str, ...]:
    """The probe of the vector-diagram pane in ``lang`` at every angle of ANGLES."""
    return ("--lang", lang, "--speeds", "40,60", "--polygons", ",".join(f"{a:g}" for a in ANGLES))


LAPTOPS = [(1366, 768), (1280, 720)]
LANGUAGES = ["en", "zh_CN"]
PLAN = {screen: [pane(lang) for lang in LANGUAGES] for screen in LAPTOPS}


@pytest.fixture(scope="module")
def shared_probe(tmp_path_factory):
    """Each probe of PLAN run once, a screen's probes in one process (layout_checks.SharedProbes)."""
    return SharedProbes(lambda: tmp_path_factory.mktemp("probe"), PLAN)


@pytest.mark.parametrize("lang", LANGUAGES)
@pytest.mark.parametrize("width,height", LAPTOPS)
def test_vector_pane_on_a_laptop(shared_probe, width, height, lang):
    """The polygon was about 40 px tall beside its legend, labels merged, the
    acceleration legend's last row cut off with no scroll bar."""
    report = shared_probe(width, height, *pane(lang))
    for shot in report["polygons"]:
        where = (shot["kind"], shot["angle"])
        texts = [(t, QRectF(*b)) for t, b in shot["texts"]]
        assert overlapping(texts) == [], where
        assert on_heads(texts, [QRectF(*h) for h in shot["heads"]]) == [], where
        canvas_w, canvas_h = shot["canvas"]
        assert all(b.bottom() <= canvas_h and b.right() <= canvas_w for _, b in texts), where   # scrolls to all
        port_w, port_h = shot["viewport"]
        x, y, w, h = shot["drawing"]
        assert y + h <= port_h, where                               # the drawing itself in view
        # beside the legend (its values "= 0.4189 m/s" with symbol and sample left of them)
        values = [b.left() for t, b in texts if t.startswith("= ")]
        free_w = min(values) - 60 if values and min(values) > port_w / 2 else port_w
        assert w >= 0.35 * free_w or h >= 0.35 * port_h, (where, shot["drawing"], shot["viewport"], free_w)
        if shot["kind"] == "velocity" and shot["angle"] in (0.0, 210.0):
            assert any(("Limit" in t or "极限" in t) for t, _ in texts), where


def test_enlarge_keeps_a_typed_scale(qtbot, tmp_path):
    window = MainWindow(DesignModel(), QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    window.show()
    qtbot.waitExposed(window)
    try:
        window.docks["polygons"].raise_()
        view = window.polygon_view
        view.set_scale("velocity", 0.01)
        small = view.canvas.size()
        view.enlarge_button.click()
        QApplication.processEvents()
        dock = window.docks["polygons"]
        assert dock.isFloating()
        assert view.canvas.width() > small.width() and view.canvas.height() > small.height()
        assert view.scale("velocity") == 0.01                  # the drawing keeps its scale
        view.enlarge_button.click()
        QApplication.processEvents()
        assert not dock.isFloating()
    finally:
        window.model.set_clean("")
        window.close()
        window.deleteLater()


def test_png_export_at_a_limit_position_keeps_the_whole_drawing(qapp, tmp_path, monkeypatch):
    """The export page was sized for a legend beside the drawing; at a limit position the
    drawing is tall and narrow, the legend went below, and the drawing ran under the note
    and the legend: its arrowheads were clipped off (seen comparing the PNG with the SVG).
    The same polygon on a page with wide margins must show exactly as much of each colour."""
    import numpy as np
    from PySide6.QtGui import QImage

    import shaperapp.vectors.export as export
    from core.linkage.geometry import synthesize
    from core.forces.polygons import polygons
    from shaperapp.vectors.paint import vector_colour

    design = synthesize(100.0, 1.4, 300.0, rod_ratio=0.4)

    def ink(path, colour):
        image = QImage(str(path)).convertToFormat(QImage.Format.Format_RGB32)
        raw = np.frombuffer(image.constBits(), np.uint8, image.sizeInBytes())
        rgb = raw.reshape(image.height(), image.bytesPerLine())[:, :image.width() * 4]
        rgb = rgb.reshape(image.height(), image.width(), 4)[..., 2::-1].astype(int)
        target = np.array([colour.red(), colour.green(), colour.blue()])
        return int((np.abs(rgb - target).max(axis=2) < 40).sum())

    for phi in (0.0, 30.0):
        polygon = polygons(design, phi, 40.0)["velocity"]
        colour = vector_colour(polygon, 1)
        export.export_polygon(str(tmp_path / "page.png"), polygon, 0.005)
        with monkeypatch.context() as m:
            m.setattr(export, "MARGIN_MM", 60.0)
            export.export_polygon(str(tmp_path / "wide.png"), polygon, 0.005)
        page, wide = ink(tmp_path / "page.png", colour), ink(tmp_path / "wide.png", colour)
        assert page > 0 and abs(page - wide) <= 0.03 * wide, (phi, page, wide)
