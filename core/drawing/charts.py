"""Charts of curves over the crank angle and vector polygons, as sheet items.

The course design draws its curves and polygons to a stated scale μ (units per
mm of paper) chosen from a round series, so a reader can measure a value with a
ruler: here every scale comes from :func:`core.forces.polygons.nice_scale` and is
returned with the items, so the caller writes it beside the drawing.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Mapping, Sequence

import numpy as np

from core.base.lettering import label_gap, word_gap
from core.forces.polygons import FINE_MANTISSAS, Polygon, nice_scale

from .dxf import DASHED, OUTLINE, THIN
from .labels import Room
from .sheet import Box, Item, Pair, Text, line, marked, number_text, smaller_height, symbol, text_width

ARROW = (3.5, 1.0)          # arrowhead length and half width, paper mm
TICK = 1.5
# φ scales: round, and at most 1.25× the exact one so a chart fills most of its box.
X_MANTISSAS = (1.0, 1.2, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)


def arrow(tail: Pair, head: Pair, layer: str = OUTLINE) -> list[Item]:
    """A line from ``tail`` to ``head`` with a filled head (none if shorter than the head)."""
    t, h = np.asarray(tail, float), np.asarray(head, float)
    d = h - t
    length = math.hypot(*d)
    if length < 1e-9:
        return []
    u = d / length
    n = np.array([-u[1], u[0]])
    size = min(ARROW[0], 0.6 * length)
    half = ARROW[1] * size / ARROW[0]
    base = h - size * u
    return [line([t, base], layer),
            line([h, base + half * n, base - half * n], layer, closed=True, filled=True)]


# ---- vector polygons ---------------------------------------------------------------------

def polygon_scale(polygons: Sequence[Polygon], room_mm: float) -> float:
    """One round scale μ for polygons drawn side by side (so they compare by eye)."""
    return nice_scale(max(p.largest() for p in polygons), room_mm, FINE_MANTISSAS)


def polygon_fit_scale(polygon: Polygon, width: float, height: float) -> float:
    """The smallest round scale μ at which the whole polygon fits ``width`` × ``height`` mm."""
    x0, y0, x1, y1 = polygon_extent(polygon, 1.0)
    if x1 == x0 and y1 == y0:       # no force at all: 1 per mm, as nice_scale gives for nothing
        return 1.0
    return max(nice_scale(max(x1 - x0, 1e-12), width, FINE_MANTISSAS),
               nice_scale(max(y1 - y0, 1e-12), height, FINE_MANTISSAS))


def polygon_extent(polygon: Polygon, scale: float) -> Box:
    pts = np.array(list(polygon.points.values())) / scale
    return (float(pts[:, 0].min()), float(pts[:, 1].min()), float(pts[:, 0].max()), float(pts[:, 1].max()))


def polygon_items(polygon: Polygon, pole: Pair, scale: float, height: float = 3.5,
                  names: Mapping[str, str | tuple[str, str] | list] | None = None,
                  taken: list[Box] | None = None, within: Box | None = None,
                  room: Room | None = None) -> list[Item]:
    """The polygon drawn from ``pole`` at μ = ``scale`` (its unit per mm): every vector as an
    arrow from its tail point to its head point, absolute ones thick, the others thin, and
    each point labelled (``names`` maps point keys to names: a part as ``sheet.symbol``
    takes it, or a list of parts; default the keys) clear of the arrows, of ``taken`` and
    inside ``within``, or in ``room`` (which then holds the arrows and labels for more)."""
    room = room or Room(within=within, taken=[] if taken is None else taken)
    at = {k: (pole[0] + x / scale, pole[1] + y / scale) for k, (x, y) in polygon.points.items()}
    items: list[Item] = []
    for v in polygon.vectors:
        layer = OUTLINE if v.role in ("absolute", "force") else THIN
        items += arrow(at[v.tail], at[v.head], layer)
    room.draw(items)
    room.name(at.values())
    centre = np.mean(np.array(list(at.values())), axis=0)

    def parts_of(key: str) -> list:
        name = (names or {}).get(key, key)
        return name if isinstance(name, list) else [name]

    for key, p in at.items():
        group = [k for k, q in at.items() if abs(q[0] - p[0]) < 0.05 and abs(q[1] - p[1]) < 0.05]
        if group[0] != key:                   # coincident points share one label
            continue
        away = np.asarray(p) - centre
        away = away if np.hypot(*away) > 1e-6 else np.array([1.0, 1.0])
        parts = [part for k in group for part in [","] + parts_of(k)][1:]
        text, spans = symbol(*parts)
        items += room.place(text, p, height, tuple(away), rings=5, subscripts=spans)   # crowded: left out
    return items


# ---- charts over the crank angle ---------------------------------------------------------

@dataclass(frozen=True)
class Curve:
    """One curve of a chart: y over the chart's x, in the chart's y unit."""

    y: np.ndarray
    layer: str = OUTLINE
    label: str = ""


@dataclass(frozen=True)
class Chart:
    """The items of a chart and what it was drawn at, for the caption and the tests."""

    items: list[Item]
    x_scale: float            # x units per mm
    y_scale: float            # y units per mm
    origin: Pair              # paper point of (x[0], 0)
    x_end: float              # paper x of the x axis' arrow tip
    y_end: float              # paper y of the y axis' arrow tip
    x_labels: tuple[str, ...] = ()   # each x tick's label as :func:`spaced_labels` kept it ("" left out)


def chart(box: Box, x: np.ndarray, curves: Sequence[Curve], x_title: str, y_title: str,
          x_ticks: Sequence[tuple[float, str]] = (), height: float = 3.5,
          mean: float | None = None,
          levels: Sequence[tuple[float, float, float]] = (),
          notes: Callable[[float, float], Sequence[str]] | None = None,
          below: float = 0.0) -> Chart:
    """Curves over ``x`` in ``box`` with a horizontal x axis through y = 0, a y axis at x[0],
    arrows on both, ticks at ``x_ticks`` (value, label) and a few round y ticks; ``mean`` a
    thin dashed horizontal line (e.g. the mean torque); ``levels`` (x from, x to, y) thin
    dashed segments over part of the span (e.g. an allowance over one phase), inside the
    y range like the curves; ``notes`` (x scale, y scale) → lines written under the y arrow's
    tip at the right (the scales μ), clear of the curves. Every text is placed after the lines,
    clear of them and a word space off each other (:mod:`labels`): the notes, the titles (first
    LABEL_GAP off the notes), then the tick numbers, as many as stand apart (:func:`spaced_labels`; a number a curve runs
    through goes beside its tick or above the axis, else is left out). Scales from
    the round series; the x axis keeps 14 mm of the box for its title, the y axis
    ``height``·6 mm for its tick labels, or more where the widest label needs it (a torque
    of 10⁵ N·m reads "-1.000e+05"); ``below`` mm more under the lowest curve, for a row of
    the caller's."""
    x0, y0, x1, y1 = box
    small = smaller_height(height)                  # the ticks' labels
    ys = np.concatenate([np.asarray(c.y, float).ravel() for c in curves]
                        + [[0.0], [lv[2] for lv in levels]])
    top, bottom = max(float(ys.max()), 0.0), min(float(ys.min()), 0.0)
    room = (y1 - y0) - 3.0 * height - 6.0 - below
    y_scale = nice_scale(max(top - bottom, 1e-12), room, FINE_MANTISSAS) if top > bottom else 1.0
    y_ticks = _round_ticks(bottom, top, y_scale, least_mm=2.0 * small)     # numbers a line apart at least
    widest = max((text_width(number_text(v), small) for v in y_ticks), default=0.0)
    left = x0 + max(6.0 * height, widest + TICK + 1.0 + 0.5)     # 0.5 mm clear of the box
    span_x = float(x[-1] - x[0])
    x_scale = nice_scale(span_x, x1 - left - 14.0, X_MANTISSAS)
    zero = y0 + 2.0 * height + 2.0 + below + (-bottom) / y_scale
    zero += ((y1 - height - 4.0) - (zero + top / y_scale)) / 2.0 if (top - bottom) > 0 else 0.0
    to_paper = lambda xv, yv: np.column_stack([left + (np.asarray(xv) - x[0]) / x_scale,  # noqa: E731
                                               zero + np.asarray(yv) / y_scale])
    x_end = left + span_x / x_scale + 8.0
    y_lo, y_hi = zero + bottom / y_scale - 2.0, zero + top / y_scale + 6.0
    items: list[Item] = [*arrow((left, zero), (x_end, zero), THIN),
                         *arrow((left, y_lo), (left, y_hi), THIN)]
    for c in curves:
        items.append(line(to_paper(x, c.y), c.layer))
    xs = [(left + (value - x[0]) / x_scale, label) for value, label in x_ticks]
    kept = spaced_labels(xs, small)
    items += [line([(px, zero - TICK), (px, zero + TICK)], THIN) for px, _ in xs]
    items += [line([(left - TICK, zero + v / y_scale), (left, zero + v / y_scale)], THIN) for v in y_ticks]
    if mean is not None:
        py = zero + mean / y_scale
        items.append(line([(left, py), (left + span_x / x_scale, py)], DASHED))
    for start, end, value in levels:
        py = zero + value / y_scale
        items.append(line([(left + (start - x[0]) / x_scale, py), (left + (end - x[0]) / x_scale, py)],
                          DASHED))
    room = Room(items, within=box)           # the labels after all the lines, clear of them
    for k, note in enumerate(notes(x_scale, y_scale) if notes else ()):
        # at the top under the y arrow's tip, at the right, else farther left or lines lower,
        # at last above the tip (a chart of a curve that is 0 throughout sits at its box's
        # foot: nothing lies under its tip); a note is the program's caption in the index
        # notation (sheet.marked: μ_s)
        plain, spans = marked(note)
        spots = [Text(plain, (x_end - f * (x_end - left), y_hi - 6.0 * (k + row)), height, "rt",
                      subscripts=spans)
                 for row in (*range(12), -1, -2, -3, -4) for f in (0.0, 0.15, 0.3, 0.45, 0.6, 0.75)]
        placed = room.first_free(spots)
        if placed is None:
            placed = spots[0]
            room.taken.append(placed.box())
        items.append(placed)
    # the titles beside their arrows' tips, else a line higher (or lower) where the curve ends there
    titles = ([Text(y_title, (left + 1.5, y_hi), height, "lt"), Text(y_title, (left - 1.5, y_hi), height, "rt")],
              [Text(x_title, (x_end, zero + side * (1.5 + k * 1.5 * height)), height, "rb" if side > 0 else "rt")
               for k in range(3) for side in (1, -1)])
    for spots in titles:                     # a title stands, before the ticks' numbers: at worst its first spot
        # first LABEL_GAP off the notes: "φ/(°)" 0.1 h under "μv = 0.08 (m/s)/mm" read as its second line
        placed = room.first_free(spots, label_gap(height)) or room.first_free(spots)
        if placed is None:
            placed = spots[0]
            room.taken.append(placed.box())
        items.append(placed)
    ticks_x = [px for px, _ in xs]
    for k, label in enumerate(kept):         # under the tick, beside it, or over the axis
        px = ticks_x[k]
        below, above = zero - TICK - 1.0, zero + TICK + 1.0
        spots = [Text(label, (sx, sy), small, al) for sx, sy, al in
                 ((px, below, "ct"), (px + 0.5, below, "lt"), (px - 0.5, below, "rt"),
                  (px, above, "cb"), (px + 0.5, above, "lb"), (px - 0.5, above, "rb"))]
        # beside its tick, a number stays nearer its own tick than the next: else it is read
        # as the neighbour's
        lo = (ticks_x[k - 1] + px) / 2.0 if k else -math.inf
        hi = (px + ticks_x[k + 1]) / 2.0 if k + 1 < len(ticks_x) else math.inf
        spots = [t for t in spots if t.align[0] == "c" or lo <= t.box()[0] and t.box()[2] <= hi]
        placed = room.first_free(spots) if label else None
        items += [placed] if placed else []
    for value in y_ticks:
        if abs(value) > 0:
            placed = room.first_free([Text(number_text(value), (left - TICK - 1.0, zero + value / y_scale),
                                           small, "rm")])
            items += [placed] if placed else []
    return Chart(items, x_scale, y_scale, (left, zero), x_end, y_hi, tuple(kept))


def spaced_labels(ticks: Sequence[tuple[float, str]], height: float) -> list[str]:
    """The labels of ``ticks`` (paper x, label) a row under them keeps, "" for one left out:
    each centred under its tick, ``height`` high, a word space (``core.base.lettering.word_gap``) off its
    neighbours, else "105120135" reads as one number. Where they do not all stand apart,
    evenly spaced ticks keep every k-th label from the first, the smallest k that leaves the
    space (every second, every third …: a drafter's way with a crowded scale); uneven ones
    (a cam's phase edges) each label that stands apart from the last one kept. The ticks
    themselves all stay: the caller draws them."""
    labels = [label for _, label in ticks]
    boxes = [Text(label, (px, 0.0), height, "ct").box() if label else None for px, label in ticks]
    gap = word_gap(height)

    def apart(first: int, second: int) -> bool:
        return boxes[second][0] - boxes[first][2] >= gap - 1e-9

    steps = np.diff([px for px, _ in ticks])
    if len(steps) > 1 and np.allclose(steps, steps[0], rtol=1e-6):
        for k in range(1, len(ticks) + 1):
            shown = [i for i in range(0, len(ticks), k) if labels[i]]
            if all(apart(a, b) for a, b in zip(shown, shown[1:])):
                return [label if i % k == 0 else "" for i, label in enumerate(labels)]
    kept, last = [], None
    for i, label in enumerate(labels):
        stands = bool(label) and (last is None or apart(last, i))
        kept.append(label if stands else "")
        last = i if stands else last
    return kept


def scale_notes(y_note: str, x_note: str | None = None, y_unit: float = 1.0
                ) -> Callable[[float, float], list[str]]:
    """A chart's ``notes``: its y scale (times ``y_unit``) written into ``y_note``'s {mu}, and
    its x scale into ``x_note``'s, if given."""
    return lambda mx, my: ([y_note.format(mu=number_text(my * y_unit))]
                           + ([x_note.format(mu=number_text(mx))] if x_note else []))


def _round_ticks(lo: float, hi: float, scale: float, every_mm: float = 20.0, least_mm: float = 0.0) -> list[float]:
    """Round values between lo and hi about every ``every_mm`` of paper (the step of the 1, 2,
    5 series at or above it); where that leaves no value but 0 in the range, the next finer
    steps, no less than ``least_mm`` apart, until one is there: a reader reads a value off a
    numbered tick. A3's torque chart, 21 mm high at μM = 40 (N·m)/mm, was ticked every
    1000 N·m up to 851 N·m and numbered nothing."""
    step = nice_scale(scale * every_mm, 1.0, (1.0, 2.0, 5.0))
    ticks = _ticks(lo, hi, step)
    while not any(ticks) and _finer(step) / scale >= least_mm and lo < hi:
        step = _finer(step)
        ticks = _ticks(lo, hi, step)
    return ticks


def _ticks(lo: float, hi: float, step: float) -> list[float]:
    """The multiples of ``step`` from lo to hi."""
    first = math.ceil(lo / step - 1e-9)
    last = math.floor(hi / step + 1e-9)
    return [k * step for k in range(first, last + 1)]


def _finer(step: float) -> float:
    """The step of the 1, 2, 5 series below ``step`` (one of it)."""
    power = 10.0 ** math.floor(math.log10(step) + 1e-9)
    return {1: 0.5, 2: 1.0, 5: 2.0}[round(step / power)] * power


# ---- a polygon's vector equations and magnitudes, beside it -------------------------------

def vector_text(keys: Sequence[str], joins: Sequence[str], position: Pair, height: float,
                align: str = "lb") -> Text:
    """The vectors ``keys`` (core's names: "a^k_A4A3" is a, index A4A3, superscript k after
    it) written one after another with ``joins`` between them (one fewer), as one text."""
    text, subs, sups = "", [], []
    for i, key in enumerate(keys):
        base, _, index = key.partition("_")
        base, _, sup = base.partition("^")
        text += base
        if index:
            subs.append((len(text), len(text) + len(index)))
            text += index
        if sup:
            sups.append((len(text), len(text) + len(sup)))
            text += sup
        if i < len(joins):
            text += joins[i]
    return Text(text, position, height, align, subscripts=tuple(subs), superscripts=tuple(sups))


def vector_equations(polygon: Polygon) -> list[tuple[list[str], list[str]]]:
    """The vector equations the polygon draws, as (left keys, right keys): at each point two
    chains of vectors from the pole meet (v_A4 = v_A3 + v_A4A3; a^n_A4 + a^t_A4 = a_A3 +
    a^k_A4A3 + a^r_A4A3), the shorter chain on the left. Read off the polygon itself, so a
    variant's own vectors (the rod's, the block's) give its own equations."""
    pole = polygon.vectors[0].tail if polygon.vectors else ""
    into: dict[str, list] = {}
    for v in polygon.vectors:
        into.setdefault(v.head, []).append(v)

    def chain(v) -> list[str]:
        keys, seen = [v.key], {v.head}
        while v.tail != pole and v.tail in into and v.tail not in seen:
            seen.add(v.tail)
            v = into[v.tail][0]
            keys.insert(0, v.key)
        return keys

    out = []
    for head, vectors in into.items():
        if len(vectors) >= 2:
            chains = sorted((chain(v) for v in vectors[:2]), key=len)
            out.append((chains[0], chains[1]))
    return out


def polygon_notes(polygon: Polygon, corner: Pair, height: float) -> list[Text]:
    """Beside a polygon, from ``corner`` (its top left) down: its vector equations, then each
    vector's magnitude (v_A2 = 0.6912 m/s), as the report lists them (4 significant digits)."""
    x, y = corner
    rows: list[Text] = []
    for left, right in vector_equations(polygon):
        rows.append(vector_text(left + right, [" + "] * (len(left) - 1) + [" = "] + [" + "] * (len(right) - 1),
                                (0.0, 0.0), height))
    equations = len(rows)
    floor = 1e-9 * polygon.largest()
    for v in polygon.vectors:
        value = v.magnitude if v.magnitude > floor else 0.0
        label = vector_text([v.key], [], (0.0, 0.0), height)
        rows.append(Text(f"{label.text} = {value:.4g} {polygon.unit}", (0.0, 0.0), height, "lb",
                         subscripts=label.subscripts, superscripts=label.superscripts))
    items: list[Text] = []
    top = y
    for k, row in enumerate(rows):          # stacked by their boxes (a superscript reaches higher)
        box = row.box()
        top -= 0.5 * height if k == equations and k else 0.0
        at = (x, top - (box[3] - row.position[1]))
        items.append(Text(row.text, at, height, "lb", subscripts=row.subscripts, superscripts=row.superscripts))
        top = at[1] - (row.position[1] - box[1]) - 0.3
    return items
