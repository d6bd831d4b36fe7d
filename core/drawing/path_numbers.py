"""The tool path's numbers on the motion sheet: 1 … N at the ram's positions, as the crank's.

Each number stands at its tick on the tool's path, spread along it so that no two meet;
where a line or circle crosses every spot near the tick (the lever's positions run through
a crowded path), it goes to the nearest free spot farther along the path and is led to its
tick by a thin line, which runs through no text.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from core.base.lettering import word_gap
from core.linkage.geometry import Design

from . import mechanism as mech
from . import sheet_dims as sd
from .dxf import THIN
from .labels import moved_boxes
from .segments import boxes_meet_strokes, crossings_each, strokes
from .sheet import Box, Item, Placement, Text, line

NUMBER_MM = 2.5           # the tool path's numbers
NUMBER_PAD = word_gap(NUMBER_MM)   # between two numbers side by side: "2" "3" is not "23"
FAR_SHIFTS = 16           # how many widths along the path a crowded number may move, either way


def spread(ideal: np.ndarray, widths: np.ndarray, pad: float = NUMBER_PAD) -> np.ndarray:
    """Centres as near ``ideal`` (sorted) as they can be with neighbours ``widths`` wide
    ``pad`` apart: overlapping neighbours are pooled into a cluster centred on the mean of
    their wishes (least squares), until none overlap."""
    clusters: list[list[int]] = []              # [first, last] indices
    centre = np.array(ideal, dtype=float)
    edges = np.concatenate([[0.0], np.cumsum(widths[:-1] / 2.0 + widths[1:] / 2.0 + pad)])

    def place(first: int, last: int) -> None:
        run = slice(first, last + 1)
        start = float(np.mean(ideal[run] - (edges[run] - edges[first])))
        centre[run] = start + edges[run] - edges[first]

    for k in range(len(ideal)):
        clusters.append([k, k])
        place(k, k)
        while len(clusters) > 1:
            (f0, l0), (f1, l1) = clusters[-2], clusters[-1]
            if centre[f1] - centre[l0] >= (widths[l0] + widths[f1]) / 2.0 + pad - 1e-9:
                break
            clusters[-2:] = [[f0, l1]]
            place(f0, l1)
    return centre


def tool_path_numbers(design: Design, place: Placement, crank_deg: np.ndarray,
                      drawn: Sequence[Item], taken: list[Box], within: Box,
                      tiles: Sequence[Box] | None = None) -> list[Item]:
    """1 … N at the tool path's ticks, spread along the path so that no two meet, each in the
    first row (under the path, over it, then farther under) where it meets none of ``taken``
    and no line or circle of ``drawn`` (labels' clearance), led to its tick by a thin line
    when it had to move; where every row's spot near the tick is crossed (the levers run
    through a crowded path), the nearest free spot farther along the path, under or over
    it, with its leader from the tick crossing the fewest lines (else the least crossed
    spot, as before). ``tiles``: what the leaders must not run through, the taken boxes
    with a tilted text's as :func:`.mechanism_dims.text_tiles` (default ``taken``)."""
    led_clear = list(taken if tiles is None else tiles)
    c = place(mech.joints(design, np.linspace(0.0, 360.0, 721))["C"].T)
    y = float(c[0, 1]) - mech.TOOL_DROP
    xs = place(mech.joints(design, np.asarray(crank_deg, dtype=float))["C"].T)[:, 0] + mech.TOOL_AHEAD
    order = np.argsort(xs, kind="stable")
    widths = np.array([Text(str(k + 1), (0.0, 0.0), NUMBER_MM).width for k in order])
    at = spread(xs[order], widths)
    at += max(0.0, within[0] + widths[0] / 2.0 - at[0]) - max(0.0, at[-1] + widths[-1] / 2.0 - within[2])
    segs = strokes(drawn)
    rows = [(y - 4.0, "ct", y - 1.5), (y + 2.2, "cb", y + 1.5)]
    rows += [(y - 4.0 - k * 1.5 * NUMBER_MM, "ct", y - 1.5) for k in range(1, 9)]
    far_rows = rows + [(y + 2.2 + k * 1.5 * NUMBER_MM, "cb", y + 1.5) for k in range(1, 9)]
    out: list[Item] = []
    for k, x0, x1, w in zip(order, xs[order], at, widths):   # rows are apart: one row's numbers can meet
        best = _best_spot(str(k + 1), x0, [x1], rows, taken, within, segs, led_clear, by_rank=True)
        if best is None or best[0] > 0:
            shifts = [x1 + s * (w + NUMBER_PAD) for n in range(1, FAR_SHIFTS + 1) for s in (n, -n)]
            farther = _best_spot(str(k + 1), x0, shifts, far_rows, taken, within, segs, led_clear)
            if farther is not None and farther[0] == 0:
                best = farther
        if best is None:
            continue
        _, _, text, box, tick, end = best
        taken.append(box)
        led_clear.append(box)
        out.append(text)
        segs = np.vstack([segs, strokes([text])])
        if abs(text.position[0] - x0) > 0.3 or text.position[1] < y - 4.5 or text.position[1] > y + 2.5:
            lead = line([(x0, tick), (text.position[0], end)], THIN)
            out.append(lead)
            segs = np.vstack([segs, strokes([lead])])
    return out


def _best_spot(number: str, x0: float, centres: Sequence[float], rows, taken: Sequence[Box],
               within: Box, segs: np.ndarray, led_clear: Sequence[Box], by_rank: bool = False) -> tuple | None:
    """The best spot for the tool path's number among each of ``centres`` in each of ``rows``
    (y, alignment, the tick's end its leader starts at) that meets no taken box and lies
    within the drawing, as (crossed, (leader's crossings, rank), text, box, tick, end); None
    if there is none. Best: its box crossed by no line and its leader through none of
    ``led_clear``, then the leader crossing the fewest lines, then the first in the order
    given (``by_rank``: the first, the leader's crossings not counted). The leaders'
    crossings are counted only for the spots crossed least, the only ones that can be best:
    the far search tries some 600 spots a number, most of them crossed, and counting every
    leader's crossings with every line of the sheet was a fifth of a crowded motion sheet
    (docs/performance.md)."""
    xs = np.repeat(np.asarray(centres, dtype=float), len(rows))
    ys = np.tile([row for row, _, _ in rows], len(centres)).astype(float)
    ticks = np.tile([tick for _, _, tick in rows], len(centres)).astype(float)
    tops = np.tile([align == "ct" for _, align, _ in rows], len(centres))
    at_origin = np.array([Text(number, (0.0, 0.0), NUMBER_MM, align).box() for align in ("cb", "ct")])
    boxes = moved_boxes(at_origin[tops.astype(int)], xs, ys)       # every spot's Text.box
    apart = boxes + np.array([-NUMBER_PAD, 0.0, NUMBER_PAD, 0.0])        # "2" "3" is not "23"
    taken_boxes = np.asarray(taken, dtype=float).reshape(-1, 4)
    keep = ~((apart[:, None, 0] < taken_boxes[:, 2]) & (taken_boxes[:, 0] < apart[:, None, 2])
             & (apart[:, None, 1] < taken_boxes[:, 3]) & (taken_boxes[:, 1] < apart[:, None, 3])).any(axis=1)
    keep &= ((within[0] <= boxes[:, 0]) & (boxes[:, 2] <= within[2]) & (within[1] <= boxes[:, 1])
             & (boxes[:, 3] <= within[3]))
    rank = np.flatnonzero(keep)
    if not len(rank):
        return None
    ends = np.where(tops[rank], boxes[rank, 3], boxes[rank, 1])      # the box's edge toward the path
    segs_led = np.column_stack([np.full(len(rank), x0), ticks[rank], xs[rank], ends])
    through = sd.crossing(np.asarray(led_clear, float), segs_led).any(axis=0)
    # a leader through a text crosses it
    crossed = boxes_meet_strokes(boxes[rank], segs).astype(int) + through.astype(int)
    least = np.flatnonzero(crossed == crossed.min())
    led = np.zeros(len(least), dtype=int) if by_rank else crossings_each(segs_led[least], segs)
    j = int(np.lexsort((rank[least], led))[0])          # the fewest crossings, then the first
    k, r = int(least[j]), int(rank[least[j]])
    text = Text(number, (float(xs[r]), float(ys[r])), NUMBER_MM, "ct" if tops[r] else "cb")
    return int(crossed[k]), (int(led[j]), r), text, text.box(), float(ticks[r]), float(ends[k])
