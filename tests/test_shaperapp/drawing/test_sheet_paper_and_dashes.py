"""The PDF's page is the paper's exact size, and the SVG's dashes are the PDF's: both the
GB/T 4457.4 pattern in mm that the DXF's linetypes hold (issue 32, item 6)."""
import io
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pikepdf
import pytest

from core.drawing.dxf import CENTER, DASHED, LINETYPES, LAYERS
from core.drawing.motion import motion_sheet
from core.drawing.sheet import PAPERS, Circle, Sheet, frame_items, line
from core.linkage.geometry import synthesize
from shaperapp.drawing.render import pdf_bytes, svg_bytes

MM_PER_PT = 25.4 / 72.0


def dashed_sheet(name: str = "A3") -> Sheet:
    """The frame, a centre-line circle and a dashed line: one item of each patterned layer."""
    p = PAPERS[name]
    return Sheet(p, tuple(frame_items(p)) + (Circle((200.0, 150.0), 60.0, CENTER),
                                              line([(50.0, 50.0), (300.0, 50.0)], DASHED)))


def pattern_mm(layer: str) -> list[float]:
    """The layer's linetype as dash and gap lengths in mm (the DXF's definition)."""
    return [abs(v) for v in LINETYPES[LAYERS[layer].linetype][1][1:]]


@pytest.mark.parametrize("name", sorted(PAPERS))
def test_pdf_media_box_is_the_paper_exactly(qapp, name):
    """MediaBox and TrimBox measure the paper to 0.001 mm (Qt alone rounds to whole points:
    A3 was 420.16 × 297.04 mm), and the file is still sound (pikepdf reads its xref)."""
    p = PAPERS[name]
    with pikepdf.open(io.BytesIO(pdf_bytes(dashed_sheet(name)))) as pdf:
        assert len(pdf.pages) == 1
        for box in (pdf.pages[0].MediaBox, pdf.pages[0].TrimBox):
            x0, y0, x1, y1 = (float(v) for v in box)
            assert (x1 - x0) * MM_PER_PT == pytest.approx(p.width, abs=1e-3)
            assert (y1 - y0) * MM_PER_PT == pytest.approx(p.height, abs=1e-3)


@pytest.mark.skipif(shutil.which("pdfinfo") is None, reason="poppler-utils not installed")
def test_pdfinfo_reads_a3_as_iso_216_in_points(qapp, tmp_path):
    out = tmp_path / "a3.pdf"
    out.write_bytes(pdf_bytes(dashed_sheet("A3")))
    info = subprocess.run(["pdfinfo", str(out)], capture_output=True, text=True, check=True).stdout
    assert re.search(r"Page size:\s+1190\.55 x 841\.89 pts", info), info


def test_the_content_keeps_its_place_on_the_exact_page(qapp):
    """The content's y flip (the paper's top edge, in pt) is the box's top, and the box's
    bottom is the paper's height below it: the border stays c from every edge."""
    with pikepdf.open(io.BytesIO(pdf_bytes(dashed_sheet("A3")))) as pdf:
        page = pdf.pages[0]
        y0, top = float(page.MediaBox[1]), float(page.MediaBox[3])
        stream = page.Contents.read_bytes().decode("latin-1")
    flip = re.search(r"([\d.]+) 0 0 -([\d.]+) 0 ([\d.]+) cm", stream)
    assert float(flip.group(3)) == pytest.approx(top)
    assert (top - y0) * MM_PER_PT == pytest.approx(297.0, abs=1e-3)


def svg_dashes_mm(data: bytes) -> list[list[float]]:
    """Every stroke-dasharray in the SVG, in paper mm (its group's scale, the viewBox's mm)."""
    root = ET.fromstring(data)
    per_mm = float(root.get("viewBox").split()[2]) / float(root.get("width").removesuffix("mm"))
    found = []
    for group in root.iter("{http://www.w3.org/2000/svg}g"):
        dashes = group.get("stroke-dasharray")
        if dashes and dashes != "none":
            matrix = re.match(r"matrix\(([-\d.e]+),", group.get("transform", "matrix(1,"))
            k = float(matrix.group(1)) / per_mm
            found.append([float(v) * k for v in dashes.split(",")])
    return found


def pdf_dashes_mm(data: bytes) -> list[list[float]]:
    """Every dash array of the PDF's content stream in paper mm (the painter's mm scale)."""
    with pikepdf.open(io.BytesIO(data)) as pdf:
        stream = pdf.pages[0].Contents.read_bytes().decode("latin-1")
    arrays = re.findall(r"\[([^\]]+)\]\s*[\d.]+\s+d", stream)
    return [[float(v) for v in a.split()] for a in arrays]     # under "47.24 0 0 47.24 cm": mm


def test_svg_and_pdf_dashes_are_the_standards_in_mm(qapp):
    sheet = dashed_sheet()
    expected = sorted([pattern_mm(CENTER), pattern_mm(DASHED)])
    for found in (svg_dashes_mm(svg_bytes(sheet)), pdf_dashes_mm(pdf_bytes(sheet))):
        patterns = sorted({tuple(round(v, 6) for v in d) for d in found})
        assert len(patterns) == 2
        for got, want in zip(patterns, expected):
            assert list(got) == pytest.approx(want)


def test_motion_sheet_svg_crank_circle_is_dashed_at_12_mm(qapp):
    """The issue's case: the crank circle's centre line was 48 mm dashes in the SVG."""
    design = synthesize(100.0, 1.4, 300.0)
    sheet = motion_sheet(design, 40.0, PAPERS["A3"]).sheet
    assert svg_dashes_mm(svg_bytes(sheet)) and all(
        d == pytest.approx(pattern_mm(CENTER)) for d in svg_dashes_mm(svg_bytes(sheet)))
