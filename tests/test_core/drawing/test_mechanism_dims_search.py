"""The motion sheet's dimension search leaves a candidate's cost unfinished once it cannot
beat the best so far (``mechanism_dims._Placed.best``): the dimensions chosen are those
of the plain search, ``min`` over every candidate's whole cost, which is kept here as the
reference and run beside it; and the dearer part of the cost (a candidate's own lines)
is built for fewer candidates."""
from __future__ import annotations

import math
import pickle

import pytest

from core.drawing import mechanism_dims, sheet_dims
from core.drawing.motion import motion_sheet
from core.drawing.sheet import paper
from core.linkage.geometry import from_dimensions, synthesize

DESIGNS = {
    "scheme I": from_dimensions(110.0, 380.0, 540.0, rod=135.0),
    # the class benchmark's students (benchmarks/test_bench_class.py): crank 100 + k, stroke 300 + 2k
    **{f"student {k}": synthesize(100.0 + k, 1.46, 300.0 + 2 * k, guide="sagitta", rod_ratio=0.3)
       for k in (0, 3)},
    "K near 3": synthesize(60.0, 2.8, 300.0, rod_ratio=0.3),
}


def _plain_best(self, candidates, extra=lambda dim: 0.0):
    """The search before the cut: every candidate's whole cost, the first least."""
    return min(candidates, key=lambda dim: self.cost(dim, extra(dim)))


def _sheet_and_own_lines(design, monkeypatch):
    """The motion sheet's dimensions, and how many candidates' own lines were built."""
    built = []

    class Counted(sheet_dims.Lines):
        def __init__(self, segs) -> None:
            built.append(1)
            super().__init__(segs)
    monkeypatch.setattr(sheet_dims, "Lines", Counted)
    dims = motion_sheet(design, 60.0, paper("A1")).dimensions
    monkeypatch.undo()
    return dims, len(built)


@pytest.mark.parametrize("name", DESIGNS)
def test_the_search_chooses_what_the_plain_search_chooses(name, monkeypatch):
    design = DESIGNS[name]
    cut, cut_lines = _sheet_and_own_lines(design, monkeypatch)
    with monkeypatch.context() as patched:
        patched.setattr(mechanism_dims._Placed, "best", _plain_best, raising=False)
        plain, plain_lines = _sheet_and_own_lines(design, patched)
    assert [d.name for d in cut] == [d.name for d in plain] and len(cut) >= 6
    assert pickle.dumps(cut) == pickle.dumps(plain)     # every point, offset, text and part, bit for bit
    assert cut_lines < 0.5 * plain_lines, (cut_lines, plain_lines)


def test_an_unfinished_cost_is_never_below_the_whole():
    """``cost(dim, extra, beat)`` is the whole cost, or inf where the whole is ``beat`` or more."""
    design = DESIGNS["scheme I"]
    drawn = motion_sheet(design, 60.0, paper("A3"))
    placed = mechanism_dims._Placed(drawn.areas["mechanism"][1])
    for dim in drawn.dimensions[:3]:
        placed.dims.append(dim)
    for dim in drawn.dimensions[3:]:
        whole = placed.cost(dim)
        for beat in (0.0, whole, whole + 1.0, 1000.0, math.inf):
            cut = placed.cost(dim, 0.0, beat)
            assert cut == whole or (cut == math.inf and whole >= beat)
