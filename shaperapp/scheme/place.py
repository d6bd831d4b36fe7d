"""Label placement as a search: candidate spots scored against every line and label drawn.

As in cartography's point-feature labelling, a label gets a short list of
candidate boxes, best first (beside its anchor on the preferred side, then the
other sides, then farther out with a leader; along its dimension line, then
flipped across it), and takes the first that no line and no label already
placed comes near. Everything here is plain numpy in the drawing's mm; boxes
are (left, right, bottom, top) rows, lines are segments k × 2 × 2, each with its
own margin (a link's half width, or a few pixels for a thin line).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from core.base.arrays import nonzero_pairs

if TYPE_CHECKING:
    from .raster import Raster

RINGS = (0.0, 0.5, 1.0, 1.6, 2.4, 3.4, 4.6, 6.0)   # rings beyond the first, in text heights
LEADER_RING = 2                          # from this ring on, a leader line leads to the label
OWN_SHARE = 0.5
"""A joint's name without a leader is at most this share of its distance to any other
joint from its own: at 0.71 (report, 方案 I, end limit) "C" stood between C and B and
read as B's."""


def clear_of_segments(boxes: np.ndarray, ends: np.ndarray, margins: np.ndarray) -> np.ndarray:
    """(m,) True where box i keeps more than ``margins[j]`` from every segment j."""
    return ~meets(boxes, ends, margins).any(axis=1)


def meets(boxes: np.ndarray, ends: np.ndarray, margins: np.ndarray) -> np.ndarray:
    """(m, k) True where segment j meets box i widened by ``margins[j]`` on every side:
    their bounding boxes overlap and the box's corners are not all on one side of the
    segment's line (separating axes), all at once. The widened box's square corners keep
    a little more than the margin there: on the safe side."""
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    if len(ends) == 0 or len(boxes) == 0:
        return np.zeros((len(boxes), len(ends)), dtype=bool)
    margin = np.broadcast_to(np.asarray(margins, dtype=float), (len(ends),))
    xs, ys = np.sort(boxes[:, :2], axis=1), np.sort(boxes[:, 2:], axis=1)
    x0, y0, x1, y1 = ends[:, 0, 0], ends[:, 0, 1], ends[:, 1, 0], ends[:, 1, 1]
    lo_x = xs[:, :1] - margin - x0           # (m, k): the widened box relative to each start
    hi_x = xs[:, 1:] + margin - x0
    lo_y = ys[:, :1] - margin - y0
    hi_y = ys[:, 1:] + margin - y0
    dx, dy = x1 - x0, y1 - y0
    hit = ((np.minimum(dx, 0.0) <= hi_x) & (np.maximum(dx, 0.0) >= lo_x)
           & (np.minimum(dy, 0.0) <= hi_y) & (np.maximum(dy, 0.0) >= lo_y))
    # the corners' sides only where the boxes overlap (a fifth of an edit's pairs), with
    # the same products and differences for those pairs
    i, j = nonzero_pairs(hit)
    across_lo, across_hi = dx[j] * lo_y[i, j], dx[j] * hi_y[i, j]    # cross product at the corners
    along_lo, along_hi = dy[j] * lo_x[i, j], dy[j] * hi_x[i, j]
    top = np.maximum(across_lo, across_hi) - np.minimum(along_lo, along_hi)
    bottom = np.minimum(across_lo, across_hi) - np.maximum(along_lo, along_hi)
    hit[i, j] = (top >= 0.0) & (bottom <= 0.0)
    return hit


def clear_of_boxes(boxes: np.ndarray, taken: np.ndarray, gap: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """(m,) True where box i overlaps none of ``taken`` (touching edges do not overlap), or
    with ``gap`` (x, y), keeps that far off each (core.base.lettering.LABEL_GAP)."""
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    if len(taken) == 0:
        return np.ones(len(boxes), dtype=bool)
    b, t = boxes[:, None, :], np.asarray(taken, dtype=float)[None, :, :]
    gx, gy = gap
    hit = ((b[..., 0] - gx < t[..., 1]) & (t[..., 0] < b[..., 1] + gx)
           & (b[..., 2] - gy < t[..., 3]) & (t[..., 2] < b[..., 3] + gy))
    return ~hit.any(axis=1)


def end_to_end(boxes: np.ndarray, taken: np.ndarray, gap: float) -> np.ndarray:
    """(m,) True where box i lies in one column with one of ``taken`` (their x ranges
    overlap) less than ``gap`` above or below it: two vertical labels end to end with
    less between them read as one text ("L2 = 282.0 h = 113.5"). Side by side (a line
    between them) they read apart."""
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    grown = boxes + np.array([0.0, 0.0, -gap, gap])
    return ~clear_of_boxes(grown, np.asarray(taken, dtype=float).reshape(-1, 4))


class Obstacles:
    """The lines and the labels' boxes one placement pass keeps clear of; a placed label
    (and its leader) joins them, so the next one keeps clear of it too, by ``spacing`` (x,
    y; mm): the labels' gap, core.base.lettering.label_gap of their text height. The
    ``boxes`` given at the start are turned texts (the L2 and h chain's, read upwards),
    which no upright label continues on its line: those keep the gap across lines, ``spacing``'s
    y, on every side."""

    def __init__(self, ends: np.ndarray, margins: np.ndarray, boxes: np.ndarray | None = None,
                 bounds: tuple[float, float, float, float] | None = None,
                 raster: "Raster | None" = None, spacing: tuple[float, float] = (0.0, 0.0)) -> None:
        self.bounds = bounds
        self.spacing = spacing
        self.raster = raster             # lines that stay put, checked on their grid             # (left, right, bottom, top): a label stays inside
        self.ends = np.asarray(ends, dtype=float).reshape(-1, 2, 2)
        self.margins = np.broadcast_to(np.asarray(margins, dtype=float), (len(self.ends),)).copy()
        # each segment's box widened by its margin, to pass over far segments quickly
        self._lo = self.ends.min(axis=1) - self.margins[:, None]
        self._hi = self.ends.max(axis=1) + self.margins[:, None]
        self.boxes = [] if boxes is None else [tuple(b) for b in np.asarray(boxes).reshape(-1, 4)]
        self.turned = len(self.boxes) * [True]
        self.covers: list[tuple] = []    # what stands over the drawing (the force caption): see cover

    def clear_of_labels(self, candidates: np.ndarray) -> np.ndarray:
        """(m,) True where a candidate box keeps the labels' gap from every label's box."""
        boxes = np.array(self.boxes).reshape(-1, 4)
        turned = np.array(self.turned, dtype=bool)
        across = (self.spacing[1], self.spacing[1])
        return (clear_of_boxes(candidates, boxes[~turned], self.spacing)
                & clear_of_boxes(candidates, boxes[turned], across))

    def _near(self, candidates: np.ndarray) -> np.ndarray:
        lo = np.array([candidates[:, :2].min(), candidates[:, 2:].min()])
        hi = np.array([candidates[:, :2].max(), candidates[:, 2:].max()])
        return np.all((self._lo <= hi) & (self._hi >= lo), axis=1)

    def clear(self, candidates: np.ndarray) -> np.ndarray:
        """(m,) True where a candidate box keeps clear of every line and box."""
        candidates = np.asarray(candidates, dtype=float).reshape(-1, 4)
        return self._clear_rows(candidates, self._near(candidates))[0]

    def _clear_rows(self, candidates: np.ndarray, near: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``clear`` of some rows, the lines passed over chosen (``near``) for all of them;
        also which of the ``near`` lines each row meets. Each row's answer depends on that
        row alone, so rows checked a few at a time answer as all at once."""
        met = meets(candidates, self.ends[near], self.margins[near])
        out = ~met.any(axis=1)
        if self.raster is not None:
            out &= self.raster.hits(candidates) == 0
        if self.covers:
            out &= clear_of_boxes(candidates, np.array(self.covers))
        return out & self.clear_of_labels(candidates) & self.inside(candidates), met

    def inside(self, candidates: np.ndarray) -> np.ndarray:
        """(m,) True where a candidate lies within the bounds (the drawing's extent)."""
        if self.bounds is None:
            return np.ones(len(candidates), dtype=bool)
        left, right, bottom, top = self.bounds
        return ((candidates[:, 0] >= left) & (candidates[:, 1] <= right)
                & (candidates[:, 2] >= bottom) & (candidates[:, 3] <= top))

    def first_clear(self, candidates: np.ndarray) -> int:
        """Index of the first clear candidate, -1 if none is."""
        return self._first(np.asarray(candidates, dtype=float).reshape(-1, 4))[0]

    def _first(self, candidates: np.ndarray, barred: np.ndarray | None = None) -> tuple[int, list[np.ndarray]]:
        """The first clear candidate not ``barred`` (-1 if none is), checked a few at a time,
        best first, stopping there; and the lines each row checked meets.

        The still labels' 74–158 candidates met the ~720 swept link axes at once, three
        times per edit, 25 ms of it (issue 43 item 4), where the first 16 mostly hold the
        answer. The lines passed over are chosen for all candidates (``_near``), as in one
        check, so every row answers as before."""
        near = self._near(candidates)
        met = []
        for lo, hi in _chunks(len(candidates)):
            ok, part = self._clear_rows(candidates[lo:hi], near)
            if barred is not None:
                ok &= ~barred[lo:hi]
            if ok.any():
                return lo + int(np.flatnonzero(ok)[0]), met
            met.append(part)
        return -1, met

    def best(self, candidates: np.ndarray, barred: np.ndarray | None = None) -> int:
        """The first clear candidate, or where none is, the one that the fewest lines and
        boxes come near (the first of those; a label nearer than the gap counts less than a
        line: a text crossed cannot be read, one close to another can); ``barred`` ones (m,)
        only when all are."""
        candidates = np.asarray(candidates, dtype=float).reshape(-1, 4)
        k, met = self._first(candidates, barred)
        if k >= 0:
            return k
        # none clear: the lines met, counted (each row checked once, not again)
        hits = np.concatenate(met).sum(axis=1) + 10000.0 * ~self.inside(candidates)
        if self.raster is not None:
            hits = hits + np.minimum(self.raster.hits(candidates), 100)
        for box, turned in zip(self.boxes, self.turned):
            overlap = ~clear_of_boxes(candidates, np.array([box]))
            close = ~clear_of_boxes(candidates, np.array([box]), (self.spacing[1],) * 2 if turned else self.spacing)
            hits += 1000.0 * overlap + CLOSE_COST * (close & ~overlap)
        if self.covers:
            hits = hits + COVER_COST * ~clear_of_boxes(candidates, np.array(self.covers))
        if barred is not None:
            hits = hits + 100000.0 * barred
        return int(np.argmin(hits))

    def cover(self, box) -> None:
        """A box standing over the drawing (the force caption in the view's corner): a label
        keeps clear of it, and where no spot is clear, one partly under it is preferred to
        one a line crosses (COVER_COST)."""
        self.covers.append(tuple(box))

    def add(self, box=None, ends: np.ndarray | None = None, margin=0.0, turned: bool = False) -> None:
        """A placed label's box (a ``turned`` text's: read upwards), or lines with their
        margin (one, or one per segment)."""
        if box is not None:
            self.boxes.append(tuple(box))
            self.turned.append(turned)
        if ends is not None and len(ends):
            ends = np.asarray(ends, dtype=float).reshape(-1, 2, 2)
            margin = np.broadcast_to(np.asarray(margin, dtype=float), (len(ends),))
            self.ends = np.concatenate([self.ends, ends])
            self.margins = np.concatenate([self.margins, margin])
            self._lo = np.concatenate([self._lo, ends.min(axis=1) - margin[:, None]])
            self._hi = np.concatenate([self._hi, ends.max(axis=1) + margin[:, None]])


CLOSE_COST = 0.5       # a label within the gap but clear of it, in lines met (Obstacles.best)
COVER_COST = 0.75      # a label partly under the force caption, in lines met: still read beside it
FIRST_CHUNK = 16       # candidates checked at once first (one ring); each chunk after doubles


def _chunks(count: int) -> list[tuple[int, int]]:
    """(lo, hi) row ranges covering ``count`` rows: FIRST_CHUNK, then doubling."""
    out, lo, size = [], 0, FIRST_CHUNK
    while lo < count:
        out.append((lo, min(lo + size, count)))
        lo, size = lo + size, 2 * size
    return out or [(0, 0)]


def box_distances(boxes: np.ndarray, points: np.ndarray) -> np.ndarray:
    """(m, j) distance from each box (m × 4) to each point (j × 2): 0 inside."""
    b = np.asarray(boxes, dtype=float).reshape(-1, 1, 4)
    p = np.asarray(points, dtype=float).reshape(1, -1, 2)
    dx = np.maximum(np.maximum(b[..., 0] - p[..., 0], p[..., 0] - b[..., 1]), 0.0)
    dy = np.maximum(np.maximum(b[..., 2] - p[..., 1], p[..., 1] - b[..., 3]), 0.0)
    return np.hypot(dx, dy)


def owned(boxes: np.ndarray, points: np.ndarray, own: int, led: np.ndarray) -> np.ndarray:
    """(m,) True where a joint's name at each box reads as joint ``own``'s of ``points``:
    its own joint the nearest to it, and with no leader (``led`` False) by far the
    nearest (OWN_SHARE), since nothing else tells the reader whose name it is."""
    d = box_distances(boxes, points)
    others = np.delete(d, own, axis=1).min(axis=1, initial=np.inf)
    return d[:, own] <= np.where(led, 1.0, OWN_SHARE) * others


def boxes_at(centres: np.ndarray, half: np.ndarray) -> np.ndarray:
    """Boxes (m, 4) of half size ``half`` (w/2, h/2) centred at ``centres`` (m, 2)."""
    c = np.asarray(centres, dtype=float).reshape(-1, 2)
    return np.column_stack([c[:, 0] - half[0], c[:, 0] + half[0], c[:, 1] - half[1], c[:, 1] + half[1]])


def directions(preferred: np.ndarray, count: int = 16) -> np.ndarray:
    """Unit directions (count, 2): ``preferred`` first, then the others of ``count``
    evenly spaced, nearest to it first (the other side comes last)."""
    start = np.arctan2(preferred[1], preferred[0])
    steps = np.arange(count)
    order = np.argsort(np.minimum(steps, count - steps), kind="stable")
    angles = start + 2.0 * np.pi * steps[order] / count
    return np.column_stack([np.cos(angles), np.sin(angles)])


def around(point: np.ndarray, half: np.ndarray, preferred: np.ndarray, gap: float,
           step: float, rings=RINGS) -> tuple[np.ndarray, np.ndarray]:
    """Candidate centres around ``point`` (a pin, an arrow's end) for a text of half
    size ``half``: its near edge ``gap`` from the point in each direction, the
    preferred first, then the same a ring farther out (``step`` each). Returns the
    centres (m, 2) and each one's ring (m,)."""
    d = directions(preferred)
    reach = np.abs(d) @ np.asarray(half)          # centre to the box's edge along d, at most
    extra = np.asarray(rings, dtype=float)[:, None]
    centres = point + d[None, :, :] * (gap + extra * step + reach[None, :])[:, :, None]
    ring = np.repeat(np.arange(len(extra)), len(d))
    return centres.reshape(-1, 2), ring


def shrinking_candidates(point: np.ndarray, half: np.ndarray, preferred: np.ndarray, gap: float,
                         small_share: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A joint name's candidates: every ring of ``around`` at full size (``half``) and one
    standard size smaller (``small_share`` of it), and the order they are taken in: the
    near rings at full size, then smaller, then farther out (with a leader). Returns the
    centres (m, 2), boxes (m, 4), which are led to (m,: from LEADER_RING on), which are
    small (m,) and the order (m,)."""
    centres, boxes, far, small = [], [], [], []
    for shrink in (False, True):
        size = half * (small_share if shrink else 1.0)
        spots, ring = around(point, size, preferred, gap, 2.0 * size[1])
        centres.append(spots)
        boxes.append(boxes_at(spots, size))
        far.append(ring >= LEADER_RING)
        small.append(np.full(len(ring), shrink))
    centres, boxes = np.concatenate(centres), np.concatenate(boxes)
    far, small = np.concatenate(far), np.concatenate(small)
    return centres, boxes, far, small, np.lexsort((np.arange(len(far)), small, far))


def along(p: np.ndarray, q: np.ndarray, normal: np.ndarray, offset: float, half: np.ndarray,
          ts=(0.5, 0.35, 0.65, 0.2, 0.8)) -> np.ndarray:
    """Candidate centres beside the line p–q at the fractions ``ts`` along it: on the
    ``normal`` side ``offset`` off it, then the same flipped across the line."""
    reach = float(np.abs(normal) @ np.asarray(half))
    out = []
    for side in (1.0, -1.0):
        for t in ts:
            out.append(p + t * (q - p) + side * normal * (offset + reach))
    return np.array(out)


def leader(point: np.ndarray, box, start_gap: float) -> np.ndarray:
    """A leader (1 × 2 × 2) from ``start_gap`` off ``point`` to the edge of ``box``."""
    left, right, bottom, top = box
    centre = np.array([(left + right) / 2.0, (bottom + top) / 2.0])
    d = centre - point
    length = float(np.hypot(*d))
    if length == 0.0:
        return np.empty((0, 2, 2))
    e = d / length
    half = np.array([(right - left) / 2.0, (top - bottom) / 2.0])
    with np.errstate(divide="ignore"):
        to_edge = float(np.min(np.where(np.abs(e) > 0, half / np.abs(e), np.inf)))
    end = length - to_edge
    if end <= start_gap:
        return np.empty((0, 2, 2))
    return np.array([[point + e * start_gap, point + e * end]])


def leaders(point: np.ndarray, boxes: np.ndarray, start_gap: float) -> np.ndarray:
    """``leader`` to each of ``boxes`` (m × 4) at once: m × 2 × 2 (a zero-length one where
    the box is too near for a leader)."""
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    centre = np.column_stack([boxes[:, :2].mean(axis=1), boxes[:, 2:].mean(axis=1)])
    half = np.column_stack([np.abs(boxes[:, 1] - boxes[:, 0]), np.abs(boxes[:, 3] - boxes[:, 2])]) / 2.0
    d = centre - point
    length = np.hypot(d[:, 0], d[:, 1])
    e = d / np.where(length > 0.0, length, 1.0)[:, None]
    with np.errstate(divide="ignore"):
        to_edge = np.min(np.where(np.abs(e) > 0, half / np.abs(e), np.inf), axis=1)
    end = np.maximum(length - to_edge, start_gap)
    return np.stack([point + e * start_gap, point + e * end[:, None]], axis=1)


def leaders_length(leads: dict[str, np.ndarray]) -> float:
    """The leaders' total length, mm (0 when every label is beside its point)."""
    return float(sum(np.hypot(*(lead[:, 1] - lead[:, 0]).T).sum() for lead in leads.values() if len(lead)))


def local_segments(polygons: list[np.ndarray]) -> np.ndarray:
    """Segments k × 2 × 2 of polylines (each p × 2)."""
    parts = [np.stack([p[:-1], p[1:]], axis=1) for p in polygons if len(p) >= 2]
    return np.concatenate(parts) if parts else np.empty((0, 2, 2))


def posed(local: np.ndarray, angle_deg: np.ndarray, pos: np.ndarray) -> np.ndarray:
    """A rigid body's segments (k × 2 × 2, its own frame) rotated by each angle (n,) and
    moved to each position (n × 2): (n·k) × 2 × 2 in the drawing."""
    a = np.radians(np.atleast_1d(angle_deg))[:, None, None]
    c, s = np.cos(a), np.sin(a)
    x, y = local[None, :, :, 0], local[None, :, :, 1]
    pos = np.asarray(pos, dtype=float).reshape(-1, 1, 1, 2)
    out = np.stack([c * x - s * y, s * x + c * y], axis=-1) + pos
    return out.reshape(-1, 2, 2)
