"""Every label is read as naming its own point (issue 40, item 2).

A label that sits nearer another named point than its own, or about as near, is read
as that point's: 方案 I of the task book at φ = 120° has a force polygon whose forces of
49 N and 470 N beside 7000 N are under 3 mm at μF = 50–60 N/mm, and its vertex numbers
and force names piled up ("1 N 3 2 4"). The reading rule here is written on its own
from the geometry (the test must not share the placement code it checks): a label is
read as its own point's when that point is the nearest named point to its box by half a
text height, or a leader line runs from its box to its point."""
import math

import numpy as np
import pytest

from core.drawing.charts import ARROW
from core.drawing.forces import forces_sheet
from core.drawing import mechanism as mech
from core.drawing.labels import Room
from core.drawing.sheet import Polyline, Text, paper
from core.forces.masses import MassProperties, masses_for_design
from core.linkage.geometry import from_dimensions

# 方案 I (孙桓《机械原理》课程设计, 牛头刨床): masses = G/9.81
SCHEME_I = from_dimensions(110.0, 380.0, 540.0, rod=135.0)
MIN_ARROW = 2.0 * ARROW[0]     # an arrow whose shaft is as long as its head
LOADS_I = masses_for_design(SCHEME_I, MassProperties(
    lever_mass_kg=200.0 / 9.81, lever_inertia_kg_m2=1.1, lever_cg_mm=270.0, ram_mass_kg=700.0 / 9.81,
    ram_cg_mm=(240.0, 50.0), cut_force_N=7000.0, cut_height_mm=80.0))


def box_distance(box, p) -> float:
    dx = max(box[0] - p[0], 0.0, p[0] - box[2])
    dy = max(box[1] - p[1], 0.0, p[1] - box[3])
    return math.hypot(dx, dy)


def tied(box, p, leaders, tol=0.6) -> bool:
    """A leader line runs from ``p`` (within tol) to the box (within tol)."""
    for seg in leaders:
        a, b = np.asarray(seg.points[0]), np.asarray(seg.points[-1])
        for near, far in ((a, b), (b, a)):
            if math.hypot(*(near - p)) <= tol + mech.PIN_RADIUS and box_distance(box, far) <= tol:
                return True
    return False


def misread(labels: list[tuple[Text, tuple[float, float]]], points, leaders) -> list[str]:
    """The labels (with their own point) not read as their own point's."""
    bad = []
    for label, own in labels:
        box = label.box()
        if tied(box, np.asarray(own), leaders):
            continue
        d_own = box_distance(box, own)
        others = [p for p in points if math.hypot(p[0] - own[0], p[1] - own[1]) > 0.05]
        if any(box_distance(box, p) < d_own + 0.5 * label.height for p in others):
            bad.append(label.text)
    return bad


def test_labels_of_crowded_points_are_each_read_as_their_own():
    """Four points within 1.2 mm, as the small forces' vertices of 方案 I's polygon at
    3.5 mm text: each number goes where it is read as its point's, or on a leader."""
    points = [(100.0, 100.0), (100.0, 100.8), (100.3, 101.2), (100.9, 100.4), (130.0, 100.0)]
    room = Room(within=(60.0, 60.0, 160.0, 140.0))
    room.name(points)
    items = []
    for k, p in enumerate(points):
        items += [(it, p) for it in room.place(str(k), p, 3.5, (p[0] - 105.0, p[1] - 100.0), rings=5)]
    labels = [(t, p) for t, p in items if isinstance(t, Text)]
    leaders = [it for it, _ in items if isinstance(it, Polyline)]
    assert len(labels) == len(points)
    assert misread(labels, points, leaders) == []


def scheme_i_sheet(size="A1"):
    return forces_sheet(SCHEME_I, 60.0, LOADS_I, paper(size), diagram_deg=(120.0, 240.0))


@pytest.mark.parametrize("size", ["A1", "A3"])
def test_scheme_i_polygon_labels_are_each_read_as_their_own(size):
    """方案 I at φ = 120°: the ram group's and the lever's polygons; every vertex number
    is read as its vertex's. The vertices are found from the drawn arrows: each arrow's
    shaft runs from its tail vertex; the numbers follow the chain 0, 1, 2 …"""
    drawn = scheme_i_sheet(size)
    for area in ("ram polygon 1", "lever polygon 1", "ram polygon 2", "lever polygon 2"):
        _, items = drawn.areas[area]
        shafts = [it for it in items if isinstance(it, Polyline) and not it.filled and len(it.points) == 2
                  and it.layer != "THIN"]
        heads = [it for it in items if isinstance(it, Polyline) and it.filled]
        tips = [tuple(h.points[0]) for h in heads]      # a head's first point is its tip
        tails = [tuple(s.points[0]) for s in shafts]
        points = tails + tips
        numbers = {t.text: t for t in items if isinstance(t, Text) and t.text.isdigit()}
        # vertex k is the tail of the k-th arrow (0 is the pole, the first tail)
        labels = [(numbers[str(k)], tails[k]) for k in range(len(tails)) if str(k) in numbers]
        leaders = [it for it in items if isinstance(it, Polyline) and it.layer == "THIN"]
        assert len(labels) == len(tails), (area, sorted(numbers))
        assert misread(labels, points, leaders) == [], area


def test_scheme_i_loads_on_the_ram_show_their_arrow_outside_the_ram():
    """φ = 120°: F_I6 (49 N, 0.16 mm at μF = 300 N/mm) and N were drawn inside the ram's
    outline, unseen; every arrow drawn is at least MIN_ARROW long and starts on or
    outside the ram body, along its force."""
    drawn = scheme_i_sheet()
    for (k, name), (tail, head) in drawn.shown.items():
        t0, h0 = drawn.arrows[(k, name)]
        assert math.hypot(*(head - tail)) >= MIN_ARROW - 1e-9, name
        u, v = (head - tail), (h0 - t0)
        assert u[0] * v[1] - u[1] * v[0] == pytest.approx(0.0, abs=1e-9) and u @ v > 0, name
    for k in range(2):
        x0, y0, x1, y1 = mech.ram_body(drawn.arrows[(k, "R_C")][0])    # the ram about C (rod variant)
        for name in ("G_6", "F_I6", "N"):
            tail, head = drawn.shown[(k, name)]
            inside = x0 + 1e-6 < tail[0] < x1 - 1e-6 and y0 + 1e-6 < tail[1] < y1 - 1e-6
            assert not inside, (k, name, tail)
            mid = (tail + head) / 2.0
            assert not (x0 < mid[0] < x1 and y0 < mid[1] < y1), (k, name)


@pytest.mark.parametrize("size", ["A0", "A1", "A2", "A3"])
def test_scheme_i_lengthened_forces_give_their_value(size):
    """A force under MIN_ARROW at μF is drawn MIN_ARROW long, so its length says nothing of
    its size: its value must be printed, after its name or in the drawing's table of such
    values. On A1 at φ = 120° G6, F_I6 and N showed no value (no room after the names).
    The value expected is the arrow at μF times μF (ForcesSheet.arrows), to the 4 significant
    digits the report's polygons write it: the sheet wrote R_O4 = 1330 N, the report 1335 N."""
    drawn = scheme_i_sheet(size)
    for k in range(2):
        _, items = drawn.areas[f"mechanism {k + 1}"]
        texts = [t for t in items if isinstance(t, Text)]
        for (j, name), (tail, head) in drawn.arrows.items():
            length = math.hypot(*(head - tail))
            if j != k or length >= MIN_ARROW:
                continue
            value = length * drawn.force_scales[k]
            letters = name.replace("_", "")
            # "= 700 N" on the line of its name "G6", a word space after it: GB/T 14691's e = 0.6 h
            # between the inks, 0.4 h between the boxes (boxes x0, y0, x1, y1)
            values = [float(t.text[2:-2]) for t in texts if t.text.startswith("= ") and t.text.endswith(" N")
                      and any(n.text == letters and abs(n.box()[2] + 0.4 * n.height - t.box()[0]) < 0.3
                              and n.box()[1] <= (t.box()[1] + t.box()[3]) / 2.0 <= n.box()[3] for n in texts)]
            half = 0.5 * 10.0 ** (math.floor(math.log10(value)) - 3)        # of the 4th digit
            assert any(abs(v - value) <= half * (1 + 1e-9) for v in values), (size, k, name, value, values)


JOINT_OF = {"O2": "R_O2", "A": "R_A", "O4": "R_O4", "B": "R_B", "C": "R_C"}


@pytest.mark.parametrize("size", ["A0", "A1", "A2", "A3"])
def test_scheme_i_joint_names_beside_their_joint_or_led(size):
    """A joint's name with no leader stands beside its pin: at most one text height off the
    pin's rim and the 1 mm gap (ring 1 of the search). On A1 at φ = 120° O2 stood 10 mm from
    O2 (60 px at 150 dpi), nothing tying it to O2 but nearness. The joints are the joint
    forces' tails (ForcesSheet.arrows)."""
    drawn = scheme_i_sheet(size)
    for k in range(2):
        _, items = drawn.areas[f"mechanism {k + 1}"]
        leaders = [it for it in items if isinstance(it, Polyline) and it.layer == "THIN" and len(it.points) == 2]
        for label in (t for t in items if isinstance(t, Text) and t.text in JOINT_OF):
            joint = drawn.arrows[(k, JOINT_OF[label.text])][0]
            if tied(label.box(), joint, leaders):
                continue
            assert box_distance(label.box(), joint) <= mech.PIN_RADIUS + 1.0 + 3.5 + 1e-6, (size, k, label.text)
