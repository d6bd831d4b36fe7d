"""A sheet's polylines in its DXF: the vertices set in one array and written in one piece
(``dxf_polyline``) write what ezdxf's own ``add_lwpolyline`` (one vertex at a time, a
``DXFVertex`` each) writes, to the character."""
from __future__ import annotations

import numpy as np
from ezdxf.lldxf import types

from core.drawing.dxf import dxf_text, new_document
from core.drawing.dxf_polyline import add_polyline
from core.drawing.sheet import Polyline, Sheet, paper
from core.drawing.sheet_dxf import sheet_document


def _entities(doc) -> str:
    """The DXF's ENTITIES section as written."""
    return dxf_text(doc).split("ENTITIES", 1)[1].split("ENDSEC", 1)[0]


def _lines() -> list[Polyline]:
    rng = np.random.default_rng(7)
    return [Polyline(tuple(map(tuple, rng.uniform(0.0, 400.0, (n, 2)))), closed=n % 2 == 1)
            for n in (2, 3, 17, 361)]


def test_polylines_write_the_dxf_ezdxf_writes_point_by_point():
    lines = _lines()
    ours = sheet_document(Sheet(paper("A3"), tuple(lines)))
    theirs = new_document()
    for line in lines:
        theirs.modelspace().add_lwpolyline([(float(x), float(y)) for x, y in line.points], close=line.closed,
                                           dxfattribs={"layer": line.layer})
    assert [len(e) for e in ours.modelspace().query("LWPOLYLINE")] == [2, 3, 17, 361]
    assert _entities(ours) == _entities(theirs)


def test_the_vertices_are_written_without_an_object_each(monkeypatch):
    """The cut itself: ezdxf's writer made a DXFVertex per vertex (383 more here than for
    the empty sheet, whose header and tables have a few of their own)."""
    made = []
    init = types.DXFVertex.__init__
    monkeypatch.setattr(types.DXFVertex, "__init__", lambda self, *a: made.append(1) or init(self, *a))
    counts = []
    for lines in ((), tuple(_lines())):
        made.clear()
        dxf_text(sheet_document(Sheet(paper("A3"), lines)))
        counts.append(len(made))
    assert counts[1] == counts[0] > 0


def test_a_vertex_with_a_width_or_bulge_is_written_by_ezdxf():
    points = [(0.0, 0.0), (10.5, 1.25), (20.0, -3.0)]
    ours, theirs = new_document(), new_document()
    packed = add_polyline(ours.modelspace(), points, False, {"layer": "0"})
    plain = theirs.modelspace().add_lwpolyline(points, dxfattribs={"layer": "0"})
    for line in (packed, plain):
        line[1] = (10.5, 1.25, 0.5, 0.5, 0.3)
    assert _entities(ours) == _entities(theirs)
