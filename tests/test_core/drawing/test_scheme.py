"""The scheme for CAD, read back with ezdxf: millimetres, the standard's layers and
linetypes, the mechanism at the asked crank angle, and DIMENSION entities whose own
measurement (from their definition points) is the design's length."""
from __future__ import annotations

import io
import math

import ezdxf
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from core.drawing import dimensions, dxf, scheme
from core.base.errors import DesignError
from core.linkage.geometry import Design, from_dimensions, synthesize
from core.linkage.metrics import analyze
from dxf_checks import measurement

finite = dict(allow_nan=False, allow_infinity=False)
BLOCK = synthesize(100, 1.4, 300)
ROD = synthesize(100, 1.4, 300, rod_ratio=0.3, guide="sagitta")
LEADING = synthesize(80, 1.6, 260, rod_ratio=0.6, rod_side="leading")


def read_back(design: Design, angle: float = 0.0):
    """The scheme as CAD reads it: written out as DXF text (after the audit) and parsed."""
    return ezdxf.read(io.StringIO(dxf.dxf_text(scheme.scheme_document(design, angle))))


def dimensions_by_name(doc) -> dict:
    dims = {}
    for dim in doc.modelspace().query("DIMENSION"):
        name, rest = dim.dxf.text.split(" = ")
        assert rest == "<>"               # CAD writes its own measurement in the text
        dims[name] = dim
    return dims


def expected(design: Design) -> dict[str, float]:
    """The design's values the dimensions must show, mm and ° (H from core's measured
    motion, θ from L1/L2 in closed form)."""
    values = {"L1": design.crank, "L2": design.frame, "L3": design.lever,
              "h": design.guide - design.frame,
              "H": analyze(design, [40]).stroke_mm,
              "θ": math.degrees(2.0 * math.asin(design.crank / design.frame))}
    if design.rod is not None:
        values["L4"] = design.rod
    return values


def points(dim) -> tuple[np.ndarray, np.ndarray]:
    """The two measured definition points of a linear or aligned dimension."""
    return np.array(dim.dxf.defpoint2)[:2], np.array(dim.dxf.defpoint3)[:2]


def moving_pins(doc, design: Design) -> list[np.ndarray]:
    """Centres of the small pin circles (A, B and C), from the drawing."""
    u = design.lever / scheme.UNITS_PER_LEVER
    return [np.array(c.dxf.center)[:2] for c in doc.modelspace().query("CIRCLE")
            if c.dxf.layer == dxf.OUTLINE and math.isclose(c.dxf.radius, scheme.PIN_MOVING * u)]


@pytest.mark.parametrize("design", [BLOCK, ROD, LEADING], ids=["block", "rod", "leading"])
def test_every_dimension_measures_the_design(design, tmp_path):
    path = tmp_path / "scheme.dxf"
    scheme.write_scheme(design, 0.0, path)
    doc = ezdxf.readfile(path)
    assert doc.header["$INSUNITS"] == 4
    dims = dimensions_by_name(doc)
    want = expected(design)
    assert set(dims) == set(want)
    for name, value in want.items():
        assert measurement(dims[name]) == pytest.approx(value, abs=1e-6), name
        assert dims[name].dxf.layer == dxf.DIMENSIONS
        assert dims[name].dxf.dimstyle == dimensions.DIMSTYLE
    assert not doc.audit().has_errors


def test_dimensions_hang_on_the_mechanism_points():
    """L2 from O4 to O2, L3 from O4 to the lever tip, L4 from the tip to the ram joint, L1
    from O2 to the crank circle: the definition points are the mechanism's, so stretching
    the geometry in CAD updates the dimension."""
    doc = read_back(ROD, 75.0)
    dims = dimensions_by_name(doc)
    pins = moving_pins(doc, ROD)
    o2 = np.array([0.0, ROD.frame])
    l2 = {tuple(np.round(p, 9)) for p in points(dims["L2"])}
    assert l2 == {(0.0, 0.0), (0.0, round(ROD.frame, 9))}
    l3, l4 = points(dims["L3"]), points(dims["L4"])
    tip = next(p for p in l3 if np.hypot(*p) > 1.0)
    assert min(np.hypot(*p) for p in l3) < 1e-9                       # O4
    assert any(np.allclose(p, tip) for p in l4)                       # B is shared
    joint = next(p for p in l4 if not np.allclose(p, tip))
    assert joint[1] == pytest.approx(ROD.guide)                       # C on the guide line
    assert any(np.allclose(joint, pin) for pin in pins)
    assert any(np.allclose(tip, pin) for pin in pins)
    l1 = points(dims["L1"])
    assert any(np.allclose(p, o2) for p in l1)


@settings(max_examples=40, deadline=None)
@given(crank=st.floats(20, 400, **finite), k=st.floats(1.05, 3.0, **finite),
       stretch=st.floats(1.05, 4.0, **finite), rod=st.one_of(st.none(), st.floats(0.3, 1.2, **finite)),
       side=st.sampled_from(["trailing", "leading"]), angle=st.floats(0.0, 360.0, **finite))
def test_measurements_and_pose_over_designs_and_angles(crank, k, stretch, rod, side, angle):
    """For any valid design and crank angle: every dimension measures the design to 1e-6 mm
    (θ to 1e-9°), the audit is clean, and the drawn pose is the mechanism at that angle:
    the crank pin A on the crank circle, turned clockwise by φ from its position at φ = 0
    (where the crank stands square to the lever at its left limit), with A and the lever
    tip B on one line through O4."""
    theta = math.pi * (k - 1) / (k + 1)
    try:
        design = synthesize(crank, k, stretch * 2 * crank * (1 + math.sin(theta / 2)),
                            rod_ratio=rod, rod_side=side)
    except DesignError:
        assume(False)
    doc = read_back(design, angle)
    dims = dimensions_by_name(doc)
    for name, value in expected(design).items():
        tolerance = 1e-9 if name == "θ" else 1e-6
        assert measurement(dims[name]) == pytest.approx(value, abs=tolerance), name
    o2 = np.array([0.0, design.frame])
    tip = next(p for p in points(dims["L3"]) if np.hypot(*p) > 1e-9)
    pins = moving_pins(doc, design)
    a = next(p for p in pins if abs(np.hypot(*(p - o2)) - design.crank) < 1e-6 * design.crank)
    assert abs(a[0] * tip[1] - a[1] * tip[0]) < 1e-9 * design.lever ** 2      # O4, A, B in line
    a0 = -design.crank * np.array([math.cos(theta / 2), math.sin(theta / 2)])  # A − O2 at φ = 0
    r = a - o2
    turned = math.degrees(math.atan2(a0[0] * r[1] - a0[1] * r[0], a0 @ r))    # counter-clockwise
    assert (-turned - angle + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=1e-6)


def test_layers_linetypes_and_texts():
    """Every entity on one of the shared layers with its layer's linetype (BYLAYER), the
    paths and axes as centre lines, the limit positions dashed, texts in the GB style at
    the standard height on paper."""
    doc = read_back(BLOCK, 40.0)
    msp = doc.modelspace()
    layers = {e.dxf.layer for e in msp}
    assert layers <= set(dxf.LAYERS)
    assert {dxf.OUTLINE, dxf.THIN, dxf.CENTER, dxf.DASHED, dxf.DIMENSIONS, dxf.TEXT} <= layers
    assert all(e.dxf.get("linetype", "BYLAYER") == "BYLAYER" for e in msp)
    assert doc.layers.get(dxf.CENTER).dxf.linetype == dxf.CENTER_LINETYPE
    circles = {e.dxf.layer for e in msp.query("CIRCLE")
               if math.isclose(e.dxf.radius, BLOCK.crank)}
    assert circles == {dxf.CENTER}                                  # the crank pin's path
    guide_lines = [e for e in msp.query("LINE") if e.dxf.start.y == e.dxf.end.y == BLOCK.guide]
    assert [e.dxf.layer for e in guide_lines] == [dxf.CENTER]       # the ram's path
    assert len(msp.query(f"LINE[layer=='{dxf.DASHED}']")) == 2       # the lever's limit positions
    style = doc.dimstyles.get(dimensions.DIMSTYLE)
    assert style.dxf.dimscale == 1.0 and style.dxf.dimdsep == ord(".")
    scale = style.dxf.dimtxt / dimensions.DIM_TEXT_MM               # the print's 1:n
    texts = msp.query("TEXT")
    assert sorted(t.dxf.text for t in texts) == ["A", "B", "O2", "O4"]
    assert all(t.dxf.height == pytest.approx(scheme.LABEL_MM * scale) and t.dxf.style == dxf.TEXT_STYLE
               for t in texts)


def test_print_scale_is_a_standard_reduction_that_fits_a3():
    """The dimension text is 5 mm times the n of the 1:n a print of the whole drawing on an
    A3 sheet would use: of GB/T 14690's series, and the whole drawing fits at it."""
    doc = read_back(ROD, 0.0)
    n = doc.dimstyles.get(dimensions.DIMSTYLE).dxf.dimtxt / dimensions.DIM_TEXT_MM
    mantissa = n / 10 ** math.floor(math.log10(n))
    assert min(abs(mantissa - m) for m in (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0)) < 1e-9
    size = ezdxf.bbox.extents(doc.modelspace()).size
    assert size.x / n <= scheme.ROOM_MM[0] * 1.05 and size.y / n <= scheme.ROOM_MM[1] * 1.05


def test_dimension_texts_show_the_values_in_mm():
    """What CAD shows before it recomputes: the value to 0.01 mm with a decimal point."""
    doc = read_back(BLOCK, 0.0)
    shown = {}
    for dim in doc.modelspace().query("DIMENSION"):
        texts = [e.plain_text() for e in dim.get_geometry_block() if e.dxftype() == "MTEXT"]
        name, value = texts[0].split(" = ")
        shown[name] = value
    assert shown["L1"] == "100" and shown["H"] == "300" and shown["θ"] == "30°"
    assert shown["L2"] == f"{BLOCK.frame:.2f}" and shown["L3"] == f"{BLOCK.lever:.2f}"


@pytest.mark.parametrize("angle", [-0.001, 360.001, float("nan"), float("inf"), "ten"])
def test_angle_outside_0_to_360_is_refused(angle, tmp_path):
    path = tmp_path / "s.dxf"
    with pytest.raises(DesignError) as err:
        scheme.write_scheme(BLOCK, angle, path)
    assert err.value.parameter == "angle"
    assert not path.exists()


@pytest.mark.parametrize("angle", [0.0, 360.0])
def test_angle_bounds_are_allowed(angle):
    assert scheme.check_angle(angle) == angle


@pytest.mark.parametrize("name", ["s.pdf", "s.svg", "s"])
def test_only_dxf_is_written(name, tmp_path):
    path = tmp_path / name
    with pytest.raises(DesignError) as err:
        scheme.write_scheme(BLOCK, 0.0, path)
    assert err.value.parameter == "output"
    assert not path.exists()


def _text_rectangles(doc) -> list[tuple[str, np.ndarray]]:
    """Each text of the scheme as the rectangle it covers (corners, model mm): the joints'
    names (TEXT, centred) and every DIMENSION's text as its block shows it (MTEXT at its
    attachment point and rotation), each as wide as ``--cad-font outline`` draws it."""
    from core.drawing.outline_text import ATTACHMENTS, OutlineFontMissing, drawn_width, outline_font
    from core.drawing.sheet import Text
    try:
        font = outline_font()
    except OutlineFontMissing:
        pytest.skip("no CJK font for the outlines (fonts-noto-cjk)")

    def corners(text, x, y, h, align, rotation):
        w = drawn_width(Text(text, (x, y), h, align, rotation), font)
        dx = {"l": 0.0, "c": -w / 2, "r": -w}[align[0]]
        dy = {"b": 0.0, "m": -h / 2, "t": -h}[align[1]]
        c, s = math.cos(math.radians(rotation)), math.sin(math.radians(rotation))
        return np.array([(x + c * px - s * py, y + s * px + c * py)
                         for px, py in ((dx, dy), (dx + w, dy), (dx + w, dy + h), (dx, dy + h))])
    msp, out = doc.modelspace(), []
    for dim in msp.query("DIMENSION"):
        for m in doc.blocks.get(dim.dxf.geometry).query("MTEXT"):
            out.append((m.plain_text(), corners(m.plain_text(), m.dxf.insert.x, m.dxf.insert.y, m.dxf.char_height,
                                                ATTACHMENTS[m.dxf.attachment_point], m.get_rotation())))
    for t in msp.query("TEXT"):
        p = t.get_placement()[1]
        out.append((t.dxf.text, corners(t.dxf.text, p.x, p.y, t.dxf.height, "cm", t.dxf.rotation)))
    return out


def _meet(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two convex quadrilaterals overlap (no separating axis among their edges' normals)."""
    for poly in (a, b):
        for i in range(4):
            edge = poly[(i + 1) % 4] - poly[i]
            normal = np.array([-edge[1], edge[0]])
            pa, pb = a @ normal, b @ normal
            if pa.max() <= pb.min() or pb.max() <= pa.min():
                return False
    return True


@pytest.mark.parametrize("angle", [110.0, 280.0])
def test_l3s_text_keeps_off_the_other_texts(angle):
    """K 1.4, H 400 (L2 near L3/2: the middle of L3's line lies by O2): at φ = 110° and 280°
    "L3 = 772.74" stood over "L1 = 100" (and at 105° and 285° over O2), as a LibreCAD print
    of the outline DXF showed at 100°. Its text now moves along its line; no two texts of
    the scheme overlap, and L3's text stays on its line between O4 and B."""
    design = synthesize(crank=100.0, time_ratio=1.4, stroke=400.0)
    doc = scheme.scheme_document(design, angle)
    rects = _text_rectangles(doc)
    hits = [(a, b) for i, (a, ra) in enumerate(rects) for b, rb in rects[i + 1:] if _meet(ra, rb)]
    assert not hits, hits
    l3 = next(r for t, r in rects if t.startswith("L3"))
    b = scheme.pose(design, angle).b
    along = float(np.dot(l3.mean(axis=0), b / design.lever))
    assert 0.0 < along < design.lever


# the default design, K 1.2 with H 500 (a crank short beside its text at the print's 1:n),
# and 方案 I–III of the task book (l_O2A, l_O2O4, l_O4B, l_BC/l_O4B)
CYCLE_DESIGNS = {"default": (BLOCK, 90.0), "K1.2 H500": (synthesize(100.0, 1.2, 500.0), 45.0),
                 "I": (from_dimensions(110.0, 380.0, 540.0, rod_ratio=0.25), 180.0),
                 "II": (from_dimensions(90.0, 350.0, 580.0, rod_ratio=0.3), 180.0),
                 "III": (from_dimensions(110.0, 430.0, 810.0, rod_ratio=0.36), 180.0)}


@pytest.mark.parametrize("name", CYCLE_DESIGNS)
def test_no_two_texts_of_the_scheme_overlap_over_a_cycle(name):
    """K 1.2, H 500: "L1 = 100" lay over O2 and A at 45 of 72 crank angles (every 5°), its
    direction chosen from the lines alone; on 方案 I over C at 155°, 160°, 255° and 260°.
    Read back from the DXF: every text's rectangle (its insert, height, rotation and drawn
    width) clear of every other, at angles through a cycle (every 1° of all five designs
    passes, 1800 documents measured once: 30 s of CPU; the test takes a few per design, the
    suite's time), 方案 I's old ones too. L1's text stands where
    the DIMENSION says (a user-defined location, which LibreCAD takes, and its block's)."""
    design, step = CYCLE_DESIGNS[name]
    angles = list(np.arange(0.0, 360.0, step)) + ([155.0, 255.0] if name == "I" else [])
    for angle in angles:
        doc = read_back(design, float(angle))
        rects = _text_rectangles(doc)
        hits = [(a, b) for i, (a, ra) in enumerate(rects) for b, rb in rects[i + 1:] if _meet(ra, rb)]
        assert not hits, (angle, hits)
        l1 = next(d for d in doc.modelspace().query("DIMENSION") if d.dxf.text.startswith("L1"))
        block_text = next(iter(doc.blocks.get(l1.dxf.geometry).query("MTEXT")))
        assert l1.dxf.dimtype & 128 and l1.dxf.text_midpoint.isclose(block_text.dxf.insert, abs_tol=1e-6), angle
