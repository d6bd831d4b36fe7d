"""Labels placed clear of the drawing: of every line, circle, arrowhead and other label.

A label on a course-design sheet names a point (a joint, a polygon's vertex, an arrow's
head); one that a lever or an arrow runs through cannot be read. So every label is
placed after the linework it names, against all of it: the first free spot of a
cascade the draughtsman's own (GB/T 4458.1 leaves the place to him, not the rule):
beside the point in the preferred direction and farther out along it, then on the other
side, then round it; then one standard height smaller; then farther still with a thin
leader line from the point to the label, at last anywhere in the drawing. A spot is free
when the label's box, a little enlarged, meets no stroke, keeps a word space (GB/T 14691:
``core.base.lettering.WORD_GAP``) off the boxes already taken beside it, and lies within its drawing;
each step first asks ``core.base.lettering.LABEL_GAP`` from the texts taken (a label that only clears another by a
word space can still read as one text with it).

The strokes are segments (n, 4): x0, y0, x1, y1 in paper mm, a circle as a polygon; a
filled arrowhead's edges are strokes like any other (a box that holds a whole arrowhead
meets its corners).
"""
from __future__ import annotations

import itertools
import math
from dataclasses import replace
from functools import partial
from typing import Callable, Iterable, Sequence

import numpy as np

from core.base.lettering import label_gap, word_gap
from .dxf import THIN
from .segments import CLEARANCE, boxes_meet_strokes, crossings_each, strokes, strokes_meet_boxes
from .sheet import Box, Item, Pair, Polyline, Text, line, smaller_height

LEADER_RINGS = 10          # rings beyond the last plain one tried with a leader line
GRID_SPOTS = 2000          # then spots anywhere in the drawing, the nearest first …
FAR_CHOICES = 12           # … of whose free ones the leader crossing fewest lines is taken
ASSOCIATION = 0.5          # text heights another named point must lie farther from a label than its own


def boxes_meet(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def first_free(candidates: Iterable[Text], taken: list[Box], segments: np.ndarray,
               within: Box | None = None, keep: Callable[[np.ndarray], np.ndarray] | None = None,
               gap: Pair = (0.0, 0.0)) -> Text | None:
    """The first candidate whose box is free (:func:`free_spots`, ``gap`` (x, y) mm off every
    taken box; and takes its box), or None; with ``keep`` (boxes (k, 4) → (k,) bools) the
    first free one it keeps. The candidates are tested in batches of 1, 2, 4 … (:func:`free_spots`, the same test of each box): one
    test a candidate scanned the whole sheet's strokes each time, some 8 % of a class's
    student (docs/performance.md)."""
    boxes_taken = np.asarray(taken, dtype=float).reshape(-1, 4)
    for batch in _batches(candidates, 1):
        boxes = spot_boxes(batch)
        free = np.arange(len(boxes)) if keep is None else np.flatnonzero(keep(boxes))
        free = free[free_spots(boxes[free], boxes_taken, segments, within, spot_gaps(batch, gap)[free])]
        if len(free):
            taken.append(batch[free[0]].box())
            return batch[free[0]]
    return None


def ring_candidates(text: str, at: Pair, height: float, preferred: Pair, gap: float,
                    rings: Sequence[int], align: str | None = None,
                    subscripts: tuple[tuple[int, int], ...] = ()) -> Iterable[Text]:
    """Spots round ``at`` on rings ``gap`` + ring·height out, in eight directions: first
    along the preferred direction ring by ring (moved along its leader), then on the other
    side the same way (flipped), then the six directions between, nearest ring first and
    the preferred direction's neighbours first; each aligned away from the point unless
    ``align`` fixes it."""
    start = math.atan2(preferred[1], preferred[0])
    order = ([(0, ring) for ring in rings] + [(4, ring) for ring in rings]
             + [(turn, ring) for ring in rings for turn in (1, -1, 2, -2, 3, -3)])
    for turn, ring in order:
        r = gap + ring * height
        angle = start + turn * math.pi / 4.0
        dx, dy = math.cos(angle), math.sin(angle)
        side = align or (("l" if dx > 0.3 else "r" if dx < -0.3 else "c")
                         + ("b" if dy > 0.3 else "t" if dy < -0.3 else "m"))
        yield Text(text, (at[0] + r * dx, at[1] + r * dy), height, side, subscripts=subscripts)


def leader(at: Pair, box: Box, gap: float) -> Polyline:
    """A thin line from ``gap`` off the point ``at`` to the nearest point of the label's
    ``box`` (CLEARANCE short of it, so it ends at the label, not in it)."""
    return line(leader_ends(at, np.asarray([box], dtype=float), gap)[0], THIN)


def leader_ends(at: Pair, boxes: np.ndarray, gap: float) -> np.ndarray:
    """:func:`leader`'s two points for each of ``boxes`` (k, 4), as segments (k, 4)."""
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    near = np.column_stack([np.minimum(np.maximum(at[0], boxes[:, 0]), boxes[:, 2]),
                            np.minimum(np.maximum(at[1], boxes[:, 1]), boxes[:, 3])])
    p = np.asarray(at, dtype=float)
    d = near - p
    length = np.hypot(d[:, 0], d[:, 1])
    along = length > 1e-9
    u = np.where(along[:, None], d / np.where(along, length, 1.0)[:, None], np.array([1.0, 0.0]))
    half = length / 2.0
    return np.hstack([p + np.minimum(gap, half)[:, None] * u, near - np.minimum(CLEARANCE, half)[:, None] * u])


def place(text: str, at: Pair, height: float, taken: list[Box], segments: np.ndarray,
          preferred: Pair = (1.0, 1.0), gap: float = 1.5, within: Box | None = None,
          rings: int = 3, align: str | None = None, subscripts: tuple[tuple[int, int], ...] = (),
          leader_gap: float = 0.0, anchors: np.ndarray | None = None, shrink: bool = True) -> list[Item]:
    """The label ``text`` for the point ``at``, clear of ``segments`` and ``taken``: [the
    label], or [the label, its leader line] when only a spot farther out is free (or only
    one there is read as naming ``at`` rather than another of ``anchors``, the points the
    drawing names), or [] when none is (the drawing is too crowded for it). Takes the
    label's box; a leader line starts ``leader_gap`` off the point (a pin's radius). Without
    ``shrink`` the label keeps its height (one series of numbers beside another of a smaller
    height: shrunk, it would join that one). Each step first with ``LABEL_GAP`` from the
    other texts, then, where no spot keeps it, a word space off them: a label lost or led away from
    its point (the crank's twelve numbers round a small crank circle) is worse than a close
    one."""
    # a label with an index keeps its height: at the smallest one its index could not be smaller
    small = height if subscripts or not shrink else smaller_height(height)
    others = _others(at, anchors)
    for apart in (True, False):
        for h in dict.fromkeys((height, small)):
            spots = ring_candidates(text, at, h, preferred, gap, range(rings), align, subscripts)
            keep = None if others is None else partial(_read_as_own, at=at, others=others, height=h)
            label = first_free(spots, taken, segments, within, keep, label_gap(h) if apart else (0.0, 0.0))
            if label is not None:
                return [label]
    h = small
    # a label on a leader stands off every other named point: beside one it reads as its
    # name, leader or not (方案 III's A3 kinetostatic sheet: R_O2 led out beside R_C's head)
    aloof = None if others is None else (lambda boxes: box_distance(boxes, others).min(axis=-1) >= h)
    for keep, spacing in itertools.product(dict.fromkeys((aloof, None)), (label_gap(h), (0.0, 0.0))):
        spots = ring_candidates(text, at, h, preferred, gap, range(rings, rings + LEADER_RINGS), None, subscripts)
        best = with_leader(spots, at, taken, segments, within, leader_gap, spacing=spacing, keep=keep)
        if (best is None or best[2]) and within is not None:     # anywhere in the drawing, nearest first
            far = with_leader(grid_candidates(text, at, h, within, subscripts), at, taken, segments, within,
                              leader_gap, enough=FAR_CHOICES, spacing=spacing, keep=keep)
            best = far if best is None or (far is not None and far[2] < best[2]) else best
        if best is not None:
            break
    if best is None:
        return []
    taken.append(best[0].box())
    return list(best[:2])


def _others(at: Pair, anchors: np.ndarray | None) -> np.ndarray | None:
    """The ``anchors`` (n, 2) farther than 0.05 mm from ``at`` (nearer ones share its
    label); None when there are none."""
    if anchors is None or not len(anchors):
        return None
    pts = np.asarray(anchors, dtype=float).reshape(-1, 2)
    others = pts[np.hypot(pts[:, 0] - at[0], pts[:, 1] - at[1]) > 0.05]
    return others if len(others) else None


def _read_as_own(boxes: np.ndarray, at: Pair, others: np.ndarray, height: float) -> np.ndarray:
    """Whether a label in each of ``boxes`` (k, 4) is read as naming ``at``, (k,) bools: each
    of ``others`` (:func:`_others`) lies ASSOCIATION·``height`` farther from the box than
    ``at``. A search's candidates at once: one at a time, with the others found again for
    each, was a quarter of the sheets' label search (docs/performance.md)."""
    return (box_distance(boxes, others).min(axis=-1)
            >= box_distance(boxes, np.asarray([at], float))[..., 0] + ASSOCIATION * height)


def box_distance(box: Box | np.ndarray, points: np.ndarray) -> np.ndarray:
    """The distance of each of ``points`` (n, 2) from the axis-parallel ``box``, mm (0
    inside), (n,); for boxes (k, 4), (k, n)."""
    b = np.asarray(box, dtype=float)[..., None, :]
    dx = np.maximum(np.maximum(b[..., 0] - points[:, 0], points[:, 0] - b[..., 2]), 0.0)
    dy = np.maximum(np.maximum(b[..., 1] - points[:, 1], points[:, 1] - b[..., 3]), 0.0)
    return np.hypot(dx, dy)


def grid_candidates(text: str, at: Pair, height: float, within: Box,
                    subscripts: tuple[tuple[int, int], ...] = ()) -> Iterable[Text]:
    """Spots all over ``within`` on a grid two text heights apart, centred on the grid's
    points, the nearest to ``at`` first (at most GRID_SPOTS of them), each made when the search
    reaches it (most searches stop after a few hundred)."""
    xs = np.arange(within[0] + height, within[2] - height, 2.0 * height)
    ys = np.arange(within[1] + height, within[3] - height, 2.0 * height)
    gx, gy = np.meshgrid(xs, ys)
    pts = np.column_stack([gx.ravel(), gy.ravel()])
    near = pts[np.argsort(np.hypot(pts[:, 0] - at[0], pts[:, 1] - at[1]), kind="stable")[:GRID_SPOTS]]
    return (Text(text, (float(x), float(y)), height, "cm", subscripts=subscripts) for x, y in near)


def moved_boxes(at_origin: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Boxes (k, 4) of texts whose box at (0, 0) is ``at_origin`` ((4,) or (k, 4)), moved to
    (``x``, ``y``): the same floats as :meth:`Text.box` at those places (a sum rounds
    monotonically, so the moved corners' min and max are the moved min and max). A search
    tries one text at many places; each candidate's own box was a tenth of a crowded motion
    sheet's label search (docs/performance.md)."""
    return at_origin + np.column_stack([x, y, x, y])


def spot_boxes(spots: Sequence[Text]) -> np.ndarray:
    """Each of ``spots``' :meth:`Text.box`, (k, 4): an upright one's as :func:`moved_boxes`
    of the same text's box at (0, 0), a turned one's its own."""
    at_origin: dict[tuple, Box] = {}
    rows = []
    for spot in spots:
        x, y = spot.position
        if spot.rotation or not (math.isfinite(x) and math.isfinite(y)):
            rows.append((0.0, 0.0) + spot.box())
            continue
        key = (spot.text, spot.height, spot.align, spot.subscripts, spot.superscripts)
        if key not in at_origin:
            at_origin[key] = Text(spot.text, (0.0, 0.0), spot.height, spot.align, subscripts=spot.subscripts,
                                  superscripts=spot.superscripts).box()
        rows.append((x, y) + at_origin[key])
    if not rows:
        return np.zeros((0, 4))
    a = np.array(rows, dtype=float)
    return moved_boxes(a[:, 2:], a[:, 0], a[:, 1])


def with_leader(spots: Iterable[Text], at: Pair, taken: Sequence[Box], segments: np.ndarray,
                within: Box | None, leader_gap: float, enough: int | None = None,
                spacing: Pair = (0.0, 0.0), keep: Callable[[np.ndarray], np.ndarray] | None = None
                ) -> tuple[Text, Polyline, int] | None:
    """Of the free ``spots`` (``spacing`` (x, y) mm off every taken box; the first ``enough``
    of them, if given), the one whose leader
    line from ``at`` crosses the fewest strokes (the first of equals) and no taken box, with
    that line and how many strokes it crosses; None if none is free. The spots are tested in
    batches, in their order; with ``keep`` (boxes (k, 4) → (k,) bools) only the spots it
    keeps."""
    best, found, order = None, 0, 0
    boxes_taken = np.asarray(taken, dtype=float).reshape(-1, 4)
    for batch in _batches(spots):
        boxes = spot_boxes(batch)
        free = np.flatnonzero(free_spots(boxes, boxes_taken, segments, within, spot_gaps(batch, spacing)))
        if keep is not None and len(free):
            free = free[keep(boxes[free])]
        ends = leader_ends(at, boxes[free], leader_gap)
        clear = ~strokes_meet_boxes(ends, boxes_taken)
        free, ends = free[clear], ends[clear]
        if enough is not None:
            free, ends = free[:enough - found], ends[:enough - found]
        for k, seg, crossed in zip(free, ends, crossings_each(ends, segments)):
            score = (int(crossed), order + int(k))
            if best is None or score < best[0]:
                best = (score, batch[k], seg)
        found += len(free)
        order += len(batch)
        if enough is not None and found >= enough:
            break
    return None if best is None else (best[1], line(best[2].reshape(2, 2), THIN), best[0][0])


def _batches(spots: Iterable[Text], size: int = 8) -> Iterable[list[Text]]:
    """``spots`` in lists of ``size``, twice that … up to 256: the first spot is often
    free, a grid search tries hundreds."""
    spots = iter(spots)
    while batch := list(itertools.islice(spots, size)):
        yield batch
        size = min(2 * size, 256)


def spot_gaps(spots: Sequence[Text], gap: Pair = (0.0, 0.0)) -> np.ndarray:
    """What each of ``spots`` keeps off a taken box, (k, 2) mm (x, y): ``gap``, and beside it
    at least the word space of its height (``core.base.lettering.word_gap``)."""
    words = np.array([word_gap(spot.height) for spot in spots], dtype=float)
    return np.column_stack([np.maximum(words, gap[0]), np.full(len(words), float(gap[1]))])


def free_spots(boxes: Sequence[Box], taken: np.ndarray, segments: np.ndarray, within: Box | None,
               gap: Pair | np.ndarray = (0.0, 0.0)) -> np.ndarray:
    """Which of ``boxes`` are free for a label: inside ``within``, clear of every stroke, and
    ``gap`` (x, y) mm off every taken box (``taken`` an (m, 4) array; one pair for all, or
    one per box, :func:`spot_gaps`)."""
    b = np.asarray(boxes, dtype=float).reshape(-1, 4)
    free = np.ones(len(b), dtype=bool)
    if within is not None:
        free &= (within[0] <= b[:, 0]) & (b[:, 2] <= within[2]) & (within[1] <= b[:, 1]) & (b[:, 3] <= within[3])
    if len(taken):
        gx, gy = np.broadcast_to(np.asarray(gap, dtype=float), (len(b), 2)).T[:, :, None]
        free &= ~((b[:, None, 0] - gx < taken[:, 2]) & (taken[:, 0] < b[:, None, 2] + gx)
                  & (b[:, None, 1] - gy < taken[:, 3]) & (taken[:, 1] < b[:, None, 3] + gy)).any(axis=1)
    free[free] = ~boxes_meet_strokes(b[free], segments)
    return free


class Room:
    """The free room of one drawing while its labels are placed: the strokes drawn so far
    (the leader lines join them) and the boxes taken by labels, captions and the like.
    Mutable on purpose: each label placed narrows the room for the next."""

    def __init__(self, items: Iterable[Item] = (), within: Box | None = None,
                 taken: list[Box] | None = None) -> None:
        self.segments = strokes(items)
        self.within = within
        self.taken = [] if taken is None else taken
        self.anchors = np.zeros((0, 2))

    def name(self, points: Iterable[Pair]) -> None:
        """Count ``points`` as named in this drawing: a label is placed beside its own point
        only where none of them could be read as the one it names (:func:`_read_as_own`).
        Name every point before the first label, so that early labels keep off later ones."""
        pts = np.asarray(list(points), dtype=float).reshape(-1, 2)
        self.anchors = np.vstack([self.anchors, pts])

    def draw(self, items: Iterable[Item]) -> None:
        """Count ``items`` (strokes) as drawn, and any texts among them as taken."""
        items = list(items)
        self.segments = np.concatenate([self.segments, strokes(items)])
        self.taken += [it.box() for it in items if isinstance(it, Text)]

    def place(self, text: str, at: Pair, height: float, preferred: Pair = (1.0, 1.0),
              gap: float = 1.5, rings: int = 3, align: str | None = None,
              subscripts: tuple[tuple[int, int], ...] = (), leader_gap: float = 0.0,
              shrink: bool = True) -> list[Item]:
        """:func:`place` in this room; a leader line placed becomes a stroke of it."""
        placed = place(text, at, height, self.taken, self.segments, preferred, gap, self.within,
                       rings, align, subscripts, leader_gap, self.anchors, shrink)
        self.segments = np.concatenate([self.segments, strokes(placed[1:])])
        return placed

    def first_free(self, candidates: Iterable[Text], gap: Pair = (0.0, 0.0)) -> Text | None:
        """:func:`first_free` in this room, ``gap`` (x, y) mm off the boxes taken."""
        return first_free(candidates, self.taken, self.segments, self.within, gap=gap)

    def block(self, lines: Sequence[Text], near: Pair) -> list[Text]:
        """``lines`` (left-aligned, top to bottom, positioned from (0, 0) down) moved as one
        block to the free spot of the drawing nearest ``near`` (a small table of values
        beside what it explains), its lines' boxes taken; [] when no spot is free. Why a
        block: a value that finds no room after its name still has to be read somewhere."""
        if not lines or self.within is None:
            return []
        boxes = np.array([t.box() for t in lines])
        lo, hi = boxes[:, :2].min(axis=0), boxes[:, 2:].max(axis=0)
        size = hi - lo
        x0, y0, x1, y1 = self.within
        step = max(min(size[1], size[0]) / 2.0, 1.0)
        xs = np.arange(x0, x1 - size[0] + 1e-9, step)
        ys = np.arange(y0, y1 - size[1] + 1e-9, step)
        if not len(xs) or not len(ys):
            return []
        gx, gy = (g.ravel() for g in np.meshgrid(xs, ys))
        centre = np.column_stack([gx, gy]) + size / 2.0
        order = np.argsort(np.hypot(centre[:, 0] - near[0], centre[:, 1] - near[1]), kind="stable")
        shift = np.column_stack([gx, gy])[order] - lo          # (m, 2): the block's moves
        whole = np.column_stack([shift[:, 0] + lo[0], shift[:, 1] + lo[1],
                                 shift[:, 0] + hi[0], shift[:, 1] + hi[1]])
        taken = np.asarray(self.taken, dtype=float).reshape(-1, 4)
        free = np.flatnonzero(free_spots(whole, taken, self.segments, self.within,
                                         (min(word_gap(t.height) for t in lines), 0.0)))
        if not len(free):
            return []
        dx, dy = shift[free[0]]
        moved = [replace(t, position=(t.position[0] + dx, t.position[1] + dy)) for t in lines]
        self.taken += [t.box() for t in moved]
        return moved
