"""The driving torque's largest and smallest value per design and speed over a cycle, exactly.

Below :mod:`core.forces.flywheel`, which samples the torque's speed-independent parts
(:mod:`core.forces.jet`) and hands them here. The torque is two smooth curves, with the cut
and without it, switched at the cut's two ends; each curve's maxima lie in the cells between
samples where its slope turns from rising to falling, and each such cell is polished by
Newton's method (:func:`core.linkage.polish.newton_maximum`) on the closed-form slope and
curvature, from the top of the quintic through the cell's ends: mostly one evaluation, where
Brent's method on the torque alone took eight or more. Which cells turn at which speed comes
from :mod:`core.forces.cells` (one binary search per sample: the slope is affine in ω²), so
the per-speed work scales with the cells found; and a cell is polished only where the chord
of its largest value, convex in ω², reaches the candidates already known at that speed
(:func:`chord_bounds`).
"""
from __future__ import annotations

import numpy as np

from core.linkage.designs import Designs
from core.linkage.polish import newton_maximum
from .cells import (Cells, Window, at_switch, cell_ends, cell_index, on_arc, pair_extremes, straddling,
                    turns_beyond)
from .jet import torque_jet
from .masses import MassProperties

# A torque peak is done when Newton's next step would raise it by at most this fraction
# (core.linkage.polish.newton_maximum's ``gain``): far below the 1e-9 the sweep's figures
# are held to against the single design's summary, which takes the same path.
PEAK_GAIN = 1e-15


def piece_peaks(d: Designs, samples: tuple, omega: np.ndarray, masses: MassProperties,
                window: Window, turns: tuple[list, list]) -> tuple[np.ndarray, np.ndarray]:
    """(largest, smallest) driving torque per design and speed, N·m, each (designs, speeds).

    ``samples`` are :func:`core.forces.flywheel._torque_samples`' (φ, jet, segments) and
    ``window`` the cut's switch angles with the jet there and the cells of each piece, ``turns``
    the cells where the slope turns in each (:func:`core.forces.cells.slope_turns`). Candidates: both curves' values
    at both switch angles, the samples beside each turning cell that lie inside the piece,
    and each polished maximum or minimum that lands inside its piece (a smooth curve's
    extremum over an arc is at an end or where its slope turns).

    A turning cell is polished unless :func:`chord_bounds` shows that it cannot beat the
    candidates already known at its speed; the bound is exact (convexity in ω²), not a
    guess from the cell's end tangents, which missed a rod's minimum torque by 2e-4 of the
    peak (K near 5, a crank of 6 mm, a short trailing rod) in the hypothesis test at 16
    speeds. A cell whose run of turning speeds reaches the slowest or the fastest speed is
    polished there first, so that the chord has two ends; the rest follow in a second pass.
    A cell that straddles a switch angle and turns beyond it is not polished at all
    (:func:`core.forces.cells.turns_beyond`).
    """
    x, jet, _ = samples
    on, off, switch = window.on, window.off, window.jet
    w2 = omega ** 2
    rest = switch.static[:, None, :] + w2[:, None] * switch.inertial[:, None, :]   # (designs, speeds, 2)
    cut = rest + switch.cut[:, None, :]
    (cut_top, cut_bottom), (rest_top, rest_bottom) = pair_extremes(cut), pair_extremes(rest)
    best = np.stack([np.maximum(cut_top, rest_top), -np.minimum(cut_bottom, rest_bottom)])   # (2, designs, speeds)
    flat = best.reshape(-1)
    found = []
    for k, cutting in enumerate((1.0, 0.0)):
        values = (jet.static + cutting * jet.cut, jet.inertial)
        at_values = (switch.static + cutting * switch.cut, switch.inertial)
        at_slopes = (switch.static1 + cutting * switch.cut1, switch.inertial1)
        for kind, cells in turns[k]:
            sign = 1.0 - 2.0 * kind
            design, speed = cells.design, cells.speed
            owner = (kind * on.size + design) * w2.size + speed
            # Each end's flat index, taken once: its a and b give the value at the cell's
            # speed and at the speeds either side of its run (the chord's ends), and the
            # slopes and curvatures are gathered only for the cells polished.
            index = cell_index(x.shape[-1], cells)
            ends = cell_ends(values, index)
            inside = [window.inside[k].take(i) for i in index]
            entry = [np.full(design.size, k), np.full(design.size, kind), design, speed,
                     cells.lo, cells.hi]
            for (a, b), within in zip(ends, inside):
                value = sign * (a + w2[speed] * b)
                np.fmax.at(flat, owner[within], value[within])
                entry.append(value)
            entry += index + [cells.rank, cells.count, cells.below, cells.above]
            entry += [cell_top(ends, w2, sign, side) for side in (cells.below, cells.above)]
            entry.append(_beyond_tops(cells, inside, k, (at_values, at_slopes), w2, sign, entry[6:8]))
            found.append(entry)
    if not found:
        return best[0], -best[1]
    (k, kind, design, speed, lo, hi, v_lo, v_hi, i_lo, i_hi, rank, count, below,
     above, top_below, top_above, beyond) = (np.concatenate(v) for v in zip(*found))
    owner = (kind * on.size + design) * w2.size + speed
    lengths = [np.broadcast_to(v, on.shape) for v in d.lengths()]
    theta = np.broadcast_to(d.theta, on.shape)
    # A cell that turns beyond its piece is never polished: its largest value inside the piece
    # (at its inside sample or at the switch) is what a chord through its run's end takes.
    skip = ~np.isnan(beyond)
    polished = beyond.copy()                                    # NaN until polished

    def fun(t, w2, sign, cutting, theta, *lengths):
        one = torque_jet(d.with_lengths(lengths, theta), t, masses)
        static, inertial, cut = one[0:3], one[3:6], one[6:9]
        return tuple(sign * (s + w2 * i + cutting * c) for s, i, c in zip(static, inertial, cut))

    def polish(which: np.ndarray) -> None:
        """Polish the cells ``which`` (indices into the entries) and count the peaks inside."""
        if which.size == 0:
            return
        i = which
        w, sign, cutting = w2[speed[i]], 1.0 - 2.0 * kind[i], 1.0 - k[i]
        ends = [sign * ((static.ravel().take(at) + cutting * cut.ravel().take(at))
                        + w * inertial.ravel().take(at))
                for static, inertial, cut in ((jet.static1, jet.inertial1, jet.cut1),
                                              (jet.static2, jet.inertial2, jet.cut2))
                for at in (i_lo[i], i_hi[i])]
        root, value = newton_maximum(fun, lo[i], hi[i], v_lo[i], v_hi[i], ends[0], ends[1],
                                     [w, sign, cutting, theta[design[i]]]
                                     + [v[design[i]] for v in lengths],
                                     gain=PEAK_GAIN, curvatures=(ends[2], ends[3]))
        polished[i] = value
        start = np.where(k[i] == 0, on[design[i]], off[design[i]])
        stop = np.where(k[i] == 0, off[design[i]], on[design[i]])
        inside = on_arc(root, start, stop)
        np.fmax.at(flat, owner[i][inside], value[inside])

    # First the runs' ends at the slowest and the fastest speed, which no chord covers.
    index = np.arange(owner.size)
    slowest, fastest = (rank == 0) & (below < 0), (rank == count - 1) & (above < 0)
    polish(np.flatnonzero((slowest | fastest) & ~skip))
    low, high = index - rank, index - rank + count - 1           # each run's first and last
    bound = chord_bounds(w2, speed, (np.where(below < 0, speed[low], below), top_below, polished[low]),
                         (np.where(above < 0, speed[high], above), top_above, polished[high]),
                         (below < 0, above < 0))
    polish(np.flatnonzero(~(slowest | fastest | skip) & ~(bound <= flat[owner])))   # NaN: polished
    return best[0], -best[1]


def _beyond_tops(cells: Cells, inside: list[np.ndarray], k: int, at: tuple, w2: np.ndarray,
                 sign: float, values: list[np.ndarray]) -> np.ndarray:
    """Per turning cell of piece ``k``: NaN, or where it straddles an end of the piece and
    turns beyond it (:func:`core.forces.cells.turns_beyond`), its largest value inside the piece:
    there the curve is monotone, so that is the larger of its inside sample's value (of
    ``values``, sign·T at the left and right samples) and the switch angle's. ``at`` holds the
    curve's (a, b) and its slope's at the switch angles (each (designs, 2))."""
    out = np.full(cells.design.size, np.nan)
    which, switch, leaving = straddling(cells, inside, k)
    w = w2.take(cells.speed.take(which))
    beyond = turns_beyond(at_switch(at[1], switch, w), leaving, sign)
    which, switch, leaving, w = which[beyond], switch[beyond], leaving[beyond], w[beyond]
    out[which] = np.maximum(np.where(leaving, values[0].take(which), values[1].take(which)),
                            sign * at_switch(at[0], switch, w))
    return out


def cell_top(ends: list[tuple[np.ndarray, np.ndarray]], w2: np.ndarray, sign: float,
             side: np.ndarray) -> np.ndarray:
    """The larger of sign·(a + ω²·b) at a cell's two samples (``ends``, :func:`cell_ends`), at
    the speeds ``side`` (its largest value over the cell where it does not turn there), NaN
    where ``side`` is -1."""
    w = w2.take(np.maximum(side, 0))
    (a0, b0), (a1, b1) = ends
    top = np.maximum(sign * (a0 + w * b0), sign * (a1 + w * b1))
    return np.where(side >= 0, top, np.nan)


def chord_bounds(w2: np.ndarray, speed: np.ndarray, lower: tuple, upper: tuple,
                 polished: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """An upper bound on a turning cell's largest value at ``speed`` (indices into ω² ``w2``),
    from two speeds on either side of it.

    The cell's largest value M(ω²) = max over φ in the cell of sign·(a(φ) + ω²·b(φ)) is the
    largest of affine functions of ω², so it is convex in ω² and lies below its chord
    between any two speeds on either side. ``lower`` and ``upper`` are each (speed index,
    M from the samples, M polished) of the chord's ends, and ``polished`` says per end which
    of the two to take: the nearest speed where the cell does not turn, where M is the larger
    of the cell's end samples (the bracketing grid's premise: at most one turn per cell), or
    the run's own end, polished, where the run reaches the slowest or the fastest speed. A
    margin of 1e-12 of the ends' values covers the rounding; NaN where an end is NaN.
    """
    (s0, top0, peak0), (s1, top1, peak1) = lower, upper
    m0, m1 = np.where(polished[0], peak0, top0), np.where(polished[1], peak1, top1)
    w0, w1 = w2[s0], w2[s1]
    with np.errstate(all="ignore"):
        t = (w2[speed] - w0) / (w1 - w0)
        return m0 * (1.0 - t) + m1 * t + 1e-12 * (np.abs(m0) + np.abs(m1))
