"""The mechanism's linework for a sheet: links at a crank angle, to scale, as items.

Joints come from :func:`core.linkage.kinematics.shape` (exact), so a length on the paper
divided by the placement's scale is the design's. Symbols that are not design
data (pivot supports, slider blocks, the ram, the tool) have fixed sizes in
paper mm, as a hand drawing's would: they look the same at 1:2 and at 1:20 and
never change a dimension. Model coordinates are :mod:`core.linkage.geometry`'s (O4 at
the origin, O2 above it, the ram guide at y = guide, the cut toward +x).
"""
from __future__ import annotations

import math
from typing import Callable, Sequence

import numpy as np

from core.linkage.geometry import Design
from core.linkage.kinematics import shape

from .dxf import CENTER, OUTLINE, THIN
from .sheet import Box, Circle, Item, Pair, Placement, line, symbol

PIN_RADIUS = 1.5            # paper mm
BLOCK = (10.0, 6.0)         # slider block along × across its slide, paper mm
RAM = (36.0, 8.0)           # ram body on the guide, paper mm
SUPPORT = 6.0               # height of a pivot's support triangle, paper mm
TOOL_DROP = 10.0            # the tool's point below the guide line, paper mm
TOOL_AHEAD = 14.0           # … ahead of the ram joint C, paper mm


def joints(design: Design, crank_deg) -> dict[str, np.ndarray]:
    """O2, O4, A, B, C in model mm at the crank angles ``crank_deg`` (scalar or (n,)):
    arrays of shape (2,) or (2, n). C is the point of the ram above B (block variant) or the
    rod's end on the guide."""
    phi = np.radians(np.atleast_1d(np.asarray(crank_deg, dtype=float)))
    sh = shape(design, phi)
    squeeze = np.ndim(crank_deg) == 0
    pick = (lambda a: a[:, 0]) if squeeze else (lambda a: a)
    n = phi.size
    o2 = np.array([[0.0] * n, [design.frame] * n])
    return {"O2": pick(o2), "O4": pick(np.zeros((2, n))), "A": pick(sh.crank_pin),
            "B": pick(sh.lever_tip), "C": pick(sh.ram_joint)}


def bounds(design: Design) -> Box:
    """Model extent of the linework over a whole cycle (links, supports' pivots, C's travel),
    without the fixed-size symbols: what must fit the drawing's box at its scale."""
    j = joints(design, np.linspace(0.0, 360.0, 721))
    pts = np.concatenate([j[k] for k in ("A", "B", "C")], axis=1)
    xs = np.concatenate([pts[0], [0.0, -design.crank, design.crank]])
    ys = np.concatenate([pts[1], [0.0, design.frame + design.crank]])
    return (float(xs.min()), float(ys.min()), float(xs.max()), float(ys.max()))


def _block(center: np.ndarray, along: np.ndarray, size: tuple[float, float], layer: str) -> Item:
    u = along / math.hypot(*along)
    v = np.array([-u[1], u[0]])
    a, b = size[0] / 2.0, size[1] / 2.0
    corners = [center + sa * a * u + sb * b * v for sa, sb in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    return line(corners, layer, closed=True)


def _pin(p: np.ndarray, layer: str) -> Item:
    return Circle((float(p[0]), float(p[1])), PIN_RADIUS, layer)


def support(p: np.ndarray) -> list[Item]:
    """A fixed pivot at paper point ``p``: triangle, ground line and hatching (thin)."""
    x, y = float(p[0]), float(p[1])
    base = y - SUPPORT
    items: list[Item] = [line([(x - 3.5, base), (x, y - PIN_RADIUS), (x + 3.5, base)], THIN),
                         line([(x - 6.0, base), (x + 6.0, base)], THIN)]
    for hx in np.linspace(x - 4.5, x + 6.0, 6):
        items.append(line([(hx, base), (hx - 2.0, base - 2.0)], THIN))
    return items


def frame_items(design: Design, where: Placement, x_range: tuple[float, float] | None = None
                ) -> list[Item]:
    """What does not move: the pivots O2 and O4 with their supports, the crank pin's
    circle (centre line), the guide line (centre line) over the ram's travel."""
    j = joints(design, np.linspace(0.0, 360.0, 721))
    o2, o4 = where([0.0, design.frame]), where([0.0, 0.0])
    items: list[Item] = [*support(o4), *support(o2),
                         Circle((float(o2[0]), float(o2[1])), where.length(design.crank), CENTER)]
    c = j["C"][0]
    lo, hi = x_range if x_range else (float(c.min()), float(c.max()))
    g0, g1 = where([lo, design.guide]), where([hi, design.guide])
    items.append(line([(g0[0] - RAM[0] / 2.0 - 6.0, g0[1]),
                       (g1[0] + RAM[0] / 2.0 + TOOL_AHEAD + 6.0, g1[1])], CENTER))
    return items


def links_at(design: Design, crank_deg: float, where: Placement, layer: str = OUTLINE,
             bodies: bool = True) -> list[Item]:
    """The moving links at one crank angle: crank O2A, the block at A, lever O4B, the block
    at B in the ram's slot (block variant) or the rod BC (rod variant), the ram and its
    tool, with the pins. ``layer`` OUTLINE for a position drawn thick, THIN for the others;
    ``bodies`` False draws the links' centre lines and the moving pins only (the many
    intermediate positions of a motion diagram)."""
    j = {k: where(v) for k, v in joints(design, float(crank_deg)).items()}
    o2, o4, a, b, c = j["O2"], j["O4"], j["A"], j["B"], j["C"]
    items: list[Item] = [line([o2, a], layer), line([o4, b], layer)]
    if not bodies:
        if design.rod is not None:
            items += [line([b, c], layer), _pin(c, layer)]
        return items + [_pin(a, layer), _pin(b, layer)]
    items.append(_block(a, b - o4, BLOCK, layer))
    if design.rod is None:
        items.append(_block(b, np.array([0.0, 1.0]), BLOCK, layer))
        ram_at = np.array([b[0], c[1]])
        # the ram's vertical slot through B, reaching the ram body
        top = max(b[1], c[1]) + RAM[1] / 2.0
        bottom = min(b[1], c[1]) - RAM[1] / 2.0
        items += [line([(b[0] - BLOCK[1] / 2.0 - 0.8, bottom), (b[0] - BLOCK[1] / 2.0 - 0.8, top)], layer),
                  line([(b[0] + BLOCK[1] / 2.0 + 0.8, bottom), (b[0] + BLOCK[1] / 2.0 + 0.8, top)], layer)]
    else:
        ram_at = c
        items += [line([b, c], layer), _pin(c, layer)]
    items += ram_items(ram_at, layer)
    items += [_pin(a, layer), _pin(b, layer), _pin(o2, layer), _pin(o4, layer)]
    return items


def ram_body(c: np.ndarray) -> tuple[float, float, float, float]:
    """The ram body's box (x0, y0, x1, y1) on the paper for the ram at paper point ``c``."""
    x, y = float(c[0]), float(c[1])
    return x - RAM[0] / 2, y - RAM[1] / 2, x + RAM[0] / 2, y + RAM[1] / 2


def ram_items(c: np.ndarray, layer: str) -> list[Item]:
    """The ram on the guide at paper point ``c`` and the tool hanging under its front."""
    x0, y0, x1, y1 = ram_body(c)
    y, h = float(c[1]), RAM[1]
    body = line([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], layer, closed=True)
    tx, ty = tool_point(c)
    tool = line([(tx - 3.0, y - h / 2), (tx - 3.0, ty + 3.0), (tx, ty), (tx + 1.5, y - h / 2)], layer)
    return [body, tool]


def tool_point(c: np.ndarray) -> Pair:
    """The tool's point for the ram joint at paper point ``c``: the tool path is C's path
    shifted by this fixed offset (the tool is rigid with the ram)."""
    return float(c[0]) + TOOL_AHEAD, float(c[1]) - TOOL_DROP


def tool_path(design: Design, where: Placement, crank_deg: np.ndarray) -> list[Item]:
    """The tool point's path (a thin line between the two extremes of its travel) with a
    tick at each of the crank angles ``crank_deg``."""
    c = where(joints(design, np.linspace(0.0, 360.0, 721))["C"].T)
    xs = c[:, 0] + TOOL_AHEAD
    y = float(c[0, 1]) - TOOL_DROP
    items: list[Item] = [line([(xs.min(), y), (xs.max(), y)], THIN)]
    marks = where(joints(design, np.asarray(crank_deg, dtype=float))["C"].T)
    for x in marks[:, 0] + TOOL_AHEAD:
        items.append(line([(x, y - 1.5), (x, y + 1.5)], THIN))
    return items


def joint_anchors(design: Design, crank_deg: float, where: Placement, height: float = 5.0
                  ) -> list[tuple[str, tuple[tuple[int, int], ...], np.ndarray, np.ndarray]]:
    """O2, O4, A, B, C (rod variant) at one crank angle as (text, subscripts, the joint on
    the paper, the direction to label it in): of eight directions, the one whose spot
    ``height``-dependent reach away is farthest from the links and the guide line there.
    The label itself is placed by :mod:`core.drawing.labels` against the whole drawing."""
    j = {k: where(v) for k, v in joints(design, float(crank_deg)).items()}
    segments = [(j["O2"], j["A"]), (j["O4"], j["B"]),
                (j["C"] - [RAM[0], 0.0], j["C"] + [RAM[0] + TOOL_AHEAD, 0.0])]
    if design.rod is not None:
        segments.append((j["B"], j["C"]))
    names = {"O2": ("O", "2"), "O4": ("O", "4"), "A": "A", "B": "B"}
    if design.rod is not None:
        names["C"] = "C"
    reach = 3.5 + 1.2 * height
    anchors = []
    for key, name in names.items():
        text, spans = symbol(name)
        p = j[key]
        ways = [np.array([math.cos(a), math.sin(a)]) for a in np.radians(np.arange(0.0, 360.0, 45.0))]
        best = max(ways, key=lambda u: min(_distance(p + reach * u, s0, s1) for s0, s1 in segments))
        anchors.append((text, spans, p, best))
    return anchors


CLEAR = 6.0                 # paper mm from a link number to the nearest line or name that is enough
LINK_NUMBERS = {"crank": "2", "block": "3", "lever": "4", "rod": "5", "ram": "6"}


def link_anchors(design: Design, crank_deg: float, where: Placement, reach: float,
                 avoid: Sequence[np.ndarray] = (),
                 free: Callable[[np.ndarray, np.ndarray, str], bool] | None = None
                 ) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """The links' numbers of the task book (crank 2, block 3, lever 4, rod 5 or, in the block
    variant, the block at B in the ram's slot 5, ram 6; seed 003's 4, one lower) at one
    crank angle as (number, the point on the link its leader starts at, the offset from it
    to the number): of eight directions at ``reach`` or 1.6 ``reach`` (2.2 for the block at B,
    which the ram's body boxes in), the spot farthest from
    the links, the ram and the points in ``avoid`` (the joints' names, the numbers placed
    before), the shorter leader when both are CLEAR; so that a student reads the sketch in
    the book's numbering. With ``free`` (the leader's start, the spot, the number → whether
    the number there and its leader are clear of the rest of the drawing: the crank's circle,
    the frame's hatching, the joints' names, a caption), a free spot before any other."""
    j = {k: where(v) for k, v in joints(design, float(crank_deg)).items()}
    x0, y0, x1, y1 = ram_body(j["C"])
    body = [np.array(p) for p in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
    segments = [(j["O2"], j["A"]), (j["O4"], j["B"])] + [(body[k], body[k - 1]) for k in range(4)]
    if design.rod is not None:
        segments.append((j["B"], j["C"]))
    along = (j["B"] - j["O4"]) / max(float(np.hypot(*(j["B"] - j["O4"]))), 1e-9)
    spots = {"crank": (j["O2"] + j["A"]) / 2.0}
    if design.rod is None:      # link 5, the block at B, boxed in by the ram: before the others
        spots["rod"] = j["B"] + [0.0, BLOCK[0] / 4.0]
    spots.update({"block": j["A"] + along * (BLOCK[0] / 2.0), "lever": j["O4"] + 0.3 * (j["B"] - j["O4"]),
                  "ram": np.array([x0 + 0.3 * RAM[0], y1])})
    if design.rod is not None:
        spots["rod"] = (j["B"] + j["C"]) / 2.0
    ways = [np.array([math.cos(a), math.sin(a)]) for a in np.radians(np.arange(0.0, 360.0, 45.0))]
    offsets = [u * r for r in (reach, 1.6 * reach) for u in ways]     # a longer leader where crowded
    anchors = []
    for link, p in spots.items():
        def score(offset: np.ndarray) -> float:
            at = p + offset
            room = min([_distance(at, s0, s1) for s0, s1 in segments]
                       + [float(np.hypot(*(at - q))) for q in avoid])
            blocked = free is not None and not free(p, at, LINK_NUMBERS[link])
            return min(room, CLEAR) - 1e-3 * float(np.hypot(*offset)) - (100.0 if blocked else 0.0)
        # the block at B sits inside the ram: its number may need a leader out of the ram's body
        farther = [u * 2.2 * reach for u in ways] if link == "rod" and design.rod is None else []
        best = max(offsets + farther, key=score)
        anchors.append((LINK_NUMBERS[link], p, best))
        avoid = [*avoid, p + best]
    return anchors


def _distance(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    """From point ``p`` to the segment ``a``–``b``."""
    d = b - a
    t = float(np.clip(np.dot(p - a, d) / max(float(np.dot(d, d)), 1e-12), 0.0, 1.0))
    return float(np.hypot(*(p - a - t * d)))
