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


def test_a_model_sheets_points_are_mapped_at_once_to_the_same_floats():
    """``_model_points`` (a polyline's vertices at once) gives, bit for bit, what ``_model``'s
    point-by-point map gives, on a sheet with a model (scaled, moved) and on one without; and
    a filled polyline's hatch gets the same vertices as its outline."""
    from dataclasses import replace

    from core.drawing.sheet import Placement
    from core.drawing.sheet_dxf import _model, _model_points
    rng = np.random.default_rng(11)
    points = rng.uniform(-50.0, 900.0, (257, 2))
    for model in (None, Placement(0.2857142857142857, (123.456, -7.89), (410.5, 297.25))):
        sheet = Sheet(paper("A1"), (), model=model)
        each = np.array([_model(sheet)[0](x, y) for x, y in points.tolist()])
        assert np.array_equal(_model_points(sheet)(points.tolist()), each)
    filled = replace(_lines()[2], filled=True)
    doc = sheet_document(Sheet(paper("A3"), (filled,)))
    outline, = doc.modelspace().query("LWPOLYLINE")
    hatch, = doc.modelspace().query("HATCH")
    assert [tuple(v[:2]) for v in hatch.paths[0].vertices] == [tuple(p) for p in outline.get_points("xy")]
