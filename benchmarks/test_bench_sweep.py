"""Speed targets of the design-space sweep (issue 11): 10^5 designs' exact cycle figures in
≤ 2 s, and at least 100× faster than ``analyze`` in a loop.

Run with ``pytest benchmarks --benchmark-enable -n 0 -k sweep``; in the normal test
run each benchmark executes once as a smoke test. The loop is measured on a
subset (``LOOP``) and compared per design.
"""
import math

import numpy as np
import pytest

from core.forces.masses import MassProperties
from core.linkage.metrics import analyze
from core.linkage.spec import Spec
from core.space.sweep import evaluate, grid

COUNT = 100_000
LOOP = 300
SPEC_BLOCK = Spec(crank=100.0, time_ratio=1.46, stroke=312.0)
SPEC_ROD = Spec(crank=100.0, time_ratio=1.46, stroke=312.0, variant="rod", rod_ratio=0.3)
# K = 3.1 with a guide above the lever tip: 28 937 of the 90 000 rods of JAMS jam at a dead centre
SPEC_JAMS = Spec(mode="dimensions", crank=300.0, frame=400.0, lever=900.0, variant="rod", rod_input="length",
                 guide_rule="height", guide_height=1000.0, rod_length=500.0)
JAMS = {"guide": (900.0, 1170.0, 300), "rod": (300.0, 1000.0, 300)}


def _values(count, rod):
    """A 2-D family like the Explore tab's: crank × K (block) or rod ratio × guide (rod)."""
    side = 4 * int(round((count / 4) ** 0.5))       # 100 000 = 632 × 158 … exactly count
    side = next(s for s in range(side, 0, -1) if count % s == 0)
    a, b = np.meshgrid(np.linspace(0, 1, side), np.linspace(0, 1, count // side), indexing="ij")
    if rod:
        return {"rod_ratio": 0.25 + 0.9 * a.ravel(), "guide": 480.0 + 200.0 * b.ravel()}
    return {"crank": 60.0 + 80.0 * a.ravel(), "time_ratio": 1.1 + 1.2 * b.ravel()}


def test_sweep_1e5_designs_block(benchmark):
    values = _values(COUNT, rod=False)
    ev = benchmark.pedantic(evaluate, args=(SPEC_BLOCK, values, [40.0]), rounds=5, iterations=1)
    assert ev.valid.size == COUNT and ev.valid.sum() > COUNT // 3


def test_sweep_1e5_designs_rod(benchmark):
    values = _values(COUNT, rod=True)
    ev = benchmark.pedantic(evaluate, args=(SPEC_ROD, values, [40.0]), rounds=5, iterations=1)
    assert ev.valid.size == COUNT and ev.valid.sum() > COUNT // 3


def test_sweep_reasons_with_many_dead_centres(benchmark):
    """The reason column of ``shaper sweep`` (each refused design's one line) where a third of
    the designs jam at a dead centre: each of those reasons names the least rod that clears it,
    searched for all of them at once when the first is read (docs/performance.md). A fresh
    evaluation each round (not timed), since the search's result is kept once made."""
    from core.cli.cmd_sweep import reasons
    out = benchmark.pedantic(reasons, setup=lambda: ((evaluate(SPEC_JAMS, grid(JAMS), [40.0]),), {}),
                             rounds=5, iterations=1)
    assert sum("dead-centre" in r for r in out) == 28_937


def _loop(spec, values):
    for i in range(LOOP):
        design = spec.__class__(**{**spec.__dict__, **_single(values, i)}).design()
        analyze(design, [40.0])


def _single(values, i):
    out = {}
    for key, v in values.items():
        if key == "guide":
            out.update(guide_rule="height", guide_height=float(v[i]))
        else:
            out[key] = float(v[i])
    return out


def test_analyze_loop_block_per_300(benchmark):
    values = _values(COUNT, rod=False)
    pick = {k: v[:: COUNT // LOOP] for k, v in values.items()}
    ok = evaluate(SPEC_BLOCK, pick, [40.0]).valid
    pick = {k: v[ok] for k, v in pick.items()}
    pick = {k: np.resize(v, LOOP) for k, v in pick.items()}
    benchmark.pedantic(_loop, args=(SPEC_BLOCK, pick), rounds=3, iterations=1)


def test_analyze_loop_rod_per_300(benchmark):
    values = _values(COUNT, rod=True)
    pick = {k: v[:: COUNT // LOOP] for k, v in values.items()}
    ok = evaluate(SPEC_ROD, pick, [40.0]).valid
    pick = {k: np.resize(v[ok], LOOP) for k, v in pick.items()}
    benchmark.pedantic(_loop, args=(SPEC_ROD, pick), rounds=3, iterations=1)


def test_sweep_2500_designs_with_loads(benchmark):
    values = _values(2500, rod=True)
    masses = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                            cut_force_N=7000.0, cut_height_mm=80.0)
    ev = benchmark.pedantic(evaluate, args=(SPEC_ROD, values, [40.0], masses), rounds=1,
                            iterations=1)
    assert ev.dynamics is not None


def test_summarize_one_design_4_speeds(benchmark):
    """The dynamics summary the GUI recomputes on every edit (exact torque peaks included)."""
    from core.forces.flywheel import summarize

    design = SPEC_ROD.design()
    masses = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                            cut_force_N=7000.0, cut_height_mm=80.0)
    summary = benchmark(summarize, design, [30.0, 40.0, 60.0, 80.0], masses)
    assert len(summary.speeds) == 4


SWEEP_1E5 = ["sweep", "--crank", "100", "--K", "1.46", "--stroke", "312", "--rod-ratio", "0.3",
             "--vary", "rod-ratio=0.25:1.15:317", "--vary", "guide=480:680:317", "--rpm", "40"]


def test_cli_sweep_100489_rod_designs_to_csv(benchmark, tmp_path):
    """Issue 24: ``shaper sweep`` of 317 × 317 rod designs to a CSV file, the whole process."""
    import shutil
    import subprocess
    import sys
    exe = shutil.which("shaper")
    cmd = ([exe] if exe else [sys.executable, "-m", "core"]) + SWEEP_1E5 + ["--csv", str(tmp_path / "s.csv")]
    benchmark.pedantic(subprocess.run, args=(cmd,), kwargs={"check": True}, rounds=3, iterations=1)
    assert sum(1 for _ in (tmp_path / "s.csv").open()) == 1 + 317 * 317


def _command_rows(rod: bool, rpms, masses) -> tuple[dict, dict]:
    """The designs of one block of ``shaper sweep`` without loads and one with ``masses``, each
    of the size the command evaluates at a time (:func:`core.cli.cmd_sweep.block_size`: 7142
    unloaded designs at 16 speeds with two varied names, 36 363 at one, ``LOADED_BLOCK`` with
    loads). The unloaded row's cost falls with the block (a fixed cost per call) and the loaded
    one's hardly does, so a ratio taken at one common size (500 designs) flattered the loaded
    path: 6-10× there was 15-16× at the command's own blocks (docs/performance.md). The
    command keeps freed memory in the process (:func:`core.cli.allocator.keep_freed_memory`),
    so this does too: without it each loaded chunk faults its pages in anew."""
    from core.cli.allocator import keep_freed_memory
    from core.cli.cmd_sweep import block_size
    keep_freed_memory()
    names = ["rod_ratio", "guide"] if rod else ["crank", "time_ratio"]
    return tuple(_values(block_size(names, rpms, m), rod=rod) for m in (None, masses))


def _row_times(spec, values, rpms, masses, rounds=3):
    """CPU seconds per design of the sweep without and with loads, the best of ``rounds``
    alternating runs of each, on ``values`` (the unloaded block, the loaded block:
    :func:`_command_rows`). CPU time of this process, not wall time: the machine is
    shared, and a ratio of CPU times hardly moves with the load around it."""
    import time
    best = [math.inf, math.inf]
    for _ in range(rounds):
        for i, loads in enumerate((None, masses)):
            size = values[i][next(iter(values[i]))].size
            start = time.process_time()
            evaluate(spec, values[i], rpms, loads)
            best[i] = min(best[i], (time.process_time() - start) / size)
    return best[0], best[1]


LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)
SPEEDS_16 = [10.0 * k for k in range(1, 17)]


@pytest.mark.parametrize("rod", [False, True], ids=["block", "rod"])
def test_loaded_row_at_most_10_unloaded_rows(benchmark, rod):
    """Issue 42, item 12: a loaded sweep row costs at most 10 unloaded ones (one speed, each
    at the command's block, 36 363 unloaded and 2000 loaded designs, the best of 5 alternating
    runs of each; 215× before the sweep's own bracketing grid, 22–28× on 360 intervals, 6–10×
    with Brent's polish, 3.5–8× with Newton's on the closed-form slope, 4.3–5.0 at the
    command's blocks). ``-s`` prints the times; the figures are in docs/performance.md."""
    values = _command_rows(rod, [40.0], LOADS)
    plain, loaded = benchmark.pedantic(_row_times, args=(SPEC_ROD if rod else SPEC_BLOCK, values,
                                                         [40.0], LOADS, 5), rounds=1, iterations=1)
    print(f"\n1 speed: unloaded {plain * 1e6:.0f} µs/row, loaded {loaded * 1e6:.0f} µs/row, "
          f"ratio {loaded / plain:.1f}")
    # The target when measured; the suite's smoke run shares the machine with its other
    # worker, where a margin keeps it from failing on the neighbour's load.
    assert loaded / plain <= (10.0 if not benchmark.disabled else 13.0)


@pytest.mark.parametrize("rod", [False, True], ids=["block", "rod"])
def test_loaded_row_at_16_speeds(benchmark, rod):
    """The issue's own case, 16 speeds, held to the same 10: each speed has its own torque and
    energy extrema while an unloaded row scales one set of peaks, but the torque's slope is
    affine in ω², so which cells hold an extremum at each speed comes from one binary search
    per sample, and a cell's largest value is convex in ω², so a chord between speeds skips
    the cells that cannot win (74× block and 95× rod on 360 intervals, 18–36× with Brent's
    polish, 7.7–12.9× with Newton's on every cell, 6.1–10.1× on 500 designs, which flattered
    it: 15–16× at the command's own blocks, 9.9–14.3 with its kept memory, 8.8–11.9 after
    the gathers' and integer cuts; 7.3–8.5 since the rest of the cycle's cells are only
    those reaching it, the energy starts from the quintic through its slope's jet and the
    grid's trig is shared, docs/performance.md). The best of 3 alternating rounds when
    measured (2 in the suite's smoke run)."""
    values = _command_rows(rod, SPEEDS_16, LOADS)
    rounds = 2 if benchmark.disabled else 3
    plain, loaded = benchmark.pedantic(_row_times, args=(SPEC_ROD if rod else SPEC_BLOCK, values,
                                                         SPEEDS_16, LOADS, rounds), rounds=1,
                                       iterations=1)
    print(f"\n16 speeds: unloaded {plain * 1e6:.0f} µs/row, loaded {loaded * 1e6:.0f} µs/row, "
          f"ratio {loaded / plain:.1f}")
    # The 10 when measured; the suite's smoke run (2 rounds, the machine shared with
    # its other worker) keeps a margin to 20.
    assert loaded / plain <= (10.0 if not benchmark.disabled else 20.0)
