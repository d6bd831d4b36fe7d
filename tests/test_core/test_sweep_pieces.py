"""Which of the loaded sweep's cells reach a piece of the cycle (the cut, or the rest), and
which of those that straddle a switch angle turn beyond it (issue 42, item 12).

:mod:`core.forces.cells` marks the cells between samples that reach into each piece; the
torque's peaks and the energy's extremes are polished only in those, and a cell that
straddles the cut's start or end is dropped when its curve turns on the far side of that
switch angle. Checked here on dense angles across every cell, not on the code's own samples:
the reach against each cell's 201 angles, the drop against the torque and the energy's slope
on 401 angles of the cell's part inside its piece.
"""
import math

import numpy as np
import pytest

import core.forces.cells as cells_
from core.forces.flywheel import _torque_samples
from core.forces.jet import torque_jet
from core.forces.masses import MassProperties
from core.linkage.cut import cut_window
from core.linkage.kinematics import rpm_to_omega
from core.linkage.spec import Spec
from core.space.sweep import SWEEP_INTERVALS, grid, spec_designs
from test_sweep_fast_paths import rod_family

LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)


def _family(variant):
    """The valid designs of the benchmark's families, 12 × 12: rod ratio × guide (rod), crank
    × K (block)."""
    if variant == "rod":
        return rod_family(12)
    spec = Spec(crank=100.0, time_ratio=1.46, stroke=312.0)
    designs, verdict = spec_designs(spec, grid({"crank": (60.0, 140.0, 12),
                                                "time_ratio": (1.1, 2.3, 12)}))
    return designs.flat().take(np.flatnonzero(verdict.ok.reshape(-1)))


def _window(d):
    phi = np.linspace(0.0, 2.0 * math.pi, SWEEP_INTERVALS + 1)
    grid = torque_jet(d.column(), phi, LOADS)
    samples = _torque_samples(d, grid, LOADS)
    on, off = cut_window(d, LOADS.idle_fraction, (phi, grid.ram_x))
    return samples, cells_.switch_window(d, samples, on, off, LOADS)


def _in_piece(t, start, stop):
    """t on the arc from start to stop, by numpy's own modulo (rad, any turn)."""
    return np.mod(t - start, 2.0 * math.pi) <= np.mod(stop - start, 2.0 * math.pi)


@pytest.mark.parametrize("variant", ["block", "rod"])
@pytest.mark.parametrize("k", [0, 1], ids=["cut", "rest"])
def test_a_cell_reaches_a_piece_where_one_of_its_angles_lies_in_it(k, variant):
    """Every cell of the benchmark's rod family whose 201 angles include one in the piece
    reaches it, and none whose angles all lie 1e-8 rad or more outside it does (the rest of
    the cycle, from off round to on, was once tested as if it ran from on to off, so every
    cell reached it, those inside the cut too: 40 % of the torque's first polish was spent
    on them)."""
    d = _family(variant)
    _, window = _window(d)
    start, stop = (window.on, window.off) if k == 0 else (window.off, window.on)
    checked = [0, 0]
    for left, right, lo, hi, reach in window.cells[k]:
        at = lo[..., None] + (hi - lo)[..., None] * np.linspace(0.0, 1.0, 201)
        a, b = start[:, None, None], stop[:, None, None]
        inside = _in_piece(at, a, b).any(axis=-1)
        near = (_in_piece(at, a - 1e-8, b + 1e-8)).any(axis=-1)
        assert np.all(reach[inside])
        assert not np.any(reach[~near])
        checked[0] += inside.sum()
        checked[1] += (~near).sum()
    assert min(checked) > 100


@pytest.mark.parametrize("variant", ["block", "rod"])
@pytest.mark.parametrize("energy", [False, True], ids=["torque", "energy"])
def test_a_straddling_cell_dropped_does_not_turn_inside_its_piece(energy, variant):
    """Each turning cell that straddles a switch angle and is dropped (:func:`_family`, 16
    speeds): its curve (the torque's slope for the peaks, the torque less its mean for the
    energy's extremes) keeps one sign on 401 angles of the cell's part inside the piece,
    so no extremum of the piece lies in it; some straddling cells are kept, and some dropped."""
    d = _family(variant)
    samples, window = _window(d)
    x, jet, _ = samples
    w2 = rpm_to_omega(np.arange(10.0, 170.0, 10.0)) ** 2
    mean = LOADS.cut_force_N * (1.0 - 2.0 * LOADS.idle_fraction) * d.stroke * 1e-3 / (2.0 * math.pi)
    counts = [0, 0]
    for k, cutting in enumerate((1.0, 0.0)):
        if energy:
            parts = (jet.static + cutting * jet.cut - mean[:, None], jet.inertial)
            at = (window.jet.static + cutting * window.jet.cut - mean[:, None], window.jet.inertial)
        else:
            parts = (jet.static1 + cutting * jet.cut1, jet.inertial1)
            at = (window.jet.static1 + cutting * window.jet.cut1, window.jet.inertial1)
        start, stop = (window.on, window.off) if k == 0 else (window.off, window.on)
        for kind, cells in cells_.turning_cells(parts, w2, window.cells[k]):
            sign = 1.0 - 2.0 * kind
            index = cells_.cell_index(x.shape[-1], cells)
            which, switch, leaving = cells_.straddling(cells, [window.inside[k].take(i) for i in index], k)
            speed = cells.speed[which]
            beyond = cells_.turns_beyond(cells_.at_switch(at, switch, w2[speed]), leaving, sign)
            counts[0] += (~beyond).sum()
            counts[1] += beyond.sum()
            which, speed, leaving = which[beyond], speed[beyond], leaving[beyond]
            design = cells.design[which]
            lo, hi = cells.lo[which], cells.hi[which]
            # the part inside: from the cell's left sample to the piece's end, or from the
            # piece's start to its right sample (the switch a turn on where the cell wraps)
            end = np.where(leaving, stop[design], start[design])
            end = end + 2.0 * math.pi * np.floor((hi - end) / (2.0 * math.pi))
            a, b = np.where(leaving, lo, end), np.where(leaving, end, hi)
            t = a[:, None] + (b - a)[:, None] * np.linspace(0.0, 1.0, 401)
            dense = torque_jet(d.take(design).column(), t, LOADS)
            if energy:
                curve = dense.static + cutting * dense.cut - mean[design][:, None]
                curve = curve + w2[speed][:, None] * dense.inertial
            else:
                curve = dense.static1 + cutting * dense.cut1 + w2[speed][:, None] * dense.inertial1
            signed = sign * curve > 0.0
            assert np.all(signed.all(axis=-1) | ~signed.any(axis=-1))
    assert min(counts) > 10
