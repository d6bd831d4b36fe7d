"""The mechanism for CAD: the scheme at 1:1 in model space, with live dimensions.

A designer carries the mechanism on into part design in a CAD program, so this
drawing is geometry first: every point is core's (``core.linkage.kinematics.shape`` at
the chosen crank angle and at the two limit positions), in core's frame (the
lever pivot O4 at the origin, O2 straight above it, the ram guide horizontal,
cutting toward +x), in millimetres at 1:1. The link lengths L1, L2, L3, L4, the
guide height h above O2, the stroke H and the swing θ are DIMENSION entities
between those points, so CAD measures them itself.

Sizes that are no design data (pins, blocks, the ram's body, the tool, the
ground symbols) scale with the unit ``u = L3 / 40``, as on screen; texts and
arrows scale with the print scale (see :mod:`core.drawing.dimensions`).

Its texts are TEXT in the GB style and CAD's own measurements, or (``cad_font`` "outline",
for LibreCAD, which leaves out θ) every one as filled outlines (:mod:`core.drawing.outline_text`).
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, replace

import numpy as np
from ezdxf import bbox
from ezdxf.document import Drawing
from ezdxf.enums import TextEntityAlignment

from core.base.errors import DesignError, require_range
from core.base.figure_text import dimension_text
from core.linkage.geometry import Design
from core.linkage.kinematics import shape
from . import dimensions as dims
from .dxf import CENTER, DASHED, OUTLINE, THIN, new_document, save_dxf, text_attribs
from .labels import boxes_meet
from .outline_text import ATTACHMENTS, add_outline_text, outline_dimension_texts
from .sheet import Text, text_width

UNITS_PER_LEVER = 40.0       # u = L3 / 40
ROOM_MM = dims.A3_ROOM_MM    # an A3 sheet's drawing area: the scale a print would use
LABEL_MM = 5.0               # joint names on paper
PIN_FIXED, PIN_MOVING = 0.5, 0.38   # pin radii, u


@dataclass(frozen=True)
class Pose:
    """The mechanism at one crank angle, and what the drawing needs of its cycle, mm."""

    o2: np.ndarray            # crank centre (0, L2)
    a: np.ndarray             # crank pin
    b: np.ndarray             # lever tip
    c: np.ndarray             # ram joint on the guide line (above B for the block variant)
    lever_limits: np.ndarray  # (2, 2) the lever tip at φ = 0 and at φ = 180° + θ
    pin_limits: np.ndarray    # (2, 2) the crank pin there
    ram_limits: np.ndarray    # (2,) x of the ram joint there
    u: float


def check_angle(angle_deg: object) -> float:
    """A crank angle for the scheme, 0 … 360° (φ of the README's conventions)."""
    return require_range("angle", angle_deg, 0.0, 360.0, "°", low_open=False)


def pose(design: Design, angle_deg: float) -> Pose:
    """core's positions at ``angle_deg`` and at the two limit positions."""
    phi = np.array([math.radians(angle_deg), 0.0, math.pi + design.theta])
    sh = shape(design, phi)
    return Pose(o2=np.array([0.0, design.frame]), a=sh.crank_pin[:, 0], b=sh.lever_tip[:, 0],
                c=sh.ram_joint[:, 0], lever_limits=sh.lever_tip[:, 1:].T,
                pin_limits=sh.crank_pin[:, 1:].T, ram_limits=sh.ram_joint[0, 1:],
                u=design.lever / UNITS_PER_LEVER)


def scheme_document(design: Design, angle_deg: float = 0.0, cad_font: str = "gb") -> Drawing:
    """The mechanism at crank angle ``angle_deg`` (0 … 360°) as a DXF document, its texts
    in ``cad_font`` (``core.drawing.CAD_FONTS``): "gb" as TEXT and live dimension texts,
    "outline" as their glyphs' outlines (OutlineFontMissing without a CJK font)."""
    angle = check_angle(angle_deg)
    p = pose(design, angle)
    doc = new_document()
    msp = doc.modelspace()
    lay = _Layout.of(design, p)
    _draw_frame(msp, design, p, lay)
    _draw_links(msp, design, p, lay)
    extents = bbox.extents(msp)
    size = extents.size
    scale = dims.print_scale(size.x, size.y)
    dims.add_dimstyle(doc, scale)
    outline = cad_font == "outline"
    labels = _draw_labels(msp, design, p, scale, outline)
    _draw_dimensions(msp, design, p, lay, scale, extents.extmin.x, labels)
    if outline:
        outline_dimension_texts(msp)
    whole = bbox.extents(msp)
    doc.set_modelspace_vport(height=whole.size.y * 1.1, center=tuple(whole.center)[:2])
    return doc


def write_scheme(design: Design, angle_deg: float, path: str | os.PathLike, cad_font: str = "gb") -> None:
    """Write the scheme to ``path`` (.dxf) atomically, its texts in ``cad_font``; DesignError
    naming ``angle`` for a bad angle and ``output`` for another suffix, before anything is
    written."""
    if os.path.splitext(os.fspath(path))[1].lower() != ".dxf":
        raise DesignError("output", os.fspath(path), "the scheme is written as DXF: name a .dxf file")
    save_dxf(scheme_document(design, angle_deg, cad_font), path)


@dataclass(frozen=True)
class _Layout:
    """The ram's body, the tool and the guide way, relative to the ram joint C, mm."""

    rear: float               # the ram body from C: rear end (−) and front end (+)
    front: float
    low: float                # its bottom and top, from the guide line
    high: float
    slot: tuple[float, float] | None   # the block variant's slot: bottom and top, from the guide
    block_half: float
    tip: tuple[float, float]  # the tool point from C
    rail: tuple[float, float]  # the guide way's ends, x

    @classmethod
    def of(cls, design: Design, p: Pose) -> "_Layout":
        u, guide = p.u, design.guide
        block_half = 1.1 * u
        low, high, slot = -1.3 * u, 1.3 * u, None
        if design.rod is None:
            # B's height runs from L3·cos(θ/2) (limits) to L3 (ψ = 0); its block slides in the slot
            b_lo, b_hi = float(p.lever_limits[0, 1]) - guide, design.lever - guide
            slot = (b_lo - block_half - 0.2 * u, b_hi + block_half + 0.2 * u)
            low, high = min(low, slot[0] - 0.5 * u), max(high, slot[1] + 0.5 * u)
        lo, hi = float(p.ram_limits.min()), float(p.ram_limits.max())
        reach = max(float(p.lever_limits[:, 0].max()), design.crank)   # links' right edge
        front = max(0.5 * design.stroke, reach + 5.0 * u - lo)        # the tool clear of them
        rear = 3.0 * u
        return cls(rear=rear, front=front, low=low, high=high, slot=slot, block_half=block_half,
                   tip=(front - 0.7 * u, low - 3.3 * u),
                   rail=(lo - rear - 3.0 * u, hi + front + 3.0 * u))


def _line(msp, p, q, layer: str) -> None:
    msp.add_line(tuple(map(float, p)), tuple(map(float, q)), dxfattribs={"layer": layer})


def _closed(msp, points, layer: str = OUTLINE) -> None:
    msp.add_lwpolyline([tuple(map(float, pt)) for pt in points], close=True,
                       dxfattribs={"layer": layer})


def _link(msp, p, q, rp: float, rq: float) -> None:
    """A link p→q as a thick line from pin rim to pin rim."""
    d = (q - p) / np.hypot(*(q - p))
    _line(msp, p + rp * d, q - rq * d, OUTLINE)


def _box(center, along, half_length: float, half_width: float) -> list[np.ndarray]:
    """The corners of a rectangle around ``center`` whose long side runs along ``along``."""
    a = np.asarray(along, dtype=float) / np.hypot(*along)
    n = np.array([-a[1], a[0]])
    return [center + sa * half_length * a + sn * half_width * n
            for sa, sn in ((-1, -1), (1, -1), (1, 1), (-1, 1))]


def _ground(msp, pivot, u: float) -> None:
    """The usual fixed-pivot symbol: a triangle from the pin down to a hatched ground line."""
    x, y = float(pivot[0]), float(pivot[1])
    r, base = PIN_FIXED * u, y - 2.0 * u
    for side in (-1.0, 1.0):
        corner = np.array([x + side * 1.2 * u, base])
        d = corner - pivot
        _line(msp, pivot + r * d / np.hypot(*d), corner, OUTLINE)
    _line(msp, (x - 2.0 * u, base), (x + 2.0 * u, base), OUTLINE)
    for hx in np.linspace(x - 1.3 * u, x + 2.0 * u, 6):
        _line(msp, (hx, base), (hx - 0.7 * u, base - 0.7 * u), THIN)


def _draw_frame(msp, design: Design, p: Pose, lay: _Layout) -> None:
    """Centre lines, paths, the lever's limit positions, the pivots' ground and the guide way."""
    u, guide = p.u, design.guide
    _line(msp, (0.0, -3.0 * u), (0.0, design.frame + design.crank + 2.0 * u), CENTER)
    msp.add_circle(tuple(p.o2), design.crank, dxfattribs={"layer": CENTER})   # path of A
    _line(msp, (lay.rail[0], guide), (lay.rail[1], guide), CENTER)               # path of C
    tips = [(x + lay.tip[0], guide + lay.tip[1]) for x in p.ram_limits]
    _line(msp, *tips, CENTER)                                                    # tool path
    for tip in p.lever_limits:
        _line(msp, (0.0, 0.0), tip, DASHED)
    for pivot in (np.zeros(2), p.o2):
        _ground(msp, pivot, u)
    way = guide + lay.high
    _line(msp, (lay.rail[0], way), (lay.rail[1], way), OUTLINE)
    for hx in np.arange(lay.rail[0], lay.rail[1] - 0.6 * u, 1.4 * u):
        _line(msp, (hx, way), (hx + 0.7 * u, way + 0.7 * u), THIN)


def _draw_links(msp, design: Design, p: Pose, lay: _Layout) -> None:
    """Pins, crank, lever, blocks, rod, the ram and its tool, at the pose."""
    u, guide, o4 = p.u, design.guide, np.zeros(2)
    fixed, moving = PIN_FIXED * u, PIN_MOVING * u
    for centre, r in ((o4, fixed), (p.o2, fixed), (p.a, moving), (p.b, moving)):
        msp.add_circle(tuple(centre), r, dxfattribs={"layer": OUTLINE})
    _link(msp, p.o2, p.a, fixed, moving)
    _link(msp, o4, p.b, fixed, moving)
    _closed(msp, _box(p.a, p.b, 1.2 * u, 0.55 * u))                 # block A on the lever
    cx = float(p.c[0])
    if design.rod is None:
        _closed(msp, _box(p.b, (0.0, 1.0), lay.block_half, 0.7 * u))  # block B in the slot
        lo, hi = lay.slot
        _closed(msp, [(cx - 0.8 * u, guide + lo), (cx + 0.8 * u, guide + lo),
                      (cx + 0.8 * u, guide + hi), (cx - 0.8 * u, guide + hi)])
    else:
        msp.add_circle(tuple(p.c), moving, dxfattribs={"layer": OUTLINE})
        _link(msp, p.b, p.c, moving, moving)
    x0, x1 = cx - lay.rear, cx + lay.front
    y0, y1 = guide + lay.low, guide + lay.high
    _closed(msp, [(x0, y0), (x1, y0), (x1, y1), (x0, y1)])          # the ram
    _closed(msp, [(x1 - 2.6 * u, y0), (x1 - 1.0 * u, y0), (x1 - 1.0 * u, y0 - 2.0 * u),
                  (x1 - 2.6 * u, y0 - 2.0 * u)])                     # tool post
    tip = (cx + lay.tip[0], guide + lay.tip[1])
    _closed(msp, [(x1 - 2.3 * u, y0 - 2.0 * u), (x1 - 1.0 * u, y0 - 2.0 * u), tip,
                  (x1 - 1.9 * u, y0 - 2.9 * u)])                     # tool bit


def _draw_labels(msp, design: Design, p: Pose, scale: float, outline: bool = False) -> list[Text]:
    """O2, O4, A, B (and C) beside their pins, clear of the links' lines and of L3's
    dimension (on the side of the lever away from O2): A and B on O2's side, A moved
    along the lever away from the crank; O4 on O2's side too, above the line that carries
    L2's dimension to the left; O2 straight away from the lever, where nothing is."""
    height, u = LABEL_MM * scale, p.u
    gap = PIN_FIXED * u + 0.6 * height
    along = p.b / design.lever
    toward_o2 = -_away_from_o2(design, p)
    crank_foot = float(np.dot(along, p.o2)) - float(np.dot(along, p.a))   # O2 along the lever from A
    shift = -math.copysign(1.2 * height, crank_foot)
    o4 = (np.array([-(gap + 2.0 * u), 0.9 * height]) if toward_o2[0] < 0
          else np.array([gap + 2.0 * u, 0.0]))
    places = {"O4": o4,
              "O2": p.o2 + (PIN_FIXED * u + 1.5 * height) * _o2_label_direction(design, p),
              "A": p.a + toward_o2 * (gap + u) + along * shift,
              "B": p.b + toward_o2 * (gap + 1.5 * u)}
    if design.rod is not None:
        places["C"] = p.c + np.array([0.0, -(gap + 1.5 * u)])
    labels = [Text(name, tuple(map(float, at)), height, "cm") for name, at in places.items()]
    for label in labels:
        if outline:
            add_outline_text(msp, label)
        else:
            msp.add_text(label.text, height=height, dxfattribs=text_attribs(text=label.text)) \
                .set_placement(label.position, align=TextEntityAlignment.MIDDLE_CENTER)
    return labels


def _away_from_o2(design: Design, p: Pose) -> np.ndarray:
    """The unit normal of the lever on the side away from O2 (where L3 is dimensioned)."""
    left = np.array([-p.b[1], p.b[0]]) / design.lever
    return -left if float(np.dot(left, p.o2)) > 0 else left


def _draw_dimensions(msp, design: Design, p: Pose, lay: _Layout, scale: float,
                     left: float, labels: list[Text]) -> None:
    """L2 and h as a vertical chain left of everything, L1 as the crank circle's radius
    where no line meets it, L3 beside the lever on the side away from O2, its text clear
    of the others' and of the ``labels`` (:func:`_clear_l3_text`), L4 along the rod, H
    under the tool path and θ between the lever's limit positions."""
    gap = 10.0 * scale                                            # 10 mm on paper
    chain = left - gap
    dims.linear(msp, (0.0, 0.0), p.o2, (chain, 0.0), 90.0, "L2")
    dims.linear(msp, p.o2, (lay.rail[0], design.guide), (chain, 0.0), 90.0, "h")
    _dimension_l1(msp, design, p, labels)
    if design.rod is not None:
        # above the ram and its guide way: below the rod the lever runs down from B
        rise = design.guide + lay.high + 0.7 * p.u + gap - float(p.b[1])
        dims.aligned(msp, p.b, p.c, rise, "L4", up=True)
    tip_y = design.guide + lay.tip[1]
    ends = [(x + lay.tip[0], tip_y) for x in p.ram_limits]
    dims.linear(msp, ends[0], ends[1], (0.0, tip_y - gap), 0.0, "H")
    right, left_tip = sorted(p.lever_limits, key=lambda t: -t[0])
    radius = 0.6 * (design.frame - design.crank)
    dims.angular(msp, (0.0, 0.0), right, left_tip, (0.0, radius), "θ")
    left_of_lever = np.array([-p.b[1], p.b[0]]) / design.lever
    side = float(np.dot(left_of_lever, _away_from_o2(design, p)))        # ±1
    taken = [t.box() for t in labels + [_dimension_text(msp, d) for d in msp.query("DIMENSION")]]
    l3 = dims.aligned(msp, (0.0, 0.0), p.b, side * gap, "L3")
    along = p.b / design.lever
    shift = _clear_l3_text(design, along, _dimension_text(msp, l3), taken)
    if shift:               # again, its text moved along its line clear of the others
        mid = l3.dxf.text_midpoint
        msp.doc.blocks.delete_block(l3.dxf.geometry, safe=False)
        msp.delete_entity(l3)
        dims.aligned(msp, (0.0, 0.0), p.b, side * gap, "L3",
                     location=(mid.x + shift * along[0], mid.y + shift * along[1]))


def _dimension_text(msp, dim) -> Text:
    """A rendered DIMENSION's text as its block shows it (ezdxf's MTEXT), for its box."""
    mtext = next(iter(msp.doc.blocks.get(dim.dxf.geometry).query("MTEXT")))
    insert = mtext.dxf.insert
    return Text(mtext.plain_text(), (insert.x, insert.y), mtext.dxf.char_height,
                ATTACHMENTS[mtext.dxf.attachment_point], mtext.get_rotation())


def _clear_l3_text(design: Design, along: np.ndarray, text: Text, taken: list) -> float:
    """How far (mm, along ``along``: toward B +, toward O4 −) L3's ``text`` moves along its
    dimension line so that its box meets none of the ``taken`` boxes (the joints' names and
    the other dimensions' texts): the smallest move in steps of a twentieth of L3, toward B
    first at equal length, the text kept on its line; 0 where it is clear, or where no
    step is. Why: with L2 near L3/2 (K 1.4, H 400) the middle of L3's line lies by O2, and
    at φ = 100° "L3 = 772.74" stood over "L1 = 100" (the screen's label search keeps them
    apart; the DXF places its texts by rule)."""
    if not any(boxes_meet(text.box(), box) for box in taken):
        return 0.0
    half = 0.5 * text_width(text.text, text.height)
    step = design.lever / 20.0
    for shift in (sign * k * step for k in range(1, 10) for sign in (1.0, -1.0)):
        if abs(shift) + half > 0.5 * design.lever:
            continue
        moved = replace(text, position=tuple(map(float, np.add(text.position, shift * along))))
        if not any(boxes_meet(moved.box(), box) for box in taken):
            return shift
    return 0.0


def _o2_label_direction(design: Design, p: Pose) -> np.ndarray:
    """From O2 straight away from the lever's line (the crank runs from O2 to the lever, so
    nothing else is there); to the right where the lever passes through O2."""
    along = p.b / design.lever
    away = p.o2 - along * float(np.dot(along, p.o2))
    size = float(np.hypot(*away))
    if size < 1e-9 * design.frame:
        return np.array([along[1], -along[0]])
    return away / size


def _dimension_l1(msp, design: Design, p: Pose, labels: list[Text]):
    """L1 as the crank circle's radius, its text clear of the joints' names: of the
    directions :func:`_l1_directions` ranks, the first where the text, between the arrows
    (where ezdxf puts it) or else just outside the circle on the line's way out, meets no
    name; the best outside spot where none does. Outside only where the text reads outward
    (the line's direction within (−60°, 120°], :func:`dimensions.reading_order`): LibreCAD
    moves a text longer than its line past the line's end in the text's reading direction,
    from where the DXF puts it; reading inward that was back over O2 ("L1 = 100" over O2 at
    K 1.2, H 500). The place is written as the dimension's own (a user-defined location),
    which LibreCAD takes. Why a search: the direction alone saw no text, and "L1 = 100" lay
    over O2 and A at 45 of 72 crank angles of that design."""
    taken = [t.box() for t in labels]
    ways = _l1_directions(design, p)
    first = None
    for way in ways:
        dim = dims.aligned(msp, p.o2, p.o2 + design.crank * way, 0.0, "L1")
        text = _dimension_text(msp, dim)
        msp.doc.blocks.delete_block(dim.dxf.geometry, safe=False)
        msp.delete_entity(dim)
        spots = [text.position]
        if -60.0 < math.degrees(math.atan2(way[1], way[0])) <= 120.0:
            out = 0.5 * design.crank + msp.doc.header["$DIMGAP"] + 0.5 * text_width(text.text, text.height)
            spots.append(tuple(map(float, np.add(text.position, out * way))))
            first = first or (way, spots[1])
        for spot in spots:
            if not any(_quad_meets_box(_text_corners(replace(text, position=spot)), box) for box in taken):
                return dims.aligned(msp, p.o2, p.o2 + design.crank * way, 0.0, "L1", location=spot)
    way, spot = first or (ways[0], None)
    return dims.aligned(msp, p.o2, p.o2 + design.crank * way, 0.0, "L1", location=spot)


def _text_corners(text: Text) -> np.ndarray:
    """The four corners (4, 2) of ``text``'s upright box turned by its rotation about its
    position: the rotated rectangle itself, not its bounds."""
    x0, y0, x1, y1 = text.upright_box()
    at = np.asarray(text.position, dtype=float)
    c, s = math.cos(math.radians(text.rotation)), math.sin(math.radians(text.rotation))
    local = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)]) - at
    return at + local @ np.array([[c, s], [-s, c]])


def _quad_meets_box(quad: np.ndarray, box) -> bool:
    """Whether the convex quadrilateral ``quad`` (4, 2) and the upright ``box`` overlap: no
    separating axis among the box's and the quadrilateral's edge normals."""
    corners = np.array([(box[0], box[1]), (box[2], box[1]), (box[2], box[3]), (box[0], box[3])])
    edges = np.diff(np.vstack([quad, quad[:1]]), axis=0)
    for normal in [np.array([1.0, 0.0]), np.array([0.0, 1.0]), *(np.array([-e[1], e[0]]) for e in edges[:2])]:
        a, b = quad @ normal, corners @ normal
        if a.max() <= b.min() or b.max() <= a.min():
            return False
    return True


def _l1_directions(design: Design, p: Pose) -> list[np.ndarray]:
    """Where L1 may be dimensioned as the crank circle's radius: the directions from O2 (in
    5° steps), the farthest first from those where a line leaves O2 or meets the circle: the
    crank, the lever's two crossings, the limit positions' tangent points, the frame's
    centre line, the sides of O2's ground symbol, and O2's name; those within 15° of one
    left out (the best one kept)."""
    along = p.b / design.lever
    mid = float(np.dot(along, p.o2))
    root = math.sqrt(max(mid * mid - design.frame ** 2 + design.crank ** 2, 0.0))
    points = [along * (mid - root), along * (mid + root), p.a, *p.pin_limits,
              p.o2 + _o2_label_direction(design, p)]
    down = -math.pi / 2.0
    taken = np.array([math.atan2(q[1] - p.o2[1], q[0] - p.o2[0]) for q in points]
                     + [down, down - 0.6, down + 0.6, math.pi / 2.0])
    candidates = np.radians(np.arange(0.0, 360.0, 5.0))
    gaps = np.abs((candidates[:, None] - taken[None, :] + math.pi) % (2 * math.pi) - math.pi).min(axis=1)
    order = np.argsort(-gaps, kind="stable")
    keep = [k for k in order if gaps[k] >= math.radians(15.0)] or [int(order[0])]
    return [np.array([math.cos(candidates[k]), math.sin(candidates[k])]) for k in keep]
