"""The mechanism's dimensions on the motion sheet (its tool path's numbers: :mod:`.path_numbers`).

Placed where no position of the mechanism goes, so a text never sits on a link: L2
(O2O4) and h as a vertical chain left of everything, L3 beside the lever's right limit
position on the side away from O2, L1 along the crank at the first limit position with
its text beyond the crank pin (outside the lever's swing, which the crank circle touches
there), H between the ram's limit positions above the rams (with L4 along the rod under
it), and θ between the lever's limit positions, at O4 on its vertical opposite angle
below the pivot (above it the intermediate positions fill the wedge). Every value is
what CAD measures on the sheet's DXF times the scale: :mod:`core.drawing.sheet_dims`.
"""
from __future__ import annotations

import math
from typing import Iterable, Sequence

import numpy as np

from core.base.lettering import word_gap
from core.linkage.geometry import Design

from . import mechanism as mech
from . import sheet_dims as sd
from .labels import boxes_meet
from .dimensions import reading_order
from .segments import crossings_each, strokes
from .sheet import Box, Item, Placement, Text, item_box, line, line_box, smaller_height

FIRST = 7.0               # the first dimension line from the linework, paper mm
STEP = 7.0                # between parallel dimension lines (DIMDLI)
BOX = 1.1 * sd.TEXT_MM + 0.25 * sd.TEXT_MM      # a dimension text's box across its line
LEFT_ROOM = FIRST + STEP + sd.GAP + BOX + 1.0   # the chain: two lines and a text
ABOVE_ROOM = FIRST + STEP + sd.GAP + BOX + 1.0  # H over L4
L3_OFFSET = 10.0
# where along the lever L3's text may stand, the preferred first; then every 2.5 % between,
# for a text that must find the gap between the chain's extension lines (K near 3)
L3_ALONG = tuple(dict.fromkeys((0.5, 0.35, 0.65, 0.2, 0.8, *np.round(np.linspace(0.1, 0.9, 33), 3))))
# a text beyond either end of the lever: its line L3_OFFSET from the lever, or farther out
# (clear of the lines round the ends) by a step or two
L3_FARTHER = (1.0, (L3_OFFSET + STEP) / L3_OFFSET, (L3_OFFSET + 2.0 * STEP) / L3_OFFSET)
THETA_START = mech.SUPPORT + 3.0                # θ's extension lines start clear of O4's support
THETA_RADIUS = (12.0, 30.0)
BELOW_ROOM = THETA_RADIUS[1] + sd.GAP + BOX + 1.0
LEAD_REACH = (6.0, 9.0, 12.0, 16.0, 20.0, 25.0, 30.0)    # a led text's leader, paper mm


class _Placed:
    """The dimensions placed so far and what a next one's text must keep clear of: the
    linework's and their lines, and their texts."""

    def __init__(self, drawn: Sequence[Item]) -> None:
        self.drawn = list(drawn)
        self.dims: list[sd.Dimension] = []
        self.defects = 0.0         # the placed texts' crossings and hits, as costed
        self.segs = strokes(self.drawn)        # the circles too (the crank's centre circle)
        self.lines = sd.Lines(self.segs)
        self.compact_asked = False    # whether h's text did not fit its line (``compact`` then counts)

    def cost(self, dim: sd.Dimension | sd.Sketch, extra: float = 0.0, beat: float = math.inf) -> float:
        """1000 per placed text its text meets or its lines cross, 10 per line its text
        crosses, plus ``extra``; inf at once where that without its own lines' crossings
        (the dearer part: their strokes, and each placed text against them; a sketch's
        lines are built for it only then) is already ``beat`` or more, so that the whole
        could not be less."""
        box = dim.text.box()
        hits = sum(boxes_meet(box, d.text.box()) for d in self.dims)
        crossed = sd.text_crossings(dim.text, self.lines)
        if 1000.0 * hits + 10.0 * crossed + extra >= beat:
            return math.inf
        whole = _built(dim)
        own = sd.Lines(strokes([*whole.parts, *whole.kept]))      # its lines through a text placed before
        hits += sum(sd.text_crossings(d.text, own) > 0 for d in self.dims)
        return 1000.0 * hits + 10.0 * crossed + extra

    def best(self, candidates: Iterable[sd.Dimension | sd.Sketch], extra=lambda dim: 0.0) -> sd.Dimension:
        """``min(candidates, key=cost + extra)``, the first of equals, each cost left
        unfinished once it cannot be less than the least so far (the same choice: a cost
        only grows by its own lines' crossings), built (a sketch's ``extra`` reads its text
        alone). Most of the motion sheet's dimension search is the hundreds of candidates
        of L3 and H costed against each placed text."""
        found, least = None, math.inf
        for dim in candidates:
            cost = self.cost(dim, extra(dim), least)
            if found is None or cost < least:
                found, least = dim, cost
        return _built(found)

    def add(self, *candidates: sd.Dimension, extra=lambda dim: 0.0) -> sd.Dimension:
        """The candidate whose text meets no placed text, whose lines cross none, and whose
        text crosses the fewest lines (then the least ``extra``; first of equals), kept."""
        return self._keep(self.best(candidates, extra))

    def add_sized(self, make, extra=lambda dim: 0.0, outward: float = 0.0) -> sd.Dimension:
        """As :meth:`add` with the candidates ``make(height)`` at the dimension text's height,
        or, where every one of them is crossed or meets a text, at labels' next smaller
        standard height if one of those is less so (the project's label cascade); and
        where that too is crossed, with ``outward`` (an aligned dimension: the side of its
        line away from the link, ±1), its text led out to the nearest clear spot (a leader
        from its line, the text horizontal: the cascade's last step)."""
        best = self.best(make(sd.TEXT_MM), extra)
        if self.cost(best) > 0:
            small = self.best(make(smaller_height(sd.TEXT_MM)), extra)
            if self.cost(small) < self.cost(best):
                best = small
        if self.cost(best) > 0 and outward:
            moved = min(self._led(best, outward), key=self._lead_cost)
            if self.cost(moved) + self._own(moved) < self.cost(best):
                best = moved
        return self._keep(best)

    def _led(self, dim: sd.Dimension, outward: float) -> list[sd.Dimension]:
        """``dim`` with its text led out to LEAD_REACH mm from its line's middle, in any
        direction on the ``outward`` side of it, at the text's height and the next smaller."""
        q1, q2 = (np.asarray(p, float) for p in dim.points)
        u = (q2 - q1) / float(np.hypot(*(q2 - q1)))
        out = np.array([-u[1], u[0]]) * math.copysign(1.0, dim.offset) * outward
        middle = (q1 + q2) / 2.0 + np.array([-u[1], u[0]]) * dim.offset
        turns = np.radians(np.arange(0.0, 360.0, 15.0))
        ways = [w for w in np.column_stack([np.cos(turns), np.sin(turns)]) if float(np.dot(w, out)) > 0.2]
        return [sd.led(dim, tuple(middle + r * w), size) for size in (sd.TEXT_MM, smaller_height(sd.TEXT_MM))
                for r in LEAD_REACH for w in ways]

    def _lead_cost(self, dim: sd.Dimension) -> float:
        """A led text's cost: as :meth:`cost`, its leader's crossings of the lines, then its length."""
        lead = strokes(list(dim.kept))
        reach = float(np.hypot(*(lead[0, 2:] - lead[0, :2])))
        smaller = 1.0 if dim.height < sd.TEXT_MM else 0.0
        return (self.cost(dim) + self._own(dim) + 10.0 * int(crossings_each(lead, self.segs).sum())
                + 0.01 * reach + 5.0 * smaller)

    @staticmethod
    def _own(dim: sd.Dimension) -> float:
        """A led text's crossings of its own lines (moved off the line, it may meet it)."""
        return 10.0 * sd.text_crossings(dim.text, strokes([p for p in dim.parts if not isinstance(p, Text)]))

    def _keep(self, best: sd.Dimension) -> sd.Dimension:
        self.defects += self.cost(best)
        self.dims.append(best)
        self.segs = np.vstack([self.segs, strokes([*best.parts, *best.kept])])
        self.lines = sd.Lines(self.segs)
        return best


def dimensions(design: Design, place: Placement, drawn: Sequence[Item],
               limits: Sequence[float], compact: bool = False) -> tuple[list[sd.Dimension], bool]:
    """The seven (six without a rod) dimensions of the mechanism ``drawn`` at ``place``: each
    of a few ways to place it (which side of its line, which end a text that does not fit
    goes beyond, where along the line) the one whose text crosses the fewest lines.
    ``compact``: h's text, where it does not fit its line, beside L2's instead of above
    the guide (the drawing no taller than its linework and H). Second, whether ``compact``
    could have changed them: False where h's text fitted its line in every try, so that
    the other ``compact`` gives the same dimensions bit for bit (the motion sheet's fit
    then skips that search, which only repeated this one)."""
    factor = place.scale
    at = [{k: place(v) for k, v in mech.joints(design, float(phi)).items()} for phi in limits]
    boxes = np.array([item_box(it) for it in drawn if not isinstance(it, Text)])
    top = float(boxes[:, 3].max())
    o2, o4 = at[0]["O2"], at[0]["O4"]
    # L1 first, so that the chain goes left of its text too: at the limit position whose
    # tangent point gives its text the fewest crossings, with the chain's extension lines
    # from O4 and O2 (running left), L3's line beside the other limit and θ's text counted
    chain_lines = [line([p, (p[0] - 1e4, p[1])]) for p in (o4, o2)]
    ranked = []
    for k, j in enumerate(at):
        best = None
        other = at[1 - k]["B"]
        shift = _left_normal(o4, other) * _side(o4, other, o2, -L3_OFFSET)
        trial = _Placed([*drawn, *chain_lines, line([o4 + shift, other + shift])])
        trial.dims.append(_theta(o4, at[0]["B"], at[1]["B"]))      # fixed, so L1 keeps off its text
        # at the dimension texts' height; at labels' next smaller one only where that is crossed
        for size in (sd.TEXT_MM, smaller_height(sd.TEXT_MM)):
            if best is not None and best[0] == 0:
                break
            crank = [sd.aligned(p, q, 0.0, "L1", factor, clear=mech.BLOCK[1] / 2.0 + 2.0, outside=True,
                                below=below, height=size)
                     for p, q in ((o2, j["A"]), (j["A"], o2)) for below in (False, True)]
            for dim in crank:
                if _beyond(dim, j["A"]) and (best is None or trial.cost(dim) < best[0]):
                    best = (trial.cost(dim), dim, 1 - k)
        if best is not None:
            ranked.append(best)
    # the rest after L1 at the better limit position; at the other where that leaves a text
    # crossed there and not here (L3's text between the chain's extension lines, K near 3)
    ranked.sort(key=lambda b: b[0])
    tries = []
    for best in ranked:
        tries.append(_after_l1(design, place, drawn, at, best, boxes, top, compact))
        if tries[-1].defects == 0:
            break
    return min(tries, key=lambda p: p.defects).dims, any(p.compact_asked for p in tries)


def _after_l1(design: Design, place: Placement, drawn: Sequence[Item], at, best, boxes: np.ndarray,
              top: float, compact: bool) -> "_Placed":
    """The dimensions with L1 ``best`` (cost, dimension, the other limit position's index)."""
    factor = place.scale
    o2, o4 = at[0]["O2"], at[0]["O4"]
    placed = _Placed(drawn)
    placed.add(best[1])
    left = min(float(boxes[:, 0].min()), placed.dims[0].text.box()[0])
    guide = (float(boxes[:, 0].min()), float(place([0.0, design.guide])[1]))
    x = left - FIRST
    l2 = sd.linear(o4, o2, (x, o4[1]), 90.0, "L2", factor, beyond_first=True)
    placed.add(l2)
    # h on the chain; where its text does not fit there it goes beyond the guide, or
    # (compact) one line out beyond O2, beside L2's
    h = sd.linear(o2, guide, (x, o2[1]), 90.0, "h", factor)
    placed.compact_asked = bool(h.kept)
    if (h.kept and compact) or boxes_meet(h.text.box(), l2.text.box()):
        low = sd.linear(o2, guide, (x - STEP, o2[1]), 90.0, "h", factor, beyond_first=True)
        if not boxes_meet(low.text.box(), l2.text.box()) and not (l2.kept and low.kept):
            h = low
    placed.add(h)
    placed.add(_theta(o4, at[0]["B"], at[1]["B"]))     # fixed: before L3, which keeps off it
    lever = at[best[2]]["B"]                  # L3 beside the limit position L1 is not at
    offset = _side(o4, lever, o2, -L3_OFFSET)
    # … else beyond either end (where the chain's extension lines from O2 and O4 leave no
    # gap on the lever for it)
    placed.add_sized(
        lambda size: [*[sd.Sketch(o4, lever, offset * far, "L3", factor, along=t, below=below, height=size)
                        for far in L3_FARTHER for t in L3_ALONG for below in (False, True)],
                      *[sd.Sketch(p, q, side * far, "L3", factor, outside=True, below=below, height=size)
                        for far in L3_FARTHER for p, q, side in ((o4, lever, offset), (lever, o4, -offset))
                        for below in (False, True)]],
        extra=_away_from(o2, place.length(design.crank),
                                float(place([0.0, design.guide])[1]) - mech.TOOL_DROP),
        outward=1.0)
    above = top + FIRST          # H over the rams; L4 (the rod) between them and H
    c0, c1 = sorted((at[0]["C"], at[1]["C"]), key=lambda p: float(p[0]))
    level = above + (STEP if design.rod is not None else 0.0)
    placed.add_sized(lambda size: [sd.linear(c0, c1, (c0[0], level), 0.0, "H", factor, height=size),
                                   sd.linear(c1, c0, (c0[0], level), 0.0, "H", factor, height=size)])
    if design.rod is not None:           # the rod at either limit position
        placed.add_sized(lambda size: _rods(at, above, factor, size))
    return placed


def _built(dim: sd.Dimension | sd.Sketch) -> sd.Dimension:
    return dim if isinstance(dim, sd.Dimension) else dim.dimension()


def _rods(at, above: float, factor: float, size: float) -> list[sd.Dimension]:
    """L4's candidates, ``size`` high: along the rod at either limit position, its line at ``above`` (under H)."""
    rods = []
    for j in at:
        q1, q2, _ = reading_order(j["B"], j["C"], 0.0)
        n = _left_normal(np.asarray(q1), np.asarray(q2))
        offset = (above - min(q1[1], q2[1])) / n[1] if abs(n[1]) > 1e-6 else above - q1[1]
        rods += [sd.aligned(p, q, offset if p is q1 else -offset, "L4", factor, below=below, height=size)
                 for p, q in ((q1, q2), (q2, q1)) for below in (False, True)]
    return rods


def _beyond(dim: sd.Dimension, end: np.ndarray) -> bool:
    """Whether the dimension's text lies nearer ``end`` than its other point."""
    p = np.asarray(dim.text.position)
    far = [np.hypot(*(p - np.asarray(q))) for q in dim.points]
    near = min(range(2), key=lambda k: far[k])
    return bool(np.allclose(dim.points[near], end))


def _away_from(o2: np.ndarray, crank: float, path: float):
    """A cost for L3's text: how much of its box lies where the crank's numbers go (9 mm round
    the crank circle) or the tool path's (above 8 mm under the path), in mm²/100."""
    keep = [(o2[0] - crank - 9.0, o2[1] - crank - 9.0, o2[0] + crank + 9.0, o2[1] + crank + 9.0),
            (-math.inf, path - 8.0, math.inf, math.inf)]

    def cost(dim: sd.Dimension) -> float:
        x0, y0, x1, y1 = dim.text.box()
        return sum(max(0.0, min(x1, k[2]) - max(x0, k[0])) * max(0.0, min(y1, k[3]) - max(y0, k[1]))
                   for k in keep) / 100.0
    return cost


def _left_normal(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    u = (q - p) / float(np.hypot(*(q - p)))
    return np.array([-u[1], u[0]])


def _side(p, q, avoid, offset: float) -> float:
    """``offset``'s sign for an aligned dimension from p to q (left of p→q is positive) so
    that its line lies away from the point ``avoid``."""
    n = _left_normal(np.asarray(p, float), np.asarray(q, float))
    toward = float(np.dot(n, np.asarray(avoid) - np.asarray(p))) > 0.0
    return -abs(offset) if toward else abs(offset)


def _theta(o4: np.ndarray, b0: np.ndarray, b1: np.ndarray) -> sd.Dimension:
    """θ on the lever's limit positions extended below O4, its arc as long as two arrows
    need within THETA_RADIUS."""
    legs = [o4 - THETA_START * (b - o4) / float(np.hypot(*(b - o4))) for b in (b0, b1)]
    turn = [math.atan2(p[1] - o4[1], p[0] - o4[0]) for p in legs]
    if (turn[1] - turn[0]) % (2.0 * math.pi) > math.pi:
        legs.reverse()
    sweep = math.acos(float(np.clip(np.dot(b0 - o4, b1 - o4)
                                    / (np.hypot(*(b0 - o4)) * np.hypot(*(b1 - o4))), -1.0, 1.0)))
    radius = min(max(THETA_RADIUS[0], (2.0 * sd.ARROW_MM + 3.0) / max(sweep, 1e-9)), THETA_RADIUS[1])
    return sd.angular(tuple(o4), tuple(legs[0]), tuple(legs[1]), radius, "θ")


def obstacles(dims: Sequence[sd.Dimension], texts_only: bool = False) -> list[Box]:
    """What a label placed by boxes must keep clear of: each dimension's text with a word space
    at either end of its line (``sheet.line_box``), and those of its
    lines whose box is not much more than the line (horizontal, vertical or short ones).
    ``texts_only``: what a leader must not run through, the texts alone, a tilted one as
    :func:`text_tiles` (a label's box keeps clear of the whole box, as the sheet's check
    has it; a leader across a dimension's line is a crossing like any other)."""
    if texts_only:
        return [box for dim in dims for box in text_tiles(dim.text)]
    boxes = [line_box(dim.text, word_gap(dim.text.height)) for dim in dims]      # a word space in its line
    for dim in dims:
        for part in (*dim.parts, *dim.kept):
            if isinstance(part, Text):
                continue
            x0, y0, x1, y1 = item_box(part)
            if min(x1 - x0, y1 - y0) < 0.5 or max(x1 - x0, y1 - y0) < 15.0:
                boxes.append((x0, y0, x1, y1))
    return boxes


def text_tiles(text: Text) -> list[Box]:
    """Upright boxes that cover ``text`` closely: its box if it is horizontal or vertical, else
    its rotated box cut into pieces about as long as it is high, each piece's upright box
    (one box round a tilted text would hold a triangle of free paper at each corner)."""
    turn = math.radians(text.rotation)
    if abs(math.sin(2.0 * turn)) < 1e-6:
        return [text.box()]
    x0, y0, x1, y1 = Text(text.text, text.position, text.height, text.align, 0.0,
                          subscripts=text.subscripts).box()
    cuts = np.linspace(x0, x1, max(1, math.ceil((x1 - x0) / (y1 - y0))) + 1)
    c, s = math.cos(turn), math.sin(turn)
    o = np.asarray(text.position, float)
    tiles = []
    for a, b in zip(cuts[:-1], cuts[1:]):
        local = np.array([[a, y0], [b, y0], [b, y1], [a, y1]]) - o
        pts = local @ np.array([[c, s], [-s, c]]) + o
        tiles.append((float(pts[:, 0].min()), float(pts[:, 1].min()), float(pts[:, 0].max()),
                      float(pts[:, 1].max())))
    return tiles
