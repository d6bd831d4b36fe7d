"""The tool path's numbers on the motion sheet: 1 … N at the ram's positions, as the crank's.

Each number stands at its tick on the tool's path, spread along it so that no two meet;
where a line or circle crosses every spot near the tick (the lever's positions run through
a crowded path), it goes to the nearest free spot farther along the path and is led to its
tick by a thin line, which runs through no text.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from core.linkage.geometry import Design

from . import mechanism as mech
from . import sheet_dims as sd
from .dxf import THIN
from .segments import boxes_meet_strokes, crossings_each, strokes
from .sheet import Box, Item, Placement, Text, line

NUMBER_MM = 2.5           # the tool path's numbers
NUMBER_PAD = 0.6          # between two numbers side by side (``spread`` keeps 0.8)
FAR_SHIFTS = 16           # how many widths along the path a crowded number may move, either way


def spread(ideal: np.ndarray, widths: np.ndarray, pad: float = 0.8) -> np.ndarray:
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
        options = _spots(str(k + 1), x0, [x1], rows, taken, within, segs, led_clear, by_rank=True)
        if not options or options[0][0] > 0:
            shifts = [x1 + s * (w + 0.8) for n in range(1, FAR_SHIFTS + 1) for s in (n, -n)]
            farther = _spots(str(k + 1), x0, shifts, far_rows, taken, within, segs, led_clear)
            if farther and farther[0][0] == 0:
                options = farther
        if not options:
            continue
        _, _, text, box, tick, end = options[0]
        taken.append(box)
        led_clear.append(box)
        out.append(text)
        segs = np.vstack([segs, strokes([text])])
        if abs(text.position[0] - x0) > 0.3 or text.position[1] < y - 4.5 or text.position[1] > y + 2.5:
            lead = line([(x0, tick), (text.position[0], end)], THIN)
            out.append(lead)
            segs = np.vstack([segs, strokes([lead])])
    return out


def _spots(number: str, x0: float, centres: Sequence[float], rows, taken: Sequence[Box],
           within: Box, segs: np.ndarray, led_clear: Sequence[Box], by_rank: bool = False) -> list[tuple]:
    """The tool path's number at each of ``centres`` in each of ``rows`` (y, alignment, the
    tick's end its leader starts at) that meets no taken box and lies within the drawing,
    as (crossed, (leader's crossings, rank), text, box, tick, end), best first: those whose
    box no line crosses and whose leader runs through none of ``led_clear`` first, then the leader
    crossing the fewest lines (in the order given; ``by_rank``: the first row, the
    leader's crossings not counted)."""
    found = []
    taken_boxes = np.asarray(taken, dtype=float).reshape(-1, 4)
    for rank, (cx, (row, align, tick)) in enumerate((cx, r) for cx in centres for r in rows):
        text = Text(number, (float(cx), row), NUMBER_MM, align)
        box = text.box()
        end = box[3] if align == "ct" else box[1]      # the box's edge toward the path
        found.append((rank, text, box, tick, end, (box[0] - NUMBER_PAD, box[1], box[2] + NUMBER_PAD, box[3])))
    if not found:
        return []
    boxes, apart = np.array([f[2] for f in found]), np.array([f[5] for f in found])    # "2" "3" is not "23"
    keep = ~((apart[:, None, 0] < taken_boxes[:, 2]) & (taken_boxes[:, 0] < apart[:, None, 2])
             & (apart[:, None, 1] < taken_boxes[:, 3]) & (taken_boxes[:, 1] < apart[:, None, 3])).any(axis=1)
    keep &= ((within[0] <= boxes[:, 0]) & (boxes[:, 2] <= within[2]) & (within[1] <= boxes[:, 1])
             & (boxes[:, 3] <= within[3]))
    found = [f for f, k in zip(found, keep) if k]
    if not found:
        return []
    segs_led = np.array([(x0, tick, float(text.position[0]), end) for _, text, _, tick, end, _ in found])
    through = sd.crossing(np.asarray(led_clear, float), segs_led).any(axis=0)
    # a leader through a text crosses it
    crossed = boxes_meet_strokes(boxes[keep], segs).astype(int) + through.astype(int)
    led = np.zeros(len(found), dtype=int) if by_rank else crossings_each(segs_led, segs)
    options = [(int(c), (int(n), rank), text, box, tick, end)
               for c, n, (rank, text, box, tick, end, _) in zip(crossed, led, found)]
    return sorted(options, key=lambda o: (o[0], o[1]))

