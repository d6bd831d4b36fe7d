"""A sheet's polylines in its DXF: the vertices set in one array write what ezdxf's own
``add_lwpolyline`` (one vertex at a time) writes, to the character."""
from __future__ import annotations

import numpy as np

from core.drawing.dxf import dxf_text, new_document
from core.drawing.sheet import Polyline, Sheet, paper
from core.drawing.sheet_dxf import sheet_document


def _entities(doc) -> str:
    """The DXF's ENTITIES section as written."""
    return dxf_text(doc).split("ENTITIES", 1)[1].split("ENDSEC", 1)[0]


def test_polylines_write_the_dxf_ezdxf_writes_point_by_point():
    rng = np.random.default_rng(7)
    lines = [Polyline(tuple(map(tuple, rng.uniform(0.0, 400.0, (n, 2)))), closed=n % 2 == 1)
             for n in (2, 3, 17, 361)]
    ours = sheet_document(Sheet(paper("A3"), tuple(lines)))
    theirs = new_document()
    for line in lines:
        theirs.modelspace().add_lwpolyline([(float(x), float(y)) for x, y in line.points], close=line.closed,
                                           dxfattribs={"layer": line.layer})
    assert [len(e) for e in ours.modelspace().query("LWPOLYLINE")] == [2, 3, 17, 361]
    assert _entities(ours) == _entities(theirs)
