"""The motion sheet's fit skips a dimension search that could only repeat the one before:
the ``compact`` trial at a scale where h's text fitted its line in the plain trial
(``mechanism_dims.dimensions``' second value). The sheet is the one of the plain loop,
which tries ``compact`` at every scale that does not fit, kept here as the reference."""
from __future__ import annotations

import pickle

import pytest

from core.drawing import mechanism_dims
from core.drawing.motion import motion_sheet
from core.drawing.sheet import paper
from core.linkage.geometry import from_dimensions, synthesize

CASES = {
    # the class benchmark's first student: scale 2 fails plain and compact, 2.5 fits
    "student 0, A1": (synthesize(100.0, 1.46, 300.0, guide="sagitta", rod_ratio=0.3), "A1"),
    # h's text does not fit its line, so compact counts and is tried (and fits)
    "scheme I, A3": (from_dimensions(110.0, 380.0, 540.0, rod=135.0), "A3"),
    "K near 3, A3": (synthesize(60.0, 2.8, 300.0, rod_ratio=0.3), "A3"),
    "block, A3": (synthesize(120.0, 1.6, 400.0), "A3"),
}


def _sheet_and_searches(design, size, monkeypatch, plain: bool):
    """The sheet and each search's (scale, compact); ``plain``: every search as if compact counted."""
    searches = []
    search = mechanism_dims.dimensions

    def counted(design, place, drawn, limits, compact=False):
        dims, asked = search(design, place, drawn, limits, compact)
        searches.append((place.scale, compact))
        return dims, asked or plain
    monkeypatch.setattr(mechanism_dims, "dimensions", counted)
    sheet = motion_sheet(design, 60.0, paper(size))
    monkeypatch.undo()
    return sheet, searches


@pytest.mark.parametrize("name", CASES)
def test_the_fit_gives_the_plain_loops_sheet(name, monkeypatch):
    design, size = CASES[name]
    sheet, _ = _sheet_and_searches(design, size, monkeypatch, plain=False)
    reference, _ = _sheet_and_searches(design, size, monkeypatch, plain=True)
    assert sheet.scale == reference.scale
    assert pickle.dumps(sheet.sheet.items) == pickle.dumps(reference.sheet.items)    # bit for bit
    assert pickle.dumps(sheet.dimensions) == pickle.dumps(reference.dimensions)


def test_a_compact_trial_that_cannot_differ_is_not_searched(monkeypatch):
    design, size = CASES["student 0, A1"]
    _, searches = _sheet_and_searches(design, size, monkeypatch, plain=False)
    _, plain = _sheet_and_searches(design, size, monkeypatch, plain=True)
    assert plain == [(2.0, False), (2.0, True), (2.5, False), (2.5, False)]    # trial, trial, fit, centred
    assert searches == [(2.0, False), (2.5, False), (2.5, False)]


def test_a_compact_trial_that_can_differ_is_searched(monkeypatch):
    design, size = CASES["scheme I, A3"]
    _, searches = _sheet_and_searches(design, size, monkeypatch, plain=False)
    assert (6.0, True) in searches
