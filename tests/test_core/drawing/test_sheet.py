"""Drawing sheets as data: paper, scales, and the motion sheet measured on the paper."""
import math
import re

import ezdxf
import numpy as np
import pytest
from ezdxf import bbox
from hypothesis import given, settings
from hypothesis import strategies as st

from core.drawing import mechanism as mech
from core.drawing.dxf import CENTER, LAYERS, LINETYPES
from core.drawing.motion import motion_sheet
from core.drawing.checks import outside_border, overlapping_texts
from core.drawing.sheet import PAPERS, TEXT_HEIGHTS, Circle, Polyline, Text, paper, standard_scale, text_width
from core.drawing.sheet_dxf import save_sheet_dxf
from core.linkage.geometry import synthesize
from motion_sheets import motion_drawn
from sheet_checks import assert_laid_out

BLOCK = synthesize(100.0, 1.4, 300.0)
ROD = synthesize(100.0, 1.46, 312.0, rod_ratio=0.3)
SERIES = sorted({m * 10.0 ** k for m in (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0) for k in range(0, 6)})


def test_papers_are_gb_14689_landscape_with_binding_margin():
    a1 = paper("a1")
    assert (a1.width, a1.height) == (841.0, 594.0)
    assert a1.border == (25.0, 10.0, 831.0, 584.0)
    assert paper("A3").border == (25.0, 5.0, 415.0, 292.0)
    for p in PAPERS.values():     # each size is half the next larger one
        assert p.width * p.height == pytest.approx(1189.0 * 841.0 / 2 ** int(p.name[1]), rel=0.01)
    with pytest.raises(KeyError, match="A0, A1, A2, A3"):
        paper("A5")


@settings(max_examples=200, deadline=None)
@given(st.floats(1.0, 1e5), st.floats(10.0, 1000.0))
def test_standard_scale_is_the_smallest_reduction_of_the_series_that_fits(extent, room):
    d = standard_scale(extent, room)
    assert any(math.isclose(d, s, rel_tol=1e-12) for s in SERIES)
    assert extent / d <= room * (1 + 1e-9)
    smaller = [s for s in SERIES if s < d * (1 - 1e-9)]
    assert not smaller or extent / smaller[-1] > room


def test_text_width_counts_chinese_characters_wider():
    assert text_width("曲柄", 5.0) > text_width("AB", 5.0) > 0.0


def stated_scale(sheet) -> float:
    """The reduction written in the mechanism's caption, '(1:d)'."""
    found = [re.search(r"1:(\d+(?:\.\d+)?)\)", t.text) for t in sheet.items if isinstance(t, Text)]
    denominators = {float(m.group(1)) for m in found if m}
    assert len(denominators) == 1
    return denominators.pop()


@pytest.mark.parametrize("design", [BLOCK, ROD], ids=["block", "rod"])
@pytest.mark.parametrize("size", ["A0", "A1", "A2"])
def test_motion_sheet_inside_the_border_without_overlapping_texts(design, size):
    drawn = motion_drawn(design, 40.0, size)
    assert outside_border(drawn.sheet) == []
    assert overlapping_texts(drawn.sheet) == []


@pytest.mark.parametrize("count", [6, 24])
def test_motion_sheet_other_position_counts(count):
    drawn = motion_sheet(ROD, 60.0, paper("A1"), count=count, diagram_deg=(45.0, 250.0))
    assert outside_border(drawn.sheet) == []
    assert overlapping_texts(drawn.sheet) == []
    numbers = {t.text for t in drawn.sheet.items if isinstance(t, Text)}
    assert {str(k) for k in range(1, count + 1)} <= numbers


@pytest.mark.parametrize("design", [BLOCK, ROD], ids=["block", "rod"])
def test_lengths_on_the_paper_over_the_stated_scale_are_the_design(design):
    """Found on the paper: the crank pin's circle (the only centre-line circle) gives L1 and
    its centre O2; the lowest pin is O4. Divided by the scale the caption states."""
    sheet = motion_drawn(design, 40.0, "A1").sheet
    d = stated_scale(sheet)
    assert d in SERIES
    track = [c for c in sheet.items if isinstance(c, Circle) and c.layer == CENTER]
    assert len(track) == 1
    assert track[0].radius * d == pytest.approx(design.crank, rel=1e-12)
    pins = [c for c in sheet.items if isinstance(c, Circle) and c.radius == mech.PIN_RADIUS]
    o4 = min(pins, key=lambda c: c.center[1])
    frame = math.dist(o4.center, track[0].center) * d
    assert frame == pytest.approx(design.frame, rel=1e-12)


def test_limit_positions_are_drawn_thick_and_the_lever_has_its_length():
    """Thick two-point lines from O4: the lever at the two limit positions, each L3 long,
    and θ apart (the lever's swing equals the extreme-position angle)."""
    drawn = motion_drawn(BLOCK, 40.0, "A1")
    o4 = np.asarray(drawn.placement([0.0, 0.0]))
    levers = [np.asarray(p.points) for p in drawn.sheet.items if isinstance(p, Polyline)
              and p.layer == "OUTLINE" and len(p.points) == 2 and np.allclose(p.points[0], o4)]
    assert len(levers) == 2
    ends = [seg[1] - seg[0] for seg in levers]
    for e in ends:
        assert math.hypot(*e) * drawn.scale == pytest.approx(BLOCK.lever, rel=1e-9)
    swing = math.acos(np.dot(ends[0], ends[1]) / (np.linalg.norm(ends[0]) * np.linalg.norm(ends[1])))
    assert swing == pytest.approx(BLOCK.theta, abs=1e-9)


def test_chinese_labels_change_the_texts_not_the_drawing():
    en = motion_drawn(BLOCK, 40.0, "A1").sheet
    zh = motion_sheet(BLOCK, 40.0, paper("A1"),
                      labels={"title": "运动分析图", "L1": "曲柄 O2A，L1"}).sheet
    lines = lambda s: [p.points.tobytes() for p in s.items if isinstance(p, Polyline)]  # noqa: E731
    assert lines(en) == lines(zh)
    assert "运动分析图" in {t.text for t in zh.items if isinstance(t, Text)}
    assert overlapping_texts(zh) == []


@pytest.mark.parametrize("design", [BLOCK, ROD], ids=["block", "rod"])
def test_dxf_reads_back_in_mm_with_layers_inside_the_border(design, tmp_path):
    drawn = motion_drawn(design, 40.0, "A1")
    path = tmp_path / "motion.dxf"
    save_sheet_dxf(drawn.sheet, path)
    doc = ezdxf.readfile(path)
    assert doc.header["$INSUNITS"] == 4
    assert doc.audit().has_errors is False
    for name, layer in LAYERS.items():
        assert doc.layers.get(name).dxf.linetype == layer.linetype
    for name in LINETYPES:
        assert name in doc.linetypes
    x0, y0, x1, y1 = paper("A1").border
    msp = doc.modelspace()
    trim = 0
    for entity in msp:
        assert entity.dxf.layer in LAYERS
        box = bbox.extents([entity])
        if np.allclose([box.extmin.x, box.extmin.y, box.extmax.x, box.extmax.y], [0, 0, 841, 594]):
            trim += 1
            continue
        assert x0 - 1e-6 <= box.extmin.x and box.extmax.x <= x1 + 1e-6, entity
        assert y0 - 1e-6 <= box.extmin.y and box.extmax.y <= y1 + 1e-6, entity
    assert trim == 1
    circles = msp.query(f'CIRCLE[layer=="{CENTER}"]')
    assert len(circles) == 1
    assert circles[0].dxf.radius * drawn.scale == pytest.approx(design.crank, rel=1e-12)


@pytest.mark.parametrize("design", [BLOCK, ROD, synthesize(60.0, 1.8, 500.0),
                                    synthesize(150.0, 1.2, 600.0, rod_ratio=0.8, rod_side="leading")],
                         ids=["block", "rod", "K1.8", "leading"])
@pytest.mark.parametrize("size", ["A1", "A3"])
def test_drawings_stay_in_their_own_areas_which_do_not_overlap(design, size):
    """Nothing overlaps: the mechanism, the curves, the polygons, the table and the title
    block each keep to an area of their own."""
    drawn = motion_drawn(design, 60.0, size, 24)
    assert_laid_out(drawn.sheet, drawn.areas)


@pytest.mark.parametrize("size", ["A0", "A1", "A2", "A3"])
def test_every_text_height_is_from_the_standard_series(size):
    sheet = motion_drawn(ROD, 40.0, size).sheet
    heights = {t.height for t in sheet.items if isinstance(t, Text)}
    assert heights <= set(TEXT_HEIGHTS), heights


def test_more_positions_than_a_sheet_can_show_are_refused():
    from core.base.errors import DesignError
    motion_sheet(BLOCK, 40.0, paper("A1"), count=72)
    with pytest.raises(DesignError, match="positions"):
        motion_sheet(BLOCK, 40.0, paper("A1"), count=73)


@pytest.mark.parametrize("align", ["lb", "cm", "rt", "cb"])
@pytest.mark.parametrize("rotation", [0.0, 90.0, 30.0])
def test_a_subscript_is_a_smaller_lowered_run_after_its_letters(align, rotation):
    """Text with subscript spans is drawn as plain runs: the index one standard size
    smaller, its baseline lowered, right after the letters; together the runs keep the
    label's width and alignment point, inside its box."""
    from core.drawing.sheet import SUBSCRIPT_DROP, item_box, symbol
    text, spans = symbol(("R", "O2"), ",", ("a", "3"))
    assert (text, spans) == ("RO2,a3", ((1, 3), (5, 6)))
    label = Text(text, (100.0, 50.0), 3.5, align, rotation, subscripts=spans)
    runs = label.runs()
    assert [r.text for r in runs] == ["R", "O2", ",a", "3"]
    assert [r.height for r in runs] == [3.5, 2.5, 3.5, 2.5]
    assert label.width == pytest.approx(sum(r.width for r in runs))
    back = np.radians(-rotation)                         # the runs in the label's own frame
    turn = np.array([[np.cos(back), -np.sin(back)], [np.sin(back), np.cos(back)]])
    local = [turn @ (np.array(r.position) - (100.0, 50.0)) for r in runs]
    for (x0, y0), (x1, y1), run in zip(local, local[1:], runs):
        assert x1 == pytest.approx(x0 + run.width)
    assert local[1][1] - local[0][1] == pytest.approx(-SUBSCRIPT_DROP * 3.5)
    start = {"l": 0.0, "c": -label.width / 2.0, "r": -label.width}[align[0]]
    assert local[0][0] == pytest.approx(start)
    outer = label.box()
    for run in runs:
        box = item_box(run)
        assert outer[0] - 1e-9 <= box[0] and outer[1] - 1e-9 <= box[1]
        assert box[2] <= outer[2] + 1e-9 and box[3] <= outer[3] + 1e-9
    assert Text("plain", (0.0, 0.0)).runs() == [Text("plain", (0.0, 0.0))]


def test_dxf_texts_carry_the_gb_width_factor(tmp_path):
    """CAD draws a TEXT at its own width factor (default 1), not its style's: every text of a
    sheet's DXF says 0.7, the GB style's, so it is as narrow as the layout reckons."""
    from core.drawing.dxf import TEXT_WIDTH
    path = tmp_path / "m.dxf"
    save_sheet_dxf(motion_drawn(BLOCK, 40.0, "A3").sheet, path)
    widths = {e.dxf.width for e in ezdxf.readfile(path).modelspace().query("TEXT")}
    assert widths == {TEXT_WIDTH} == {0.7}


@settings(max_examples=200, deadline=None)
@given(st.floats(-500.0, 500.0), st.floats(-500.0, 500.0), st.sampled_from([1.8, 2.5, 3.5, 5.0]),
       st.sampled_from(["lb", "cm", "rt", "lm"]), st.sampled_from([(), ((1, 2),)]))
def test_an_upright_texts_box_is_its_corners_extent(x, y, height, align, subscripts):
    """The box of an unrotated text (plain floats) is the extent numpy takes of its four
    corners, to the last bit: the label searches compare these boxes."""
    text = Text("L3 = 5", (x, y), height, align, subscripts=subscripts)
    w = text.width
    dx = {"l": 0.0, "c": -w / 2.0, "r": -w}[align[0]]
    dy = {"b": 0.0, "m": -height / 2.0, "t": -height}[align[1]]
    parts = text._parts()
    below = max([0.25 * height] + [drop + 0.25 * size for _, size, drop in parts])
    above = max([1.1 * height] + [1.1 * size - drop for _, size, drop in parts])
    corners = np.array([[dx, dy - below], [dx + w, dy - below], [dx + w, dy + above], [dx, dy + above]])
    corners = corners + np.asarray((x, y))
    want = (corners[:, 0].min(), corners[:, 1].min(), corners[:, 0].max(), corners[:, 1].max())
    assert text.box() == text.upright_box() == tuple(map(float, want))
