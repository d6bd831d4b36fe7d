"""Dimensions a CAD program keeps live: DIMENSION entities in a GB dimension style.

A dimension written as lines and a text is a picture of a number; a DIMENSION
entity keeps its definition points, so CAD measures it again (and updates it when
the geometry is stretched). Every one carries a text like ``L1 = <>``: CAD puts
its own measurement where ``<>`` stands, so the text cannot disagree with the
geometry.

Model space is drawn at 1:1 in mm and printed at a reduced scale 1:n. Arrows and
texts must print at their standard sizes (text 5 mm after GB/T 14691, arrows
3.5 mm) whatever the size of the mechanism, so the style holds every size already
multiplied by n, with ``DIMSCALE`` = 1. CAD's own convention would be the paper
sizes and ``DIMSCALE`` = n, but not every reader honours it: LibreCAD 2.2 ignores
DIMSCALE and drew the scheme's dimension texts at a quarter of the labels' height.
Every DXF this tool writes (the scheme, the cam) dimensions in this one style:
decimal point, text above the line, so no reader strikes the text through.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from core.base.figure_text import DIMENSION_DECIMALS

from .dxf import DIMENSIONS, UNICODE_STYLE
from .sheet import standard_scale

if TYPE_CHECKING:
    from ezdxf.document import Drawing

DIMSTYLE = "GB_MM"
DIM_TEXT_MM = 5.0            # text height on paper, GB/T 14691's series
ARROW_MM = 3.5               # arrow length on paper (≥ 6d for d = 0.5 mm)
DECIMALS = DIMENSION_DECIMALS      # the dimension texts' places, one rule with the screen's
A3_ROOM_MM = (380.0, 260.0)  # an A3 sheet's drawing area: the scale a print would use


def print_scale(width_mm: float, height_mm: float) -> float:
    """n of the GB/T 14690 reduction 1:n at which a drawing ``width_mm`` × ``height_mm``
    (model space, with a quarter more room for its dimensions) fits an A3 sheet."""
    return max(standard_scale(width_mm * 1.25, A3_ROOM_MM[0]),
               standard_scale(height_mm * 1.25, A3_ROOM_MM[1]))


def add_dimstyle(doc: Drawing, scale: float = 1.0, text_mm: float = DIM_TEXT_MM) -> str:
    """Add the GB dimension style (mm, ``text_mm`` text, ``.`` as decimal sign, trailing zeros
    dropped, text above the line and aligned with it) for a print at 1:``scale``: its sizes
    are the paper's times ``scale`` and DIMSCALE is 1 (see the module's docstring). A sheet's
    dimensions are 3.5 mm: LibreCAD draws every text at the header's DIMTXT (it ignores a
    DIMENSION's own override), so the header must hold the sheet's height."""
    n = float(scale)
    attribs = {
        "dimscale": 1.0, "dimlfac": 1.0, "dimtxt": text_mm * n, "dimasz": ARROW_MM * n,
        "dimexe": 2.0 * n, "dimexo": 0.0, "dimgap": 1.0 * n, "dimdli": 7.0 * n,
        "dimtad": 1, "dimtih": 0, "dimtoh": 0, "dimjust": 0,
        "dimdec": DECIMALS, "dimzin": 8, "dimdsep": ord("."), "dimlunit": 2,
        "dimaunit": 0, "dimadec": DECIMALS, "dimazin": 2, "dimtxsty": UNICODE_STYLE,
    }
    doc.dimstyles.new(DIMSTYLE, dxfattribs=dict(attribs))
    # The drawing's current dimension variables too: LibreCAD draws every dimension from
    # these and not from its style (the cam came out with "Standard"'s decimal comma).
    doc.header["$DIMSTYLE"] = DIMSTYLE
    for name, value in attribs.items():
        doc.header[f"${name.upper()}"] = value
    return DIMSTYLE


_ON_LAYER = {"layer": DIMENSIONS}
# Each dimension is rendered at once: its block is what CAD shows before it measures again.


def _render(dim, override: dict | None, location):
    """Apply a drawing's own ``override`` (e.g. DIMLFAC for a sheet drawn at 1:n) and text
    ``location`` (where the drawing's layout put the text), then render the block; the
    DIMENSION entity."""
    if override:
        dim.dimstyle_attribs.update(override)
    if location is not None:
        dim.set_location(tuple(float(v) for v in location[:2]))
    dim.render()
    return dim.dimension


def reading_order(p1, p2, offset: float, up: bool = False):
    """p1, p2 and the offset as :func:`aligned` draws them: ordered so that the text reads
    from below or from the right (GB/T 4458.4), never upside down; with ``up`` the
    offset's side is the upper one."""
    (x1, y1), (x2, y2) = (float(v) for v in p1[:2]), (float(v) for v in p2[:2])
    if up:
        offset = math.copysign(offset, x2 - x1)    # left of a rightward line is up
    if not -60.0 < math.degrees(math.atan2(y2 - y1, x2 - x1)) <= 120.0:
        (x1, y1), (x2, y2), offset = (x2, y2), (x1, y1), -offset
    return (x1, y1), (x2, y2), offset


def aligned(msp, p1, p2, offset: float, name: str, up: bool = False, *,
            override: dict | None = None, location=None, text: str | None = None):
    """``name = |p1p2|`` measured along p1→p2, its line ``offset`` mm to the left of p1→p2
    (with ``up``: on the upper side), in :func:`reading_order`; ``text`` replaces CAD's
    own "name = <>". The DIMENSION entity."""
    (x1, y1), (x2, y2), offset = reading_order(p1, p2, offset, up)
    return _render(msp.add_aligned_dim(p1=(x1, y1), p2=(x2, y2), distance=float(offset), text=text or f"{name} = <>",
                                dimstyle=DIMSTYLE, dxfattribs=_ON_LAYER), override, location)


def linear(msp, p1, p2, base, angle_deg: float, name: str, *, override: dict | None = None,
           location=None, text: str | None = None) -> None:
    """``name`` = the distance of p1 and p2 along ``angle_deg`` (0 horizontal, 90 vertical),
    its line through ``base``."""
    _render(msp.add_linear_dim(base=tuple(base), p1=tuple(p1), p2=tuple(p2), angle=angle_deg,
                               text=text or f"{name} = <>", dimstyle=DIMSTYLE, dxfattribs=_ON_LAYER),
            override, location)


def angular(msp, center, p1, p2, base, name: str, *, override: dict | None = None,
            location=None, text: str | None = None) -> None:
    """``name`` = the angle at ``center`` from p1 to p2 (counter-clockwise), its arc
    through ``base``. Written as the angle of two lines from ``center``, the angular
    dimension every reader knows: LibreCAD 2.2 leaves out the three-point one. The lines
    go in the order ezdxf's renderer needs to draw the counter-clockwise angle (p2's
    first: given p1's first, it drew 330° for 30°)."""
    c = tuple(map(float, center))[:2]
    _render(msp.add_angular_dim_2l(base=tuple(base), line1=(c, tuple(map(float, p2))[:2]),
                                   line2=(c, tuple(map(float, p1))[:2]), text=text or f"{name} = <>",
                                   dimstyle=DIMSTYLE, dxfattribs=_ON_LAYER), override, location)
