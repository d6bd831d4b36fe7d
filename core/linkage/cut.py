"""Where the cutting force acts: the cut's two switch angles and the one rule that
decides, at any crank angle, whether the tool is cutting.

The cut runs while the advancing ram is between idle·H and (1 − idle)·H of its
travel from the dead point at φ = 0. With idle 0 its switch angles are the limit
positions themselves, 0 and π + θ in closed form (a root of x(φ) = H is a double
root, which a root finder can only place to √ε, 1.4e-8 rad); otherwise they are
exact roots of the closed-form displacement. The cut is the **closed** interval
between them:
the tool cuts at both switch angles (with idle 0, at both dead points), and an
angle within ``SWITCH_TOLERANCE`` of a switch counts as at it, so round-off in
a crank angle (240° typed, π + θ computed) cannot decide which side a row shows.
Every table, curve, position and ``--at`` angle uses this rule; the cycle's
energy and torque peaks take the switch angles as the ends of their pieces.

Level: beside ``dynamics``, which applies the force; imports kinematics only.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from .designs import Designs
from .kinematics import Shape, ram_origin, ram_position
from .polish import bracket_root

# Uniform samples per cycle that bracket the switch angles before they are polished (the
# ram advances monotonically over the working stroke, so a coarse grid brackets each once).
WINDOW_INTERVALS = 360
# A crank angle this close to a switch angle (rad, 2e-7°) counts as at it.
SWITCH_TOLERANCE = 1e-9


def cutting(design, phi: np.ndarray, idle_fraction: float) -> np.ndarray:
    """Whether the tool cuts at each crank angle ``phi`` (rad, any turn): the closed
    window [cut start, cut end] of :func:`cut_window`, taken modulo a turn."""
    on, off = _window(design, float(idle_fraction))
    since = np.mod(np.asarray(phi, dtype=float) - on + SWITCH_TOLERANCE, 2.0 * math.pi)
    return since <= off - on + 2.0 * SWITCH_TOLERANCE


@lru_cache(maxsize=32)
def _window(design, idle_fraction: float) -> tuple[float, float]:
    """The switch angles of one design (a frozen, hashable ``Design``): one edit solves
    the forces for several views, and the root search costs more than the rest."""
    on, off = cut_window(Designs.of(design), idle_fraction)
    return float(on[0]), float(off[0])


def cutting_force(design, sh: Shape, masses) -> np.ndarray:
    """Cutting force magnitude P over the shape's angles, (n,) N: ``masses.cut_force_N``
    where :func:`cutting` says the tool cuts, else 0."""
    return np.where(cutting(design, sh.phi, masses.idle_fraction), masses.cut_force_N, 0.0)


def cut_window(d: Designs, idle_fraction: float,
               grid: tuple[np.ndarray, np.ndarray] | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Crank angles (rad, in [0, π + θ]) where the cut starts and ends, each of d's shape:
    the ram, advancing on the working stroke φ ∈ [0, π + θ], reaches idle·H and
    (1 − idle)·H (see :func:`cutting_force`). Used by the cycle summary and the
    positions table's special rows.

    Each is bracketed between the samples of ``grid``, (φ, the ram joint's x in mm) for
    one-dimensional ``d``, one design per row, uniform φ over the cycle (by default
    ``WINDOW_INTERVALS`` steps), and
    polished as a root of the closed-form displacement. A switch at or before φ = 0
    (idle 0, or an idle·H below round-off) is 0; one never reached is π + θ.

    With idle 0 the window is exactly the working stroke [0, π + θ]: the ram's dead
    points are the lever's limit positions (dCx/dφ = L3·ψ′·(cos ψ ∓ d·sin ψ/r) for the
    rod, whose second factor vanishes only at the rod's dead centre, which validation
    refuses), where the crank is square to the lever, at φ = 0 and φ = π + θ.
    """
    if idle_fraction == 0.0:
        return np.zeros(np.shape(d.theta)), math.pi + np.asarray(d.theta, dtype=float)
    if grid is None:
        phi = np.linspace(0.0, 2.0 * math.pi, WINDOW_INTERVALS + 1)
        grid = phi, ram_position(d.column(), phi)
    phi, ram_x = grid
    idle = idle_fraction * d.stroke
    origin = ram_origin(d)
    targets = np.stack([idle, d.stroke - idle]) + origin            # Cx at the two switches
    end = np.broadcast_to(math.pi + d.theta, targets.shape)
    working = phi <= end[..., None]
    reached = (ram_x[None] >= targets[..., None]) & working
    first = np.argmax(reached, axis=-1)
    # Not reached on a grid sample: between the last sample of the working stroke and its
    # end, where the ram is at H (a dead point between samples, or a sample on π + θ that
    # rounds an ulp past it).
    missed = ~reached.any(axis=-1)
    last = np.maximum(np.searchsorted(phi, end, side="right") - 1, 0)
    inner = (~missed & (first > 0)) | (missed & (phi[last] < end))
    lo = np.where(missed, phi[last], phi[np.maximum(first - 1, 0)])
    hi = np.where(missed, end, np.minimum(phi[first], end))
    root = np.where(reached[..., 0], 0.0, end)                      # at or before φ = 0, or never
    lengths = [np.broadcast_to(v, targets.shape) for v in [d.theta] + d.lengths()]

    def travel(phi, target, theta, *lengths):
        return ram_position(d.with_lengths(lengths, theta), phi) - target

    if inner.any():
        root[inner] = bracket_root(travel, lo[inner], hi[inner],
                                   [v[inner] for v in [targets] + lengths])
    return root[0], root[1]
