"""The cam's extremes, solved rather than sampled: the largest pressure angle of the rise and
of the return, and the pitch curve's smallest convex radius of curvature.

A grid of each phase only brackets them; they are polished as the linkage's peaks are
(``core.linkage.extrema``). The pressure angle has a closed-form slope (it needs ψ, ψ′ and ψ″ only),
so its largest value is the zero of that slope, found by a bracketed root search
(:func:`core.linkage.extrema.grid_argmax`); the synthesis imposes the allowance there too
(``synthesis``). The curvature's slope would need ψ‴ and the pitch curve's third derivative,
so the curvature is polished without a slope (:func:`core.linkage.extrema.piece_maximum`, Brent's
parabolic steps), on each piece where the law's acceleration is smooth, both one-sided values
at a jump counting (the parabolic law's middle, the phases' ends). The largest curvature,
not the smallest radius, is sought: it stays finite where the curve turns from convex to
concave, where the radius runs off to infinity.

The dwells are arcs about the cam centre (ψ constant, the pressure angle there that of the
phases' ends), so the phases and the base circle hold every extreme of the turn.
"""
from __future__ import annotations

import math
from functools import lru_cache
from typing import NamedTuple

import numpy as np

from core.linkage.extrema import grid_argmax, piece_maximum
from .follower import TURN, Follower, pitch_of_motion
from .laws import Motion, Program, law, law_piece, pieces

GRID = 2001
"""Samples per phase (or per smooth piece of a phase) that bracket the extremes."""
PHASES = np.array([0, 1])                   # the rise, the return
SIGNS = np.array([1.0, -1.0])               # the cam pushing the roller outward, inward


def phase_motion(program: Program, phase: np.ndarray, u: np.ndarray,
                 piece: np.ndarray | None = None) -> tuple[np.ndarray, Motion]:
    """(δ, motion) at the fraction ``u`` ∈ [0, 1] of phase ``phase`` (0 the rise, 1 the
    return; arrays of one shape), by each law's formula on ``piece`` when given (see
    ``laws.law_piece``) or by the piece u lies in."""
    by_piece = piece is not None
    phase, u, piece = np.broadcast_arrays(np.asarray(phase), np.asarray(u, dtype=float),
                                          np.asarray(0 if piece is None else piece))
    up = phase == 0
    rise, dwell, ret = (math.radians(v) for v in (program.rise_deg, program.dwell_deg,
                                                  program.return_deg))
    s, s1, s2 = laws = np.empty((3,) + u.shape)
    for here, name in ((up, program.rise_law), (~up, program.return_law)):   # each law where it runs
        at = u[here]
        laws[:, here] = law_piece(name, at, piece[here]) if by_piece else law(name, at)
    span = np.where(up, rise, ret)
    sign = np.where(up, 1.0, -1.0)
    swing = math.radians(program.swing_deg)
    motion = Motion(swing * np.where(up, s, 1.0 - s), sign * swing * s1 / span,
                    sign * swing * s2 / span ** 2)
    return np.where(up, 0.0, rise + dwell) + u * span, motion


def _push(f: Follower, program: Program, u: np.ndarray, phase: np.ndarray, sign: np.ndarray,
          piece: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """sign·tan α and its slope d/du at ``u`` of ``phase`` (by the law's formula on ``piece``):
    tan α = |N|/D with N = l·ψ′ + k·(l − a·cos β) and D = a·sin β (``follower.
    pressure_angle``), so N′ = l·ψ″ + k·a·sin β·ψ′ and D′ = a·cos β·ψ′ (′ = d/dδ, and
    dδ/du the phase's span)."""
    _, m = phase_motion(program, phase, u, piece)
    l, a, k = f.arm_mm, f.distance_mm, f.k
    beta = math.radians(f.initial_deg) + m.psi
    cb, sb = np.cos(beta), np.sin(beta)
    num, den = l * m.psi1 + k * (l - a * cb), a * sb
    num1, den1 = l * m.psi2 + k * a * sb * m.psi1, a * cb * m.psi1
    span = np.where(phase == 0, math.radians(program.rise_deg), math.radians(program.return_deg))
    return sign * num / den, sign * span * (num1 * den - num * den1) / den ** 2


class PressurePeaks(NamedTuple):
    """The largest pressure angle of the rise and of the return (°), and where each sense of
    push (outward, inward) is largest: ``u`` (2, 2) the phase fraction and ``tan`` (2, 2)
    sign·N/D there, per phase (rows) and sense (columns)."""

    rise_deg: float
    return_deg: float
    u: np.ndarray
    tan: np.ndarray


@lru_cache(maxsize=16)          # the synthesis's last candidate is the cam's: asked for again
def pressure_peaks(f: Follower, program: Program, samples: int = GRID) -> PressurePeaks:
    """The largest pressure angles, polished to the zero of their closed-form slope (cached
    on the frozen follower and program: the arrays returned are shared, not to be written).

    Each phase is taken in its halves, each half by its own formula: the parabolic law's
    acceleration jumps at u = ½, so the slope does too, and a peak there is the halves'
    common end sample instead of a root search that could only bisect towards the jump."""
    half = np.linspace(0.0, 0.5, samples // 2 + 1)
    phase, sign, piece = PHASES[:, None, None, None], SIGNS[None, :, None, None], \
        np.array([0, 1])[None, None, :, None]
    u = half + 0.5 * piece
    values, slopes = _push(f, program, u, phase, 1.0, piece)      # inward: the same, negated
    values, slopes = (np.concatenate([v, -v], axis=1) for v in (values, slopes))
    tan, where = grid_argmax(lambda t, p, s, q: _push(f, program, t, p, s, q), u, values, slopes,
                             args=(phase, sign, piece))
    best = np.argmax(tan, axis=2)[..., None]
    tan, where = (np.take_along_axis(v, best, axis=2)[..., 0] for v in (tan, where))
    worst = np.degrees(np.arctan(np.max(tan, axis=1)))
    return PressurePeaks(float(worst[0]), float(worst[1]), where, tan)


def _convex_curvature(f: Follower, program: Program, u: np.ndarray, phase: np.ndarray,
                      piece: np.ndarray) -> np.ndarray:
    """The pitch curve's curvature (1/mm), positive where it is convex (``follower.
    curvature_radius``'s sign), at ``u`` of ``phase`` by the law's formula on ``piece``."""
    delta, m = phase_motion(program, phase, u, piece)
    p = pitch_of_motion(f, delta, m)
    cross = p.d1[0] * p.d2[1] - p.d1[1] * p.d2[0]
    speed = np.hypot(p.d1[0], p.d1[1])
    # A pitch curve that stops (a cusp) is as sharp as can be: no roller fits there.
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(speed > 0.0, -TURN * cross / speed ** 3, np.inf)


def _piece_grid(program: Program, samples: int) -> tuple[np.ndarray, ...]:
    """Each smooth piece of the rise's and the return's law (rows): its phase, its index,
    its ends lo and hi (u), and ``samples`` fractions u from lo to hi (rows, samples)."""
    rows = [(phase, index, lo, hi)
            for phase, name in enumerate((program.rise_law, program.return_law))
            for index, (lo, hi) in enumerate(zip(pieces(name)[:-1], pieces(name)[1:]))]
    phase, piece, lo, hi = (np.array(v) for v in zip(*rows))
    return phase, piece, lo, hi, lo[:, None] + (hi - lo)[:, None] * np.linspace(0.0, 1.0, samples)


@lru_cache(maxsize=16)          # a checked cam's two arrangements are compared, then one kept
def min_convex_radius(f: Follower, program: Program, samples: int = GRID) -> float:
    """The pitch curve's smallest convex radius of curvature (mm): 1 / the largest convex
    curvature of the phases' smooth pieces, polished, or the base radius (the inner dwell's
    arc; the outer dwell's arc is farther out) if that is smaller."""
    phase, piece, lo, hi, x = _piece_grid(program, samples)

    def curvature(t, p, q):
        return _convex_curvature(f, program, t, p, q)
    values = curvature(x, phase[:, None], piece[:, None])
    top = piece_maximum(curvature, x, values, lo, hi, args=(phase[:, None], piece[:, None]))
    return 1.0 / max(float(np.max(top)), 1.0 / f.base_radius_mm)


def sampled_min_convex_radius(f: Follower, program: Program, base_mm: np.ndarray,
                              samples: int) -> np.ndarray:
    """:func:`min_convex_radius` of many cam centres at once, unpolished (mm, shape (n,)):
    ``f``'s centre distance and angle are arrays (n,) with their base radii ``base_mm``.
    Why: a search over centres screens thousands of them, which the polish would make
    seconds; the grid's largest curvature is at most the true one, so this is at least the
    true radius (by at most 6.02e-4 of it over 120 random cams, 101 samples a piece), and a
    centre it keeps is checked with :func:`min_convex_radius` afterwards."""
    phase, piece, _, _, x = _piece_grid(program, samples)
    many = Follower(f.arm_mm, np.asarray(f.distance_mm)[:, None, None],
                    np.asarray(f.initial_deg)[:, None, None], f.side)
    values = _convex_curvature(many, program, x, phase[:, None], piece[:, None])
    return 1.0 / np.maximum(np.max(values, axis=(1, 2)), 1.0 / np.asarray(base_mm))
