"""A :class:`~core.drawing.sheet.Sheet` as DXF, in paper mm at 1:1.

Every item goes on its layer of :mod:`core.drawing.dxf` with BYLAYER linetype,
weight and colour, so a CAD user can switch the centre lines or the texts off
by layer, and prints the sheet at 1:1 on the paper it names.
"""
from __future__ import annotations

import os
from typing import Callable

import numpy as np
from ezdxf import zoom
from ezdxf.document import Drawing
from ezdxf.enums import TextEntityAlignment

from . import dimensions as dims
from .dxf import literal_text, new_document, save_dxf, text_attribs
from .dxf_polyline import add_polyline
from .dxf_text_entity import add_text
from .outline_text import add_outline_text, as_drawn
from .sheet import Circle, Polyline, Sheet, Text

ALIGNMENTS = {
    "lb": TextEntityAlignment.LEFT, "cb": TextEntityAlignment.CENTER, "rb": TextEntityAlignment.RIGHT,
    "lm": TextEntityAlignment.MIDDLE_LEFT, "cm": TextEntityAlignment.MIDDLE_CENTER,
    "rm": TextEntityAlignment.MIDDLE_RIGHT, "lt": TextEntityAlignment.TOP_LEFT,
    "ct": TextEntityAlignment.TOP_CENTER, "rt": TextEntityAlignment.TOP_RIGHT,
}


def _model(sheet: Sheet):
    """Paper mm → the DXF's coordinates and its length factor: the paper itself, or the
    sheet's model (``Sheet.model``: its drawing at 1:1, everything else scaled with it)."""
    if sheet.model is None:
        return (lambda x, y: (float(x), float(y))), 1.0
    k, (ox, oy), (ax, ay) = sheet.model.scale, sheet.model.origin, sheet.model.anchor
    return (lambda x, y: (float(ax + (x - ox) * k), float(ay + (y - oy) * k))), float(k)


def _model_points(sheet: Sheet):
    """:func:`_model`'s map of points (n, 2) at once, the same arithmetic in the same order
    (so the same floats): a point at a time was some 1 % of a class's student (a sheet's
    polylines hold tens of thousands of vertices; docs/performance.md)."""
    if sheet.model is None:
        return lambda points: np.asarray(points, dtype=float).reshape(-1, 2)
    k, origin, anchor = sheet.model.scale, sheet.model.origin, sheet.model.anchor
    o, a = np.asarray(origin, dtype=float), np.asarray(anchor, dtype=float)
    return lambda points: a + (np.asarray(points, dtype=float).reshape(-1, 2) - o) * k


def sheet_document(sheet: Sheet, cad_font: str = "gb") -> Drawing:
    """The sheet in model space (paper mm, origin at the trimmed edge's lower left; or, for
    a sheet with a model, in the model's mm); each of its dimensions a DIMENSION entity in
    place of its picture (only sheets without a model have dimensions: they are written in
    paper mm). ``cad_font`` (``dxf.CAD_FONTS``): "gb" writes each text as TEXT in the GB
    style, "outline" as its glyphs' filled outlines, a dimension's text included (the
    DIMENSION keeps its lines and its measurement, its own text blank)."""
    doc = new_document()
    msp = doc.modelspace()
    to, k = _model(sheet)
    to_all = _model_points(sheet)
    low, high = to(0.0, 0.0), to(sheet.paper.width, sheet.paper.height)
    layout = msp.dxf_layout.dxf          # the limits ezdxf writes to the header: the paper
    layout.limmin, layout.limmax = low, high
    pictures = {id(part) for dim in sheet.dimensions for part in dim.parts}
    if sheet.dimensions:
        # the sheet prints at 1:1, each one's DIMLFAC scales it; the header's DIMTXT is the
        # sheet's dimension text (LibreCAD draws every one at it)
        dims.add_dimstyle(doc, 1.0, max(dim.height for dim in sheet.dimensions))
    outline = cad_font == "outline"
    for dim in sheet.dimensions:
        _dimension(msp, dim, blank=outline)
        if outline:
            add_outline_text(msp, dim.text, to, k)
    for item in sheet.items:
        if id(item) in pictures:
            continue
        attribs = {"layer": item.layer}
        if isinstance(item, Polyline):
            points = to_all(item.points)
            add_polyline(msp, points, item.closed, attribs)
            if item.filled:
                hatch = msp.add_hatch(dxfattribs=attribs)
                hatch.paths.add_polyline_path(list(map(tuple, points.tolist())), is_closed=True)
        elif isinstance(item, Circle):
            msp.add_circle(to(*item.center), item.radius * k, dxfattribs=attribs)
        elif isinstance(item, Text):
            add_sheet_text(msp, item, cad_font, to, k)
    zoom.window(msp, low, high)            # CAD opens on the whole sheet
    return doc


def add_sheet_text(msp, item: Text, cad_font: str = "gb",
                   to: Callable[[float, float], tuple[float, float]] = as_drawn, k: float = 1.0) -> None:
    """A sheet's text (subscripts as ``r_0``) in ``cad_font``: "gb", each run a TEXT in its GB
    style (``dxf.text_style``), a subscript a smaller text of its own; "outline", the glyphs
    as filled outlines. ``to`` and ``k`` map paper mm to the drawing's (by default its own
    coordinates)."""
    if cad_font == "outline":
        add_outline_text(msp, item, to, k)
        return
    attribs = text_attribs(item.layer, item.text)     # one style for all of the text's runs
    for run in item.runs():
        text = add_text(msp, literal_text(run.text), run.height * k, run.rotation, attribs)
        text.set_placement(to(*run.position), align=ALIGNMENTS[run.align])


def _dimension(msp, dim, blank: bool = False) -> None:
    """A sheet's dimension as a DIMENSION entity, its text where the sheet has it. The text is
    the sheet's, the true value, not CAD's "<>": LibreCAD ignores DIMLFAC (in the style and in
    an override) and would show the length on the paper; the definition points and DIMLFAC
    still make CAD's own measurement the true length where CAD honours it. ``blank``: the
    text is " ", which DXF reads as no text (the outline of the sheet's text is drawn
    in its place)."""
    where = {"override": dim.override, "location": dim.text.position,
             "text": " " if blank else dim.text.text}
    if dim.kind == "aligned":
        dims.aligned(msp, dim.points[0], dim.points[1], dim.offset, dim.name, **where)
    elif dim.kind == "linear":
        dims.linear(msp, dim.points[0], dim.points[1], dim.base, dim.angle, dim.name, **where)
    else:
        dims.angular(msp, dim.center, dim.points[0], dim.points[1], dim.base, dim.name, **where)


def save_sheet_dxf(sheet: Sheet, path: str | os.PathLike, cad_font: str = "gb") -> None:
    """Write the sheet as DXF atomically (``dxf.save_dxf``: audited first), its texts in
    ``cad_font`` (``dxf.CAD_FONTS``)."""
    save_dxf(sheet_document(sheet, cad_font), path)
