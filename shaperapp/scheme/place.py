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

import numpy as np

RINGS = (0.0, 0.5, 1.0, 1.6, 2.4, 3.4, 4.6, 6.0)   # rings beyond the first, in text heights
LEADER_RING = 2                          # from this ring on, a leader line leads to the label


def clear_of_segments(boxes: np.ndarray, ends: np.ndarray, margins: np.ndarray) -> np.ndarray:
    """(m,) True where box i keeps more than ``margins[j]`` from every segment j."""
    return ~meets(boxes, ends, margins).any(axis=1)


def meets(boxes: np.ndarray, ends: np.ndarray, margins: np.ndarray) -> np.ndarray:
    """(m, k) True where segment j comes within ``margins[j]`` of box i: each segment is
    clipped to each widened box (Liang–Barsky), all at once."""
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    if len(ends) == 0 or len(boxes) == 0:
        return np.zeros((len(boxes), len(ends)), dtype=bool)
    lows = np.stack([np.minimum(boxes[:, 0], boxes[:, 1]), np.minimum(boxes[:, 2], boxes[:, 3])], axis=1)
    highs = np.stack([np.maximum(boxes[:, 0], boxes[:, 1]), np.maximum(boxes[:, 2], boxes[:, 3])], axis=1)
    margin = np.broadcast_to(np.asarray(margins, dtype=float), (len(ends),))[None, :, None]
    lows, highs = lows[:, None, :] - margin, highs[:, None, :] + margin       # (m, k, 2)
    start, step = ends[None, :, 0, :], ends[None, :, 1, :] - ends[None, :, 0, :]
    shape = (len(boxes), len(ends))
    enter, leave = np.zeros(shape), np.ones(shape)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):   # ±inf: no crossing there
        for axis in (0, 1):
            s, d = start[..., axis], step[..., axis]
            flat = np.broadcast_to(d == 0.0, shape)
            outside = flat & ((s < lows[..., axis]) | (s > highs[..., axis]))
            t_low = (lows[..., axis] - s) / d
            t_high = (highs[..., axis] - s) / d
            enter = np.where(flat, enter, np.maximum(enter, np.minimum(t_low, t_high)))
            leave = np.where(flat, leave, np.minimum(leave, np.maximum(t_low, t_high)))
            leave = np.where(outside, -1.0, leave)
    return enter <= leave


def clear_of_boxes(boxes: np.ndarray, taken: np.ndarray) -> np.ndarray:
    """(m,) True where box i overlaps none of ``taken`` (touching edges do not overlap)."""
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    if len(taken) == 0:
        return np.ones(len(boxes), dtype=bool)
    b, t = boxes[:, None, :], np.asarray(taken, dtype=float)[None, :, :]
    hit = (b[..., 0] < t[..., 1]) & (t[..., 0] < b[..., 1]) & (b[..., 2] < t[..., 3]) & (t[..., 2] < b[..., 3])
    return ~hit.any(axis=1)


class Obstacles:
    """The lines and the labels' boxes one placement pass keeps clear of; a placed label
    (and its leader) joins them, so the next one keeps clear of it too."""

    def __init__(self, ends: np.ndarray, margins: np.ndarray, boxes: np.ndarray | None = None,
                 bounds: tuple[float, float, float, float] | None = None) -> None:
        self.bounds = bounds             # (left, right, bottom, top): a label stays inside
        self.ends = np.asarray(ends, dtype=float).reshape(-1, 2, 2)
        self.margins = np.broadcast_to(np.asarray(margins, dtype=float), (len(self.ends),)).copy()
        # each segment's box widened by its margin, to pass over far segments quickly
        self._lo = self.ends.min(axis=1) - self.margins[:, None]
        self._hi = self.ends.max(axis=1) + self.margins[:, None]
        self.boxes = [] if boxes is None else [tuple(b) for b in np.asarray(boxes).reshape(-1, 4)]

    def _near(self, candidates: np.ndarray) -> np.ndarray:
        lo = np.array([candidates[:, :2].min(), candidates[:, 2:].min()])
        hi = np.array([candidates[:, :2].max(), candidates[:, 2:].max()])
        return np.all((self._lo <= hi) & (self._hi >= lo), axis=1)

    def clear(self, candidates: np.ndarray) -> np.ndarray:
        """(m,) True where a candidate box keeps clear of every line and box."""
        candidates = np.asarray(candidates, dtype=float).reshape(-1, 4)
        near = self._near(candidates)
        out = clear_of_segments(candidates, self.ends[near], self.margins[near])
        return out & clear_of_boxes(candidates, np.array(self.boxes).reshape(-1, 4)) & self.inside(candidates)

    def inside(self, candidates: np.ndarray) -> np.ndarray:
        """(m,) True where a candidate lies within the bounds (the drawing's extent)."""
        if self.bounds is None:
            return np.ones(len(candidates), dtype=bool)
        left, right, bottom, top = self.bounds
        return ((candidates[:, 0] >= left) & (candidates[:, 1] <= right)
                & (candidates[:, 2] >= bottom) & (candidates[:, 3] <= top))

    def first_clear(self, candidates: np.ndarray) -> int:
        """Index of the first clear candidate, -1 if none is."""
        ok = np.flatnonzero(self.clear(candidates))
        return int(ok[0]) if len(ok) else -1

    def best(self, candidates: np.ndarray) -> int:
        """The first clear candidate, or where none is, the one that the fewest lines and
        boxes come near (the first of those)."""
        k = self.first_clear(candidates)
        if k >= 0:
            return k
        candidates = np.asarray(candidates, dtype=float).reshape(-1, 4)
        near = self._near(candidates)
        ends, margins = self.ends[near], self.margins[near]
        hits = meets(candidates, ends, margins).sum(axis=1) + 10000.0 * ~self.inside(candidates)
        for box in self.boxes:
            hits += 1000.0 * ~clear_of_boxes(candidates, np.array([box]))
        return int(np.argmin(hits))

    def add(self, box=None, ends: np.ndarray | None = None, margin=0.0) -> None:
        """A placed label's box, or lines with their margin (one, or one per segment)."""
        if box is not None:
            self.boxes.append(tuple(box))
        if ends is not None and len(ends):
            ends = np.asarray(ends, dtype=float).reshape(-1, 2, 2)
            margin = np.broadcast_to(np.asarray(margin, dtype=float), (len(ends),))
            self.ends = np.concatenate([self.ends, ends])
            self.margins = np.concatenate([self.margins, margin])
            self._lo = np.concatenate([self._lo, ends.min(axis=1) - margin[:, None]])
            self._hi = np.concatenate([self._hi, ends.max(axis=1) + margin[:, None]])


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
    centres, ring = [], []
    for k, extra in enumerate(rings):
        centres.append(point + d * (gap + extra * step + reach)[:, None])
        ring.append(np.full(len(d), k))
    return np.concatenate(centres), np.concatenate(ring)


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
