"""Run pytest benchmarks in two trees in turn: ``python tools/bench_alternate.py REV ROUNDS -- PYTEST-ARGS…``.

Why: this 2-core machine runs the same code up to 40 % slower from one minute to the
next, so "no figure got worse" (issue 24, item 5) is only a fair claim when the
previous commit and the work tree are measured in one run, alternating. This exports
commit REV (``git archive``), copies the work tree's ``benchmarks/`` into it (so both
run the same benchmark code), then runs ``python -m pytest -n 0 --benchmark-enable
--benchmark-json=… PYTEST-ARGS…`` ROUNDS times in each tree in turn and prints, per
benchmark, the median of each run's median and the best min of each tree, and the
ratio work tree / REV.

Example: ``python tools/bench_alternate.py HEAD~1 3 -- benchmarks/test_bench_gui.py
benchmarks/test_bench_frame.py -k "nudge or jump or frame"``. Only a developer's tool.
"""
from __future__ import annotations

import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from perf_alternate import export_commit     # its neighbour in tools/ (on sys.path when run)

ROOT = Path(__file__).resolve().parents[1]


def _export(rev: str, target: Path) -> None:
    export_commit(rev, target)
    shutil.rmtree(target / "benchmarks")
    shutil.copytree(ROOT / "benchmarks", target / "benchmarks")


def _run(tree: Path, args: list[str], scratch: Path, out: Path) -> dict[str, tuple[float, float]]:
    env = dict(os.environ, PYTHONPATH=str(tree), QT_QPA_PLATFORM="offscreen",
               XDG_CONFIG_HOME=str(scratch / "home"), XDG_DATA_HOME=str(scratch / "home"))
    done = subprocess.run([sys.executable, "-m", "pytest", "-q", "-n", "0", "-p", "no:cacheprovider",
                           "--benchmark-enable", f"--benchmark-json={out}", *args],
                          cwd=tree, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"{tree}: pytest failed:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    found = json.loads(out.read_text())["benchmarks"]
    return {b["fullname"]: (b["stats"]["median"], b["stats"]["min"]) for b in found}


def main(argv: list[str]) -> int:
    if "--" not in argv or argv.index("--") != 2:
        print(__doc__.splitlines()[0], file=sys.stderr)
        return 2
    rev, rounds, args = argv[0], int(argv[1]), argv[3:]
    with tempfile.TemporaryDirectory() as scratch_name:
        scratch = Path(scratch_name)
        base = scratch / "base"
        base.mkdir()
        _export(rev, base)
        trees = {rev: base, "work tree": ROOT}
        medians: dict[str, dict[str, list[float]]] = {name: {} for name in trees}
        mins: dict[str, dict[str, float]] = {name: {} for name in trees}
        for i in range(rounds):
            for name, tree in trees.items():
                for bench, (median, low) in _run(tree, args, scratch, scratch / f"{i}.json").items():
                    medians[name].setdefault(bench, []).append(median)
                    mins[name][bench] = min(low, mins[name].get(bench, low))
    for bench in sorted(medians["work tree"]):
        if bench not in medians[rev]:
            continue
        before, after = (statistics.median(medians[n][bench]) for n in (rev, "work tree"))
        print(f"{bench}\n    {rev}: median {before * 1e3:.3f} ms (min {mins[rev][bench] * 1e3:.3f})"
              f"  work tree: median {after * 1e3:.3f} ms (min {mins['work tree'][bench] * 1e3:.3f})"
              f"  ratio {after / before:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
