"""Positions table (12 + 6 positions × 2 speeds, with forces) and the three polygons at one angle.

Measure with: python -m pytest benchmarks/test_bench_deliverables.py --benchmark-enable -n 0 -q
"""
from __future__ import annotations

import numpy as np
import pytest

from core.forces.masses import MassProperties
from core.linkage.geometry import synthesize
from core.forces.polygons import polygons
from core.course_design.positions import position_table, positions

LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)
DESIGNS = {"block": synthesize(100.0, 1.4, 300.0),
           "rod": synthesize(100.0, 1.4, 300.0, guide="sagitta", rod_ratio=0.45)}


@pytest.mark.parametrize("variant", sorted(DESIGNS))
def test_bench_positions_table(benchmark, variant):
    design = DESIGNS[variant]
    table = benchmark(lambda: position_table(design, positions(design), [40.0, 60.0], LOADS))
    assert table.data.shape[0] == 2 * 18 and np.isfinite(table.data[:, :5]).all()


def test_bench_polygons(benchmark):
    out = benchmark(polygons, DESIGNS["rod"], 100.0, 40.0, LOADS)
    assert out["force"].closure_error() < 1e-9 * out["force"].largest()
