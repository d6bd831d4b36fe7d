"""The pair as the Gear tab turns it (core.gear.mesh): the teeth never interpenetrate at
any crank angle, and they mesh without backlash (turning the pinion by a hair either way
makes them overlap), for standard, shifted and undercut-prone pairs.

The reference is the tooth as a region: in the gear's own frame a point at radius ρ lies in
a tooth when ρ ≤ ra and its angle from the nearest tooth axis is below the flank's angle
at ρ (core.gear.profile.flank), or when ρ < rf. Each gear's outline points are tested
against the other gear's region; the depth of a point inside is the least of the arc to
the flank and the way out past the tip circle."""
from __future__ import annotations

import math

import numpy as np
import pytest

from core.gear import GearPair, GearPairInputs, design_pair
from core.gear.mesh import gear_outline, mesh_angles, placed
from core.gear.profile import flank

PAIRS = [GearPairInputs(13, 40, 6.0, centre_mm=162.0), GearPairInputs(13, 40, 6.0),
         GearPairInputs(10, 36, 5.0, x1=0.45, x2=0.2), GearPairInputs(20, 20, 2.0),
         GearPairInputs(17, 51, 4.0, x1=0.0, x2=0.0), GearPairInputs(8, 60, 3.0),
         GearPairInputs(12, 25, 10.0, pressure_angle_deg=25.0, addendum=0.8, clearance=0.25)]


def depth_into(pair: GearPair, k: int, axis: float, points: np.ndarray) -> float:
    """How deep (mm) the deepest of ``points`` lies inside gear k turned to ``axis``
    (−inf when none is inside)."""
    gear = pair.gear1 if k == 1 else pair.gear2
    rel = points - (np.zeros(2) if k == 1 else np.array([pair.centre_mm, 0.0]))
    f = flank(pair.inputs, gear)
    rho = np.hypot(rel[:, 0], rel[:, 1])
    pitch = 2 * math.pi / gear.teeth
    off_axis = np.abs(np.mod(np.arctan2(rel[:, 1], rel[:, 0]) - axis + pitch / 2, pitch) - pitch / 2)
    half = np.interp(rho, f.radius, f.angle)
    inside = (rho <= gear.ra) & ((rho < gear.rf) | (off_axis < half))
    depth = np.where(rho < gear.rf, np.inf, np.minimum(rho * (half - off_axis), gear.ra - rho))
    return float(np.where(inside, depth, -np.inf).max())


def overlap(pair: GearPair, cranks: np.ndarray, pinion_offset: float = 0.0,
            ratio_sign: float = 1.0) -> float:
    """The deepest overlap (mm) of the two gears over ``cranks`` (rad), the pinion turned
    by ``pinion_offset`` more (rad) and, with ``ratio_sign`` −1, the wrong way."""
    one, two = gear_outline(pair, 1), gear_outline(pair, 2)
    turn1, turn2 = mesh_angles(pair, cranks)
    start = float(mesh_angles(pair, 0.0)[0])
    worst = -np.inf
    for a1, a2 in zip(turn1, turn2):
        a1 = start + ratio_sign * (a1 - start) + pinion_offset
        p1, p2 = placed(one, a1), placed(two, a2, (pair.centre_mm, 0.0))
        worst = max(worst, depth_into(pair, 2, a2, p1), depth_into(pair, 1, a1, p2))
    return worst


@pytest.mark.parametrize("inputs", PAIRS, ids=lambda p: f"{p.z1}-{p.z2}-m{p.module_mm:g}")
def test_the_teeth_never_overlap_and_touch_without_backlash(inputs):
    pair = design_pair(inputs)
    m = inputs.module_mm
    pitch2 = 2 * math.pi / pair.gear2.teeth          # the mesh repeats every pitch of the gear
    cranks = np.concatenate([np.linspace(0.0, pitch2, 21), np.random.default_rng(7).uniform(0, 2 * math.pi, 12)])
    assert overlap(pair, cranks) <= 1e-6 * m
    # no backlash: a pinion turned by an arc of m/100 on its working circle either way digs in
    nudge = 0.01 * m / pair.gear1.rw
    few = cranks[::4]
    assert overlap(pair, few, +nudge) > 0.005 * m
    assert overlap(pair, few, -nudge) > 0.005 * m


def test_the_check_sees_a_pinion_turning_the_wrong_way():
    pair = design_pair(PAIRS[0])
    assert overlap(pair, np.linspace(0.05, 0.5, 10), ratio_sign=-1.0) > 0.1 * pair.inputs.module_mm


def test_the_gear_turns_with_the_crank_and_the_pinion_i_times_the_other_way():
    pair = design_pair(PAIRS[0])
    crank = np.array([0.0, 0.3, 2.0])
    t1, t2 = mesh_angles(pair, crank)
    assert np.allclose(t2 - t2[0], -crank, atol=1e-15)                       # clockwise, as the crank
    assert np.allclose(t1 - t1[0], crank * 40 / 13, atol=1e-15)              # counter-clockwise, i times
    # the working pitch circles roll on each other: equal arcs at P
    assert pair.gear1.rw * 40 / 13 == pytest.approx(pair.gear2.rw, rel=1e-12)


def test_the_outline_is_every_tooth_of_the_profile():
    pair = design_pair(PAIRS[0])
    outline = gear_outline(pair, 2)
    rho = np.hypot(outline[:, 0], outline[:, 1])
    assert rho.max() == pytest.approx(pair.gear2.ra, rel=1e-9)
    assert rho.min() == pytest.approx(pair.gear2.rf, rel=1e-9)
    tips = np.arctan2(outline[:, 1], outline[:, 0])[np.isclose(rho, pair.gear2.ra, rtol=1e-9)]
    assert len(np.unique(np.mod(np.round(tips / (2 * math.pi / 40)), 40))) == 40
