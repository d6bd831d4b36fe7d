"""The feed cam as DXF, at 1:1 in mm in the cam's own frame (issue 23).

The cam centre at the origin and the follower's pivot on +x at the centre distance, as in
the CSV; the follower drawn at cam angle 0 (the start of the rise). Layers from
``core.drawing.dxf``: the actual profile on OUTLINE (thick), the pitch curve and the base
circle on CENTER (the textbook draws the theoretical profile dash-dot), the line of centres
on CENTER with the centre distance a dimensioned in the GB dimension style of
``core.drawing.dimensions`` (the scheme's: decimal point, text above the line, sizes for
the scale an A3 print would use), the roller and the arm on THIN. Its notes (r0, r, a, l, ψ0,
the pressure angles, in the cam sheet's words and language) and the dimension's text are TEXT
in the GB style, or with ``cad_font`` "outline" filled outlines
(:mod:`core.drawing.outline_text`), as every DXF of ``--cad-font`` writes them.

Level: a drawing, above ``core.drawing`` (its document factory) and ``core.cam``.
"""
from __future__ import annotations

import math
import os
from typing import Mapping

import numpy as np

from core.cam import Cam
from core.cam.follower import pitch, profile
from ezdxf import bbox

from . import dimensions as dims
from .cam_sheet import ENGLISH, figure_values
from .dxf import CENTER, OUTLINE, THIN, new_document, save_dxf
from .outline_text import outline_dimension_texts
from .sheet import marked_text
from .sheet_dxf import add_sheet_text

POINTS = 1440
"""Points of each closed curve (a quarter degree of cam angle apart)."""
NOTE_MM = 3.5
"""The notes' text height on paper (GB/T 14691), times the print scale in model space."""
NOTE_KEYS = ("base", "roller", "distance", "arm", "initial", "max_pressure")
"""The figures the notes give, one a line, by their word in the cam sheet's table; then the
sheet's note on the lines (actual profile thick, pitch curve dash-dot, the cam turns clockwise)."""


def cam_document(cam: Cam, cad_font: str = "gb", labels: Mapping[str, str] | None = None):
    """The DXF document of ``cam`` (an ezdxf Drawing, not yet audited), its texts in
    ``cad_font`` (``core.drawing.CAD_FONTS``; OutlineFontMissing without a CJK font) and its
    notes in the words of the cam's sheet, ``labels`` (``cam_sheet.ENGLISH``'s keys, English
    when None): the same words and figures as the sheet's table, in its language."""
    doc = new_document()
    msp = doc.modelspace()
    delta = np.linspace(0.0, 2.0 * math.pi, POINTS, endpoint=False)
    p = pitch(cam.follower, cam.program, delta)
    q = profile(p, cam.roller_mm)
    msp.add_lwpolyline(q.T.tolist(), close=True, dxfattribs={"layer": OUTLINE})
    msp.add_lwpolyline(p.point.T.tolist(), close=True, dxfattribs={"layer": CENTER})
    f = cam.follower
    r0, a = cam.base_radius_mm, f.distance_mm
    msp.add_circle((0.0, 0.0), r0, dxfattribs={"layer": CENTER})
    reach = max(r0, a) * 0.15
    msp.add_line((-r0 - reach, 0.0), (a + reach, 0.0), dxfattribs={"layer": CENTER})
    msp.add_line((0.0, -r0 - reach), (0.0, r0 + reach), dxfattribs={"layer": CENTER})
    roller = p.point[:, 0]
    msp.add_circle(tuple(roller), cam.roller_mm, dxfattribs={"layer": THIN})
    msp.add_line((a, 0.0), tuple(roller), dxfattribs={"layer": THIN})
    msp.add_circle((a, 0.0), max(a, r0) * 0.02, dxfattribs={"layer": THIN})
    below = -(r0 + reach)
    size = bbox.extents(msp).size
    scale = dims.print_scale(size.x, size.y)
    dims.add_dimstyle(doc, scale)
    dims.linear(msp, (0.0, 0.0), (a, 0.0), (a / 2.0, below), 0.0, "a")
    height = NOTE_MM * scale
    lab = {**ENGLISH, **(labels or {})}
    values = figure_values(cam, lab)
    lines = [f"{lab[key]} = {values[key]}" for key in NOTE_KEYS] + [lab["profile_note"]]
    for i, text in enumerate(lines):
        at = (-r0 - reach, below - (2 + 1.6 * i) * height)
        add_sheet_text(msp, marked_text(text, at, height, "lb"), cad_font)    # r_0: r with 0 below
    if cad_font == "outline":
        outline_dimension_texts(msp)
    return doc


def write_cam_dxf(cam: Cam, path: str | os.PathLike, cad_font: str = "gb",
                  labels: Mapping[str, str] | None = None) -> None:
    """Write the cam's DXF atomically, after the audit of ``core.drawing.dxf``, its texts in
    ``cad_font``, its notes in ``labels``' language (:func:`cam_document`)."""
    save_dxf(cam_document(cam, cad_font, labels), path)
