"""A drawing sheet as plain data: paper, border, title block and items in paper mm.

One description, several writers: the GUI paints a :class:`Sheet` into PDF and
SVG with QPainter, :mod:`core.drawing.sheet_dxf` writes it as DXF. So the three
files of one sheet cannot disagree, and the tests measure the description
itself (every item inside the border, no two texts overlapping: :mod:`core.drawing.checks`;
a length divided by its scale equal to the design's).

Coordinates are millimetres on the paper, origin at its lower-left corner, y up.
Each item is on one of :mod:`core.drawing.dxf`'s layers, which fixes its line
type after GB/T 4457.4 (thick, thin, centre, dashed). Paper sizes and the border
follow GB/T 14689 (landscape, with a binding margin), scales GB/T 14690, text
heights GB/T 14691's series; the title block (GB/T 10609.1) is
:mod:`core.drawing.title_block`'s.
"""
from __future__ import annotations

import bisect
import itertools
import math
import re
import unicodedata
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import Sequence, Union

import numpy as np

from .advances import ADVANCES, KERNS
from .dxf import OUTLINE, TEXT, THIN
from .paper import BINDING_MARGIN, PAPERS, Box, Paper, paper  # noqa: F401  (imported from here too)
from .scales import (SCALE_MANTISSAS, Placement, fit, number_text, scale_text, shrink,  # noqa: F401  (too)
                     standard_scale)

Pair = tuple[float, float]

TEXT_HEIGHTS = (2.5, 3.5, 5.0, 7.0, 10.0)
SUBSCRIPT_DROP = 0.25     # a subscript's baseline under its text's, in text heights
SUPERSCRIPT_RAISE = 0.45  # a superscript's baseline above the text's, × its height
# Estimated advance per character as a fraction of the text height. CJK characters are set
# square (WIDE_ADVANCE: the renderers condense their fonts' wider CJK glyphs to it, as GB
# drawings write Chinese narrower than the Latin font would); every other character at its
# own advance in the renderers' fonts (``advances.ADVANCES``, the largest of them), and one
# not measured there at the widest measured advance, so no renderer squeezes it. A renderer
# squeezes a text that comes out wider than the estimate, so the estimate is what the
# layout and the overlap checks can rely on.
WIDE_ADVANCE = 1.05
UNKNOWN_ADVANCE = max(ADVANCES.values())


@dataclass(frozen=True)
class Polyline:
    """Straight segments through ``points`` ((n, 2) paper mm); ``filled`` also fills it."""

    points: np.ndarray
    layer: str = THIN
    closed: bool = False
    filled: bool = False


@dataclass(frozen=True)
class Circle:
    center: Pair
    radius: float
    layer: str = THIN
    filled: bool = False


@dataclass(frozen=True)
class Text:
    """One line of text. ``height`` is the character height (GB/T 14691: h, the height of
    the capitals), ``align`` a horizontal (l, c, r) and a vertical (b, m, t) letter, e.g.
    "lb" or "cm"; ``rotation`` in degrees counter-clockwise about ``position``.
    ``subscripts`` are spans (start, end) of ``text`` set as subscripts: one size smaller
    and lowered, as GB/T 14691 writes indices (F with I6 in F_I6). The text itself stays
    plain letters, which every CAD font has; Unicode's subscript digits are not in them,
    and it has no capital subscripts at all. ``superscripts`` the same, raised (the k of
    the Coriolis acceleration a^k_A4A3, written after its index)."""

    text: str
    position: Pair
    height: float = 3.5
    align: str = "lb"
    rotation: float = 0.0
    layer: str = TEXT
    subscripts: tuple[tuple[int, int], ...] = ()
    superscripts: tuple[tuple[int, int], ...] = ()

    @cached_property
    def width(self) -> float:
        return sum(text_width(part, h) for part, h, _ in self._parts())

    def _parts(self) -> list[tuple[str, float, float]]:
        """The text in runs: (text, height, baseline drop), sub- and superscripts one size
        smaller, lowered or raised."""
        small = smaller_height(self.height)
        spans = sorted([(a, b, SUBSCRIPT_DROP * self.height) for a, b in self.subscripts]
                       + [(a, b, -SUPERSCRIPT_RAISE * self.height) for a, b in self.superscripts])
        parts, at = [], 0
        for start, end, drop in spans:
            if start > at:
                parts.append((self.text[at:start], self.height, 0.0))
            parts.append((self.text[start:end], small, drop))
            at = end
        if at < len(self.text) or not parts:
            parts.append((self.text[at:], self.height, 0.0))
        return parts

    def _start(self) -> tuple[float, float]:
        """Where the baseline starts, from ``position``, before rotating (by ``align``)."""
        w, h = self.width, self.height
        return ({"l": 0.0, "c": -w / 2.0, "r": -w}[self.align[0]],
                {"b": 0.0, "m": -h / 2.0, "t": -h}[self.align[1]])

    def runs(self) -> list["Text"]:
        """The text as plain texts, one per run, each aligned "lb" at its own baseline: what
        the renderers draw (itself when it has no subscripts)."""
        if not self.subscripts and not self.superscripts:
            return [self]
        x, y = self._start()
        runs = []
        for part, size, drop in self._parts():
            origin = _rotate(np.array([[x, y - drop]]), self.rotation)[0] + np.asarray(self.position)
            runs.append(Text(part, (float(origin[0]), float(origin[1])), size, "lb", self.rotation, self.layer))
            x += text_width(part, size)
        return runs

    def box(self) -> Box:
        """Its extent on the paper (estimated width, a descender below, a subscript's
        below that), rotated."""
        return self._boxes[0]

    def upright_box(self) -> Box:
        """:meth:`box` as if not rotated: the text's own frame about ``position`` (the box
        a rotated text's crossings are counted in)."""
        return self._boxes[1]

    @cached_property
    def _boxes(self) -> tuple[Box, Box]:
        """Both boxes, computed once: a text is frozen, and the label and dimension
        searches ask a placed text for its box thousands of times per sheet."""
        w, dx, dy, below, above = _extent(self.text, self.height, self.align, self.subscripts,
                                          self.superscripts)
        if not self.rotation and not any(map(math.isnan, (dx, dy, w, below, above, *self.position))):
            # upright: the corners' extent in plain floats, the same sums numpy makes (a
            # label search asks for the boxes of thousands of candidates; numpy's overhead
            # on four points was most of it)
            x, y = self.position
            xs, ys = (float(dx + x), float((dx + w) + x)), (float((dy - below) + y), float((dy + above) + y))
            upright = (min(xs), min(ys), max(xs), max(ys))
            return upright, upright
        corners = np.array([[dx, dy - below], [dx + w, dy - below],
                            [dx + w, dy + above], [dx, dy + above]])
        at = np.asarray(self.position)
        upright = _bounds(corners + at)
        return (_bounds(_rotate(corners, self.rotation) + at) if self.rotation else upright), upright


@lru_cache(maxsize=4096)
def _extent(text: str, height: float, align: str, subscripts: tuple, superscripts: tuple
            ) -> tuple[float, float, float, float, float]:
    """A text's width, where its baseline starts from its position (dx, dy) and how far it
    reaches below and above the baseline: the same for every position and rotation, so a
    label search's candidates (one text at many spots) share them, computed once."""
    at = Text(text, (0.0, 0.0), height, align, subscripts=subscripts, superscripts=superscripts)
    dx, dy = at._start()
    below = max([0.25 * height] + [drop + 0.25 * size for _, size, drop in at._parts()])
    above = max([1.1 * height] + [1.1 * size - drop for _, size, drop in at._parts()])
    return at.width, dx, dy, below, above


Item = Union[Polyline, Circle, Text]


def smaller_height(height: float) -> float:
    """The standard text height one size below ``height`` (the smallest stays): a
    subscript's, a tick label's."""
    return max((h for h in TEXT_HEIGHTS if h < height), default=height)


def line_box(text: "Text", gap: float) -> Box:
    """``text``'s box lengthened by ``gap`` at both ends of its line, turned as it is drawn:
    the room a text in that line keeps clear of (a word space off a tilted dimension text
    runs along the text, not across the paper)."""
    x0, y0, x1, y1 = text.upright_box()
    at = np.asarray(text.position, dtype=float)
    corners = np.array([[x0 - gap, y0], [x1 + gap, y0], [x1 + gap, y1], [x0 - gap, y1]]) - at
    return _bounds(_rotate(corners, text.rotation) + at)


def symbol(*parts: str | tuple[str, str]) -> tuple[str, tuple[tuple[int, int], ...]]:
    """Text and subscript spans for a name written in parts: a plain string, or a pair
    (letters, index) whose index is a subscript. ``symbol(("R", "O2"))`` is R with O2
    below; ``symbol(("a", "3"), ",", ("a", "4"))`` two coincident points."""
    text, spans = "", []
    for part in parts:
        base, index = (part, "") if isinstance(part, str) else part
        text += base
        if index:
            spans.append((len(text), len(text) + len(index)))
            text += index
    return text, tuple(spans)


# The sheets' index notation in captions and translated strings: an underscore before the
# index, which is a run of Latin or Greek letters or a run of digits (so "O_2O_4" is two
# indices, and a Chinese word may follow an index without a space), or several such runs
# joined by commas with no space ("v_w,max" is v with "w,max" below, one index).
_INDEX_RUN = "(?:[A-Za-z\u0391-\u03a9\u03b1-\u03c9]+|[0-9]+)"
INDEX_MARK = re.compile(f"_({_INDEX_RUN}(?:,{_INDEX_RUN})*)")


def marked(text: str) -> tuple[str, tuple[tuple[int, int], ...]]:
    """Text and subscript spans from a caption in the index notation: ``M_m`` is M with m
    below, ``ΔW_max`` ΔW with max, ``O_2O_4`` O2O4 with both digits below. Why: a
    translated string cannot hold :class:`Text`'s spans, and a literal underscore on a
    sheet is no way to write an index (GB/T 14691 lowers it one size smaller). Only the
    program's own words are read so; a user's text (a design name) is taken as it is."""
    plain, spans, at = "", [], 0
    for match in INDEX_MARK.finditer(text):
        plain += text[at:match.start()]
        spans.append((len(plain), len(plain) + len(match.group(1))))
        plain += match.group(1)
        at = match.end()
    return plain + text[at:], tuple(spans)


def marked_text(text: str, position: Pair, height: float, align: str = "lb", room: float | None = None,
                layer: str = TEXT) -> Text:
    """A :class:`Text` of a caption in the index notation (see :func:`marked`), clipped with
    an ellipsis to ``room`` mm when given."""
    plain, spans = marked(text)
    if room is not None:
        plain, spans = clipped_spans(plain, spans, room, height)
    return Text(plain, position, height, align, layer=layer, subscripts=spans)


def clipped(text: str, room: float, height: float) -> str:
    """``text`` cut with an ellipsis to fit ``room`` at ``height``: its longest start whose
    width with "…" (:func:`text_width`'s sum, from the running sum of the advances, taken
    once, searched by bisection) fits. Measuring each shorter start again was quadratic in
    the text: the title block tries thousands of line breaks of a 200-character name, 15 s
    a sheet."""
    if text_width(text, height) <= room:
        return text
    advances = map(_ADVANCE.__getitem__, text)
    if _KERNED.search(text):
        kerns = map(KERNS.get, map(str.__add__, "\0" + text, text), itertools.repeat(0.0))  # before each
        advances = map(float.__add__, advances, kerns)
    starts = list(itertools.accumulate(advances, initial=0.0))     # nondecreasing
    ellipsis = _ADVANCE["…"] + _BEFORE_ELLIPSIS
    k = min(bisect.bisect_right(starts, room, key=lambda start: height * (start + ellipsis)) - 1, len(text))
    return text[:k] + "…" if k > 0 else ""


def clipped_spans(text: str, spans: tuple[tuple[int, int], ...], room: float,
                  height: float) -> tuple[str, tuple[tuple[int, int], ...]]:
    """``text`` cut as :func:`clipped` cuts it, its subscript spans cut with it."""
    cut = clipped(text, room, height)
    if cut == text:
        return text, spans
    kept = len(cut) - 1 if cut.endswith("…") else len(cut)
    return cut, tuple((a, min(b, kept)) for a, b in spans if a < kept)


class _Advances(dict):
    """:data:`ADVANCES`, and a character not in it at its fallback (CJK square, any other
    at the widest measured advance), kept once looked up: a label search measures the same
    few characters millions of times."""

    def __missing__(self, ch: str) -> float:
        self[ch] = WIDE_ADVANCE if is_square(ch) else UNKNOWN_ADVANCE
        return self[ch]


_ADVANCE = _Advances(ADVANCES)
# the widest kern before an ellipsis (DejaVu Sans has none)
_BEFORE_ELLIPSIS = max((kern for pair, kern in KERNS.items() if pair[1] == "…"), default=0.0)
# a first character of a kerned pair, then a second: where a text may hold one (a search in C,
# so the pairs of most texts, which have none, are not looked up one by one)
_KERNED = re.compile("[%s][%s]" % tuple(re.escape("".join(sorted({pair[k] for pair in KERNS})))
                                         for k in (0, 1)))


def is_square(ch: str) -> bool:
    """Set square (:data:`WIDE_ADVANCE`, renderers condense it): CJK the table lacks."""
    return ch not in ADVANCES and unicodedata.east_asian_width(ch) in "WF"


def char_advance(ch: str) -> float:
    """``ch``'s estimated advance in text heights (see :data:`WIDE_ADVANCE`)."""
    return _ADVANCE[ch]


def text_width(text: str, height: float) -> float:
    """Estimated width of ``text`` at ``height`` mm: the sum of its characters' advances
    (:func:`char_advance`) and of the few pairs the font kerns wider ("O-": KERNS), never
    narrower than a renderer draws it."""
    advance = sum(map(_ADVANCE.__getitem__, text))
    if _KERNED.search(text):
        advance += sum(map(KERNS.get, map(str.__add__, text, text[1:]), itertools.repeat(0.0)))
    return height * advance


def _rotate(points: np.ndarray, degrees: float) -> np.ndarray:
    if not degrees:
        return points
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return points @ np.array([[c, s], [-s, c]])


def _bounds(points: np.ndarray) -> Box:
    return (float(points[:, 0].min()), float(points[:, 1].min()),
            float(points[:, 0].max()), float(points[:, 1].max()))


def item_box(item: Item) -> Box:
    """An item's extent on the paper."""
    if isinstance(item, Text):
        return item.box()
    if isinstance(item, Circle):
        (x, y), r = item.center, item.radius
        return (x - r, y - r, x + r, y + r)
    return _bounds(np.asarray(item.points, dtype=float))


def line(points: Sequence[Pair] | np.ndarray, layer: str = THIN, closed: bool = False,
         filled: bool = False) -> Polyline:
    return Polyline(np.asarray(points, dtype=float).reshape(-1, 2), layer, closed, filled)


def rectangle(box: Box, layer: str = THIN) -> Polyline:
    x0, y0, x1, y1 = box
    return line([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], layer, closed=True)


# ---- paper -------------------------------------------------------------------------------

@dataclass(frozen=True)
class Sheet:
    """``model``: for a sheet drawn around one drawing in model coordinates (the gear pair),
    paper mm ↔ model mm; its DXF is then written in the model's coordinates, the drawing at
    1:1 and the paper's items scaled with it (print at the sheet's scale to get the sheet).
    ``dimensions`` (:class:`core.drawing.sheet_dims.Dimension`, on sheets without a model)
    are drawn by their pictures among ``items``; the DXF writes them as DIMENSION entities
    instead."""

    paper: Paper
    items: tuple[Item, ...] = field(default_factory=tuple)
    model: "Placement | None" = None
    dimensions: tuple = ()


def frame_items(p: Paper) -> list[Item]:
    """The trimmed edge (thin) and the border (thick)."""
    return [rectangle((0.0, 0.0, p.width, p.height), THIN), rectangle(p.border, OUTLINE)]
