"""The mechanism sketch draws what core computes, follows the model, fits and exports."""
from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pytest
from PySide6.QtCore import QEvent, QRectF
from PySide6.QtGui import QImage
from PySide6.QtWidgets import QApplication, QCheckBox

from shaperapp.design.model import DesignModel
from shaperapp.scheme.view import SchemeWidget




def core_joints(model: DesignModel, index: int) -> dict[str, np.ndarray]:
    sh = model.motion.shape
    return {"A": sh.crank_pin[:, index], "B": sh.lever_tip[:, index], "C": sh.ram_joint[:, index]}


def assert_drawn_at(scheme: SchemeWidget, model: DesignModel, index: int) -> None:
    """Markers and the far ends of the moved link bodies sit on core's joints."""
    drawn, ends = scheme.drawn_joints(), scheme.drawn_link_ends()
    core = core_joints(model, index)
    np.testing.assert_allclose(drawn["O4"], (0.0, 0.0), atol=1e-9)
    np.testing.assert_allclose(drawn["O2"], (0.0, model.design.frame), atol=1e-9)
    np.testing.assert_allclose(drawn["A"], core["A"], atol=1e-9)
    np.testing.assert_allclose(drawn["B"], core["B"], atol=1e-9)
    np.testing.assert_allclose(ends["crank"], core["A"], atol=1e-6)
    np.testing.assert_allclose(ends["lever"], core["B"], atol=1e-6)
    if model.design.rod is not None:
        np.testing.assert_allclose(drawn["C"], core["C"], atol=1e-9)
        np.testing.assert_allclose(ends["rod"], core["C"], atol=1e-6)
    else:
        assert "C" not in drawn and "rod" not in ends


@pytest.mark.parametrize("index", [0, 37, 120, 211, 300, 360])
def test_block_variant_joints_equal_core(scheme, model, index):
    model.set_angle_index(index)
    assert model.angle_index == index
    assert_drawn_at(scheme, model, index)


@pytest.mark.parametrize("side", ["trailing", "leading"])
def test_rod_variant_joints_equal_core(scheme, model, side):
    model.set_spec(variant="rod", rod_ratio=0.3, rod_side=side)
    assert model.error is None and model.design.rod is not None
    for index in (0, 90, 233):
        model.set_angle_index(index)
        assert_drawn_at(scheme, model, index)
        assert scheme.drawn_joints()["C"][1] == pytest.approx(model.design.guide)


def test_angle_change_moves_the_crank(scheme, model):
    model.set_angle_index(10)
    before = scheme.drawn_link_ends()["crank"]
    model.set_angle_index(100)
    after = scheme.drawn_link_ends()["crank"]
    assert np.hypot(after[0] - before[0], after[1] - before[1]) > 0.5 * model.design.crank
    np.testing.assert_allclose(after, model.motion.shape.crank_pin[:, 100], atol=1e-6)


def test_new_design_redraws(scheme, model):
    model.set_angle_index(50)
    old_b = scheme.drawn_joints()["B"]
    old_frame = model.design.frame
    model.set_spec(time_ratio=1.6)
    assert model.error is None and model.design.frame != old_frame
    assert_drawn_at(scheme, model, model.angle_index)
    assert scheme.drawn_joints()["B"] != old_b
    assert f"L2 = {model.design.frame:.2f}".rstrip("0").rstrip(".") in scheme.dimension_labels()


def test_items_are_created_once(scheme, model):
    view = scheme.plot_widget().getPlotItem().getViewBox()
    before = [id(item) for item in view.addedItems]
    model.set_spec(variant="rod", rod_ratio=0.3)
    model.set_angle_index(200)
    model.set_spec(time_ratio=1.7)
    assert [id(item) for item in view.addedItems] == before


def test_a_frame_emits_no_python_signals(scheme, model):
    """PySide6 6.12 drops a reference to True on every Python-side emit; the frame
    update must not emit (model.set_angle_index itself emits angleChanged once)."""
    import sys
    model.set_angle_index(1)
    before = sys.getrefcount(True)
    for index in range(2, 60):
        model.set_angle_index(index)
    assert sys.getrefcount(True) >= before - 58
    assert_drawn_at(scheme, model, 59)


def test_aspect_is_locked(scheme):
    view = scheme.plot_widget().getPlotItem().getViewBox()
    assert view.state["aspectLocked"] == 1.0
    for widget_size in ((900, 650), (500, 800)):
        scheme.resize(*widget_size)
        scheme.fit()
        mm_per_px_x, mm_per_px_y = view.viewPixelSize()
        assert mm_per_px_x == pytest.approx(mm_per_px_y, rel=1e-3)


def trace_bounds(model: DesignModel) -> QRectF:
    """The region every joint sweeps over the cycle, plus O4, from core."""
    sh = model.motion.shape
    pts = np.hstack([sh.crank_pin, sh.lever_tip, sh.ram_joint, np.zeros((2, 1))])
    return QRectF(pts[0].min(), pts[1].min(), np.ptp(pts[0]), np.ptp(pts[1]))


def test_fit_shows_the_whole_mechanism(scheme, model):
    view = scheme.plot_widget().getPlotItem().getViewBox()
    view.scaleBy((0.2, 0.2))            # zoom far in
    assert not view.viewRect().contains(trace_bounds(model))
    scheme.fit()
    assert view.viewRect().contains(trace_bounds(model))


def test_fit_once_per_new_design_only(scheme, model):
    view = scheme.plot_widget().getPlotItem().getViewBox()
    view.scaleBy((0.5, 0.5))
    zoomed = view.viewRect()
    model.set_rpms([30.0, 90.0])         # same design: the user's zoom stays
    QApplication.processEvents()         # the scheme rebuilds once the edit is announced
    assert view.viewRect() == zoomed
    model.set_spec(stroke=450.0)         # new design: fitted again
    QApplication.processEvents()
    assert model.error is None
    assert view.viewRect() != zoomed
    assert view.viewRect().contains(trace_bounds(model))


def test_tool_path_follows_the_ram(scheme, model):
    ram = model.motion.shape.ram_joint[0]
    metrics = model.metrics
    for index in (0, 150, 300, model.angle_count - 1):
        model.set_angle_index(index)
        x, y = scheme.tool_path()
        offset = x[0] - ram[0]                     # the tip rides at a fixed distance from C
        assert x[-1] - offset == pytest.approx(ram[index], abs=1e-9)
        visited = ram[: index + 1] + offset
        assert all(np.min(np.abs(visited - xv)) < 1e-9 for xv in x)   # every vertex is a past tip
        travelled = np.ptp(ram[: index + 1])
        assert np.ptp(x) == pytest.approx(travelled, abs=1e-9)
    # A whole cycle sweeps the stroke core measured; the return runs above the cut.
    assert np.ptp(x) == pytest.approx(metrics.stroke_mm, abs=0.05)
    assert y.max() > y[0]


def test_dimensions_show_core_values_and_toggle(scheme, model):
    design = model.design
    values = (design.frame, design.guide_above_crank, design.lever, design.crank, model.metrics.stroke_mm)
    # the drawings' rule for a dimension's text (CAD's: 2 places, trailing zeros dropped)
    assert scheme.dimension_labels() == [f"{name} = {value:.2f}".rstrip("0").rstrip(".")
                                         for name, value in zip(("L2", "h", "L3", "L1", "H"), values)]
    box = scheme.findChild(QCheckBox)
    assert box.isChecked() and scheme.dimensions_visible()
    box.setChecked(False)
    assert not scheme.dimensions_visible()
    assert not scheme.dimensions_action.isChecked()
    scheme.dimensions_action.setChecked(True)
    assert box.isChecked()


def test_export_png_and_svg(scheme, tmp_path):
    png, svg = tmp_path / "scheme.png", tmp_path / "scheme.svg"
    scheme.export_image(str(png))
    image = QImage(str(png))
    assert not image.isNull() and image.width() >= 1600
    colours = {image.pixel(x, y) for x in range(0, image.width(), 37)
               for y in range(0, image.height(), 37)}
    assert len(colours) > 3                      # something is drawn on the white page
    scheme.export_image(str(svg))
    root = ET.parse(svg).getroot()
    assert root.tag.endswith("svg")
    assert len(root.findall(".//{http://www.w3.org/2000/svg}path")) > 10
    with pytest.raises(ValueError):
        scheme.export_image(str(tmp_path / "scheme.txt"))


def test_language_change_keeps_texts(scheme):
    QApplication.sendEvent(scheme, QEvent(QEvent.LanguageChange))
    assert scheme.fit_action.text()
    assert scheme.findChild(QCheckBox).text()
    assert all(scheme.dimension_labels())


def test_a_nudged_input_keeps_the_view_while_the_drawing_fits(scheme, model):
    """K 1.40 → 1.41 changes the drawing a little: the view stays (no jump) and still
    holds the whole travel; a design twice as large is fitted again."""
    view = scheme.plot_widget().getPlotItem().getViewBox()
    before = view.viewRect()
    model.set_spec(time_ratio=1.41)
    QApplication.processEvents()
    assert view.viewRect() == before
    assert view.viewRect().contains(trace_bounds(model))
    model.set_spec(crank=200.0, stroke=600.0)
    QApplication.processEvents()
    assert view.viewRect() != before and view.viewRect().contains(trace_bounds(model))



@pytest.mark.parametrize("spec", [dict(time_ratio=1.46, stroke=312.0),
                                  dict(mode="dimensions", crank=110.0, frame=380.0, lever=540.0)])
def test_the_schemes_dimensions_read_as_the_motion_sheets(scheme, model, spec):
    """One precision per kind: the scheme's labels (the window's, the report's) read h = 170.3
    and L3 = 538.8 where the motion sheet drew 170.35 and 538.82; both are a drawing's
    dimension texts (core.base.figure_text.dimension_text)."""
    from core.drawing.motion import motion_sheet
    from core.drawing.sheet import PAPERS
    model.set_spec(**spec)
    sheet = motion_sheet(model.design, 40.0, PAPERS["A3"]).sheet
    drawn = {d.text.text for d in sheet.dimensions}
    assert set(scheme.dimension_labels()) <= drawn
