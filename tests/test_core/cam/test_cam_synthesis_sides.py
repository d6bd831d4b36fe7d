"""The smallest cam over both arrangements polishes only a side that can still win
(issue 40 item 5: the losing side's pressure peaks and cuts were a fifth of a cam edit),
and chooses exactly the follower that polishing both sides chooses."""
from __future__ import annotations

import itertools

import pytest

from core.cam import synthesis
from core.cam.laws import LAWS, Program
from core.cam.synthesis import Allowance, smallest, synthesize


def both_polished(arm_mm: float, program: Program, allowance: Allowance):
    """The rule of ``synthesize`` applied to each side polished in full."""
    found = [f for f in (smallest(arm_mm, program, allowance, s) for s in (1, -1)) if f is not None]
    return min(found, key=lambda f: (round(f.base_radius_mm, 9), -f.side))


def test_a_side_that_cannot_win_is_not_polished(monkeypatch):
    """Neither its polygon of every condition (only that of a part, for the bound) nor its
    pressure peaks are computed."""
    polished, polygons = [], []
    peaks, polygon = synthesis.pressure_peaks, synthesis._polygon
    monkeypatch.setattr(synthesis, "pressure_peaks", lambda f, p: polished.append(f.side) or peaks(f, p))
    monkeypatch.setattr(synthesis, "_polygon", lambda h, c: polygons.append(len(h)) or polygon(h, c))
    program, allowance = Program(rise_deg=61.0), Allowance(40.0, 70.0)
    chosen = synthesize.__wrapped__(120.0, program, allowance)
    assert set(polished) == {chosen.side}
    every = max(polygons)
    assert polygons.count(every) == 1 and len(polygons) == 3      # both parts, one whole
    assert chosen == both_polished(120.0, program, allowance)


@pytest.mark.parametrize("rise_law,return_law", list(itertools.product(LAWS, repeat=2)))
@pytest.mark.parametrize("arm_mm,swing_deg", [(120.0, 15.0), (60.0, 30.0)])
def test_the_chosen_follower_is_the_one_both_sides_polished_give(rise_law, return_law, arm_mm, swing_deg):
    program = Program(swing_deg=swing_deg, rise_deg=70.0, dwell_deg=10.0, return_deg=90.0,
                      rise_law=rise_law, return_law=return_law)
    allowance = Allowance(35.0, 60.0)
    assert synthesize.__wrapped__(arm_mm, program, allowance) == both_polished(arm_mm, program, allowance)
