"""The label search checks candidates a few at a time and stops at the first clear one
(issue 43 item 4): every label must land where checking them all at once put it. The
reference is the search as it was before (``reference_best``, kept here only), run on
the same obstacles in the same process."""
from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtWidgets import QApplication

from shaperapp.design.model import DesignModel
from shaperapp.scheme import labels as labels_module
from shaperapp.scheme.place import Obstacles, Raster, around, boxes_at, clear_of_boxes, clear_of_segments, meets


def reference_clear(obstacles: Obstacles, candidates: np.ndarray) -> np.ndarray:
    """``Obstacles.clear`` as it was: every candidate at once."""
    candidates = np.asarray(candidates, dtype=float).reshape(-1, 4)
    near = obstacles._near(candidates)
    out = clear_of_segments(candidates, obstacles.ends[near], obstacles.margins[near])
    if obstacles.raster is not None:
        out &= obstacles.raster.hits(candidates) == 0
    return (out & clear_of_boxes(candidates, np.array(obstacles.boxes).reshape(-1, 4))
            & obstacles.inside(candidates))


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
    for box in obstacles.boxes:
        hits += 1000.0 * ~clear_of_boxes(candidates, np.array([box]))
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
                          bounds, raster)
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
