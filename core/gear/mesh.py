"""Where the two gears stand at a crank angle: the whole outlines and the turning angles.

No geometry is derived here: one tooth comes from ``core.gear.profile`` (true involutes and
the rack-generated fillets), its flank angle at the working pitch circle from
``core.gear.involute.half_angle``. The frame is the meshing sheet's: the pinion's centre O1
at the origin, the gear's O2 on +x at a′, y up. At crank angle 0 a flank of each gear passes
through the pitch point P (as on the sheet); the gear z2, on the crank's shaft, then turns
clockwise with the crank (the crank turns clockwise in the scheme, core.linkage.geometry) and the
pinion counter-clockwise i = z2/z1 times as fast: the working pitch circles roll on each
other (r′1 i = r′2), so the involutes stay conjugate and the teeth mesh at every angle.
Used by the GUI's Gear tab (which paints these arrays) and the meshing sheet (the line of
action).
"""
from __future__ import annotations

import math

import numpy as np

from .involute import half_angle
from .pair import GearPair
from .profile import tooth_outline


def gear_outline(pair: GearPair, k: int) -> np.ndarray:
    """Gear k (1 the pinion, 2 the gear) whole, closed, about its own centre with a tooth's
    axis on +x: (n, 2) mm."""
    gear = pair.gear1 if k == 1 else pair.gear2
    one = tooth_outline(pair.inputs, gear)[:-1]          # the last point is the next tooth's first
    step = 2.0 * math.pi / gear.teeth
    turns = np.arange(gear.teeth)[:, None] * step
    radius = np.hypot(one[:, 0], one[:, 1])[None, :]
    angle = np.arctan2(one[:, 1], one[:, 0])[None, :] + turns
    return np.column_stack([(radius * np.cos(angle)).ravel(), (radius * np.sin(angle)).ravel()])


def mesh_angles(pair: GearPair, crank: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
    """The angles (rad, counter-clockwise) of a tooth axis of the pinion and of the gear
    at crank angles ``crank`` (rad): the gear clockwise by the crank angle, the pinion
    counter-clockwise by i times it, from the position in contact at P."""
    crank = np.asarray(crank, dtype=float)
    p = pair.inputs
    psi = [float(half_angle(g.rw, g.r, g.s, p.alpha, g.rb)) for g in (pair.gear1, pair.gear2)]
    ratio = pair.gear2.teeth / pair.gear1.teeth
    return -psi[0] + ratio * crank, math.pi - psi[1] - crank


def placed(outline: np.ndarray, angle: float, centre: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """``outline`` turned counter-clockwise by ``angle`` (rad) about its origin, then moved
    to ``centre``: (n, 2) mm."""
    c, s = math.cos(angle), math.sin(angle)
    return outline @ np.array([[c, s], [-s, c]]) + np.asarray(centre, dtype=float)


def line_points(pair: GearPair) -> dict[str, np.ndarray]:
    """N1, N2, P, B1, B2 and the pb steps K1 (B2 + pb), K2 (B1 − pb) in the frame, mm: the
    line of action is tangent to both base circles and passes through P at α′ to the common
    tangent (the pinion turning counter-clockwise drives)."""
    aw = pair.alpha_w
    n1 = pair.gear1.rb * np.array([math.cos(aw), -math.sin(aw)])
    u = np.array([math.sin(aw), math.cos(aw)])
    at = {"N1": 0.0, "N2": pair.n1n2, "P": pair.n1p, "B1": pair.n1b1, "B2": pair.n1b2,
          "K1": pair.n1b2 + pair.pb, "K2": pair.n1b1 - pair.pb}
    return {name: n1 + g * u for name, g in at.items()}
