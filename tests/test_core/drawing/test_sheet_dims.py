"""Dimensions on a sheet drawn at 1:n: the value each shows, what CAD measures on its DXF,
the segment-against-box test the placements rely on, and the spreading of a row of labels.

References are independent of the module: distances and angles from numpy, CAD's own
measurement from ezdxf, a segment clipped to a box by Liang–Barsky.
"""
from __future__ import annotations

import io
import math

import ezdxf
import numpy as np
import pytest
from ezdxf.entities import DimStyleOverride

from dxf_checks import measurement
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from core.drawing import sheet_dims as sd
from core.drawing.mechanism_dims import text_tiles
from core.drawing.path_numbers import spread
from core.drawing.dxf import dxf_text
from core.drawing.sheet import Sheet, Text, paper
from core.drawing.sheet_dxf import sheet_document

coord = st.floats(30.0, 380.0, allow_nan=False)
factor = st.sampled_from([1.0, 1.5, 2.5, 4.0, 10.0, 25.0])


def read_back(dims: list[sd.Dimension]):
    sheet = Sheet(paper("A3"), tuple(p for d in dims for p in (*d.parts, *d.kept)), dimensions=tuple(dims))
    doc = ezdxf.read(io.StringIO(dxf_text(sheet_document(sheet))))
    return doc.modelspace().query("DIMENSION")


@settings(max_examples=12, deadline=None)
@given(coord, coord, coord, coord, st.floats(-20.0, 20.0), factor)
def test_aligned_shows_factor_times_the_paper_length_and_cad_measures_the_same(x1, y1, x2, y2, offset, n):
    length = math.hypot(x2 - x1, y2 - y1)
    assume(length > 1.0)
    dim = sd.aligned((x1, y1), (x2, y2), offset, "L", n)
    assert dim.value == pytest.approx(n * length, rel=1e-12)
    assert float(dim.text.text.split(" = ")[1]) == pytest.approx(round(n * length, 2), abs=1e-9)
    (back,) = read_back([dim])
    assert back.get_measurement() * DimStyleOverride(back).get("dimlfac") == pytest.approx(n * length, rel=1e-9)


@settings(max_examples=12, deadline=None)
@given(coord, coord, coord, coord, st.sampled_from([0.0, 90.0, 30.0]), factor)
def test_linear_shows_the_projected_distance(x1, y1, x2, y2, angle, n):
    u = np.array([math.cos(math.radians(angle)), math.sin(math.radians(angle))])
    along = abs(float(np.dot(np.array([x2 - x1, y2 - y1]), u)))
    assume(along > 1.0)
    dim = sd.linear((x1, y1), (x2, y2), (200.0, 150.0), angle, "H", n)
    assert dim.value == pytest.approx(n * along, rel=1e-9)
    (back,) = read_back([dim])
    assert back.get_measurement() * DimStyleOverride(back).get("dimlfac") == pytest.approx(n * along, rel=1e-9)


@pytest.mark.parametrize("height", [3.5, 2.5])
def test_a_smaller_text_is_drawn_and_written_to_the_dxf_at_its_height(height):
    """A dimension whose text drops to labels' next smaller height (2.5 mm) says so in its
    DIMENSION's DIMTXT, so CAD draws the text the size the PDF shows; the text still clears
    its line by GAP (its box 0.75 h under its middle), and the value is unchanged."""
    dims = [sd.aligned((50.0, 50.0), (150.0, 50.0), 10.0, "L", 2.0, height=height),
            sd.linear((50.0, 80.0), (50.0, 180.0), (30.0, 80.0), 90.0, "H", 2.0, height=height)]
    for dim, back in zip(dims, read_back(dims)):
        assert dim.text.height == height
        assert DimStyleOverride(back).get("dimtxt") == pytest.approx(height)
        assert dim.value == pytest.approx(200.0)
    aligned_line_y = 60.0
    assert dims[0].text.position[1] - 0.75 * height == pytest.approx(aligned_line_y + sd.GAP)


@settings(max_examples=12, deadline=None)
@given(st.floats(-170.0, 170.0), st.floats(2.0, 150.0), st.floats(10.0, 40.0))
def test_angular_shows_the_angle_between_its_legs(start, sweep, radius):
    c = np.array([200.0, 150.0])
    legs = [c + 8.0 * np.array([math.cos(math.radians(t)), math.sin(math.radians(t))])
            for t in (start, start + sweep)]
    dim = sd.angular(tuple(c), tuple(legs[0]), tuple(legs[1]), radius, "θ")
    assert dim.value == pytest.approx(sweep, abs=1e-9)
    assert dim.text.text == f"θ = {sd.value_text(sweep)}°"
    (back,) = read_back([dim])
    assert measurement(back) == pytest.approx(sweep, abs=1e-9)   # θ is a two-line angle (dxf_checks)


@pytest.mark.parametrize("value, text", [(100.0, "100"), (345.4, "345.4"), (579.5551, "579.56"),
                                         (30.0, "30"), (0.004, "0"), (1054.0, "1054")])
def test_value_text_is_two_decimals_without_trailing_zeros(value, text):
    assert sd.value_text(value) == text


def liang_barsky(box, seg) -> bool:
    """Whether the segment has a point strictly inside the box (clipping, then the middle
    of the clipped part tested)."""
    x0, y0, x1, y1 = box
    (px, py), (qx, qy) = seg[:2], seg[2:]
    dx, dy = qx - px, qy - py
    lo, hi = 0.0, 1.0
    for p, q in ((-dx, px - x0), (dx, x1 - px), (-dy, py - y0), (dy, y1 - py)):
        if abs(p) < 1e-15:
            if q <= 0:
                return False
            continue
        t = q / p
        if p < 0:
            lo = max(lo, t)
        else:
            hi = min(hi, t)
    if hi - lo <= 1e-9:
        return False
    t = (lo + hi) / 2.0
    x, y = px + t * dx, py + t * dy
    return x0 < x < x1 and y0 < y < y1


@settings(max_examples=300, deadline=None)
@given(st.lists(st.floats(0.0, 20.0), min_size=4, max_size=4), st.lists(st.floats(0.0, 20.0), min_size=4, max_size=4))
def test_crossing_agrees_with_clipping(b, s):
    box = (min(b[0], b[2]), min(b[1], b[3]), max(b[0], b[2]), max(b[1], b[3]))
    assume(box[2] - box[0] > 0.1 and box[3] - box[1] > 0.1)
    seg = np.array(s)
    assume(np.hypot(*(seg[2:] - seg[:2])) > 1e-3)
    # skip grazing cases, where "meets the inside" depends on rounding
    corners = [(box[0], box[1]), (box[2], box[1]), (box[2], box[3]), (box[0], box[3])]
    d = seg[2:] - seg[:2]
    sides = [d[0] * (cy - seg[1]) - d[1] * (cx - seg[0]) for cx, cy in corners]
    assume(min(abs(v) for v in sides) > 1e-6)
    assume(all(abs(v - w) > 1e-6 for v in seg[[0, 2]] for w in box[::2]))
    assume(all(abs(v - w) > 1e-6 for v in seg[[1, 3]] for w in box[1::2]))
    assert sd.crossings(box, seg[None, :]) == int(liang_barsky(box, seg))


@settings(max_examples=200, deadline=None)
@given(st.lists(st.floats(0.0, 100.0), min_size=1, max_size=30),
       st.lists(st.sampled_from([1.95, 3.9]), min_size=30, max_size=30))
def test_spread_separates_keeps_order_and_moves_as_little_in_sum(xs, ws):
    ideal = np.sort(np.array(xs))
    widths = np.array(ws[:len(xs)])
    out = spread(ideal, widths)
    gaps = np.diff(out) - (widths[:-1] + widths[1:]) / 2.0
    assert (gaps >= 1.0 - 1e-9).all()           # a word space of the 2.5 mm numbers (0.4 h)
    assert float(np.sum(out - ideal)) == pytest.approx(0.0, abs=1e-9)     # each cluster at its mean wish
    if (np.diff(ideal) - (widths[:-1] + widths[1:]) / 2.0 >= 1.0).all():
        assert np.allclose(out, ideal)


@settings(max_examples=12, deadline=None)
@given(coord, coord, coord, coord, st.floats(-20.0, 20.0), factor,
       st.floats(-30.0, 30.0), st.floats(-30.0, 30.0), st.sampled_from([3.5, 2.5]))
def test_a_led_text_is_horizontal_on_a_leader_from_the_middle_of_its_line(x1, y1, x2, y2, offset, n,
                                                                         dx, dy, height):
    """The cascade's last step (issue 32, item 3: "then a leader line"): the text moved out
    along a leader. Still the true value; the line whole with both arrows; the text upright
    on a shoulder line as long as the text, the leader from the dimension line's middle (half
    way between the arrow tips) to the shoulder's near end; in the DXF the DIMENSION with
    that text there, horizontal (DIMTOH), CAD's measurement times DIMLFAC the true length."""
    assume(math.hypot(x2 - x1, y2 - y1) > 20.0 and abs(offset) > 1.0 and math.hypot(dx, dy) > 5.0)
    plain = sd.aligned((x1, y1), (x2, y2), offset, "L3", n)
    tips = np.array([p.points[0] for p in plain.parts if getattr(p, "filled", False)])
    middle = tips.mean(axis=0)
    corner = (float(middle[0] + dx), float(middle[1] + dy))
    dim = sd.led(plain, corner, height)
    assert dim.value == pytest.approx(n * math.hypot(x2 - x1, y2 - y1), rel=1e-9)
    assert dim.text.text == f"L3 = {sd.value_text(dim.value)}" and dim.text.rotation == 0.0
    assert dim.text.height == height
    assert len([p for p in dim.parts if getattr(p, "filled", False)]) == 2
    (leader,) = dim.kept
    pts = np.asarray(leader.points)
    assert pts[0] == pytest.approx(middle, abs=1e-9) and pts[1] == pytest.approx(corner, abs=1e-9)
    x0, y0, x1_, _ = dim.text.box()
    assert pts[2][1] == pytest.approx(corner[1]) and pts[2][1] <= y0 + 1e-9      # under the text
    assert sorted([pts[1][0], pts[2][0]]) == pytest.approx([x0, x1_], abs=1e-6)  # as long as it
    (back,) = read_back([dim])
    style = DimStyleOverride(back)
    assert style.get("dimtoh") == 1
    assert back.get_measurement() * style.get("dimlfac") == pytest.approx(dim.value, rel=1e-9)
    texts = [e for e in back.get_geometry_block() if e.dxftype() in ("TEXT", "MTEXT")]
    assert [t.dxf.get("rotation", 0.0) for t in texts] == [0.0]
    assert np.asarray(texts[0].dxf.insert)[:2] == pytest.approx(dim.text.position, abs=1e-6)


@settings(max_examples=20, deadline=None)
@given(st.floats(-180.0, 180.0), st.sampled_from([2.5, 3.5, 5.0]), st.text("L3= .0123456789", min_size=1, max_size=14))
def test_tiles_cover_a_tilted_text_and_no_more_than_its_box(rotation, height, label):
    """A tool path number's leader must not run through a tilted dimension text, yet may pass
    the free corners of its upright box. The tiles cover every point of the text's rotated
    box (points sampled on it, rotated here with numpy) and lie within its upright box."""
    text = Text(label, (200.0, 150.0), height, "cm", rotation)
    tiles = np.array(text_tiles(text))
    upright = Text(label, (200.0, 150.0), height, "cm", 0.0).box()
    u, v = np.meshgrid(np.linspace(upright[0], upright[2], 25), np.linspace(upright[1], upright[3], 7))
    t = math.radians(rotation)
    local = np.column_stack([u.ravel() - 200.0, v.ravel() - 150.0])
    pts = local @ np.array([[math.cos(t), math.sin(t)], [-math.sin(t), math.cos(t)]]) + (200.0, 150.0)
    inside = ((pts[:, None, 0] >= tiles[None, :, 0] - 1e-9) & (pts[:, None, 0] <= tiles[None, :, 2] + 1e-9)
              & (pts[:, None, 1] >= tiles[None, :, 1] - 1e-9) & (pts[:, None, 1] <= tiles[None, :, 3] + 1e-9))
    assert inside.any(axis=1).all()
    box = text.box()
    assert (tiles[:, :2] >= np.array(box[:2]) - 1e-9).all() and (tiles[:, 2:] <= np.array(box[2:]) + 1e-9).all()
    if abs(math.sin(2.0 * t)) > 0.5 and upright[2] - upright[0] > 3.0 * (upright[3] - upright[1]):
        area = ((tiles[:, 2] - tiles[:, 0]) * (tiles[:, 3] - tiles[:, 1])).sum()
        assert area < 0.9 * (box[2] - box[0]) * (box[3] - box[1])      # the corners left free


def test_the_sheet_dxf_header_draws_dimension_texts_at_the_sheets_height():
    """LibreCAD draws every DIMENSION's text at the header's $DIMTXT, ignoring the entity's
    own override: the header holds the sheet's 3.5 mm (it held the scheme's 5 mm, and
    LibreCAD printed the motion sheet's dimension texts larger than its labels)."""
    dims = [sd.aligned((50.0, 50.0), (150.0, 50.0), 10.0, "L", 2.0),
            sd.linear((50.0, 80.0), (50.0, 180.0), (30.0, 80.0), 90.0, "H", 2.0)]
    sheet = Sheet(paper("A3"), tuple(p for d in dims for p in (*d.parts, *d.kept)), dimensions=tuple(dims))
    doc = ezdxf.read(io.StringIO(dxf_text(sheet_document(sheet))))
    assert doc.header["$DIMTXT"] == pytest.approx(sd.TEXT_MM)
    assert doc.dimstyles.get("GB_MM").dxf.dimtxt == pytest.approx(sd.TEXT_MM)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(*[st.floats(0.0, 60.0)] * 4), min_size=0, max_size=40),
       st.floats(0.0, 60.0), st.floats(0.0, 60.0), st.sampled_from([0.0, 30.0, 90.0, -47.5]),
       st.sampled_from(["lb", "cm", "rt"]))
def test_text_crossings_with_lines_indexed_counts_as_every_segment_tried(segs, x, y, rotation, align):
    """Lines (the extents computed once, the segments apart from the text skipped) counts
    what trying every segment counts: the rotated text's crossings in its own frame."""
    text = Text("L3 = 518.1", (x, y), 3.5, align, rotation)
    segs = np.array(segs, float).reshape(-1, 4)
    if rotation:
        t = math.radians(rotation)
        turn = np.array([[math.cos(t), math.sin(t)], [-math.sin(t), math.cos(t)]])
        o = np.array([x, y])
        local = np.hstack([(segs[:, :2] - o) @ turn.T + o, (segs[:, 2:] - o) @ turn.T + o])
        every = int(sd.crossing(np.array([text.upright_box()]), local).sum())
    else:
        every = int(sd.crossing(np.array([text.box()]), segs).sum())
    assert sd.text_crossings(text, sd.Lines(segs)) == every == sd.text_crossings(text, segs)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.floats(-1e3, 1e3), min_size=2, max_size=2),
       st.lists(st.floats(-1e3, 1e3), min_size=2, max_size=2), st.sampled_from([0.0, 1e-9, 1e-7, 1e-3]))
def test_close_points_are_what_numpy_allclose_says(a, b, nudge):
    b = [b[0], b[1]] if nudge == 0.0 else [a[0] + nudge * a[0], a[1] - nudge]
    assert sd._close(a, b) == bool(np.allclose(a, b))
    assert sd._close(a, [math.inf, b[1]]) == bool(np.allclose(a, [math.inf, b[1]]))
