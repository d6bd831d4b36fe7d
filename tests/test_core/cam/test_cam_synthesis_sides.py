"""The smallest cam over both arrangements polishes only a side that can still win
(issue 40 item 5: the losing side's pressure peaks and cuts were a fifth of a cam edit),
and chooses exactly the follower that polishing both sides chooses."""
from __future__ import annotations

import itertools

import numpy as np
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


def test_a_usual_cam_needs_no_linear_program(monkeypatch):
    """The interior points come from the grid and the polygons' centroids (issue 40 item 5:
    the two LPs, most of it scipy's setting up, were a sixth of a Cam edit)."""
    solved = []
    chebyshev = synthesis._chebyshev
    monkeypatch.setattr(synthesis, "_chebyshev", lambda h: solved.append(len(h)) or chebyshev(h))
    synthesize.__wrapped__(120.0, Program(rise_deg=61.0), Allowance(40.0, 70.0))
    assert solved == []


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("swing_deg,allowance", [(15.0, Allowance(40.0, 70.0)), (30.0, Allowance(25.0, 50.0))])
def test_the_deep_point_is_as_deep_as_a_third_of_the_widest_circle(law, swing_deg, allowance):
    """The centroid of a convex polygon is at least a third of its width in every direction
    from its edges, and the width is at least the diameter 2r of the largest inscribed
    circle (the LP's Chebyshev centre), so each condition keeps a margin ≥ 2r/3 there."""
    program = Program(swing_deg=swing_deg, rise_law=law, return_law=law)
    for side in (1, -1):
        h = synthesis._halfspaces(120.0, synthesis.TURN * side, program, allowance)
        rows = h[synthesis._rows(h)]
        centre = synthesis._chebyshev(rows)
        point, ring = synthesis._deep_point(rows, 120.0)
        assert (centre is None) == (point is None)
        if centre is not None:
            radius = -np.max(rows[:, :2] @ centre + rows[:, 2])
            assert -np.max(rows[:, :2] @ point + rows[:, 2]) >= 2.0 * radius / 3.0 * (1.0 - 1e-9)


def test_without_a_grid_point_the_linear_program_gives_the_same_cam(monkeypatch):
    """Where the grid finds no point inside (a tight allowance) the Chebyshev centre starts
    the polygon, as before: the same cam, to rounding."""
    program, allowance = Program(rise_deg=61.0, swing_deg=22.0), Allowance(35.0, 60.0)
    usual = synthesize.__wrapped__(120.0, program, allowance)
    monkeypatch.setattr(synthesis, "_grid_point", lambda rows, arm: None)
    solved = synthesize.__wrapped__(120.0, program, allowance)
    assert solved.side == usual.side
    for name in ("distance_mm", "initial_deg", "base_radius_mm"):
        assert getattr(solved, name) == pytest.approx(getattr(usual, name), rel=1e-9)
