"""Speed targets of the core issue: measured here, reported in docs/performance.md.

Run with ``pytest benchmarks --benchmark-enable -n 0``; in the normal test run each
benchmark executes once as a smoke test.
"""
import shutil
import subprocess
import sys

import numpy as np

from core.linkage.geometry import synthesize
from core.linkage.kinematics import solve
from core.linkage.metrics import analyze

ANGLES = np.radians(np.linspace(0, 360, 3601))
RPMS = [30, 40, 60, 80]


def test_kinematics_3601_angles_4_speeds_block(benchmark):
    design = synthesize(100, 1.4, 300)
    motion = benchmark(solve, design, ANGLES, RPMS)
    assert motion.ram_a.shape == (4, 3601)


def test_kinematics_3601_angles_4_speeds_rod(benchmark):
    design = synthesize(100, 1.4, 300, rod_ratio=0.3)
    motion = benchmark(solve, design, ANGLES, RPMS)
    assert motion.rod_alpha.shape == (4, 3601)


def test_kinematics_3601_angles_4_speeds_rod_held(benchmark):
    """As the GUI's model does: the previous cycle stays alive while the next is solved.

    The rows above drop each result at once; then glibc gives the ~1.8 MB of arrays that a
    cycle returns back to the system (its heap trim threshold is 128 KB, or twice the largest
    block it once mapped) and the next call faults them in again, which can triple the time
    (docs/performance.md, issue 24). Holding the previous cycle keeps that memory in the heap.
    """
    design = synthesize(100, 1.4, 300, rod_ratio=0.3)
    held = [solve(design, ANGLES, RPMS)]

    def next_cycle():
        held[0] = solve(design, ANGLES, RPMS)

    benchmark(next_cycle)
    assert held[0].rod_alpha.shape == (4, 3601)


def test_cycle_metrics(benchmark):
    design = synthesize(100, 1.4, 300, rod_ratio=0.3)
    metrics = benchmark(analyze, design, RPMS)
    assert len(metrics.speeds) == 4


def _cli_csv(target, *variant):
    exe = shutil.which("shaper")
    cmd = [exe] if exe else [sys.executable, "-m", "core"]
    subprocess.run(cmd + ["curves", "--crank", "100", "--K", "1.4", "--stroke", "300", *variant,
                          "--rpm", "40", "60", "--step", "0.01", "--csv", str(target)], check=True)


def test_cli_csv_36001_angles_2_speeds(benchmark, tmp_path):
    target = tmp_path / "curves.csv"
    benchmark.pedantic(_cli_csv, args=(target, "--rod-ratio", "0.3"), rounds=5, iterations=1)
    assert sum(1 for _ in target.open()) == 1 + 2 * 36001


def test_cli_csv_36001_angles_2_speeds_block(benchmark, tmp_path):
    """Issue 24's command (block variant, 11 columns), whole process including start-up."""
    target = tmp_path / "curves.csv"
    benchmark.pedantic(_cli_csv, args=(target,), rounds=5, iterations=1)
    assert sum(1 for _ in target.open()) == 1 + 2 * 36001


def _curve_table_36001_2():
    from core.files.io import curve_table
    motion = solve(synthesize(100, 1.4, 300), np.radians(np.linspace(0, 360, 36001)), [40, 60])
    return curve_table(motion)


def test_csv_text_of_curves_72002_rows(benchmark):
    """Issue 24: the text of ``shaper curves``' table (block variant, 72 002 rows × 11
    columns) as core.files.io writes it, the vectorized "%.10g" of core.files.numtext."""
    from core.files.io import table_csv
    names, data = _curve_table_36001_2()
    text = benchmark.pedantic(table_csv, args=(names, data), rounds=5, iterations=1)
    assert text.count("\n") == 72003


def test_csv_text_of_curves_72002_rows_python_percent(benchmark):
    """The same numbers with Python's % per block of rows, as core.files.io wrote them before
    issue 24: the comparison for the row above."""
    from core.files.io import snap_zeros
    names, data = _curve_table_36001_2()

    def python_text():
        values = snap_zeros(data)
        row = ",".join(["%.10g"] * values.shape[1]) + "\n"
        return ",".join(names) + "\n" + "".join(
            (row * len(block)) % tuple(block.ravel().tolist())
            for block in (values[i:i + 20_000] for i in range(0, len(values), 20_000)))

    text = benchmark.pedantic(python_text, rounds=5, iterations=1)
    assert text.count("\n") == 72003
