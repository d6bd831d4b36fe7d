"""The driving torque split by speed (core.forces.jet) against the Newton–Euler elimination.

The loaded sweep and the cycle summary take the torque as V′ + ω²·K′ + P·dCx/dφ and its
slope and curvature from the closed form; that only holds if the solver's torque, which
eliminates every joint force, is exactly that sum at every speed (virtual work for a
frictionless chain at constant crank speed), and if the closed-form rates are the slopes
of the values, which central differences check."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from test_extrema import corner_designs
from test_sweep_loaded import _loads

from core.forces.dynamics import solve_dynamics
from core.forces.jet import torque_jet
from core.linkage.designs import Designs
from core.linkage.kinematics import sharp_angles


def _angles(design) -> np.ndarray:
    """A cycle's uniform samples and samples close to the sharp angles of a rod near upright."""
    near = (sharp_angles(design)[:, None] + np.array([-1e-3, -1e-5, 0.0, 1e-5, 1e-3])).ravel()
    return np.sort(np.concatenate([np.linspace(0.0, 2.0 * math.pi, 721), near]))


@settings(max_examples=30, deadline=None)
@given(corner_designs(), st.integers(0, 2 ** 32 - 1))
def test_the_solvers_torque_is_the_jets_sum_at_every_speed(design, seed):
    rng = np.random.default_rng(seed)
    masses = _loads(rng, design.rod is not None)
    phi = _angles(design)
    rpms = np.sort(rng.uniform(1.0, 400.0, 4))
    dyn = solve_dynamics(design, phi, rpms, masses)
    jet = torque_jet(Designs.of(design).column(), phi, masses)
    cutting = dyn.cut_force[0] > 0.0
    got = jet.static[0] + dyn.omega[:, None] ** 2 * jet.inertial[0] + cutting * jet.cut[0]
    scale = np.max(np.abs(dyn.crank_torque), axis=-1, keepdims=True)
    # A rod a hair longer than its reach divides by a reach of ~1e-3·L4 in both: some digits go.
    assert np.all(np.abs(got - dyn.crank_torque) <= 1e-9 * scale)


@pytest.mark.parametrize("ratio, side", [(None, "leading"), (0.3, "leading"), (0.9, "trailing")])
def test_the_jets_rates_are_the_slopes_of_its_values(ratio, side):
    from core.linkage.spec import Spec
    from core.forces.masses import MassProperties
    spec = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant="block" if ratio is None else "rod",
                rod_ratio=ratio or 0.3, rod_side=side)
    masses = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                            rod_mass_kg=0.0 if ratio is None else 6.0, block_mass_kg=3.0,
                            cut_force_N=7000.0, cut_height_mm=80.0)
    col = Designs.of(spec.design()).column()
    phi, h = np.linspace(0.0, 2.0 * math.pi, 361), 1e-5
    jet, ahead, behind = (torque_jet(col, phi + s, masses) for s in (0.0, h, -h))
    for name in ("static", "inertial", "cut"):
        for order, suffix in ((1, "1"), (2, "2")):
            value = name if order == 1 else name + "1"
            slope = (getattr(ahead, value) - getattr(behind, value)) / (2.0 * h)
            exact = getattr(jet, name + suffix)
            assert np.max(np.abs(slope - exact)) <= 1e-8 * np.max(np.abs(exact)), (name, order)


@settings(max_examples=20, deadline=None)
@given(corner_designs(), st.integers(0, 2 ** 32 - 1))
def test_the_jet_without_its_curvature_is_the_same_jet(design, seed):
    """The energy's polish asks for the jet without its ``*2`` fields (the fourth derivatives
    not taken); every other field is the full jet's bit for bit (the rod's mass included),
    and so with θ handed to the designs rather than computed."""
    rng = np.random.default_rng(seed)
    masses = _loads(rng, design.rod is not None)
    col = Designs.of(design).column()
    phi = _angles(design)
    full = torque_jet(col, phi, masses)
    given_theta = col.with_lengths(col.lengths(), np.asarray(col.theta).copy())
    lean = torque_jet(given_theta, phi, masses, curvature=False)
    for name, value in zip(full._fields, lean):
        if name.endswith("2"):
            assert value is None
        else:
            np.testing.assert_array_equal(value, getattr(full, name))


def test_the_grids_trig_by_angle_addition_is_numpys_to_rounding():
    """cos β and sin β on a grid shared by many designs (core.forces.jet.grid_trig, the sweep's
    and the summary's grid) against numpy's cos and sin of β = π + θ/2 − φ, and against
    long double: every sample within 1e-15, as near the exact cosine as numpy's own."""
    from core.forces.jet import grid_trig
    rng = np.random.default_rng(3)
    crank = rng.uniform(20.0, 140.0, 500)
    d = Designs(crank, crank / rng.uniform(0.05, 0.86, 500), np.full(500, 600.0), np.full(500, 500.0))
    col = d.column()
    phi = np.linspace(0.0, 2.0 * math.pi, 91)
    cb, sb = grid_trig(col, phi)
    beta = math.pi + np.asarray(col.theta) / 2.0 - phi
    assert np.abs(cb - np.cos(beta)).max() <= 1e-15 and np.abs(sb - np.sin(beta)).max() <= 1e-15
    exact = np.longdouble(math.pi) + np.asarray(col.theta, dtype=np.longdouble) / 2 - phi.astype(np.longdouble)
    for got, numpy_, want in ((cb, np.cos(beta), np.cos(exact)), (sb, np.sin(beta), np.sin(exact))):
        assert np.abs(got - want).max() <= max(np.abs(numpy_ - want).max(), 2 ** -52) * 1.5
