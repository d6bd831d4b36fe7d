"""The loaded sweep's shortcuts at many speeds give the figures of polishing every turning
cell to the end (issue 42, item 12).

:mod:`core.forces.torque_peaks` skips a turning cell when its chord bound in ω²
(:func:`~core.forces.torque_peaks.chord_bounds`) shows that it cannot beat the candidates
known at its speed, and Newton's method starts from the top of the quintic through the
cell's ends (:func:`core.linkage.polish.newton_maximum` with ``curvatures``), stopping when
the next step would change the value by 1e-15 of itself, for the torque's peaks and the
energy's extremes alike. Checked here against independent references: the chord against
each cell's dense maximum, the quintic's top against a peak known in closed form, and the
sweep's figures against the path without the shortcuts (every cell polished, from the
cubic's top, to a step of 1e-12 rad).
"""
import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from test_sweep_fast_paths import rod_family, skewed_peak
from test_sweep_loaded import KEYS, _loads, random_family

import core.forces.cells as cells_
import core.forces.flywheel as flywheel
import core.forces.torque_peaks as torque_peaks
import core.linkage.polish as polish
from core.forces.jet import torque_jet
from core.forces.masses import MassProperties
from core.linkage.cut import cut_window
from core.linkage.kinematics import rpm_to_omega
from core.space.sweep import SWEEP_INTERVALS, spec_designs

finite = dict(allow_nan=False, allow_infinity=False)
LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       rod_mass_kg=4.0, cut_force_N=7000.0, cut_height_mm=80.0)


def test_a_cells_chord_bound_lies_above_its_largest_value_on_401_angles():
    """The bound a skipped cell is judged by: for every turning cell of the benchmark's rod
    family at 16 speeds whose run of turning speeds has a speed outside it on both sides,
    the chord in ω² lies above sign·T on 401 angles across the cell (T from the jet: the
    convexity argument, not the code's own samples, is what is checked)."""
    d = rod_family(12)
    omega = rpm_to_omega(np.arange(10.0, 170.0, 10.0))
    w2 = omega ** 2
    phi = np.linspace(0.0, 2.0 * math.pi, SWEEP_INTERVALS + 1)
    grid = torque_jet(d.column(), phi, LOADS)
    samples = flywheel._torque_samples(d, grid, LOADS)
    on, off = cut_window(d, LOADS.idle_fraction, (phi, grid.ram_x))
    window = cells_.switch_window(d, samples, on, off, LOADS)
    jet = samples[1]
    checked = 0
    for k, cutting in enumerate((1.0, 0.0)):
        values = (jet.static + cutting * jet.cut, jet.inertial)
        slopes = (jet.static1 + cutting * jet.cut1, jet.inertial1)
        for kind, cells in cells_.turning_cells(slopes, w2, window.cells[k]):
            sign = 1.0 - 2.0 * kind
            both = (cells.below >= 0) & (cells.above >= 0)
            cells = cells_.Cells(*(v[both] for v in cells))
            ends = cells_.cell_ends(values, cells_.cell_index(values[0].shape[-1], cells))
            sides = [torque_peaks.cell_top(ends, w2, sign, s) for s in (cells.below, cells.above)]
            polished = np.zeros(cells.design.size, dtype=bool)
            bound = torque_peaks.chord_bounds(w2, cells.speed, (cells.below, sides[0], sides[0]),
                                              (cells.above, sides[1], sides[1]), (polished, polished))
            at = cells.lo[:, None] + (cells.hi - cells.lo)[:, None] * np.linspace(0.0, 1.0, 401)
            one = torque_jet(d.take(cells.design).column(), at, LOADS)
            torque = sign * (one.static + w2[cells.speed][:, None] * one.inertial + cutting * one.cut)
            assert np.all(torque.max(axis=-1) <= bound)
            checked += cells.design.size
    assert checked > 1000


@settings(max_examples=60, deadline=None)
@given(centre=st.floats(-3.0, 3.0, **finite), offset=st.floats(0.01, 0.99, **finite),
       width=st.floats(0.01, 0.1, **finite), size=st.floats(0.1, 1e4, **finite),
       skew=st.floats(-0.9, 0.9, **finite))
# drawn in a run: 7 ulps under the top, the gain's 1e-15 and the value's own rounding
@example(centre=0.0, offset=0.90625, width=0.016540005342472006, size=3.0, skew=-0.21875)
def test_from_the_quintics_top_newton_ends_sooner_on_a_known_peak(centre, offset, width, size, skew):
    """test_sweep_fast_paths' skewed peak, top at c: given the ends' curvatures, the polish
    starts nearer c than from the cubic's top (or both within 1e-13 of the cell) and, with
    the sweep's gain, ends at c's value in no more evaluations. "At c's value": within the
    gain (the polish stops once the step's predicted rise is at most gain·|value|) plus
    the rounding of the value itself (a few ulps: cos, sin², a sum and a product)."""
    calls = []
    fun = skewed_peak(centre, size, skew, calls)
    lo, hi = np.array([centre - offset * width]), np.array([centre + (1.0 - offset) * width])
    (v_lo, s_lo, c_lo), (v_hi, s_hi, c_hi) = fun(lo), fun(hi)
    args = (v_lo, v_hi, s_lo * width, s_hi * width)
    cubic = polish._cubic_top(*args)
    quintic = polish._quintic_top(*args, c_lo * width ** 2, c_hi * width ** 2, cubic)
    assert abs(quintic[0] - offset) <= max(abs(cubic[0] - offset), 1e-13)
    counts = []
    for curvatures in (None, (c_lo, c_hi)):
        calls.clear()
        x, value = polish.newton_maximum(fun, lo, hi, v_lo, v_hi, s_lo, s_hi,
                                         gain=torque_peaks.PEAK_GAIN, curvatures=curvatures)
        assert value[0] == pytest.approx(size, rel=torque_peaks.PEAK_GAIN + 4 * np.finfo(float).eps, abs=0.0)
        counts.append(len(calls))
    assert counts[1] <= counts[0]


@settings(max_examples=60, deadline=None)
@given(centre=st.floats(-3.0, 3.0, **finite), offset=st.floats(0.01, 0.99, **finite),
       width=st.floats(0.01, 0.1, **finite), size=st.floats(0.1, 1e4, **finite),
       skew=st.floats(-0.9, 0.9, **finite))
def test_from_the_quintic_through_the_slopes_jet_newton_finds_a_known_crossing(
        centre, offset, width, size, skew):
    """The energy's start (:func:`core.linkage.polish.newton_crossing`): on test_sweep_fast_paths'
    skewed peak, whose slope g = f′ falls through zero at c exactly, the zero of the quintic
    through g, g′ = f″ and g″ = f‴ = size·(sin t − 2·skew·sin 2t) at the cell's ends lies
    within 1e-8 of the cell from c (1.05e-9 was the worst of 20 000 random cells up to 0.1 rad
    wide), and Newton's method from it ends at the peak's value after at most two evaluations
    with the sweep's gain."""
    calls = []
    fun = skewed_peak(centre, size, skew, calls)
    lo, hi = np.array([centre - offset * width]), np.array([centre + (1.0 - offset) * width])
    (_, g_lo, r_lo), (_, g_hi, r_hi) = fun(lo), fun(hi)
    third = [size * (np.sin(t) - 2.0 * skew * np.sin(2.0 * t)) for t in (lo - centre, hi - centre)]
    start = polish._quintic_zero(g_lo, g_hi, r_lo * width, r_hi * width,
                                 third[0] * width ** 2, third[1] * width ** 2)
    assert abs(start[0] - offset) <= 1e-8
    calls.clear()
    x, value = polish.newton_crossing(fun, lo, hi, (g_lo, g_hi), (r_lo, r_hi), tuple(third),
                                      gain=torque_peaks.PEAK_GAIN)
    assert value[0] == pytest.approx(size, rel=torque_peaks.PEAK_GAIN + 4 * np.finfo(float).eps, abs=0.0)
    assert len(calls) <= 2


def _reference(monkeypatch):
    """The path without the shortcuts: no cell skipped (neither by its chord nor for turning
    beyond a switch angle), Newton from the cubic's top (the energy's: from the secant's
    zero of its slope) to a step of 1e-12 rad (what the sweep did before, up to the rounding
    of its last step)."""
    monkeypatch.setattr(torque_peaks, "chord_bounds",
                        lambda w2, speed, *rest: np.full(speed.shape, np.inf))
    for module in (torque_peaks, flywheel):
        monkeypatch.setattr(module, "turns_beyond",
                            lambda slope, leaving, sign: np.zeros(leaving.shape, dtype=bool))
    monkeypatch.setattr(polish, "_quintic_top", lambda v0, v1, m0, m1, c0, c1, t, steps=3: t)
    monkeypatch.setattr(polish, "_quintic_zero",
                        lambda g0, g1, m0, m1, c0, c1, steps=4: np.clip(g0 / (g0 - g1), 0.0, 1.0))
    monkeypatch.setattr(torque_peaks, "PEAK_GAIN", 0.0)
    monkeypatch.setattr(flywheel, "PEAK_GAIN", 0.0)


@pytest.mark.parametrize("variant, seed", [("block", 11), ("rod", 12), ("rod", 13)])
def test_at_16_speeds_the_shortcuts_give_every_cells_polish(monkeypatch, variant, seed):
    """Random designs (test_sweep_loaded's family), random loads, 16 random speeds
    from 1 to 400 r/min: every figure equals the reference path's to 1e-9 (of the peak torque
    for the torques), and the shortcut polishes under 60 % of the reference's torque cells
    (46-50 % on these three families)."""
    rng = np.random.default_rng(seed)
    n = 60
    spec, values = random_family(rng, variant, n)
    designs, verdict = spec_designs(spec, values)
    d = designs.flat().take(np.flatnonzero(verdict.ok.reshape(-1)))
    assert d.shape[0] >= n // 3
    omega = rpm_to_omega(np.sort(rng.uniform(1.0, 400.0, 16)))
    masses = _loads(rng, variant == "rod")
    cells = []
    newton = torque_peaks.newton_maximum

    def counted(fun, lo, *rest, **kw):
        cells.append(lo.size)
        return newton(fun, lo, *rest, **kw)
    monkeypatch.setattr(torque_peaks, "newton_maximum", counted)
    fast = flywheel.cycle_summary(d, omega, masses, intervals=SWEEP_INTERVALS)
    polished, cells[:] = sum(cells), []
    _reference(monkeypatch)
    slow = flywheel.cycle_summary(d, omega, masses, intervals=SWEEP_INTERVALS)
    assert polished < 0.6 * sum(cells)
    scale = np.maximum(np.abs(slow["max_torque_N_m"]), np.abs(slow["min_torque_N_m"]))
    for key in KEYS:
        size = scale if "torque" in key else np.abs(slow[key])
        assert np.all(np.abs(fast[key] - slow[key]) <= 1e-9 * np.maximum(size, 1e-12)), key
