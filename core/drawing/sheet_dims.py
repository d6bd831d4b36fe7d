"""Dimensions on a sheet drawn to a scale: a picture on the paper and a DIMENSION for CAD.

A mechanism on a sheet is drawn at 1:n in paper mm, so a dimension's points are n
times closer than the design's. Each :class:`Dimension` here is both:

- its picture (extension lines, the dimension line or arc, arrows, the text with the
  design's true value) as ordinary sheet items, which the sheet's items include, so the
  painter, the layout and the sheet's checks see it like any other line and text;
- its definition for CAD: :mod:`core.drawing.sheet_dxf` writes a DIMENSION entity in
  place of the picture, with DIMLFAC = n in an override, so CAD's measurement of the
  paper length times n is the true one, and the picture's text (the true value) where
  the picture has it (LibreCAD ignores DIMLFAC, so "<>" would show the paper length there).

The picture follows what CAD draws from the same definition with this module's sizes
(arrow ``dimensions.ARROW_MM`` long, the text ``GAP`` above the line, extension lines
``EXTEND`` beyond it): a text above the line in its reading direction, arrows inside,
or outside with a short tail where they do not fit (an angle's arc).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from core.base.figure_text import dimension_text

from .dimensions import ARROW_MM, reading_order
from .dxf import DIMENSIONS
from .sheet import Box, Item, Pair, Polyline, Text, line

TEXT_MM = 3.5             # dimension text height on the sheet (GB/T 14691)
GAP = 1.0                 # between the dimension line and its text
EXTEND = 2.0              # extension lines beyond the dimension line
ARROW_HALF = ARROW_MM / 6.0     # CAD's closed filled arrow: a sixth of its length each side


@dataclass(frozen=True)
class Dimension:
    """One dimension on the paper. ``kind`` "aligned", "linear" or "angular"; ``points`` the
    two measured points (for an angle, one on each of its legs); ``offset`` the aligned
    line's distance left of p1→p2; ``base`` a point of the linear line or of the arc;
    ``angle`` the linear one's direction (°); ``center`` the angle's vertex; ``factor``
    the true length per paper mm (DIMLFAC; 1 for an angle); ``value`` what the text shows
    (mm or °); ``parts`` the picture, also among the sheet's items, that the DIMENSION
    replaces in the DXF; ``text`` its text; ``kept`` lines of it that stay lines there (a
    dimension line extended under a text that did not fit between the arrows); ``height``
    its text's height, which the DXF's DIMTXT override carries too."""

    kind: str
    name: str
    points: tuple[Pair, Pair]
    factor: float
    value: float
    parts: tuple[Item, ...]
    text: Text
    kept: tuple[Item, ...] = ()
    offset: float = 0.0
    base: Pair = (0.0, 0.0)
    angle: float = 0.0
    center: Pair = (0.0, 0.0)
    height: float = TEXT_MM     # its text's; labels' next smaller one where every spot is crossed
    led: bool = False           # its text moved out along a leader (among ``kept``), horizontal

    @property
    def override(self) -> dict[str, float]:
        """The DIMENSION's style override: the scale and the sizes the picture was laid out with
        (a led text horizontal: DIMTOH, as a moved text is drawn outside)."""
        out = {"dimlfac": float(self.factor), "dimtxt": float(self.height), "dimasz": ARROW_MM,
               "dimgap": GAP, "dimexe": EXTEND, "dimexo": 0.0}
        return {**out, "dimtoh": 1} if self.led else out


value_text = dimension_text
"""A measurement as CAD writes it in this style (``core.base.figure_text.dimension_text``)."""


def _arrow(tip: np.ndarray, back: np.ndarray) -> Polyline:
    """A filled arrowhead at ``tip`` whose body lies along the unit vector ``back``."""
    n = np.array([-back[1], back[0]])
    base = tip + ARROW_MM * back
    return line([tip, base + ARROW_HALF * n, base - ARROW_HALF * n], DIMENSIONS, closed=True, filled=True)


def _straight(p1, p2, a, b, name: str, value: float, beyond: int,
              clear: float = 2.0, outside: bool = False, below: bool = False, along: float = 0.5,
              height: float = TEXT_MM) -> tuple[list[Item], list[Item], Text]:
    """Extension lines p1→a, p2→b (EXTEND beyond), the line a–b with arrows inside and the
    text above its middle, reading along a→b (:func:`_straight_text`). The picture, the
    lines that stay, and the text."""
    p1, p2, a, b = (np.asarray(v, float) for v in (p1, p2, a, b))
    length = max(float(np.hypot(*(b - a))), 1e-12)
    u = (b - a) / length
    parts: list[Item] = []
    for p, q in ((p1, a), (p2, b)):
        out = q - p
        size = float(np.hypot(*out))
        if size > 1e-9:
            parts.append(line([p, q + EXTEND * out / size], DIMENSIONS))
    parts += [line([a, b], DIMENSIONS), _arrow(a, u), _arrow(b, -u)]
    text, kept = _straight_text(a, b, name, value, beyond, clear, outside, below, along, height)
    return parts + [text], kept, text


def _straight_text(a, b, name: str, value: float, beyond: int, clear: float, outside: bool,
                   below: bool, along: float, height: float) -> tuple[Text, list[Item]]:
    """The text of the line a–b above its middle, reading along a→b, and the lines that stay:
    a text longer than the line goes beyond the end ``beyond`` (0: a, 1: b), ``clear`` mm
    from it, over an extension of the line, which stays a line in the DXF (always with
    ``outside``); ``below`` puts the text under the line instead, ``along`` the fraction of
    the line from a to the text's middle, ``height`` the text's height. Apart from the
    picture because a search costs most candidates by their text alone (:class:`Sketch`)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    length = max(float(np.hypot(*(b - a))), 1e-12)
    u = (b - a) / length
    rotation = math.degrees(math.atan2(u[1], u[0]))
    up = np.array([-u[1], u[0]])
    label = f"{name} = {value_text(value)}"
    width = Text(label, (0.0, 0.0), height).width
    # a text's box reaches 0.75 h under its middle (descenders) and 0.6 h over it
    lift = -up * (GAP + 0.6 * height) if below else up * (GAP + 0.75 * height)
    kept: list[Item] = []
    if width + 2.0 * ARROW_MM <= length and not outside:
        room = (ARROW_MM + 1.0 + width / 2.0) / length
        t = min(max(along, room), 1.0 - room)
        centre = a + t * (b - a) + lift
    else:
        end, away = (b, u) if beyond else (a, -u)
        centre = end + away * (clear + width / 2.0) + lift
        kept.append(line([end, end + away * (2.0 * clear + width)], DIMENSIONS))
    return Text(label, (float(centre[0]), float(centre[1])), height, "cm", rotation, DIMENSIONS), kept


def _aligned_frame(p1: Pair, p2: Pair, offset: float, factor: float):
    """An aligned dimension's points in reading order, its offset, its line's ends, its value
    and whether p1, p2 were swapped."""
    q1, q2, offset = reading_order(p1, p2, offset)
    a1, a2 = np.asarray(q1), np.asarray(q2)
    u = (a2 - a1) / float(np.hypot(*(a2 - a1)))
    n = np.array([-u[1], u[0]]) * offset
    value = factor * float(np.hypot(*(a2 - a1)))
    return q1, q2, offset, a1, a2, n, value, not _close(q2, p2[:2])


def aligned(p1: Pair, p2: Pair, offset: float, name: str, factor: float, clear: float = 2.0,
            outside: bool = False, below: bool = False, along: float = 0.5,
            height: float = TEXT_MM) -> Dimension:
    """``name`` = factor·|p1p2| along p1→p2, its line ``offset`` mm left of it (in
    ``dimensions.reading_order``, as the DXF has it); a text that does not fit (or any, with
    ``outside``) goes beyond p2, ``clear`` mm from it; ``below``: the text under the line;
    ``along``: where along p1→p2 the text's middle is (as far as the arrows leave room);
    ``height``: the text's."""
    q1, q2, offset, a1, a2, n, value, swapped = _aligned_frame(p1, p2, offset, factor)
    parts, kept, text = _straight(a1, a2, a1 + n, a2 + n, name, value, 0 if swapped else 1, clear,
                                  outside, below, 1.0 - along if swapped else along, height)
    return Dimension("aligned", name, (q1, q2), factor, value, tuple(parts), text, tuple(kept),
                     offset=offset, height=height)


class Sketch:
    """An aligned dimension's candidate as its text alone, the whole :func:`aligned` built
    when asked: the motion sheet's search costs hundreds of candidates of L3 by their text
    and drops most before their lines count, and the picture (extension lines, arrows) was
    three quarters of building one. ``text`` is the built one's, bit for bit (the same
    code computes both)."""

    __slots__ = ("text", "_args", "_built")

    def __init__(self, p1: Pair, p2: Pair, offset: float, name: str, factor: float, clear: float = 2.0,
                 outside: bool = False, below: bool = False, along: float = 0.5,
                 height: float = TEXT_MM) -> None:
        self._args = (p1, p2, offset, name, factor, clear, outside, below, along, height)
        self._built: Dimension | None = None
        _, _, _, a1, a2, n, value, swapped = _aligned_frame(p1, p2, offset, factor)
        self.text = _straight_text(a1 + n, a2 + n, name, value, 0 if swapped else 1, clear, outside,
                                   below, 1.0 - along if swapped else along, height)[0]

    def dimension(self) -> Dimension:
        """The candidate built: ``aligned`` of the same arguments."""
        if self._built is None:
            self._built = aligned(*self._args)
        return self._built


def _close(a: Sequence[float], b: Sequence[float]) -> bool:
    """``np.allclose(a, b)`` of two points in plain floats (its test: |a − b| ≤ 1e-8 + 1e-5·|b|
    with b finite, or a = b): the dimension search builds hundreds of candidates, and
    numpy's overhead on two numbers was a fifth of building one."""
    pairs = [(float(p), float(q)) for p, q in zip(a, b, strict=True)]
    return all((abs(p - q) <= 1e-8 + 1e-5 * abs(q) and math.isfinite(q)) or p == q for p, q in pairs)


def led(dim: Dimension, corner: Pair, height: float = TEXT_MM) -> Dimension:
    """The aligned ``dim`` with its text moved out along a leader, the last step of the labels'
    cascade where no spot on or beyond its line is free (L3 between the chain's extension
    lines, K near 3): the text horizontal, ``height`` high, the near end of its underline at
    ``corner``; the leader from the middle of the dimension line to ``corner``, then under
    the text (as CAD draws a moved text's leader). The line stays whole, arrows inside."""
    base = aligned(dim.points[0], dim.points[1], dim.offset, dim.name, dim.factor)
    (q1, q2), offset = base.points, base.offset
    a1, a2 = np.asarray(q1, float), np.asarray(q2, float)
    u = (a2 - a1) / float(np.hypot(*(a2 - a1)))
    middle = (a1 + a2) / 2.0 + np.array([-u[1], u[0]]) * offset
    label = f"{dim.name} = {value_text(dim.value)}"
    width = Text(label, (0.0, 0.0), height).width
    c = np.asarray(corner, float)
    sense = 1.0 if c[0] >= middle[0] else -1.0        # the text runs away from the line
    centre = (float(c[0] + sense * width / 2.0), float(c[1] + 0.75 * height))
    text = Text(label, centre, height, "cm", 0.0, DIMENSIONS)
    far = (float(c[0] + sense * width), float(c[1]))
    leader = line([middle, c, far], DIMENSIONS)
    parts = tuple(p for p in base.parts if not isinstance(p, Text))
    return Dimension("aligned", dim.name, base.points, dim.factor, base.value, (*parts, text), text,
                     (leader,), offset=offset, height=height, led=True)


def linear(p1: Pair, p2: Pair, base: Pair, angle: float, name: str, factor: float,
           beyond_first: bool = False, height: float = TEXT_MM) -> Dimension:
    """``name`` = factor × the distance of p1 and p2 along ``angle`` (°), its line through
    ``base``; a text that does not fit goes beyond p2 (p1 with ``beyond_first``), ``height``
    high."""
    u = np.array([math.cos(math.radians(angle)), math.sin(math.radians(angle))])
    c = np.asarray(base, float)
    a, b = (c + u * float(np.dot(np.asarray(p, float) - c, u)) for p in (p1, p2))
    value = factor * abs(float(np.dot(np.asarray(p2, float) - np.asarray(p1, float), u)))
    forward = float(np.dot(b - a, u)) >= 0
    first, second, lo, hi = (p1, p2, a, b) if forward else (p2, p1, b, a)
    parts, kept, text = _straight(first, second, lo, hi, name, value, int(forward != beyond_first),
                                  height=height)
    return Dimension("linear", name, (tuple(p1), tuple(p2)), factor, value, tuple(parts), text,
                     tuple(kept), base=tuple(base), angle=angle, height=height)


def angular(center: Pair, p1: Pair, p2: Pair, radius: float, name: str) -> Dimension:
    """``name`` = the angle at ``center`` from p1 to p2 counter-clockwise (< 180°), its arc
    at ``radius``, the text horizontal outside the arc's middle; the arrows outside with a
    tail where two arrows do not fit on the arc."""
    c = np.asarray(center, float)
    t1, t2 = (math.atan2(p[1] - c[1], p[0] - c[0]) for p in (p1, p2))
    sweep = (t2 - t1) % (2.0 * math.pi)
    items: list[Item] = []
    for t, p in ((t1, p1), (t2, p2)):
        d = np.array([math.cos(t), math.sin(t)])
        start = float(np.hypot(*(np.asarray(p, float) - c)))
        items.append(line([c + start * d, c + (radius + EXTEND) * d], DIMENSIONS))
    inside = radius * sweep >= 2.0 * ARROW_MM + 2.0
    tail = ARROW_MM / radius
    lo, hi = (t1, t1 + sweep) if inside else (t1 - 2.0 * tail, t1 + sweep + 2.0 * tail)
    arc = np.linspace(lo, hi, max(8, int(math.degrees(hi - lo)) + 2))
    items.append(line(c + radius * np.column_stack([np.cos(arc), np.sin(arc)]), DIMENSIONS))
    for t, sense in ((t1, 1.0), (t1 + sweep, -1.0)):
        tangent = sense * np.array([-math.sin(t), math.cos(t)]) * (1.0 if inside else -1.0)
        items.append(_arrow(c + radius * np.array([math.cos(t), math.sin(t)]), tangent))
    mid = t1 + sweep / 2.0
    d = np.array([math.cos(mid), math.sin(mid)])
    value = math.degrees(sweep)
    label = f"{name} = {value_text(value)}°"
    probe = Text(label, (0.0, 0.0), TEXT_MM, "cm")
    box = probe.box()
    # the text's centre far enough along d that its box clears the arc by GAP
    reach = radius + EXTEND + GAP + 0.5 * (abs(d[0]) * (box[2] - box[0]) + abs(d[1]) * (box[3] - box[1]))
    at = c + reach * d
    text = Text(label, (float(at[0]), float(at[1])), TEXT_MM, "cm", 0.0, DIMENSIONS)
    base = c + radius * d
    return Dimension("angular", name, (tuple(p1), tuple(p2)), 1.0, value, tuple(items + [text]), text, (),
                     base=(float(base[0]), float(base[1])), center=tuple(center))


# ---- a local check: is a text clear of the lines? ------------------------------------------

def segments(items: Sequence[Item]) -> np.ndarray:
    """The straight segments of the polylines among ``items``, (m, 4): x1, y1, x2, y2."""
    out = []
    for it in items:
        if isinstance(it, Polyline) and len(it.points) > 1:
            pts = np.asarray(it.points, float)
            if it.closed:
                pts = np.vstack([pts, pts[:1]])
            out.append(np.hstack([pts[:-1], pts[1:]]))
    return np.vstack(out) if out else np.zeros((0, 4))


class Lines:
    """Segments (m, 4) with each one's extent and their whole extent, computed once: the
    dimension search counts the crossings of hundreds of candidate texts with the same
    lines, and most texts are nowhere near most of them."""

    def __init__(self, segs: np.ndarray) -> None:
        self.segs = np.asarray(segs, float).reshape(-1, 4)
        self.low = np.minimum(self.segs[:, :2], self.segs[:, 2:])      # each one's min x, min y
        self.high = np.maximum(self.segs[:, :2], self.segs[:, 2:])
        whole = (*self.low.min(axis=0), *self.high.max(axis=0)) if len(self.segs) else ()
        # (a NaN point makes no whole extent: every segment is then tried)
        self.whole = tuple(map(float, whole)) if np.all(np.isfinite(whole)) else ()

    def near(self, box: Box, spare: float) -> np.ndarray | None:
        """Which segments' extents overlap ``box`` grown by ``spare`` (strictly, as
        :func:`crossing` asks); None when the whole extent does not, so none does."""
        x0, y0, x1, y1 = box
        w = self.whole
        if w and not (w[0] < x1 + spare and w[2] > x0 - spare and w[1] < y1 + spare and w[3] > y0 - spare):
            return None
        return ((self.low[:, 0] < x1 + spare) & (self.high[:, 0] > x0 - spare)
                & (self.low[:, 1] < y1 + spare) & (self.high[:, 1] > y0 - spare))


def text_crossings(text: Text, segs: np.ndarray | Lines) -> int:
    """How many of ``segs`` cross ``text``, in its own (rotated) frame: its box, not the
    larger upright box around it. ``segs`` as :class:`Lines` where many texts are tried
    against the same lines."""
    lines = segs if isinstance(segs, Lines) else Lines(segs)
    if not len(lines.segs):
        return 0
    if not text.rotation:
        box = text.box()
        near = lines.near(box, 0.0)        # a segment apart from the box never crosses it
        return 0 if near is None else crossings(box, lines.segs[near])
    # only the segments near the rotated box can cross it (1 mm spare, far above rounding):
    # the dimension search asks this of every line on the sheet for hundreds of candidates
    near = lines.near(text.box(), 1.0)
    if near is None:
        return 0
    segs = lines.segs[near]
    t = math.radians(text.rotation)
    turn = np.array([[math.cos(t), math.sin(t)], [-math.sin(t), math.cos(t)]])     # by −rotation
    o = np.asarray(text.position, float)
    local = np.hstack([(segs[:, :2] - o) @ turn.T + o, (segs[:, 2:] - o) @ turn.T + o])
    return crossings(text.upright_box(), local)


def crossings(box: Box, segs: np.ndarray) -> int:
    """How many of ``segs`` meet the inside of ``box``."""
    return int(crossing(np.asarray([box], float), segs).sum())


def crossing(boxes: np.ndarray, segs: np.ndarray) -> np.ndarray:
    """(boxes, segments) → whether each segment meets the inside of each box, (n, m): their
    extents overlap and the box's corners are not all on one side of the segment's line."""
    b = np.asarray(boxes, float).reshape(-1, 4)[:, :, None]
    s = np.asarray(segs, float).reshape(-1, 4)
    if b.shape[0] == 0 or s.shape[0] == 0:
        return np.zeros((b.shape[0], s.shape[0]), bool)
    x1, y1, x2, y2 = s.T
    near = ((np.minimum(x1, x2) < b[:, 2]) & (np.maximum(x1, x2) > b[:, 0])
            & (np.minimum(y1, y2) < b[:, 3]) & (np.maximum(y1, y2) > b[:, 1]))
    sides = np.stack([(x2 - x1) * (b[:, j] - y1) - (y2 - y1) * (b[:, i] - x1)
                      for i, j in ((0, 1), (2, 1), (2, 3), (0, 3))])
    split = ~((sides > 0).all(axis=0) | (sides < 0).all(axis=0))
    return near & split
