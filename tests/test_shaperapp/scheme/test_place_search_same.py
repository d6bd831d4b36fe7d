"""The label search checks candidates a few at a time and stops at the first clear one
(issue 43 item 4), and ``meets`` takes the corners' cross products only for the pairs
whose boxes overlap (issue 40 item 5): every label must land where checking them all at
once put it. The references are the search as it was before (``reference_best``) and
``meets`` one pair at a time (``pair_meets``), kept here only, run on the same obstacles
in the same process."""
from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtWidgets import QApplication

from shaperapp.design.model import DesignModel
from shaperapp.scheme import labels as labels_module, place as place_module
from shaperapp.scheme.place import Obstacles, around, boxes_at, clear_of_boxes, clear_of_segments, meets
from shaperapp.scheme.raster import Raster


def reference_clear(obstacles: Obstacles, candidates: np.ndarray) -> np.ndarray:
    """``Obstacles.clear`` as it was: every candidate at once."""
    candidates = np.asarray(candidates, dtype=float).reshape(-1, 4)
    near = obstacles._near(candidates)
    out = clear_of_segments(candidates, obstacles.ends[near], obstacles.margins[near])
    if obstacles.raster is not None:
        out &= obstacles.raster.hits(candidates) == 0
    for box, gap in zip(obstacles.boxes, gaps(obstacles)):
        out &= clear_of_boxes(candidates, np.array([box]), gap)
    return out & obstacles.inside(candidates)


def gaps(obstacles: Obstacles) -> list[tuple[float, float]]:
    """The gap (x, y) each taken box keeps: the labels' spacing, a turned text's its y both ways."""
    x, y = obstacles.spacing
    return [(y, y) if turned else (x, y) for turned in obstacles.turned]


def reference_best(obstacles: Obstacles, candidates: np.ndarray, barred: np.ndarray | None = None) -> int:
    """``Obstacles.best`` as it was: every candidate at once, the lines met counted again."""
    ok = reference_clear(obstacles, candidates)
    if barred is not None:
        ok &= ~barred
    if ok.any():
        return int(np.flatnonzero(ok)[0])
    candidates = np.asarray(candidates, dtype=float).reshape(-1, 4)
    near = obstacles._near(candidates)
    hits = (meets(candidates, obstacles.ends[near], obstacles.margins[near]).sum(axis=1)
            + 10000.0 * ~obstacles.inside(candidates))
    if obstacles.raster is not None:
        hits = hits + np.minimum(obstacles.raster.hits(candidates), 100)
    for box, gap in zip(obstacles.boxes, gaps(obstacles)):
        overlap = ~clear_of_boxes(candidates, np.array([box]))
        hits += 1000.0 * overlap + place_module.CLOSE_COST * (~clear_of_boxes(candidates, np.array([box]), gap)
                                                             & ~overlap)
    if barred is not None:
        hits = hits + 100000.0 * barred
    return int(np.argmin(hits))


LINES = (0, 5, 20, 40, 300)    # lines in a scene: none, a few (the first ring clear), many (none clear)


def scene(rng: np.random.Generator, lines: int) -> tuple[Obstacles, np.ndarray]:
    """Random lines, boxes taken and a raster around a point, and candidates around it
    (rings of 16, as the joints' and O₄'s)."""
    ends = rng.uniform(-40.0, 40.0, (lines, 2, 2))
    raster = Raster(rng.uniform(-40.0, 40.0, (rng.integers(0, 4), 2, 2)), (-50.0, 50.0, -50.0, 50.0), 0.5, 0.4) \
        if rng.random() < 0.5 else None
    bounds = (-45.0, 45.0, -45.0, 45.0) if rng.random() < 0.5 else None
    taken = rng.uniform(-30.0, 30.0, (rng.integers(0, 4), 2))
    obstacles = Obstacles(ends, rng.uniform(0.2, 2.0, lines), boxes_at(taken, np.array([3.0, 1.5])),
                          bounds, raster, (rng.uniform(0.0, 3.0), rng.uniform(0.0, 1.0)))
    for box in boxes_at(rng.uniform(-30.0, 30.0, (rng.integers(0, 3), 2)), np.array([4.0, 1.5])):
        obstacles.add(box)                        # upright labels placed, beside the turned ones
    half = rng.uniform(1.0, 6.0, 2)
    centres, _ = around(rng.uniform(-10.0, 10.0, 2), half, rng.normal(size=2), 1.0, 2.0 * half[1])
    return obstacles, boxes_at(centres, half)


@pytest.mark.parametrize("seed", range(60))
def test_the_search_picks_what_checking_all_at_once_picked(seed):
    rng = np.random.default_rng(seed)
    obstacles, candidates = scene(rng, int(rng.choice(LINES)))
    barred = rng.random(len(candidates)) < 0.3 if seed % 2 else None
    assert obstacles.best(candidates, barred) == reference_best(obstacles, candidates, barred)
    expected = np.flatnonzero(reference_clear(obstacles, candidates))
    assert obstacles.first_clear(candidates) == (int(expected[0]) if len(expected) else -1)
    assert np.array_equal(obstacles.clear(candidates), reference_clear(obstacles, candidates))


def test_the_scenes_reach_every_branch():
    """Among the scenes some first clear candidates lie past the first chunk, and some
    have none clear (the count of lines met decides): the comparison covers both."""
    firsts = []
    for seed in range(60):
        rng = np.random.default_rng(seed)
        obstacles, candidates = scene(rng, int(rng.choice(LINES)))
        ok = np.flatnonzero(reference_clear(obstacles, candidates))
        firsts.append(int(ok[0]) if len(ok) else -1)
    assert -1 in firsts and max(firsts) >= 16 and min(f for f in firsts if f >= 0) < 16


def placed_labels(qtbot, designs: list[dict]) -> list[dict[str, tuple[float, float]]]:
    """Every label's position in a shown scheme after each edit of ``designs``."""
    from shaperapp.scheme.view import SchemeWidget
    model = DesignModel()
    scheme = SchemeWidget(model)
    qtbot.addWidget(scheme)
    scheme.resize(900, 600)
    scheme.show()
    out = []
    for spec in designs:
        model.set_spec(**spec)
        QApplication.processEvents()
        boxes = scheme.dimension_label_boxes()           # the still labels placed, read back
        layout = scheme._labels
        for index in (0, 7, 20):
            layout.place_frame(index, scheme._view.viewPixelSize())
            joints = {name: (label.x(), label.y()) for name, label in scheme._mechanism.labels.items()}
            out.append({**{k: tuple(v) for k, v in boxes.items()}, **joints,
                        "leaders": (tuple(layout._leaders.x), tuple(layout._leaders.y))})
    scheme.close()
    return out


def test_the_schemes_labels_land_where_they_did(qtbot, monkeypatch):
    designs = [dict(time_ratio=1.4), dict(time_ratio=1.9), dict(time_ratio=1.15), dict(time_ratio=1.6)]
    now = placed_labels(qtbot, designs)
    monkeypatch.setattr(labels_module.Obstacles, "best", reference_best)
    monkeypatch.setattr(labels_module.Obstacles, "clear", reference_clear)
    monkeypatch.setattr(labels_module.Obstacles, "first_clear", lambda self, candidates: int(
        (list(np.flatnonzero(reference_clear(self, candidates))) + [-1])[0]))
    before = placed_labels(qtbot, designs)
    assert len(now) == len(before) == 12
    assert now == before


def pair_meets(left: float, right: float, bottom: float, top: float,
               x0: float, y0: float, x1: float, y1: float, margin: float) -> bool:
    """One box and one segment, in the arithmetic ``meets`` had on main (0c2e8a4): the
    widened box against the segment's box relative to its start, then the corners' cross
    products, in Python floats (the same IEEE doubles, one operation at a time)."""
    x_lo, x_hi = sorted((left, right))
    y_lo, y_hi = sorted((bottom, top))
    lo_x, hi_x = x_lo - margin - x0, x_hi + margin - x0
    lo_y, hi_y = y_lo - margin - y0, y_hi + margin - y0
    dx, dy = x1 - x0, y1 - y0
    if not (min(dx, 0.0) <= hi_x and max(dx, 0.0) >= lo_x and min(dy, 0.0) <= hi_y and max(dy, 0.0) >= lo_y):
        return False
    across, along = (dx * lo_y, dx * hi_y), (dy * lo_x, dy * hi_x)
    return max(across) - min(along) >= 0.0 and min(across) - max(along) <= 0.0


def reference_meets(boxes: np.ndarray, ends: np.ndarray, margins: np.ndarray) -> np.ndarray:
    """``pair_meets`` of every box and segment: (m, k)."""
    b = np.asarray(boxes, dtype=float).reshape(-1, 4)
    e = np.asarray(ends, dtype=float).reshape(-1, 2, 2)
    margin = np.broadcast_to(np.asarray(margins, dtype=float), (len(e),))
    if len(b) == 0 or len(e) == 0:
        return np.zeros((len(b), len(e)), dtype=bool)
    return np.vectorize(pair_meets, otypes=[bool])(
        *(b[:, None, i] for i in range(4)), *(e[None, :, p, q] for p in (0, 1) for q in (0, 1)), margin[None, :])


@pytest.mark.parametrize("seed", range(20))
def test_meets_finds_what_each_pair_found(seed):
    """Random boxes and lines around them, some upright, flat, of zero length or along a
    box's edge: some pairs overlap, not all."""
    rng = np.random.default_rng(seed)
    boxes = boxes_at(rng.uniform(-20.0, 20.0, (30, 2)), rng.uniform(0.5, 4.0, 2))
    ends = rng.uniform(-30.0, 30.0, (60, 2, 2))
    ends[::7, 1, 0] = ends[::7, 0, 0]
    ends[::5, 1, 1] = ends[::5, 0, 1]
    ends[::11, 1] = ends[::11, 0]
    ends[::13, :, 0] = boxes[0, 1]
    margins = rng.uniform(0.0, 1.5, 60)
    margins[::3] = 0.0
    now = place_module.meets(boxes, ends, margins)
    assert now.shape == (30, 60) and now.dtype == bool
    assert np.array_equal(now, reference_meets(boxes, ends, margins))
    assert 0 < now.sum() < now.size


def test_the_schemes_labels_land_where_each_pair_put_them(qtbot, monkeypatch):
    designs = [dict(time_ratio=1.4), dict(time_ratio=1.9), dict(time_ratio=1.15)]
    now = placed_labels(qtbot, designs)
    monkeypatch.setattr(place_module, "meets", reference_meets)
    monkeypatch.setattr(labels_module, "meets", reference_meets)
    before = placed_labels(qtbot, designs)
    assert len(now) == len(before) == 9
    assert now == before
