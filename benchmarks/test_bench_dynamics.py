"""Joint forces for 3601 crank angles × 4 speeds; target median ≤ 5 ms per variant.

Measure with: python -m pytest benchmarks/test_bench_dynamics.py --benchmark-enable -n 0 -q
"""
from __future__ import annotations

import numpy as np
import pytest

from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties
from core.linkage.geometry import synthesize

ANGLES = np.linspace(0.0, 2.0 * np.pi, 3601)
RPMS = [20.0, 40.0, 60.0, 80.0]
DESIGNS = {
    "block": synthesize(100.0, 1.4, 300.0),
    "rod": synthesize(100.0, 1.4, 300.0, guide="sagitta", rod_ratio=0.45),
}


@pytest.mark.parametrize("variant", sorted(DESIGNS))
def test_bench_forces(benchmark, variant):
    design = DESIGNS[variant]
    masses = MassProperties(lever_mass_kg=25.0, lever_inertia_kg_m2=0.8, ram_mass_kg=60.0,
                            ram_cg_mm=(40.0, -20.0), block_mass_kg=2.5, crank_mass_kg=8.0,
                            rod_mass_kg=5.0 if design.rod is not None else 0.0,
                            cut_force_N=3000.0, cut_height_mm=60.0)
    dyn = benchmark(solve_dynamics, design, ANGLES, RPMS, masses)
    assert dyn.crank_torque.shape == (4, 3601)
    assert np.isfinite(dyn.crank_torque).all()
