"""Comparing at the finest step fits in bounded memory (issue 33, item 7).

``library compare base rod16 --step 0.0002 --csv`` peaked at 1.5 GB though the table does
not depend on the step, and six designs with ``--curves-csv`` at 3 GB: every
intermediate of the mechanism was kept for 1.8 million angles and the CSV was made as
one string. Now the table computes no curves, the curves are solved in chunks into the
arrays they fill, and the CSV is written in pieces. Peaks are measured with tracemalloc
(numpy reports its arrays to it).
"""
import csv
import io
import tracemalloc

import numpy as np
import pytest

from core.space import compare as compare_module
from core.space.compare import Candidate, compare, curves_csv
from core.forces.masses import MassProperties
from core.files.io import snap_zeros
from core.linkage.kinematics import MIN_STEP_DEG, crank_angles, solve
from core.library import Library
from core.linkage.spec import Spec

from cli_runner import shaper_in_process

MASSES = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0, cut_force_N=7000.0)
SPECS = [Spec(), Spec(time_ratio=1.6, variant="rod"), Spec(crank=80.0, time_ratio=1.5, stroke=250.0),
         Spec(crank=90.0, time_ratio=1.45, stroke=280.0), Spec(crank=110.0, time_ratio=1.3, stroke=320.0, variant="rod"), Spec(time_ratio=1.55)]


def peak_mb(work):
    tracemalloc.start()
    try:
        work()
        return tracemalloc.get_traced_memory()[1] / 1e6
    finally:
        tracemalloc.stop()


def make_library(path, count):
    with Library(path) as lib:
        for i, spec in enumerate(SPECS[:count]):
            lib.add(f"d{i}", {"spec": spec, "rpm": [60.0], "step_deg": 1.0, "masses": MASSES if i % 2 == 0 else None})


def test_the_table_at_the_finest_step_computes_no_curves(tmp_path):
    library = tmp_path / "L.sqlite"
    make_library(library, 2)
    out = tmp_path / "t.csv"
    result = []
    peak = peak_mb(lambda: result.append(shaper_in_process("library", "compare", "d0", "d1", "--step",
                                                           f"{MIN_STEP_DEG:g}", "--csv", out, "--library", library)))
    assert result[0][0] == 0, result[0][2]
    assert peak < 50, f"{peak:.0f} MB"
    assert out.read_text().startswith("figure,unit,better,d0,d1")


def test_six_designs_curves_take_little_more_than_the_curves(tmp_path):
    library = tmp_path / "L.sqlite"
    make_library(library, 6)
    step = 0.002
    n = crank_angles(step).size
    curves_mb = 6 * 4 * n * 8 / 1e6                       # x, v, a, torque per design and angle
    result = []
    peak = peak_mb(lambda: result.append(shaper_in_process(
        "library", "compare", *[f"d{i}" for i in range(6)], "--step", f"{step:g}", "--curves-csv", "/dev/null",
        "--csv", tmp_path / "t.csv", "--library", library)))
    assert result[0][0] == 0, result[0][2]
    assert peak < curves_mb + 40, f"{peak:.0f} MB for {curves_mb:.0f} MB of curves"


def reference_csv(candidates, rpm, step):
    """The curves CSV from one solve over all angles, written row by row (the old way)."""
    phi = crank_angles(step)
    columns = {"x": [], "v": [], "a": [], "t": []}
    from core.forces.dynamics import solve_dynamics
    from core.forces.masses import masses_for_design
    for c in candidates:
        design = c.spec.design()
        motion = solve(design, phi, [rpm])
        columns["x"].append(motion.ram_x)
        columns["v"].append(motion.ram_v[0])
        columns["a"].append(motion.ram_a[0])
        columns["t"].append(np.full(phi.size, np.nan) if c.masses is None else
                            solve_dynamics(design, phi, [rpm], masses_for_design(design, c.masses)).crank_torque[0])
    snapped = {k: snap_zeros(np.reshape(v, (-1, 1))).reshape(np.shape(v)) for k, v in columns.items()}
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(compare_module.CURVE_COLUMNS)
    for k, c in enumerate(candidates):
        for j, deg in enumerate(np.degrees(phi)):
            writer.writerow([c.label, "%.10g" % deg, *("%.10g" % snapped[key][k][j] for key in "xva"),
                             "" if c.masses is None else "%.10g" % snapped["t"][k][j]])
    return out.getvalue()


@pytest.mark.parametrize("step", [1.0, 0.37, 0.1])
def test_curves_solved_in_chunks_are_the_curves(monkeypatch, step):
    monkeypatch.setattr(compare_module, "CURVE_CHUNK", 500)
    candidates = [Candidate("a,\"b\"", SPECS[0], MASSES), Candidate("rod", SPECS[1]), Candidate("=c", SPECS[2], MASSES)]
    result = compare(candidates, 60.0, step)
    phi = crank_angles(step)
    for k, c in enumerate(candidates):
        motion = solve(c.spec.design(), phi, [60.0])
        np.testing.assert_allclose(result.ram_x_mm[k], motion.ram_x, rtol=0, atol=1e-9)
        np.testing.assert_allclose(result.ram_a_m_s2[k], motion.ram_a[0], rtol=1e-12, atol=1e-12)
    assert curves_csv(result) == reference_csv([Candidate("'" + c.label if c.label.startswith("=") else c.label,
                                                          c.spec, c.masses) for c in candidates], 60.0, step)
