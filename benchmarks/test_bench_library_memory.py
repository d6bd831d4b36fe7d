"""Peak memory of the library's heavy cases (issue 33, item 7): each bounded by 600 MB.

Each case runs in a fresh process that reports its own peak resident size (VmHWM; see
test_bench_sweep_memory.py for why not ru_maxrss), importing numpy and scipy being
about 40 MB of it:

- ``library compare A B --step 0.0002 --csv``: the table only (1.5 GB before);
- the same with ``--curves-csv`` (six designs: 3.07 GB and 31 s in the issue), three designs
  (see the test for why three hold the bound as six did); marked ``slow``;
- the Library pane opening a library whose one design has 50 MB of notes, then renaming
  another design (2.1 GB and 8.8 s to open, 4.5 s an edit, in the issue).

``--benchmark-enable -n 0`` reports the peaks (MB) as extra info.
"""
import subprocess
import sys
import textwrap

import pytest

LIMIT_MB = 600.0
MIN_STEP = "0.0002"
PEAK = ("peak = next(l for l in open('/proc/self/status') if l.startswith('VmHWM:'))\n"
        "print('PEAK_KB', peak.split()[1], file=sys.stderr)\n")
CLI = "import sys\nfrom core.cli import main\nstatus = main(sys.argv[1:])\n" + PEAK + "sys.exit(status)\n"
DESIGNS = [("base", ["--crank", "100", "--K", "1.4", "--stroke", "300", "--lever-mass", "20",
                     "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000"]),
           ("rod16", ["--crank", "100", "--K", "1.6", "--stroke", "300", "--rod-ratio", "0.3"]),
           ("c3", ["--crank", "80", "--K", "1.5", "--stroke", "250", "--lever-mass", "20",
                   "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000"]),
           ("d4", ["--crank", "90", "--K", "1.45", "--stroke", "280"]),
           ("d5", ["--crank", "110", "--K", "1.3", "--stroke", "320", "--rod-ratio", "0.3"]),
           ("d6", ["--crank", "100", "--K", "1.5", "--stroke", "300", "--lever-mass", "20",
                   "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000"])]


def run_peak_mb(code: str, *args: str) -> float:
    done = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    line = next(l for l in done.stderr.splitlines() if l.startswith("PEAK_KB"))
    return int(line.split()[1]) / 1024.0


def library_of(tmp_path, count: int) -> str:
    from core.cli import main
    path = str(tmp_path / "L.sqlite")
    for name, options in DESIGNS[:count]:
        assert main(["library", "add", *options, "--name", name, "--library", path]) == 0
    return path


def test_compare_table_at_the_finest_step(benchmark, tmp_path):
    library = library_of(tmp_path, 2)
    peak = {}
    benchmark.pedantic(lambda: peak.update(mb=run_peak_mb(
        CLI, "library", "compare", "base", "rod16", "--step", MIN_STEP, "--csv", str(tmp_path / "t.csv"),
        "--library", library)), rounds=1, iterations=1)
    benchmark.extra_info["peak_MB"] = round(peak["mb"], 1)
    print(f"peak {peak['mb']:.0f} MB")
    assert peak["mb"] <= LIMIT_MB


CURVES_DESIGNS = 3


@pytest.mark.slow
def test_compare_designs_curves_at_the_finest_step(benchmark, tmp_path):
    """Three designs, not the issue's six: half the work (six took 21.8 s of the suite), and
    600 MB still breaks if either half of the curves' fix is undone. Measured at 0.0002°
    (docs/performance.md, "The test suite's time (29 November, afternoon)"): three designs
    peak at 253 MB; with the curves solved for every angle at once (``CURVE_CHUNK`` = all)
    1644 MB, with the curves' CSV text made whole before it is written 1140 MB; on a0e1020^,
    before the fix (its table bloated too), 1795 MB. Six designs peak at 391–400 MB."""
    library = library_of(tmp_path, CURVES_DESIGNS)
    names = [name for name, _ in DESIGNS[:CURVES_DESIGNS]]
    peak = {}
    benchmark.pedantic(lambda: peak.update(mb=run_peak_mb(
        CLI, "library", "compare", *names, "--step", MIN_STEP, "--csv",
        str(tmp_path / "t.csv"), "--curves-csv", str(tmp_path / "c.csv"), "--library", library)),
        rounds=1, iterations=1)
    benchmark.extra_info["peak_MB"] = round(peak["mb"], 1)
    print(f"peak {peak['mb']:.0f} MB")
    assert peak["mb"] <= LIMIT_MB


PANE = textwrap.dedent("""
    import sys, time
    from PySide6.QtWidgets import QApplication
    from shaperapp.design.model import DesignModel
    from shaperapp.library.pane import LibraryPane
    app = QApplication([])
    pane = LibraryPane(DesignModel())
    pane.resize(1200, 500)
    pane.show()
    app.processEvents()
    start = time.perf_counter()
    assert pane.open_library(sys.argv[1])
    app.processEvents()
    opened = time.perf_counter() - start
    start = time.perf_counter()
    assert pane.actions.rename("small", "small2")
    app.processEvents()
    print("TIMES", opened, time.perf_counter() - start, file=sys.stderr)
""") + PEAK


def test_pane_with_50_mb_of_notes(benchmark, tmp_path):
    from core.library import Library
    from core.linkage.spec import Spec
    path = tmp_path / "L.sqlite"
    with Library(path) as lib:
        lib.add("big", {"spec": Spec(), "rpm": [40.0], "step_deg": 1.0, "masses": None}, notes="n" * 50_000_000)
        lib.add("small", {"spec": Spec(time_ratio=1.5), "rpm": [40.0], "step_deg": 1.0, "masses": None})
    peak = {}
    benchmark.pedantic(lambda: peak.update(mb=run_peak_mb(PANE, str(path))), rounds=1, iterations=1)
    benchmark.extra_info["peak_MB"] = round(peak["mb"], 1)
    print(f"peak {peak['mb']:.0f} MB")
    assert peak["mb"] <= LIMIT_MB
