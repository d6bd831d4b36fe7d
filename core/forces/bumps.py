"""Pairs of the energy's extrema that hide inside one cell between samples.

Below :mod:`core.forces.flywheel`, whose energy search brackets each zero of E′ = T − T_mean
where E′ changes sign between two samples. Two zeros in one cell leave E′ of one sign at
both its samples: a small bump of E′ through zero, a minimum of E and a maximum beside it,
that no sign change shows (a rod at 80 r/min: E′ −0.077 and −0.0016 N·m at 32° and 36°,
zeros at 33.56° and 35.94°, the swing 4.3e-4 J low). E′ then turns inside the cell, so
E″ = T′ changes sign there: such a cell is one of the torque's turning cells
(:func:`core.forces.cells.turning_cells` of E″), and E′'s extremum there is polished and
tested. Nearly all are ruled out by a bound (:func:`tangent_bound`): of the benchmark's
2000 loaded designs at 16 speeds, 10 cells of the rods' 19 784 and 38 of the blocks' 13 612
are polished.
"""
from __future__ import annotations

import numpy as np

from core.linkage.designs import Designs
from core.linkage.polish import newton_maximum
from .cells import Cells, cell_ends, cell_index
from .jet import torque_jet
from .masses import MassProperties


def tangent_bound(values: tuple[np.ndarray, np.ndarray], slopes: tuple[np.ndarray, np.ndarray],
                  width: np.ndarray) -> np.ndarray:
    """An upper bound on a concave curve over a cell of ``width``, from its ``values`` and
    ``slopes`` at both ends (the slope rising at the left end, m0 > 0 ≥ m1): where its two end
    tangents meet. A concave curve lies below each tangent; the one from the left rises and
    the one from the right falls, so the lower of the two is largest where they cross.
    NaN where the slopes are equal or not finite (no bound: the cell is kept)."""
    (g0, g1), (m0, m1) = values, slopes
    with np.errstate(all="ignore"):
        t = (g1 - g0 - m1 * width) / (m0 - m1)
        return np.where(m0 > m1, g0 + m0 * t, np.nan)


def hidden_bumps(g: list[np.ndarray], m: list[np.ndarray], c: list[np.ndarray],
                 width: np.ndarray) -> np.ndarray:
    """Which cells of ``width`` where E″ turns (sign·E″ falls through zero, sign 1 for an E′
    maximum, −1 for a minimum) and sign·E′ is at most 0 at both samples (a sign change is
    the crossing search's) may hold a pair of E′'s zeros: sign·E′'s largest value inside
    may reach 0. ``g``, ``m``, ``c``: sign·E′, sign·E″ and sign·E‴ at the cells' two samples.

    A cell is ruled out where sign·E′ is concave across it and its :func:`tangent_bound` is
    below 0. Concave: sign·E‴ ≤ 0 at both samples, so throughout by the grid's premise one
    derivative up (E‴ = T″ changes sign at most once in a cell, as T′ does for the torque's
    peaks). A bump however small is kept: the bound is never below the curve's maximum."""
    concave = (c[0] <= 0.0) & (c[1] <= 0.0)
    return ~(concave & (tangent_bound(g, m, width) < 0.0))


def bump_cells(curves: tuple[tuple[np.ndarray, np.ndarray], ...], w2: np.ndarray, cutting: float,
               piece: tuple[np.ndarray, np.ndarray], turns: list[tuple[int, Cells]]) -> list[list]:
    """The cells of one piece of the cycle (``piece``: its start and stop per design; the cut
    if ``cutting`` is 1) that may hide a pair of E′'s zeros (:func:`hidden_bumps`), among
    ``turns``, the (kind, :class:`~core.forces.cells.Cells`) where E″ = T′ changes sign
    (:func:`core.forces.cells.slope_turns`): per kind a list of design, speed, lo, hi, the
    bump's sign (1 where E′ has a maximum), ``cutting``, the piece's start and stop, then
    sign·E′, sign·E″, sign·E‴ at lo, then the same at hi. ``curves`` holds E′'s, E″'s and E‴'s
    (a, b) at the samples, each (designs, n), the curve at speed ω² being a + ω²·b (the
    energy search's own). E′ is gathered for every cell, E″ and E‴ only for those where E′
    keeps its sign (a fifth)."""
    parts, slopes, curvatures = curves
    out = []
    for kind, cells in turns:
        sign = 1.0 - 2.0 * kind
        index = cell_index(parts[0].shape[-1], cells)
        w = w2.take(cells.speed)
        g = [sign * (a + w * b) for a, b in cell_ends(parts, index)]
        low = np.flatnonzero((g[0] <= 0.0) & (g[1] <= 0.0))
        index, w, g = [i.take(low) for i in index], w.take(low), [v.take(low) for v in g]
        m, c = ([sign * (a + w * b) for a, b in cell_ends(p, index)] for p in (slopes, curvatures))
        at = np.flatnonzero(hidden_bumps(g, m, c, cells.hi.take(low) - cells.lo.take(low)))
        if at.size == 0:
            continue
        keep = low.take(at)
        design = cells.design.take(keep)
        out.append([design, cells.speed.take(keep), cells.lo.take(keep), cells.hi.take(keep),
                    np.full(keep.size, sign), np.full(keep.size, cutting),
                    piece[0].take(design), piece[1].take(design)]
                   + [v.take(at) for pair in zip(g, m, c) for v in pair])
    return out


def split_bumps(d: Designs, masses: MassProperties, w2: np.ndarray, mean: np.ndarray,
                bumps: list[list]) -> list[list]:
    """The cells ``bumps`` (:func:`bump_cells`'s, of both pieces) split where they hide a pair
    of E′'s zeros, as entries for the energy's polish (:func:`core.forces.flywheel._energy_extremes`:
    design, speed, lo, hi, E's sign, cutting, the piece's start and stop, then sign·E′,
    sign·E″, sign·E‴ at lo and at hi).

    E′'s extremum in each cell is polished by Newton's method on E″ and E‴
    (:func:`core.linkage.polish.newton_maximum`, from the quintic's top), all cells in one
    pass. Where it lies beyond zero the cell splits there into two across which E′ changes
    sign: before it a minimum of E for an E′ maximum (a maximum for a minimum), after it the
    other."""
    if not bumps:
        return []
    (design, speed, lo, hi, sign, cutting, first, last,
     g0, m0, c0, g1, m1, c1) = (np.concatenate(v) for v in zip(*bumps))
    args = [w2.take(speed), mean.take(design), sign, cutting, np.broadcast_to(d.theta, mean.shape).take(design)] \
        + [np.broadcast_to(v, mean.shape).take(design) for v in d.lengths()]

    def fun(t, w2, offset, sign, cutting, theta, *lengths):
        one = torque_jet(d.with_lengths(lengths, theta), t, masses)
        e1 = one.static + w2 * one.inertial + cutting * one.cut - offset         # E′ = T − mean
        e2 = one.static1 + w2 * one.inertial1 + cutting * one.cut1               # E″
        e3 = one.static2 + w2 * one.inertial2 + cutting * one.cut2               # E‴
        return sign * e1, sign * e2, sign * e3

    top, value = newton_maximum(fun, lo, hi, g0, g1, m0, m1, args, curvatures=(c0, c1))
    pair = np.flatnonzero(value > 0.0)                            # sign·E′ > 0 there: two zeros
    if pair.size == 0:
        return []
    at = fun(top[pair], *(v[pair] for v in args))                # sign·E′, E″, E‴ at the split
    design, speed, lo, hi, top, sign, cutting, first, last = (
        v[pair] for v in (design, speed, lo, hi, top, sign, cutting, first, last))
    ends = [v[pair] for v in (g0, m0, c0)], list(at), [v[pair] for v in (g1, m1, c1)]
    out = []
    for side, (a, b), (left, right) in ((-1.0, (lo, top), ends[:2]), (1.0, (top, hi), ends[1:])):
        out.append([design, speed, a, b, side * sign, cutting, first, last]
                   + [side * v for both in zip(left, right) for v in both])
    return out
