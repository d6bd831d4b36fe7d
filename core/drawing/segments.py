"""Strokes as segments (n, 4) and the vectorized tests of boxes against them: geometry the label search asks, apart from it."""

from __future__ import annotations

import math
from typing import Iterable

import numpy as np

from core.base.arrays import nonzero_pairs
from .sheet import Box, Circle, Item, Polyline

CLEARANCE = 0.4            # paper mm kept between a label's box and a stroke
CIRCLE_SIDES = 48


def strokes(items: Iterable[Item]) -> np.ndarray:
    """The lines, polylines (closed ones with their closing side) and circles of ``items``
    as segments (n, 4); texts add none."""
    parts = [np.zeros((0, 4))]
    for item in items:
        if isinstance(item, Circle):
            t = np.linspace(0.0, 2.0 * math.pi, CIRCLE_SIDES + 1)
            pts = np.column_stack([item.center[0] + item.radius * np.cos(t),
                                   item.center[1] + item.radius * np.sin(t)])
        elif isinstance(item, Polyline):
            pts = np.asarray(item.points, dtype=float).reshape(-1, 2)
            if item.closed or item.filled:
                pts = np.vstack([pts, pts[:1]])
        else:
            continue
        parts.append(np.column_stack([pts[:-1], pts[1:]]))
    return np.concatenate(parts)


def meets_strokes(box: Box, segments: np.ndarray, clearance: float = CLEARANCE) -> bool:
    """Whether any segment comes within ``clearance`` of the axis-parallel ``box``
    (vectorized clipping of every segment against the enlarged box)."""
    return bool(boxes_meet_strokes(np.asarray([box], dtype=float), segments, clearance)[0])


def boxes_meet_strokes(boxes: np.ndarray, segments: np.ndarray, clearance: float = CLEARANCE) -> np.ndarray:
    """:func:`meets_strokes` for each of ``boxes`` (k, 4) at once, (k,) bools. Why: the
    label search tries thousands of spots against thousands of strokes; one call per
    spot cost seconds a sheet."""
    hit = np.zeros(len(np.asarray(boxes).reshape(-1, 4)), dtype=bool)
    hit[_meeting(boxes, segments, clearance)[0]] = True
    return hit


def strokes_meet_boxes(segments: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """Whether each of ``segments`` (k, 4) meets any of ``boxes`` (no clearance), (k,)
    bools: :func:`meets_strokes` turned round, for a batch of leader lines."""
    hit = np.zeros(len(segments), dtype=bool)
    hit[_meeting(boxes, segments, 0.0)[1]] = True
    return hit


def _meeting(boxes: np.ndarray, segments: np.ndarray, clearance: float) -> tuple[np.ndarray, np.ndarray]:
    """The (box, segment) index pairs where a segment comes within ``clearance`` of a box:
    :func:`meets_strokes`' clipping, only of the pairs whose extents meet."""
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    none = (np.zeros(0, dtype=int), np.zeros(0, dtype=int))
    if not len(segments) or not len(boxes):
        return none
    x0, y0 = boxes[:, 0] - clearance, boxes[:, 1] - clearance
    x1, y1 = boxes[:, 2] + clearance, boxes[:, 3] + clearance
    s = np.asarray(segments, dtype=float).reshape(-1, 4)
    kept = np.flatnonzero(_within(s, (x0.min(), y0.min(), x1.max(), y1.max())))   # all the boxes' extent first
    s = s[kept]
    near = ((np.minimum(s[:, 0], s[:, 2]) <= x1[:, None]) & (np.maximum(s[:, 0], s[:, 2]) >= x0[:, None])
            & (np.minimum(s[:, 1], s[:, 3]) <= y1[:, None]) & (np.maximum(s[:, 1], s[:, 3]) >= y0[:, None]))
    b, k = nonzero_pairs(near)
    if not len(b):
        return none
    x0, y0, x1, y1, s = x0[b], y0[b], x1[b], y1[b], s[k]
    px, py, dx, dy = s[:, 0], s[:, 1], s[:, 2] - s[:, 0], s[:, 3] - s[:, 1]
    lo, hi = np.zeros(len(s)), np.ones(len(s))
    ok = np.ones(len(s), dtype=bool)
    for p, q in ((-dx, px - x0), (dx, x1 - px), (-dy, py - y0), (dy, y1 - py)):
        flat = np.abs(p) < 1e-12
        ok &= ~(flat & (q < 0.0))
        t = q / np.where(flat, 1.0, p)
        lo = np.where(~flat & (p < 0.0), np.maximum(lo, t), lo)
        hi = np.where(~flat & (p > 0.0), np.minimum(hi, t), hi)
    meet = ok & (lo <= hi)
    return b[meet], kept[k[meet]]


def _within(s: np.ndarray, box: Box) -> np.ndarray:
    """Which segments (n, 4) reach into ``box`` (edges included) by their extents."""
    return ((np.minimum(s[:, 0], s[:, 2]) <= box[2]) & (np.maximum(s[:, 0], s[:, 2]) >= box[0])
            & (np.minimum(s[:, 1], s[:, 3]) <= box[3]) & (np.maximum(s[:, 1], s[:, 3]) >= box[1]))


def crossings(seg: np.ndarray, segments: np.ndarray) -> int:
    """How many of ``segments`` (n, 4) the segment ``seg`` (4,) properly crosses."""
    return int(crossings_each(np.asarray(seg, dtype=float).reshape(1, 4), segments)[0])


def crossings_each(segs: np.ndarray, segments: np.ndarray) -> np.ndarray:
    """:func:`crossings` for each of ``segs`` (k, 4) at once, (k,) counts. Only the pairs
    whose extents come within 1 mm are solved (two segments that cross share a point, so
    their extents meet): a leader search asks this of hundreds of spots against every
    stroke of a sheet."""
    segs = np.asarray(segs, dtype=float).reshape(-1, 4)
    if not len(segments) or not len(segs):
        return np.zeros(len(segs), dtype=int)
    lo, hi = np.minimum(segs[:, :2], segs[:, 2:]) - 1.0, np.maximum(segs[:, :2], segs[:, 2:]) + 1.0
    segments = segments[_within(segments, (*lo.min(axis=0), *hi.max(axis=0)))]
    s_lo, s_hi = np.minimum(segments[:, :2], segments[:, 2:]), np.maximum(segments[:, :2], segments[:, 2:])
    near = ((s_lo[:, 0] <= hi[:, None, 0]) & (s_hi[:, 0] >= lo[:, None, 0])
            & (s_lo[:, 1] <= hi[:, None, 1]) & (s_hi[:, 1] >= lo[:, None, 1]))
    k, n = nonzero_pairs(near)
    p, r = segs[k, :2], segs[k, 2:] - segs[k, :2]
    q, s = segments[n, :2], segments[n, 2:] - segments[n, :2]
    cross = lambda a, b: a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]    # noqa: E731
    denom = cross(r, s)
    ok = np.abs(denom) > 1e-12
    d = np.where(ok, denom, 1.0)
    t, u = cross(q - p, s) / d, cross(q - p, r) / d
    hit = ok & (t > 1e-9) & (t < 1.0 - 1e-9) & (u >= 0.0) & (u <= 1.0)
    return np.bincount(k[hit], minlength=len(segs))
