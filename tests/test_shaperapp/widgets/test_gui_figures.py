"""One drawing everywhere: each exportable view's SVG, replayed with QSvgRenderer at the
PNG's size, agrees with its PNG, and replayed into a larger canvas leaves the margin
blank (an SVG cannot clip, so nothing may lie outside a plot's view or the canvas).

Tolerance (``figure_checks``): blocks of 16 × 16 PNG px compared by mean colour; a
block differs above 24 (of 255) and at most 0.2 % of the blocks may differ. Measured
on the fixed views: the largest block difference is 27 in one block of the scheme
(text laid out anew by QSvgRenderer), 16 elsewhere; on a748eb2 the kinematics plots
had 1.5 % of their blocks different at 40 and 349 120 px of margin ink (the stroke
bands), the forces 11–15 %. The margin ignores EDGE px next to the frame: a line on
the canvas edge has half its width outside, antialiased (the PNG cuts that half).
"""
from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtGui import QImage

from core.space.compare import Candidate
from core.forces.masses import MassProperties
from core.linkage.spec import Spec
from shaperapp.compare.view import CompareView
from shaperapp.explore.view import ExploreView
from shaperapp.plots.forces_panel import ForcesPanel
from shaperapp.plots.kinematics import PlotsWidget
from shaperapp.scheme.view import SchemeWidget
from shaperapp.vectors.view import PolygonView

import figure_checks as fc
from gui_helpers import shown

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000)
SPECS = {"block": Spec(), "rod": Spec(variant="rod", rod_input="ratio", rod_ratio=0.3)}
SPEEDS = {2: [40.0, 60.0], 16: [float(20 + 5 * i) for i in range(16)]}
EDGE = 3


def exported(view, tmp_path, name: str) -> tuple[QImage, bytes]:
    view.export_image(str(tmp_path / f"{name}.png"))
    view.export_image(str(tmp_path / f"{name}.svg"))
    return QImage(str(tmp_path / f"{name}.png")), (tmp_path / f"{name}.svg").read_bytes()


def assert_faithful(png: QImage, svg: bytes) -> None:
    assert not png.isNull() and png.width() >= 1600
    assert fc.differing_share(png, svg) <= fc.MAX_DIFFERENT
    assert fc.margin_ink(svg, png.width(), png.height(), EDGE) == 0


@pytest.fixture(params=[(v, n) for v in SPECS for n in SPEEDS], ids=lambda p: f"{p[0]}-{p[1]}")
def loaded(request, model):
    variant, count = request.param
    model.load_state(SPECS[variant], SPEEDS[count], 1.0, masses=LOADS)
    return model


@pytest.mark.parametrize("kind", ["plots", "forces", "scheme", "scheme+forces"])
def test_view_svg_agrees_with_png(qtbot, loaded, tmp_path, kind):
    cls = {"plots": PlotsWidget, "forces": ForcesPanel}.get(kind, SchemeWidget)
    view = shown(qtbot, cls(loaded), 900, 700)
    loaded.set_angle_index(40)          # a cursor mid-plot: not in a printed figure
    if kind == "scheme+forces":
        view.set_forces_visible(True)
    assert_faithful(*exported(view, tmp_path, kind))


def test_plots_svg_agrees_with_png_when_zoomed(qtbot, model, tmp_path):
    """Zoomed in, the curves run out of the view: the SVG cuts them as the screen does."""
    model.load_state(SPECS["rod"], SPEEDS[2], 1.0, masses=LOADS)
    view = shown(qtbot, PlotsWidget(model), 900, 700)
    view.plot_item("ram_v").getViewBox().setRange(xRange=(100, 200), yRange=(0.1, 0.3), padding=0)
    qtbot.wait(10)
    assert_faithful(*exported(view, tmp_path, "zoomed"))


@pytest.mark.parametrize("cls", [PlotsWidget, ForcesPanel])
def test_a_printed_figure_has_no_cursor(qtbot, model, tmp_path, cls):
    """The animation's cursor (dashed line and dots) is on screen, not in the file: the
    export at φ = 0 and at φ = 90° is the same picture."""
    model.load_state(SPECS["block"], SPEEDS[2], 1.0, masses=LOADS)
    view = shown(qtbot, cls(model), 900, 700)
    model.set_angle_index(0)
    first = exported(view, tmp_path, "at0")
    model.set_angle_index(90)
    moved = exported(view, tmp_path, "at90")
    key = "ram_x" if cls is PlotsWidget else "torque"
    stack = view.plots.stack() if cls is ForcesPanel else view.stack()
    assert stack.plot(key).cursor_positions() == pytest.approx([90.0])   # on screen
    assert_same_picture(fc.pixels(first[0]), fc.pixels(moved[0]), "PNG")
    assert_same_picture(fc.pixels(fc.replay(first[1], 900, 700)), fc.pixels(fc.replay(moved[1], 900, 700)),
                        "SVG")


def assert_same_picture(a: np.ndarray, b: np.ndarray, kind: str) -> None:
    """Every pixel equal, compared as arrays: as lists (``tolist()``) the 1600 × 1244 px
    PNG took 3.3–3.8 s of CPU a comparison (at a load of 7), and a failure printed no
    count of the pixels that differ."""
    assert a.shape == b.shape, (kind, a.shape, b.shape)
    different = int((a != b).any(axis=-1).sum())
    assert different == 0, f"{kind}: {different} px differ between φ = 0 and φ = 90°"


@pytest.mark.parametrize("count, size", [(2, (900, 800)), (6, (700, 520))])
def test_compare_svg_agrees_with_png(qtbot, model, tmp_path, count, size):
    view = shown(qtbot, CompareView(model), *size)
    view.set_candidates([Candidate(f"d{k}", Spec(stroke=280.0 + 10 * k), LOADS if k % 2 else None)
                         for k in range(count)])
    assert view.comparison is not None
    assert_faithful(*exported(view, tmp_path, "compare"))


def test_explore_map_svg_agrees_with_png_and_no_map_is_refused(qtbot, model, tmp_path):
    view = shown(qtbot, ExploreView(model), 760, 820)
    try:
        view.runner.cancel()
        view.runner.wait()
        view._refresh_timer.stop()
        view.result = None
        with pytest.raises(ValueError, match="no map"):
            view.export_image(str(tmp_path / "none.svg"))
        assert list(tmp_path.iterdir()) == []
        view.compute.click()
        qtbot.waitUntil(lambda: view.runner.job is None and view.result is not None, timeout=30_000)
        # Exported as a user exports it: after the map's layout has settled. Exported in
        # the event turn the map arrived in, the SVG had its colour-bar title past the
        # view's edge in 4 of 6 whole-suite runs on 1 December (never with this module
        # alone; the bar stood some 16 px right of its place, as if its layout were
        # pending; the cause is not proven).
        qtbot.wait(200)
        assert_faithful(*exported(view, tmp_path, "map"))
    finally:
        view.shutdown()


@pytest.mark.xfail(strict=True, reason="vectors.paint: text and legend lines still differ between "
                   "the PNG and the SVG by more than the tolerance (0.2-1.2 % of blocks); the "
                   "clipped arrowheads this test found at a limit position are fixed")
def test_polygon_svg_agrees_with_png(qtbot, model, tmp_path):
    model.load_state(SPECS["rod"], SPEEDS[2], 1.0, masses=LOADS)
    view = shown(qtbot, PolygonView(model), 600, 600)
    for i in range(view.kind_box.count()):
        view.kind_box.setCurrentIndex(i)
        assert_faithful(*exported(view, tmp_path, f"polygon{i}"))


def test_compare_legend_keeps_off_the_plots(qtbot, model):
    """Six designs take two legend rows; the second ran into the plots' top tick labels."""
    view = shown(qtbot, CompareView(model), 700, 520)
    view.set_candidates([Candidate(f"d{k}", Spec(stroke=280.0 + 10 * k), None) for k in range(6)])
    legend = view.plots._legend
    rows = {round(item.sceneBoundingRect().top()) for _, item in legend.items}
    assert len(rows) == 2
    bottom = max(item.sceneBoundingRect().bottom() for _, item in legend.items)
    for key in ("ram_x_mm", "ram_v_m_s"):
        assert bottom <= view.plots.item(key).sceneBoundingRect().top() + 1


def test_clip_polyline_keeps_exactly_the_inside():
    """Cut polylines: every point kept lies in the rect, every point inside is kept, and
    the kept length equals the inside length measured on a dense resampling."""
    from PySide6.QtCore import QRectF

    from shaperapp.plots.clip import clip_polyline
    rng = np.random.default_rng(7)
    rect = QRectF(-1.0, -0.5, 2.0, 1.0)
    for _ in range(200):
        x, y = rng.normal(0, 1.2, 12), rng.normal(0, 0.8, 12)
        x[rng.integers(12)] = np.nan
        cx, cy = clip_polyline(x, y, rect)
        kept = np.isfinite(cx)
        assert ((cx[kept] >= -1 - 1e-12) & (cx[kept] <= 1 + 1e-12)).all()
        assert ((cy[kept] >= -0.5 - 1e-12) & (cy[kept] <= 0.5 + 1e-12)).all()
        inside = (np.abs(x) <= 1) & (np.abs(y) <= 0.5)
        joined = np.zeros(12, bool)                  # on a drawn segment (a NaN's neighbours
        joined[:-1] |= np.isfinite(x[1:])            # may have no segment at all)
        joined[1:] |= np.isfinite(x[:-1])
        for px, py in zip(x[inside & joined], y[inside & joined]):
            assert np.any((cx == px) & (cy == py))
        t = np.linspace(0, 1, 2001)[:, None]
        dense_x, dense_y = x[:-1] + t * np.diff(x), y[:-1] + t * np.diff(y)
        step = np.hypot(np.diff(x), np.diff(y)) / 2000
        mid_in = (np.abs((dense_x[1:] + dense_x[:-1]) / 2) <= 1) & \
            (np.abs((dense_y[1:] + dense_y[:-1]) / 2) <= 0.5)
        expected = np.nansum(mid_in * step)
        seg = np.hypot(np.diff(cx), np.diff(cy))
        assert np.nansum(seg) == pytest.approx(expected, rel=2e-3, abs=1e-3)
