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
    """The search before the cut: every candidate's whole cost, the first least (built, where
    the candidates are sketches)."""
    return mechanism_dims._built(min(candidates, key=lambda dim: self.cost(dim, extra(dim))))


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


@pytest.mark.parametrize("name", DESIGNS)
def test_sketched_candidates_give_the_sheet_of_built_ones(name, monkeypatch):
    """L3's candidates as ``sheet_dims.Sketch`` (their text; the picture built for the few
    whose text leaves them a chance): the sheet is the one every candidate built with
    ``aligned`` gives, and far fewer are built."""
    design = DESIGNS[name]
    made, built = [], []
    make, build = sheet_dims.Sketch.__init__, sheet_dims.Sketch.dimension

    def made_counted(self, *args, **kwargs):
        made.append(1)
        make(self, *args, **kwargs)

    def built_counted(self):
        built.append(1)
        return build(self)
    monkeypatch.setattr(sheet_dims.Sketch, "__init__", made_counted)
    monkeypatch.setattr(sheet_dims.Sketch, "dimension", built_counted)
    sketched = motion_sheet(design, 60.0, paper("A1"))
    monkeypatch.setattr(sheet_dims, "Sketch", sheet_dims.aligned)      # each candidate whole
    whole = motion_sheet(design, 60.0, paper("A1"))
    assert pickle.dumps(sketched.sheet.items) == pickle.dumps(whole.sheet.items)    # bit for bit
    assert pickle.dumps(sketched.dimensions) == pickle.dumps(whole.dimensions)
    assert 0 < len(built) < 0.1 * len(made), (len(built), len(made))


@pytest.mark.parametrize("outside", (False, True))
@pytest.mark.parametrize("below", (False, True))
@pytest.mark.parametrize("along", (0.02, 0.35, 0.5, 0.98))
@pytest.mark.parametrize("turn", (0.0, 37.0, 90.0, 135.0, 200.0, 271.0))
def test_a_sketch_is_the_text_of_its_dimension(turn, along, below, outside):
    """A sketch's text is ``aligned``'s, for texts that fit their line or go beyond either end
    (lines 8 and 150 mm long, every reading direction)."""
    for length, offset in ((8.0, 10.0), (150.0, -17.0)):
        t = math.radians(turn)
        p, q = (31.7, 12.9), (31.7 + length * math.cos(t), 12.9 + length * math.sin(t))
        args = (p, q, offset, "L3", 2.5)
        sketch = sheet_dims.Sketch(*args, outside=outside, below=below, along=along, height=2.5)
        whole = sheet_dims.aligned(*args, outside=outside, below=below, along=along, height=2.5)
        assert pickle.dumps(sketch.text) == pickle.dumps(whole.text)
        assert pickle.dumps(sketch.dimension()) == pickle.dumps(whole)
