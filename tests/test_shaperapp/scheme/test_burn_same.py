"""The raster's burn samples each segment in groups of one sample count, broadcast
(issue 40 item 5: an edit's swept burn was a third of the label search): it must mark
exactly the cells the burn as it was marked, and the segments cut to the grid one axis at
a time must be the same numbers. The reference (``reference_burn``, the per-sample
``repeat`` version, and ``reference_clipped``, kept here only) runs on the same segments
in the same process. Equal grids give equal summed tables and so equal placements: the grid is all
the search reads of the burn."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import shaperapp.scheme.raster as raster_module
from gui_helpers import shown
from shaperapp.design.model import DesignModel
from shaperapp.scheme.raster import Raster
from shaperapp.scheme.view import SchemeWidget

BOUNDS = (-20.0, 60.0, -10.0, 30.0)


def reference_clipped(ends: np.ndarray, bounds: tuple[float, float, float, float]) -> np.ndarray:
    """``clipped`` as it was (in place.py on main, 0c2e8a4): on (k, 2) rows."""
    if len(ends) == 0:
        return ends
    lows, highs = np.array([bounds[0], bounds[2]]), np.array([bounds[1], bounds[3]])
    start, step = ends[:, 0, :], ends[:, 1, :] - ends[:, 0, :]
    enter, leave = np.zeros(len(ends)), np.ones(len(ends))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for axis in (0, 1):
            flat = step[:, axis] == 0.0
            t_low = (lows[axis] - start[:, axis]) / step[:, axis]
            t_high = (highs[axis] - start[:, axis]) / step[:, axis]
            enter = np.where(flat, enter, np.maximum(enter, np.minimum(t_low, t_high)))
            leave = np.where(flat, leave, np.minimum(leave, np.maximum(t_low, t_high)))
            leave[flat & ((start[:, axis] < lows[axis]) | (start[:, axis] > highs[axis]))] = -1.0
    keep = enter <= leave
    s, d = start[keep], step[keep]
    return np.stack([s + enter[keep, None] * d, s + leave[keep, None] * d], axis=1)


def reference_burn(self: Raster, ends: np.ndarray) -> None:
    """``Raster.burn`` as it was (main 0c2e8a4) in its plain form: every sample's offset,
    step and start repeated per sample, ``start + t·d`` on (samples, 2) rows. Its runs of
    BURN_POINTS samples marked the union of their cells (``test_raster.py``), so the
    samples go at once here."""
    ends = reference_clipped(np.asarray(ends, dtype=float).reshape(-1, 2, 2),
                             (self.left, self.left + self.nx * self.cell,
                              self.bottom, self.bottom + self.ny * self.cell))
    if len(ends):
        d = ends[:, 1] - ends[:, 0]
        count = np.ceil(np.hypot(d[:, 0], d[:, 1]) / (0.5 * self.cell)).astype(int) + 1
        k = np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
        t = k / np.repeat(np.maximum(count - 1, 1), count)
        samples = np.repeat(d, count, axis=0) * t[:, None] + np.repeat(ends[:, 0], count, axis=0)
        cells = ((samples - [self.left, self.bottom]) / self.cell).astype(np.intp)
        self._grid[np.clip(cells[:, 1], 0, self.ny - 1), np.clip(cells[:, 0], 0, self.nx - 1)] = True
    table = self._sat[1:, 1:]
    np.cumsum(self._grid, axis=1, dtype=np.int32, out=table)
    np.cumsum(table, axis=0, out=table)


def both_burns(base: Raster, ends: np.ndarray) -> tuple[Raster, Raster]:
    """``base.copy_with(ends)`` by the burn now and by the reference."""
    now = base.copy_with(ends)
    with pytest.MonkeyPatch.context() as m:
        m.setattr(Raster, "burn", reference_burn)
        before = base.copy_with(ends)
    return now, before


def mixed_lines(rng: np.random.Generator, count: int) -> np.ndarray:
    """Segments from a point to a few cells to across the grid and beyond it, some
    horizontal or vertical, some of zero length: many sample counts, some repeated."""
    ends = rng.uniform(-30.0, 70.0, (count, 2, 2))
    short = rng.random(count) < 0.6
    ends[short, 1] = ends[short, 0] + rng.normal(0.0, 1.5, (short.sum(), 2))
    upright = rng.random(count) < 0.15
    ends[upright, 1, 0] = ends[upright, 0, 0]
    flat = rng.random(count) < 0.15
    ends[flat, 1, 1] = ends[flat, 0, 1]
    dot = rng.random(count) < 0.05
    ends[dot, 1] = ends[dot, 0]
    return ends


@pytest.mark.parametrize("seed", range(12))
@pytest.mark.parametrize("burn_points", [7, 1000, raster_module.BURN_POINTS])
def test_the_grouped_burn_marks_the_cells_the_burn_as_it_was_marked(seed, burn_points, monkeypatch):
    rng = np.random.default_rng(seed)
    monkeypatch.setattr(raster_module, "BURN_POINTS", burn_points)
    cell = float(rng.uniform(0.05, 2.0))
    base = Raster(mixed_lines(rng, 5), BOUNDS, cell, 0.3)
    now, before = both_burns(base, mixed_lines(rng, int(rng.integers(1, 400))))
    assert np.array_equal(now._grid, before._grid)
    assert np.array_equal(now._sat, before._sat)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(*[st.floats(-30.0, 70.0)] * 4), min_size=1, max_size=30),
       st.floats(0.05, 3.0), st.integers(1, 300))
def test_the_grouped_burn_agrees_on_any_lines(lines, cell, burn_points):
    base = Raster(np.empty((0, 2, 2)), BOUNDS, cell, 0.0)
    with pytest.MonkeyPatch.context() as m:
        m.setattr(raster_module, "BURN_POINTS", burn_points)
        now, before = both_burns(base, np.array(lines, dtype=float).reshape(-1, 2, 2))
    assert np.array_equal(now._grid, before._grid)


@pytest.mark.parametrize("seed", range(12))
def test_the_segments_are_cut_to_the_same_numbers(seed):
    """Inside, across one or two edges, outside, upright, flat and of zero length."""
    rng = np.random.default_rng(seed)
    ends = mixed_lines(rng, 500)
    box = (-10.0, 40.0, 0.0, 20.0)
    now, before = raster_module.clipped(ends, box), reference_clipped(ends, box)
    assert now.shape == before.shape and len(now) < len(ends)
    assert np.array_equal(now, before)
    inside = ends[(ends[..., 0] > -10.0).all(1) & (ends[..., 0] < 40.0).all(1)
                  & (ends[..., 1] > 0.0).all(1) & (ends[..., 1] < 20.0).all(1)]
    assert len(inside) > 10 and np.array_equal(raster_module.clipped(inside, box), reference_clipped(inside, box))


def test_the_schemes_swept_lines_burn_the_same_cells(qtbot):
    """What the label search burns per edit: the moving bodies over the cycle (some 20 000
    segments, 19 sample counts) on the still lines' raster of a shown scheme, for four
    designs."""
    model = DesignModel()
    scheme = shown(qtbot, SchemeWidget(model), 900, 600)
    counts = []
    for ratio in (1.4, 1.9, 1.15, 1.6):
        model.set_spec(time_ratio=ratio)
        scheme.dimension_label_boxes()     # read back: the labels (placed after the paint) caught up
        layout = scheme._labels
        assert layout._raster is not None and len(layout._swept) > 10000
        now, before = both_burns(layout._raster, layout._swept)
        assert np.array_equal(now._grid, before._grid) and np.array_equal(now._sat, before._sat)
        counts.append(int(now._grid.sum() - layout._raster._grid.sum()))
    assert min(counts) > 1000          # the swept lines did mark cells of their own
    scheme.close()


def test_the_first_searchs_burn_keeps_its_memory_small(qtbot):
    """Issue 43 item 5: the swept lines' burn (its temporaries, beyond the new grid and summed
    table) took 9.5 MB here, 900 × 600 px (all of a sample count's segments at once, up to
    500 000 samples), fresh pages that the window's first paint faulted in; with BURN_POINTS
    samples at once, and the level and upright segments burnt without samples, 5.8 MB, for
    the same cells."""
    import tracemalloc
    model = DesignModel()
    scheme = shown(qtbot, SchemeWidget(model), 900, 600)
    scheme.dimension_label_boxes()
    layout = scheme._labels
    grid_bytes = layout._raster._grid.nbytes + layout._raster._sat.nbytes      # the copy's
    tracemalloc.start()
    now = layout._raster.copy_with(layout._swept)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak - grid_bytes < 7.5e6, peak / 1e6
    _, before = both_burns(layout._raster, layout._swept)
    assert np.array_equal(now._grid, before._grid)
    scheme.close()
