"""Every page of the PDF report, as pixels: no figure's ink leaves its box and no body
text lies on a figure's ink (shading, bands, a cursor), in English and Chinese, for the
block and the rod variant, with and without loads and a comparison.

Each report is printed twice through ``pdf_bytes``: its figures alone and its text
alone (tables, headings, captions, title block, footers), both rasterized by
pdftoppm at 50 dpi; ``page_boxes`` says where the layout put each piece. On a748eb2
the stroke bands, the cutting-zone shading and the φ cursor ran over the page. Every
report here has the feed cam's and the gear pair's sections too (issues 23 and 35).
"""
from __future__ import annotations

import shutil
from pathlib import Path
import subprocess

import numpy as np
import pytest
from PySide6.QtGui import QImage

from core.cam import CamInputs
from core.space.compare import Candidate
from core.gear import GearPairInputs
from core.forces.masses import MassProperties
from core.linkage.spec import Spec
from shaperapp.report.content import Options, build
from shaperapp.report.pdf import PAGE_MM, page_boxes, pdf_bytes
from shaperapp.widgets import i18n

from figure_checks import pixels

pytestmark = [pytest.mark.slow, pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="pdftoppm not installed")]
DPI = 50
LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
                       cut_height_mm=80)
SPECS = {"block": Spec(), "rod": Spec(variant="rod", rod_input="ratio", rod_ratio=0.3)}
OTHERS = (Candidate("rod 1.6", Spec(time_ratio=1.6, variant="rod", rod_input="ratio", rod_ratio=0.3),
                    LOADS), Candidate("no loads", Spec(crank=110.0), None))
GEAR = GearPairInputs(z1=13, z2=40, module_mm=6.0, centre_mm=162.0)
CASES = [("en", "block", True, True), ("zh_CN", "rod", True, False), ("en", "rod", False, False),
         ("zh_CN", "block", False, True)]


def rasters(data: bytes, folder, stem: str) -> list[np.ndarray]:
    pdf = folder / f"{stem}.pdf"
    pdf.write_bytes(data)
    subprocess.run(["pdftoppm", "-r", str(DPI), "-png", str(pdf), str(folder / stem)], check=True)
    pages = sorted(folder.glob(f"{stem}-*.png"))
    return [pixels(QImage(str(p))) for p in pages]


def ink(page: np.ndarray) -> np.ndarray:
    return (page < 235).any(axis=2)


def box_mask(shape, boxes, part: str, grow_mm: float) -> np.ndarray:
    px = DPI / 25.4
    mask = np.zeros(shape[:2], bool)
    for kind, box in boxes:
        if kind == part:
            top, bottom = int((box.top() - grow_mm) * px), int(np.ceil((box.bottom() + grow_mm) * px))
            mask[max(top, 0):bottom, :] = True       # a figure is centred across the text width
    return mask


@pytest.fixture(scope="module", params=CASES, ids=lambda c: "-".join(map(str, c)))
def printed(request, tmp_path_factory, qapp):
    language, variant, loads, compare = request.param
    i18n.set_language(language)
    try:
        report = build(SPECS[variant], [40.0, 60.0], LOADS if loads else None, "Pages",
                       "2026-01-01", language, Options(compare=OTHERS if compare else (),
                                                       cam=(CamInputs(), None),    # issue 23's page too
                                                       gear=GEAR))                 # and issue 35's
    finally:
        i18n.set_language("en")
    folder = tmp_path_factory.mktemp("pages")
    figures = rasters(pdf_bytes(report, ("figure",))[0], folder, "figures")
    texts = rasters(pdf_bytes(report, ("text",))[0], folder, "texts")
    return report, page_boxes(report), figures, texts


def test_every_page_is_laid_out(printed):
    report, boxes, figures, texts = printed
    assert len(boxes) == len(figures) == len(texts) >= 6
    assert sum(kind == "figure" for page in boxes for kind, _ in page) >= 6
    h, w = figures[0].shape[:2]
    assert abs(h / w - PAGE_MM[1] / PAGE_MM[0]) < 0.01


def test_no_figure_ink_leaves_its_box(printed):
    _, boxes, figures, _ = printed
    outside = []
    for n, (page, placed) in enumerate(zip(figures, boxes)):
        stray = ink(page) & ~box_mask(page.shape, placed, "figure", 0.5)
        if stray.sum():
            outside.append((n + 1, int(stray.sum())))
    assert outside == []


def test_no_text_lies_on_a_figure(printed):
    _, boxes, figures, texts = printed
    shared = []
    for n, (fig, text) in enumerate(zip(figures, texts)):
        both = ink(text) & (fig < 250).any(axis=2)
        if both.sum():
            shared.append((n + 1, int(both.sum())))
    assert shared == []


def test_no_page_is_left_half_empty_for_a_figure(printed):
    """A figure starting a page would not have fitted at the foot of the page before, even
    shrunk to SHRINK of its height (with its caption); a figure at a stated scale (the gear
    pair) never shrinks, so it would not have fitted whole."""
    from shaperapp.report.blocks import Figure
    from shaperapp.report.pdf import BOTTOM_MM, SHRINK
    report, boxes, _, _ = printed
    figures = iter(b for b in report.blocks if isinstance(b, Figure))     # one drawing each, in order
    drawn = [[next(figures) if kind == "figure" else None for kind, _ in page] for page in boxes]
    assert next(figures, None) is None
    bottom = PAGE_MM[1] - BOTTOM_MM
    for before, page, blocks in zip(boxes, boxes[1:], drawn[1:]):
        if page[0][0] == "figure":
            free = bottom - before[-1][1].bottom()
            figure, caption = page[0][1], page[1][1]
            share = 1.0 if blocks[0].to_scale else SHRINK
            assert free < share * figure.height() + caption.height(), (free, figure.height())


def test_the_gear_figure_keeps_its_height(printed):
    """Drawn at the scale its caption states, the pair in mesh is laid out at its full height."""
    from shaperapp.report.blocks import Figure
    report, boxes, _, _ = printed
    gear = [b for b in report.blocks if isinstance(b, Figure)][-1]
    assert gear.to_scale
    last = [box for page in boxes for kind, box in page if kind == "figure"][-1]
    assert last.height() == pytest.approx(gear.height_mm, abs=0.01)


@pytest.mark.parametrize("kind", ["curves", "forces"])
def test_report_figures_are_the_laid_out_views(qapp, tmp_path, kind):
    """The report takes its plots' SVG from views it lays out first: the SVG agrees with a
    PNG of the same view taken once everything is settled. Exported before layout (as on
    a748eb2, with no event loop on the command line), the legends sat on the top tick
    labels and the joint forces' title on its legend."""
    from PySide6.QtCore import QCoreApplication
    from PySide6.QtGui import QImage

    import figure_checks as fc
    from core.linkage.metrics import analyze
    from shaperapp.report.figures import ReportViews
    spec, rpms = SPECS["rod"], [40.0, 60.0]
    views = ReportViews(spec, rpms, LOADS, analyze(spec.design(), rpms))
    made: list[bytes] = []
    render = views._svg             # the SVG the report paints, as it renders it (in memory)
    views._svg = lambda widget: made.append(render(widget)) or made[-1]
    try:
        getattr(views, kind)()
        svg = made[-1]
        for _ in range(3):
            QCoreApplication.processEvents()
        views._widgets[-1].export_image(str(tmp_path / "settled.png"))
        png = QImage(str(tmp_path / "settled.png"))
        assert fc.differing_share(png, svg) <= fc.MAX_DIFFERENT
    finally:
        views.close()
