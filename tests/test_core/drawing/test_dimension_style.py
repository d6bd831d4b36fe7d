"""One GB dimension style in every DXF, written so that every reader draws it alike
(issue 32, item 6): sizes already at the print scale (DIMSCALE 1, which LibreCAD ignores
anyway), a decimal point, the text above the line, and the same values as the drawing's
current dimension variables (the header), which LibreCAD draws every dimension from."""
from __future__ import annotations

import io
import math

import ezdxf
import pytest

from core.cam import CamInputs, Program, design_cam
from core.drawing.cam_dxf import cam_document
from core.drawing import dimensions, dxf, scheme
from core.linkage.geometry import synthesize

BLOCK = synthesize(100.0, 1.4, 300.0)
ROD = synthesize(100.0, 1.46, 312.0, rod_ratio=0.3)
# The sizes on paper GB/T 4458.4 and 14691 ask for, mm: text, arrow, extension beyond the
# dimension line, gap between text and line
PAPER_MM = {"dimtxt": 5.0, "dimasz": 3.5, "dimexe": 2.0, "dimgap": 1.0}


def read_back(doc):
    return ezdxf.read(io.StringIO(dxf.dxf_text(doc)))


def cam():
    return design_cam(CamInputs(120.0, Program(15.0, 60.0, 10.0, 60.0)), BLOCK)


def documents():
    return {"scheme block": read_back(scheme.scheme_document(BLOCK, 30.0)),
            "scheme rod": read_back(scheme.scheme_document(ROD, 200.0)),
            "cam": read_back(cam_document(cam()))}


@pytest.fixture(scope="module")
def docs():
    return documents()


@pytest.mark.parametrize("name", ["scheme block", "scheme rod", "cam"])
def test_every_dimension_in_the_gb_style_with_a_decimal_point_and_text_above(docs, name):
    doc = docs[name]
    dims = doc.modelspace().query("DIMENSION")
    assert len(dims) >= 1
    assert {d.dxf.dimstyle for d in dims} == {dimensions.DIMSTYLE}
    style = doc.dimstyles.get(dimensions.DIMSTYLE).dxf
    assert style.dimdsep == ord(".") and style.dimtad == 1 and style.dimscale == 1.0
    assert doc.header["$DIMSTYLE"] == dimensions.DIMSTYLE
    for key in ("dimtxt", "dimasz", "dimexe", "dimgap", "dimtad", "dimdsep", "dimdec", "dimscale"):
        assert doc.header[f"${key.upper()}"] == pytest.approx(style.get(key)), key


@pytest.mark.parametrize("name", ["scheme block", "scheme rod", "cam"])
def test_sizes_are_the_papers_times_one_print_scale_of_gb_14690(docs, name):
    """Every size is its paper size times one n of GB/T 14690's series (1, 1.5, 2, 2.5, 3,
    4, 5, 6 × 10^k), so it prints right with DIMSCALE ignored."""
    style = docs[name].dimstyles.get(dimensions.DIMSTYLE).dxf
    assert style.dimscale == 1.0
    ratios = {key: style.get(key) / mm for key, mm in PAPER_MM.items()}
    n = ratios["dimtxt"]
    assert all(r == pytest.approx(n) for r in ratios.values()), ratios
    mantissa = n / 10 ** math.floor(math.log10(n))
    assert min(abs(mantissa - m) for m in (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0)) < 1e-9


@pytest.mark.parametrize("name", ["scheme block", "scheme rod"])
def test_scheme_dimension_text_is_as_high_as_its_labels(docs, name):
    """The issue's LibreCAD case: the dimension texts at a quarter of the labels' height.
    The joint names are 5 mm on paper, the dimension texts too: one height in model space."""
    doc = docs[name]
    labels = [t.dxf.height for t in doc.modelspace().query("TEXT")]
    assert labels and labels == pytest.approx([doc.dimstyles.get(dimensions.DIMSTYLE).dxf.dimtxt] * len(labels))


def test_cam_dimension_names_the_centre_distance_and_measures_it(docs):
    c = cam()
    (dim,) = docs["cam"].modelspace().query("DIMENSION")
    assert dim.dxf.text == "a = <>"
    assert dim.get_measurement() == pytest.approx(c.follower.distance_mm, rel=1e-12)
    texts = [e.plain_text() for e in dim.get_geometry_block() if e.dxftype() == "MTEXT"]
    assert texts == [f"a = {c.follower.distance_mm:.2f}".rstrip("0").rstrip(".")]


def test_angles_are_two_line_angular_dimensions(docs):
    """θ as the angle of two lines (DIMENSION type 2), which LibreCAD 2.2 draws; it left the
    three-point angular dimension (type 5) out."""
    types = {d.dimtype for name in ("scheme block", "scheme rod") for d in docs[name].modelspace().query("DIMENSION")}
    assert 2 in types and 5 not in types


@pytest.mark.parametrize("start, turn", [(75.0, 30.0), (10.0, 200.0), (300.0, 90.0)])
def test_angular_shows_the_counter_clockwise_angle_from_p1_to_p2(start, turn):
    """The helper's promise kept by the two-line dimension ezdxf renders (which showed
    360° − θ for the lines in the order p1, p2)."""
    doc = ezdxf.new()
    dimensions.add_dimstyle(doc, 1.0)
    msp = doc.modelspace()
    ray = lambda deg: (100.0 * math.cos(math.radians(deg)), 100.0 * math.sin(math.radians(deg)))  # noqa: E731
    middle = ray(start + turn / 2.0)
    dimensions.angular(msp, (0.0, 0.0), ray(start), ray(start + turn), (0.6 * middle[0], 0.6 * middle[1]), "t")
    (dim,) = msp.query("DIMENSION")
    texts = [e.plain_text() for e in dim.get_geometry_block() if e.dxftype() == "MTEXT"]
    assert texts == [f"t = {turn:g}°"]
