"""The label search's raster: lines that stay put burnt into a grid of cells with its
summed table, so that any number of candidate boxes is checked against thousands of
segments (the still lines, and what the moving bodies sweep over the cycle) in a few
array operations. Split from place.py, whose search reads it through ``Raster.hits``."""
from __future__ import annotations

import numpy as np


def clipped(ends: np.ndarray, bounds: tuple[float, float, float, float]) -> np.ndarray:
    """The parts of segments ``ends`` (k × 2 × 2) inside ``bounds`` (left, right, bottom, top),
    one axis at a time: numpy's loops over (k, 2) rows run pair by pair (4 of 6 ms on an
    edit's 21 720 swept segments, issue 40 item 5)."""
    if len(ends) == 0:
        return ends
    lows, highs = np.array([bounds[0], bounds[2]]), np.array([bounds[1], bounds[3]])
    start = [ends[:, 0, axis] for axis in (0, 1)]
    step = [ends[:, 1, axis] - ends[:, 0, axis] for axis in (0, 1)]
    enter, leave = np.zeros(len(ends)), np.ones(len(ends))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for axis in (0, 1):
            flat = step[axis] == 0.0
            t_low = (lows[axis] - start[axis]) / step[axis]
            t_high = (highs[axis] - start[axis]) / step[axis]
            enter = np.where(flat, enter, np.maximum(enter, np.minimum(t_low, t_high)))
            leave = np.where(flat, leave, np.minimum(leave, np.maximum(t_low, t_high)))
            leave[flat & ((start[axis] < lows[axis]) | (start[axis] > highs[axis]))] = -1.0
    out = np.empty((len(ends), 2, 2))
    for end, t in ((0, enter), (1, leave)):    # start + t·step
        for axis in (0, 1):
            np.multiply(t, step[axis], out=out[:, end, axis])
            out[:, end, axis] += start[axis]
    keep = enter <= leave
    return out if keep.all() else out[keep]


RASTER_CELLS = 2.0e6         # the still lines' raster: at most this many cells (coarser when zoomed in far)


def raster_region(window: tuple[float, float, float, float], bounds: tuple[float, float, float, float],
                  px: float) -> tuple[tuple[float, float, float, float], float]:
    """Where the still lines are burnt, (left, right, bottom, top) mm, and the cell's size:
    over the view's ``window`` and the drawing's ``bounds`` both (a still label may sit off
    the view when zoomed in), at a pixel ``px`` a cell or coarser: at most RASTER_CELLS cells."""
    area = ((max(window[1], bounds[1]) - min(window[0], bounds[0]))
            * (max(window[3], bounds[3]) - min(window[2], bounds[2])))
    cell = max(px, float(np.sqrt(area / RASTER_CELLS)))
    region = (min(window[0], bounds[0]), max(window[1], bounds[1]),
              min(window[2], bounds[2]), max(window[3], bounds[3]))
    return region, cell


BURN_POINTS = 65_536
"""Samples (or a run's cells) burnt at once: their arrays are half a MB each, whatever the
lines. Why not more: each array is fresh memory, and at 500 000 the burns of the first
label search of a start (the window's first paint) faulted in 3 039 pages (12 MB), the
kernel's time; later chunks reuse the first one's memory (with _burn_runs, the search's
faults 4 400 → 2 451, its CPU 20.5 → 17.0 ms: docs/performance.md, issue 43 item 5)."""


class Raster:
    """Lines that stay put burnt into a grid of cells (about a pixel each) with its summed
    table, so that any number of candidate boxes is checked against them in a few array
    operations whatever the number of lines (the crank circle and the tool path alone
    are some 700 segments). A box counts the marked cells it covers once widened by the
    margin and a cell for the sampling; cells outside the grid (off the view) count as free."""

    def __init__(self, ends: np.ndarray, bounds: tuple[float, float, float, float],
                 cell: float, margin: float) -> None:
        self.left, self.bottom, self.cell = bounds[0], bounds[2], float(cell)
        self.margin = margin       # a box reaches into every cell it touches: rounding is on the safe side
        self.nx = max(int(np.ceil((bounds[1] - bounds[0]) / cell)), 1)
        self.ny = max(int(np.ceil((bounds[3] - bounds[2]) / cell)), 1)
        self._grid = np.zeros((self.ny, self.nx), dtype=bool)
        self._sat = np.zeros((self.ny + 1, self.nx + 1), dtype=np.int32)
        self.burn(ends)

    def burn(self, ends: np.ndarray) -> None:
        """Mark the cells the segments pass through (sampled at half a cell; a level or
        upright segment's cells, the same, as one run: _burn_runs)."""
        ends = clipped(np.asarray(ends, dtype=float).reshape(-1, 2, 2),
                       (self.left, self.left + self.nx * self.cell,
                        self.bottom, self.bottom + self.ny * self.cell))
        if len(ends):
            d = np.stack([ends[:, 1, axis] - ends[:, 0, axis] for axis in (0, 1)], axis=1)
            upright = d[:, 0] == 0.0
            level = (d[:, 1] == 0.0) & ~upright
            slanted = ~(upright | level)
            self._burn_runs(ends[level, 0], d[level, 0], across=1)
            self._burn_runs(ends[upright, 0], d[upright, 1], across=0)
            d = d[slanted]
            count = np.ceil(np.hypot(d[:, 0], d[:, 1]) / (0.5 * self.cell)).astype(int) + 1
            self._burn_samples(ends[slanted, 0], d, count)
        self._sum()

    def _cell(self, value: np.ndarray, axis: int) -> np.ndarray:
        """The cell index along ``axis`` (0: x, 1: y) of sample coordinates ``value`` (mm),
        by _burn_samples' own operations: ``(value − origin) / cell``, truncated, clipped."""
        origin, n = (self.left, self.nx) if axis == 0 else (self.bottom, self.ny)
        return np.clip(((value - origin) / self.cell).astype(np.intp), 0, n - 1)

    def _burn_runs(self, start: np.ndarray, step: np.ndarray, across: int) -> None:
        """Mark the cells that _burn_samples marks for segments along one axis (``across``,
        the other axis, constant: ``step`` along it, mm), without their samples.

        Why: the ram's, the tool's and block B's sides move level, and their swept sides
        were a third of the first label search's 491 000 samples (issue 43 item 5). Along
        such a segment the samples' cells are exactly one run: every sample's cross
        coordinate is ``0·step + start``, the start itself, so one row (or column); along
        it, each operation of t·d + start − origin, ÷ cell, truncation and clipping keeps
        the samples' order (rounding is monotonic), and consecutive samples lie at most half
        a cell apart (the count), so no cell between the first sample's (t = 0: the start)
        and the last's (t = 1: d + start) is skipped. So the run from one to the other is
        the samples' cells, to the bit (``test_burn_same.py``)."""
        along = 1 - across
        first = self._cell(start[:, along], along)
        last = self._cell(step + start[:, along], along)
        low, length = np.minimum(first, last), np.abs(last - first) + 1
        line = self._cell(start[:, across], across)
        if along == 0:          # the grid read row by row: a run along x is one row's cells
            base, stride = line * self.nx + low, 1
        else:
            base, stride = low * self.nx + line, self.nx
        grid = self._grid.reshape(-1)
        ends = np.cumsum(length)
        lo = 0                  # at most about BURN_POINTS cells at once, as the samples
        while lo < len(length):
            hi = max(int(np.searchsorted(ends, ends[lo] - length[lo] + BURN_POINTS, "right")), lo + 1)
            count = length[lo:hi]
            offset = np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
            grid[np.repeat(base[lo:hi], count) + offset * stride] = True
            lo = hi

    @classmethod
    def of_cells(cls, marked: np.ndarray, margin: float) -> "Raster":
        """A raster of cells marked already (rows of ``marked`` up from 0), each a unit square
        from (0, 0): a picture's pixels read back, the report's scheme that θ's label keeps
        clear of, whose lines are ink and no longer segments."""
        out = cls.__new__(cls)
        out.left = out.bottom = 0.0
        out.cell, out.margin = 1.0, margin
        out.ny, out.nx = marked.shape
        out._grid = np.asarray(marked, dtype=bool)
        out._sat = np.zeros((out.ny + 1, out.nx + 1), dtype=np.int32)
        out._sum()
        return out

    def _sum(self) -> None:
        """The summed table of the grid."""
        # the summed table in place, along the rows first (contiguous) and then adding row to
        # row: exact integers as before, a quarter of the time on a large grid
        table = self._sat[1:, 1:]
        np.cumsum(self._grid, axis=1, dtype=np.int32, out=table)
        np.cumsum(table, axis=0, out=table)

    def _burn_samples(self, start: np.ndarray, d: np.ndarray, count: np.ndarray) -> None:
        """Mark the cells of ``count`` samples along each segment ``start`` + t·``d``, t = k/(count − 1).

        By groups of one count, (count × segments) arrays broadcast from t: an edit's 21 720
        swept segments have 19 counts, so no per-sample ``repeat`` (the same float operations
        in the same order, so the same cells: ``test_burn_same.py``). At most BURN_POINTS
        samples at once: a report's swept lines sampled at once took 250 MB (issue 41)."""
        order = np.argsort(count, kind="stable")
        counts, firsts = np.unique(count[order], return_index=True)
        grid = self._grid.reshape(-1)
        for c, lo, hi in zip(counts.tolist(), firsts.tolist(), [*firsts[1:].tolist(), len(order)]):
            t = (np.arange(c, dtype=float) / max(c - 1, 1))[:, None]
            rows = max(BURN_POINTS // c, 1)
            for part in range(lo, hi, rows):
                pick = order[part:min(part + rows, hi)]
                flat = None             # each sample's cell in the grid read row by row
                for axis, origin, n in ((1, self.bottom, self.ny), (0, self.left, self.nx)):
                    v = t * d[pick, axis]           # (count, segments): long rows
                    v += start[pick, axis]
                    v -= origin
                    v /= self.cell
                    cell = v.astype(np.intp)
                    np.clip(cell, 0, n - 1, out=cell)
                    if flat is None:
                        flat = cell
                        flat *= self.nx
                    else:
                        flat += cell
                grid[flat.reshape(-1)] = True

    def copy_with(self, ends: np.ndarray) -> "Raster":
        """A raster of these lines and ``ends``."""
        out = Raster.__new__(Raster)
        out.__dict__.update(self.__dict__)
        out._grid = self._grid.copy()
        out._sat = np.zeros_like(self._sat)           # burn sums it afresh
        out.burn(ends)
        return out

    def hits(self, boxes: np.ndarray) -> np.ndarray:
        """(m,) marked cells within each box (left, right, bottom, top) widened by the margin."""
        b = np.asarray(boxes, dtype=float).reshape(-1, 4)
        x = np.clip(np.floor((np.sort(b[:, :2], axis=1) + [-self.margin, self.margin] - self.left)
                             / self.cell), 0, self.nx).astype(int)
        y = np.clip(np.floor((np.sort(b[:, 2:], axis=1) + [-self.margin, self.margin] - self.bottom)
                             / self.cell), 0, self.ny).astype(int)
        x[:, 1] = np.minimum(x[:, 1] + 1, self.nx)
        y[:, 1] = np.minimum(y[:, 1] + 1, self.ny)
        s = self._sat
        return s[y[:, 1], x[:, 1]] - s[y[:, 0], x[:, 1]] - s[y[:, 1], x[:, 0]] + s[y[:, 0], x[:, 0]]
