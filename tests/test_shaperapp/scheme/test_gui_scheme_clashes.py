"""No label of the scheme is crossed or covered (issue 32 item 3), checked as a user sees it.

Every label shown (the joint names, the dimension texts, the force magnitudes) is
read back as the viewport shows it, and every line drawn is read back from the
scene's own items (each item's painter path mapped into the drawing's mm): link,
block and ram outlines, pins, the frame's lines, the crank circle, the tool path,
dimension and extension lines, arrow heads and the force arrows. A label is crossed
when a point of such a line lies inside its box, checked on points spaced a small
part of the label's size apart (independent of the clipping the placement uses).
The PNG and SVG exports render this same scene, so they show what is checked here.
"""
from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtGui import QPainterPath
from PySide6.QtWidgets import QGraphicsEllipseItem, QGraphicsPathItem
from pyqtgraph.functions import ndarray_from_qpolygonf

from core.forces.masses import MassProperties
from core.linkage.spec import Spec
from gui_helpers import shown
from shaperapp.scheme.view import SchemeWidget

pytestmark = pytest.mark.slow

DESIGNS = {
    "default": {},
    "K=1.6": {"time_ratio": 1.6},
    "L1=50.7": {"crank": 50.7},
    "K=5,H=2000": {"time_ratio": 5.0, "stroke": 2000.0},
    "rod": {"variant": "rod", "rod_ratio": 0.3},
}
INSET_PX = 2.0       # a box's padding around the glyphs: a line may graze it


def polygon_points(polygon) -> np.ndarray:
    """The polygon's points (x, y), the same doubles as each ``QPointF``'s, read from its
    buffer at once (a list of ``p.x(), p.y()`` took a tenth of the sweep's time)."""
    return ndarray_from_qpolygonf(polygon).copy()


def drawn_polylines(scheme) -> list[tuple[str, np.ndarray]]:
    """Every path and ellipse item shown in the drawing, as polylines in mm."""
    group = scheme._view.childGroup
    out = []
    stack = list(scheme._view.addedItems)
    while stack:
        item = stack.pop()
        if not item.isVisible():
            continue
        stack.extend(item.childItems())
        if isinstance(item, QGraphicsEllipseItem):
            path = QPainterPath()
            path.addEllipse(item.rect())
        elif isinstance(item, QGraphicsPathItem):
            path = item.path()
        else:
            continue
        mapped = item.mapToItem(group, path)
        for polygon in mapped.toSubpathPolygons():
            pts = polygon_points(polygon)
            if len(pts) >= 2:
                out.append((type(item).__name__, pts))
    return out


def shown_labels(scheme) -> dict[str, tuple]:
    """Every label shown in the pane (zoomed in, some lie outside it), by a name, as the
    viewport shows it (left, right, bottom, top), mm."""
    items = {f"joint {k}": v for k, v in scheme._mechanism.labels.items()}
    items.update({f"dim {k}": v for k, v in scheme._dimensions.texts().items()})
    items.update({f"force {k}": v for k, v in scheme._forces.tags().items()})
    view = scheme._view.viewRect()
    out = {}
    for name, item in items.items():
        box = scheme._screen_box(item)
        if item.isVisible() and box[0] < view.right() and box[1] > view.left() \
                and box[2] < view.bottom() and box[3] > view.top():
            out[name] = box
    return out


def points_along(polylines: list[np.ndarray], spacing: float) -> tuple[np.ndarray, np.ndarray]:
    """Points along each polyline, no farther apart than ``spacing``, and the index of the
    polyline each belongs to: each segment p→q at t = j/(n − 1), j < n − 1 (numpy.linspace's
    points without its end), and each polyline's last point. All segments of all polylines
    at once (one call per polyline, some 120 a frame, took a quarter of the sweep's time);
    each point is the same p + t·(q − p) as a polyline's own call made."""
    if not polylines:
        return np.zeros((0, 2)), np.zeros(0, dtype=int)
    ends = np.concatenate(polylines)
    sizes = np.array([len(line) for line in polylines])
    last = np.cumsum(sizes) - 1
    starts = np.setdiff1d(np.arange(len(ends) - 1), last[:-1])    # segments within a polyline
    line_of = np.repeat(np.arange(len(polylines)), sizes)
    p, q = ends[starts], ends[starts + 1]
    n = np.maximum(2, np.ceil(np.hypot(*(q - p).T) / spacing).astype(int) + 1)
    seg = np.repeat(np.arange(len(p)), n - 1)
    j = np.arange(len(seg)) - np.repeat(np.cumsum(n - 1) - (n - 1), n - 1)
    t = (j * (1.0 / (n - 1))[seg])[:, None]
    points = np.concatenate([ends[last], p[seg] + t * (q - p)[seg]])
    owner = np.concatenate([np.arange(len(polylines)), line_of[starts][seg]])
    return points, owner


def clashes(scheme) -> list[tuple[str, str]]:
    """(label, what crosses it) for every label crossed by a line or overlapping another
    label: the first line, in drawn_polylines' order, with a point inside its box."""
    px = max(scheme._view.viewPixelSize())
    inset = INSET_PX * px
    boxes = {name: (b[0] + inset, b[1] - inset, b[2] + inset, b[3] - inset)
             for name, b in shown_labels(scheme).items()}
    spacing = 2.0 * px                                    # far below any text's height
    lines = drawn_polylines(scheme)
    pts, owner = points_along([line for _, line in lines], spacing)
    out = []
    for name, (left, right, bottom, top) in boxes.items():
        inside = ((pts[:, 0] > left) & (pts[:, 0] < right)
                  & (pts[:, 1] > bottom) & (pts[:, 1] < top))
        if inside.any():
            out.append((name, lines[int(owner[inside].min())][0]))
    names = list(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            p, q = boxes[a], boxes[b]
            if p[0] < q[1] and q[0] < p[1] and p[2] < q[3] and q[2] < p[3]:
                out.append((a, b))
    return out


def sweep(qtbot, scheme, model, zooms) -> list:
    """Clashes at every fifth crank angle of the fitted view (zoom 1), and at every tenth,
    the ones between, at each other zoom (a factor on the fitted view): every angle the
    fitted view checks, half as many frames again per zoom (the suite's time)."""
    found = []
    for zoom in zooms:
        scheme.fit()
        scheme._view.scaleBy((zoom, zoom))
        qtbot.wait(20)                                    # repainted, as on screen
        first, step = (0, 5) if zoom == 1.0 else (5, 10)
        for index in range(first, model.angle_count, step):
            model.set_angle_index(index)
            scheme._catch_up()
            found += [(zoom, index, *c) for c in clashes(scheme)]
    return found


CROWDED = pytest.mark.xfail(strict=True, reason=(
    "residual, the laptop pane (420 x 330 px) with the forces shown only: at 3 of 72 angles "
    "(95, 100, 295 of 360) no spot around B, within the rings searched, is clear of the force "
    "arrows, the links and the labels placed before it, so B takes the spot the fewest lines "
    "cross and a force arrow or a link outline still runs through it"))


@pytest.mark.parametrize("design, forces", [
    pytest.param(d, f, id=f"{d}-{'forces' if f else 'plain'}")
    for d in DESIGNS for f in (False, True)])
def test_no_label_crossed_at_any_angle_and_zoom(qtbot, model, design, forces):
    """Issue 32: "L1 = 100.0" touched A and the L2/h line ran through it; at K = 1.6 L1
    covered h; at L1 = 50.7 or K = 5, H = 2000 "L1", "A" and "O₄" were one pile; with
    forces shown the 7.8 kN arrow ran through "O₂"."""
    if DESIGNS[design]:
        model.set_spec(**DESIGNS[design])
        assert model.error is None
    scheme = shown(qtbot, SchemeWidget(model), 900, 650)
    scheme.set_forces_visible(forces)
    found = sweep(qtbot, scheme, model, (1.0, 0.5, 1.5))
    assert found == [], (len(found), found[:12])


@pytest.mark.parametrize("design", [pytest.param("default", marks=CROWDED), "K=1.6", "K=5,H=2000"])
def test_no_label_crossed_in_the_laptop_pane(qtbot, model, design):
    """The mechanism pane of a 1366 × 768 screen, forces shown."""
    if DESIGNS[design]:
        model.set_spec(**DESIGNS[design])
        assert model.error is None
    scheme = shown(qtbot, SchemeWidget(model), 420, 330)
    scheme.set_forces_visible(True)
    found = sweep(qtbot, scheme, model, (1.0,))
    assert found == [], (len(found), found[:12])


CAPTION_LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
                               cut_height_mm=80)


def under_caption(scheme, model) -> list[tuple[int, str]]:
    """(angle index, label) for every label shown under the force caption, at every fifth
    crank angle: the caption stands over the drawing in the view's corner, on its own box."""
    found = []
    for index in range(0, model.angle_count, 5):
        model.set_angle_index(index)
        scheme._catch_up()
        cap = scheme._screen_box(scheme._forces.caption_item())
        for name, b in shown_labels(scheme).items():
            if b[0] < cap[1] and cap[0] < b[1] and b[2] < cap[3] and cap[2] < b[3]:
                found.append((index, name))
    return found


def caption_sweep(qtbot, model, design: str, size: tuple[int, int]) -> list[tuple[int, str]]:
    spec = Spec(variant="rod", rod_input="ratio", rod_ratio=0.3) if design == "rod" else Spec()
    model.load_state(spec, [40.0, 60.0], 1.0, masses=CAPTION_LOADS)
    scheme = shown(qtbot, SchemeWidget(model), *size)
    scheme.set_forces_visible(True)
    assert scheme._forces.caption_item() is not None
    return under_caption(scheme, model)


@pytest.mark.parametrize("design", ["default", "rod"])
def test_no_label_under_the_force_caption(qtbot, model, design):
    """Seen in the README's Forces screenshot (30 November): with forces shown, O₂ stood half
    under "Forces at 40 r/min, scale: …" at φ = 0 in the 1366 × 768 window. The frame's
    labels keep off the caption's box: before, in this pane, the guide force's magnitude
    sat under it at 19 of 72 angles (block)."""
    assert caption_sweep(qtbot, model, design, (900, 650)) == []


@pytest.mark.parametrize("design, before", [("default", 14), ("rod", 113)])
def test_the_laptop_pane_keeps_labels_off_the_force_caption_where_it_can(qtbot, model, design, before):
    """The laptop pane (420 × 330 px), forces shown: a label goes under the caption only
    where no spot round it within the rings searched is clear of the arrows, the links and
    the labels placed before it, and every other spot a line crosses (a text crossed is
    read worse than one beside a caption: COVER_COST). That leaves B at 3 of 72 angles
    (block: 40, 45, 50 of 360 at every fifth) and 4 (rod: 30, 40, 170, 335), against
    ``before`` label-frames on 9525240 (the caption no obstacle)."""
    found = caption_sweep(qtbot, model, design, (420, 330))
    assert len(found) <= 4 and {name for _, name in found} <= {"joint B"}, found
