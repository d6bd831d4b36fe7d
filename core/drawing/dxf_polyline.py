"""A sheet's polylines as DXF LWPOLYLINEs, built and written with their vertices in one piece.

Why: a student's four sheets hold tens of thousands of polyline vertices, and ezdxf
handles each as Python objects: appending them one at a time copies the array it has so
far (quadratic), and writing makes a ``DXFVertex`` per vertex and formats its two tags
through it (7 % of a ``shaper class`` student's time, py-spy, docs/performance.md). The
text written is ezdxf's own, character for character (``"%3d\\n%s\\n"`` of each
coordinate, as its ``DXFTag.dxfstr`` formats it): the tests compare the two.
"""
from __future__ import annotations

import numpy as np
from ezdxf.entities import factory
from ezdxf.entities.lwpolyline import LWPolyline, LWPolylinePoints, acdb_lwpolyline
from ezdxf.lldxf.tagwriter import AbstractTagWriter

from .dxf_tags import ENTITY, plain, plan, tags

_CODE = LWPolylinePoints.VERTEX_CODE
_VERTEX = f"{_CODE:3d}\n%s\n{_CODE + 10:3d}\n%s\n"      # x, then y: TAG_STRING_FORMAT twice
# LWPolyline.export_entity's attributes before its vertices, and after them
_BEFORE = plan(acdb_lwpolyline, ("count", "flags", "const_width", "elevation", "thickness"))
_AFTER = plan(acdb_lwpolyline, ("extrusion",), marker=False)


class PackedPolyline(LWPolyline):
    """An LWPOLYLINE whose vertices are written by one string formatting, and its attributes
    by :func:`.dxf_tags.tags`, where :func:`.dxf_tags.plain` holds and no vertex has a width
    or a bulge; ezdxf's own export otherwise (a binary DXF, an audit's tag collector)."""

    def export_entity(self, tagwriter: AbstractTagWriter) -> None:
        values = self.lwpoints.values
        if not plain(tagwriter, self) or values[:, 2:].any():
            super().export_entity(tagwriter)
            return
        version = tagwriter.dxfversion          # LWPolyline.export_entity's order; the
        xy = tuple(values[:, :2].ravel().tolist())   # vertices in one formatting of them all
        tagwriter.write_str("".join((tags(self, ENTITY, version), tags(self, _BEFORE, version),
                                     (_VERTEX * len(values)) % xy, tags(self, _AFTER, version))))


def add_polyline(msp, points: list[tuple[float, float]] | np.ndarray, closed: bool, attribs: dict) -> LWPolyline:
    """``msp.add_lwpolyline(points, close=closed, dxfattribs=attribs)`` as a
    :class:`PackedPolyline`, its vertices set in one array (widths 0, bulge 0): the same
    entity, handle and DXF text."""
    line = PackedPolyline.new(dxfattribs=dict(attribs))
    factory.bind(line, msp.doc)
    msp.add_entity(line)
    line.closed = closed
    vertices = np.zeros((len(points), LWPolylinePoints.VERTEX_SIZE))
    if len(points):
        vertices[:, :2] = points
    line.lwpoints.extend(vertices)
    return line
