"""No label on a sheet is crossed by a line, a circle or an arrowhead (issue 32, item 3).

First the check itself (tests/sheet_checks.crossed_texts) on hand-made sheets whose
answer is plain geometry, then core.drawing.labels' placement against random strokes,
checked by that independent check, then the sheets over designs, papers and variants."""
import math

import numpy as np
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from core.cam import CamInputs, Program, design_cam
from core.drawing.cam_sheet import cam_sheet
from core.drawing.charts import arrow
from core.drawing.forces import forces_sheet
from core.drawing.labels import place
from core.drawing.motion import motion_sheet
from core.drawing.checks import outside_border, overlapping_texts
from core.drawing.sheet import Circle, Sheet, Text, char_advance, line, paper
from core.forces.masses import MassProperties, masses_for_design
from core.base.errors import DesignError
from core.linkage.geometry import synthesize
from sheet_checks import crossed_texts, crowded_texts
from sweeps import examples

A1 = paper("A1")
DEFAULT = synthesize(100.0, 1.4, 300.0)
LOADS = dict(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000, cut_height_mm=80)
finite = dict(allow_nan=False, allow_infinity=False)


def crossed(*items) -> list[str]:
    return [t.text for t, _ in crossed_texts(Sheet(A1, tuple(items)))]


# ---- the check ---------------------------------------------------------------------------

def test_a_line_through_the_letters_crosses_them_one_along_the_box_does_not():
    """"AB" at (100, 100), 5 mm high, 9.39 mm wide: a line through its middle crosses it;
    one 0.2 mm under its baseline (in the descender's room, where a leader line ends),
    one beyond its end and one above its capitals do not."""
    label = Text("AB", (100.0, 100.0), 5.0, "lb")
    assert crossed(label, line([(90.0, 102.5), (120.0, 102.5)])) == ["AB"]
    assert crossed(label, line([(104.0, 90.0), (104.0, 110.0)])) == ["AB"]
    assert crossed(label, line([(90.0, 99.8), (120.0, 99.8)])) == []
    assert crossed(label, line([(110.1, 90.0), (110.1, 110.0)])) == []
    assert crossed(label, line([(90.0, 105.3), (120.0, 105.3)])) == []


def test_a_circle_a_closed_outline_and_a_subscript_are_checked_too():
    label = Text("RO2", (100.0, 100.0), 3.5, "lb", subscripts=((1, 3),))
    index_x = 100.0 + 3.5 * char_advance("R") + 1.0    # inside the subscript run, 2.5 mm high
    assert crossed(label, Circle((index_x, 99.0), 0.3)) == []          # inside, touching nothing
    assert crossed(label, Circle((index_x + 0.8, 98.9), 0.7)) == ["RO2"]    # into the index's body
    box = line([(95.0, 101.0), (99.0, 101.0), (99.0, 90.0), (95.0, 90.0)], closed=True)
    assert crossed(label, box) == []                                   # open: its last side is drawn
    beside = Text("X", (93.5, 95.0), 3.5, "lb")                       # over the left side, x = 95
    assert crossed(beside, line(box.points)) == [] and crossed(beside, box) == ["X"]


def test_a_rotated_text_is_checked_along_its_baseline():
    label = Text("ABCD", (100.0, 100.0), 5.0, "lb", rotation=90.0)     # upwards, left of x = 100
    assert crossed(label, line([(90.0, 110.0), (99.0, 110.0)])) == ["ABCD"]
    assert crossed(label, line([(101.0, 90.0), (101.0, 130.0)])) == []


def test_an_arrowhead_over_a_small_text_covers_it():
    """A filled head larger than the text: no side meets the glyphs, its area does."""
    small = Text("4", (100.0, 100.0), 2.5, "cm")
    head = line([(94.0, 94.0), (106.0, 100.0), (94.0, 106.0)], closed=True, filled=True)
    assert crossed(small, head) == ["4"]
    assert crossed(small, line([(94.0, 94.0), (106.0, 100.0), (94.0, 106.0)])) == []  # not filled, open


# ---- placement -----------------------------------------------------------------------------

segment = st.tuples(*[st.floats(60.0, 140.0, **finite)] * 4)


@settings(max_examples=60, deadline=None)
@given(st.lists(segment, min_size=0, max_size=12), st.floats(0.0, 2 * math.pi), st.sampled_from([2.5, 3.5, 5.0]),
       st.sampled_from(["N", "R", "a4′", "12"]))
def test_a_placed_label_is_clear_of_every_stroke_and_its_leader_ends_at_it(segs, way, height, text):
    strokes = [line([(x0, y0), (x1, y1)]) for x0, y0, x1, y1 in segs]
    taken = []
    placed = place(text, (100.0, 100.0), height, taken, np.array(segs).reshape(-1, 4),
                   (math.cos(way), math.sin(way)), within=(40.0, 40.0, 160.0, 160.0))
    assert len(placed) in (0, 1, 2)
    if not placed:
        return
    label = placed[0]
    assert crossed(label, *strokes) == []
    assert taken == [label.box()]
    assert label.height in (height, {2.5: 2.5, 3.5: 2.5, 5.0: 3.5}[height])
    if len(placed) == 2:                       # from the point to the label's box
        leader = np.asarray(placed[1].points)
        x0, y0, x1, y1 = label.box()
        assert np.allclose(leader[0], (100.0, 100.0))
        assert x0 - 0.5 <= leader[1][0] <= x1 + 0.5 and y0 - 0.5 <= leader[1][1] <= y1 + 0.5
        assert crossed(label, placed[1]) == []


def test_a_label_moves_off_a_line_through_its_first_spot():
    """A line right through the spot beside the point (up and right): the label goes elsewhere."""
    wall = line([(100.0, 101.0), (130.0, 101.0)])
    first = place("B", (100.0, 100.0), 3.5, [], np.zeros((0, 4)), (1.0, 0.0))[0]
    assert crossed(first, wall) == ["B"]
    moved = place("B", (100.0, 100.0), 3.5, [], np.asarray(wall.points).reshape(1, 4), (1.0, 0.0))[0]
    assert crossed(moved, wall) == [] and moved.height == 3.5


# ---- the sheets ---------------------------------------------------------------------------

def test_the_default_designs_a1_sheets_have_no_crossed_label():
    """The issue's case: lever lines through "7" and "O2", N and F_I6 under the ram, G4
    under an arrowhead, tick marks and curves through their numbers (13, 17 and 5 texts
    crossed on the motion, kinetostatic and cam sheets before)."""
    masses = masses_for_design(DEFAULT, MassProperties(**LOADS))
    cam = design_cam(CamInputs(120.0, Program(15.0, 60.0, 10.0, 60.0, "sine", "sine")), DEFAULT)
    for sheet in (motion_sheet(DEFAULT, 40.0, A1).sheet, forces_sheet(DEFAULT, 40.0, masses, A1).sheet,
                  cam_sheet(cam, 40.0, A1).sheet):
        assert [(t.text, t.position) for t, _ in crossed_texts(sheet)] == []


def assert_labels_clear(sheet):
    """No text crossed, none on another or crowding it, all inside the border (the labels' part of
    assert_laid_out: a large K on A2/A3 has the motion sheet's guide line leave its area,
    a separate matter)."""
    assert outside_border(sheet) == [] and overlapping_texts(sheet) == []
    crossed_now = [(t.text, t.position) for t, _ in crossed_texts(sheet)]
    assert crossed_now == [], crossed_now
    crowded = [(a.text, b.text, round(clear, 2)) for a, b, clear in crowded_texts(sheet)]
    assert crowded == [], crowded


def _design(crank, k, stretch, rod):
    theta = math.pi * (k - 1) / (k + 1)
    try:
        return synthesize(crank, k, stretch * 2 * crank * (1 + math.sin(theta / 2)), rod_ratio=rod)
    except DesignError:
        assume(False)


designs = dict(crank=st.floats(20.0, 300.0, **finite), k=st.floats(1.02, 2.95, **finite),
               stretch=st.floats(1.05, 4.0, **finite),
               rod=st.one_of(st.none(), st.floats(0.25, 1.0, **finite)),
               size=st.sampled_from(["A0", "A1", "A2", "A3"]))


@pytest.mark.slow
@settings(max_examples=examples(12), deadline=None)
@example(crank=100.0, k=1.4, stretch=1.2, rod=None, size="A1", count=12)
@example(crank=30.0, k=2.95, stretch=4.0, rod=0.3, size="A3", count=24)
@given(count=st.integers(6, 24), **designs)
def test_no_label_is_crossed_on_the_motion_sheet_of_any_design(crank, k, stretch, rod, size, count):
    assert_labels_clear(motion_sheet(_design(crank, k, stretch, rod), 40.0, paper(size), count=count).sheet)


# Designs where L3's text has no clear spot on or beyond its line (the L2/h chain's extension
# lines cross the lever at every spot, K near 3): found by sweeps of random designs
CROWDED = [(163.3100549160719, 2.854394933909055, 1.4752708575229196, 0.4838735890078641, "A3", 14),
           (92.27943851928474, 2.9380656255228192, 3.825967684221733, None, "A3", 14),
           (171.79469707718076, 2.590822135516199, 2.0810086031678265, 0.6107855296173742, "A3", 13),
           (92.93070710645779, 2.7857323990518026, 1.4238124977007258, 0.33268725667119436, "A3", 16)]


@pytest.mark.parametrize("crank, k, stretch, rod, size, count", CROWDED)
def test_no_label_is_crossed_where_l3_has_no_room_on_its_line(crank, k, stretch, rod, size, count):
    """L3's text, crossed by the chain's extension lines even at 2.5 mm, led out along a
    leader; the tool path's numbers led clear of it (their leaders ran through it)."""
    assert_labels_clear(motion_sheet(_design(crank, k, stretch, rod), 40.0, paper(size), count=count).sheet)


@pytest.mark.slow
@settings(max_examples=examples(12), deadline=None)
@example(crank=100.0, k=1.02, stretch=1.05, rod=None, size="A2")
@example(crank=205.0, k=1.75, stretch=2.0, rod=None, size="A3")      # μφ under the energy curve
@example(crank=35.5, k=2.1732, stretch=3.6722, rod=None, size="A3")  # … and for lines lower
@given(**designs)
def test_no_label_is_crossed_on_the_kinetostatic_sheet_of_any_design(crank, k, stretch, rod, size):
    design = _design(crank, k, stretch, rod)
    extra = {"rod_mass_kg": 8.0} if design.rod is not None else {}
    assert_labels_clear(forces_sheet(design, 60.0, masses_for_design(design, MassProperties(**LOADS, **extra)),
                                     paper(size)).sheet)


def test_arrow_items_are_what_the_check_reads_as_an_arrowhead():
    """The sheets' arrowheads are filled closed outlines: the check's area case is the real one."""
    head = arrow((0.0, 0.0), (20.0, 0.0))[1]
    assert head.filled and head.closed


def test_crossings_counts_the_segments_a_leader_runs_across():
    from core.drawing.segments import crossings
    lead = np.array([0.0, 0.0, 10.0, 0.0])
    walls = np.array([[5.0, -1.0, 5.0, 1.0],      # across: 1
                      [2.0, 1.0, 2.0, 3.0],       # above, not reached
                      [0.0, 1.0, 10.0, 1.0],      # parallel
                      [7.0, -2.0, 9.0, 2.0]])     # across: 2
    assert crossings(lead, walls) == 2 and crossings(lead, np.zeros((0, 4))) == 0


def _orient(a, b, c) -> float:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _proper_cross(p, q, a, b) -> bool:
    """Segments pq and ab cross at a point inside both (plain orientation tests)."""
    return _orient(p, q, a) * _orient(p, q, b) < 0 and _orient(a, b, p) * _orient(a, b, q) < 0


def _segment_meets_box(seg, box) -> bool:
    """An end inside the box, or the segment crossing one of its sides."""
    p, q = seg[:2], seg[2:]
    x0, y0, x1, y1 = box
    if any(x0 <= x <= x1 and y0 <= y <= y1 for x, y in (p, q)):
        return True
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    return any(_proper_cross(p, q, corners[i], corners[(i + 1) % 4]) for i in range(4))


def _random_boxes_and_segments(seed: int):
    """Boxes inside (0, 100)², segments over (−40, 140)²: many lie beyond every box, so a
    batch's first cut (the boxes' common extent) drops some and keeps others."""
    rng = np.random.default_rng(seed)
    corner = rng.uniform(0.0, 90.0, (25, 2))
    boxes = np.hstack([corner, corner + rng.uniform(2.0, 10.0, (25, 2))])
    start = rng.uniform(-40.0, 140.0, (300, 2))
    segs = np.hstack([start, start + rng.uniform(-30.0, 30.0, (300, 2))])
    return boxes, segs


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_batched_box_and_segment_tests_agree_with_plain_geometry(seed):
    """The label search's batched tests (each leader line against every taken box, each
    spot's box against every stroke, each leader's crossings) give what the plain
    geometry of one pair at a time gives, for segments in and beyond the boxes' extent."""
    from core.drawing.segments import boxes_meet_strokes, crossings_each, strokes_meet_boxes
    boxes, segs = _random_boxes_and_segments(seed)
    meets = np.array([[_segment_meets_box(s, b) for s in segs] for b in boxes])
    assert meets.any(axis=0).sum() > 20 and (~meets.any(axis=0)).sum() > 20       # both kinds present
    assert strokes_meet_boxes(segs, boxes).tolist() == meets.any(axis=0).tolist()
    assert boxes_meet_strokes(boxes, segs, 0.0).tolist() == meets.any(axis=1).tolist()
    leaders = segs[:40]
    want = [sum(_proper_cross(a[:2], a[2:], b[:2], b[2:]) for b in segs) for a in leaders]
    assert crossings_each(leaders, segs).tolist() == want


@pytest.mark.parametrize("seed", [4, 5, 6])
def test_the_read_as_own_test_of_a_batch_is_each_boxs_own(seed):
    """A ring search tests its spots' boxes for being read as naming their point all at once
    (``first_free``'s ``keep``): each box's answer is the definition's, the nearest other
    named point ASSOCIATION heights farther than the own one (distances by hand), and the
    spot found is the first free one of those kept, as filtering the spots one by one gave."""
    from core.drawing.labels import ASSOCIATION, _others, _read_as_own, first_free, ring_candidates
    rng = np.random.default_rng(seed)
    boxes, segs = _random_boxes_and_segments(seed)
    at, height = (50.0, 50.0), 3.5
    anchors = np.vstack([[at], [at[0] + 0.01, at[1]], rng.uniform(30.0, 70.0, (8, 2))])

    def by_hand(box):
        far = [math.hypot(max(box[0] - x, 0.0, x - box[2]), max(box[1] - y, 0.0, y - box[3]))
               for x, y in anchors if math.hypot(x - at[0], y - at[1]) > 0.05]
        own = math.hypot(max(box[0] - at[0], 0.0, at[0] - box[2]), max(box[1] - at[1], 0.0, at[1] - box[3]))
        return min(far) >= own + ASSOCIATION * height
    spots = list(ring_candidates("A", at, height, (1.0, 1.0), 1.5, range(4)))
    boxes = np.vstack([boxes, [s.box() for s in spots]])
    kept = _read_as_own(boxes, at, _others(at, anchors), height)
    assert kept.tolist() == [by_hand(b) for b in boxes] and 0 < kept.sum() < len(kept)
    one_by_one, batched = [], []
    first = first_free((s for s in spots if by_hand(s.box())), one_by_one, segs[:60])
    keep = lambda b: _read_as_own(b, at, _others(at, anchors), height)    # noqa: E731
    assert first_free(spots, batched, segs[:60], keep=keep) == first and first is not None
    assert batched == one_by_one
