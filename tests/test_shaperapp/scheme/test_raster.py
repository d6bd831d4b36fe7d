"""The label search's raster (``raster.Raster``): its summed table must count exactly the
marked cells a box covers, after burning and after ``copy_with`` (which sums afresh and
leaves the original alone). Brute force over the grid is the reference."""
from __future__ import annotations

import numpy as np
from hypothesis import given, settings, strategies as st

from shaperapp.scheme.raster import Raster, clipped

BOUNDS = (-20.0, 60.0, -10.0, 30.0)


def brute_hits(raster: Raster, box: np.ndarray) -> int:
    left, right = sorted(box[:2])
    bottom, top = sorted(box[2:])
    x0 = int(np.clip(np.floor((left - raster.margin - raster.left) / raster.cell), 0, raster.nx))
    x1 = int(np.clip(np.floor((right + raster.margin - raster.left) / raster.cell), 0, raster.nx))
    y0 = int(np.clip(np.floor((bottom - raster.margin - raster.bottom) / raster.cell), 0, raster.ny))
    y1 = int(np.clip(np.floor((top + raster.margin - raster.bottom) / raster.cell), 0, raster.ny))
    return int(raster._grid[y0:min(y1 + 1, raster.ny), x0:min(x1 + 1, raster.nx)].sum())


segments = st.lists(st.tuples(*[st.floats(-30.0, 70.0)] * 4), min_size=0, max_size=6)


@settings(max_examples=40, deadline=None)
@given(segments, segments, st.lists(st.tuples(*[st.floats(-30.0, 70.0)] * 4), min_size=1, max_size=8))
def test_hits_count_the_marked_cells_in_each_box(first, more, boxes):
    raster = Raster(np.array(first).reshape(-1, 2, 2), BOUNDS, 0.7, 0.3)
    grid_before = raster._grid.copy()
    both = raster.copy_with(np.array(more).reshape(-1, 2, 2))
    assert np.array_equal(raster._grid, grid_before)            # the original is untouched
    b = np.array(boxes, dtype=float)
    for r in (raster, both):
        assert r._sat[0].sum() == 0 and r._sat[:, 0].sum() == 0
        assert r._sat[-1, -1] == r._grid.sum()
        assert list(r.hits(b)) == [brute_hits(r, box) for box in b]
    assert np.all(both.hits(b) >= raster.hits(b))


def test_many_long_lines_burn_the_same_cells_in_bounded_memory():
    """Issue 41: the report's scheme burnt millions of samples at once, its peak (438 MB)
    the class run's limit. The samples now go in runs: the cells are the union of those
    each batch of segments marks, and the burn's own allocations stay bounded (some
    400 MB for these 5·10⁶ samples before, under 150 MB now)."""
    import tracemalloc
    rng = np.random.default_rng(7)
    ends = rng.uniform(-20.0, 60.0, (3000, 2, 2))
    raster = Raster(np.empty((0, 2, 2)), BOUNDS, 0.02, 0.0)       # 4000 × 2000 cells
    tracemalloc.start()
    both = raster.copy_with(ends)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    grid_bytes = raster._grid.nbytes + raster._sat.nbytes
    assert peak - grid_bytes < 150e6, peak / 1e6
    # 50 segments at a time, each far below a run, burnt one batch after another into one
    # grid: the union of the cells each batch marks. Its summed table is not made after
    # each batch (only the grid is compared): 60 tables of 8·10⁶ cells were most of the test.
    reference = raster.copy_with(np.empty((0, 2, 2)))
    reference._sum = lambda: None
    for batch in np.array_split(ends, 60):
        reference.burn(batch)
    assert np.array_equal(both._grid, reference._grid)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(*[st.floats(-30.0, 70.0)] * 4), min_size=1, max_size=40),
       st.integers(1, 400))
def test_burning_in_batches_marks_the_cells_burning_at_once_does(lines, batch):
    """Issue 42: the samples of every segment at once took 230 MB for a design of 16 speeds at
    0.1°; they are burnt BURN_POINTS at a time, which must mark exactly the same cells."""
    import shaperapp.scheme.raster as raster_module
    ends = np.array(lines).reshape(-1, 2, 2)
    whole = Raster(ends, BOUNDS, 0.2, 0.3)
    saved = raster_module.BURN_POINTS
    raster_module.BURN_POINTS = batch
    try:
        parts = Raster(ends, BOUNDS, 0.2, 0.3)
    finally:
        raster_module.BURN_POINTS = saved
    assert np.array_equal(parts._grid, whole._grid) and np.array_equal(parts._sat, whole._sat)


def naive_cells(raster: Raster, ends: np.ndarray) -> np.ndarray:
    """The cells of the samples at half a cell along each segment, one segment and one
    sample at a time (the definition the burn vectorises), on a fresh grid; the segments
    first cut to the grid as the burn cuts them."""
    grid = np.zeros_like(raster._grid)
    box = (raster.left, raster.left + raster.nx * raster.cell,
           raster.bottom, raster.bottom + raster.ny * raster.cell)
    for (x0, y0), (x1, y1) in clipped(ends, box):
        dx, dy = x1 - x0, y1 - y0
        count = int(np.ceil(np.hypot(dx, dy) / (0.5 * raster.cell))) + 1
        for i in range(count):
            t = i / max(count - 1, 1)
            ix = min(max(int((x0 + t * dx - raster.left) / raster.cell), 0), raster.nx - 1)
            iy = min(max(int((y0 + t * dy - raster.bottom) / raster.cell), 0), raster.ny - 1)
            grid[iy, ix] = True
    return grid


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(*[st.floats(-30.0, 70.0)] * 4), min_size=1, max_size=8),
       st.floats(0.05, 3.0))
def test_the_burn_marks_the_cells_of_each_sample_as_defined(lines, cell):
    """The vectorised burn (per axis, in place: issue 43 item 5) marks exactly the cells
    of the samples taken one at a time."""
    ends = np.array(lines, dtype=float).reshape(-1, 2, 2)
    raster = Raster(np.empty((0, 2, 2)), BOUNDS, cell, 0.0)
    burnt = raster.copy_with(ends)
    assert np.array_equal(burnt._grid, naive_cells(raster, ends))


# level and upright segments: one coordinate drawn from a few values, some on a cell's
# edge (multiples of the cell from the grid's corner), some off the grid, some of zero length
edges = st.sampled_from([-25.0, -20.0, -19.3, -10.0, 0.0, 0.1, 7.0, 29.9, 30.0, 41.3, 60.0, 65.0])
level_or_upright = st.tuples(st.booleans(), st.one_of(edges, st.floats(-30.0, 70.0)),
                             st.one_of(edges, st.floats(-30.0, 70.0)), st.one_of(edges, st.floats(-30.0, 70.0)))


@settings(max_examples=80, deadline=None)
@given(st.lists(level_or_upright, min_size=1, max_size=12), st.lists(st.tuples(*[st.floats(-30.0, 70.0)] * 4), max_size=4),
       st.sampled_from([0.05, 0.1, 0.7, 1.0, 2.5]))
def test_level_and_upright_segments_mark_their_samples_cells_without_samples(lines, slanted, cell):
    """Issue 43 item 5: a level or upright segment (the ram's, the tool's and block B's
    sides over the cycle, a third of the first search's samples) is burnt as one run of
    cells, to the bit the cells of its samples (``naive_cells``); only the other
    segments are sampled."""
    ends = [((a, b), (a, c)) if upright else ((b, a), (c, a)) for upright, a, b, c in lines]
    ends = np.array(ends + [((x0, y0), (x1, y1)) for x0, y0, x1, y1 in slanted], dtype=float).reshape(-1, 2, 2)
    raster = Raster(np.empty((0, 2, 2)), BOUNDS, cell, 0.0)
    sampled = []
    burn_samples = raster._burn_samples

    def spy(start, d, count):
        sampled.append(d.copy())
        burn_samples(start, d, count)

    raster._burn_samples = spy
    raster.burn(ends)
    assert np.array_equal(raster._grid, naive_cells(raster, ends))
    assert all(np.all((d[:, 0] != 0.0) & (d[:, 1] != 0.0)) for d in sampled)
