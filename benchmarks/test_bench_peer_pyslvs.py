"""Issue 24, item 3: the kinematics cycle against pyslvs 22.7 solving positions only.

pyslvs is no dependency of this project: it runs in its own interpreter, named by
``$SHAPER_PYSLVS_PYTHON``, a virtualenv outside the repository. Built here on 25 November
(3 min 11 s, Python 3.11.7 as ours): ``python3.11 -m venv /work/peers/pyslvs-venv``, then
``PIP_CONSTRAINT=c.txt /work/peers/pyslvs-venv/bin/pip install pyslvs==22.7.0`` with
``cython==3.0.12`` in c.txt: its sdist compiles with Cython 3.0 (Cython 3.1 and later
refuse its bfgs.pyx; the 3.0 alphas it was released with are no longer on PyPI). That
installs pyslvs 22.7.0 (``__version__`` "22.07.0"), lark-parser 0.12.0 and numpy 2.4.6,
the numpy we use. Each round runs
``peers/pyslvs_positions.py`` in that interpreter, which poses our rod-variant default
design (the one of ``test_bench_core.py``'s rod rows) in pyslvs and times its solve of
the 3 601 crank angles' positions in its own process, then times
``core.linkage.kinematics.solve`` (3 601 angles × 4 speeds, every quantity) here, the previous
result held as the GUI's model holds it and dropped at once, as
``test_bench_core.py`` does. The test asserts that pyslvs's joint positions (crank pin,
lever tip, ram joint) equal ours to 1e-9 mm; nothing about speed.

Measure with ``SHAPER_PYSLVS_PYTHON=… python -m pytest -n 0 -p no:cacheprovider
benchmarks/test_bench_peer_pyslvs.py --benchmark-enable -s``: the figures are printed
and kept in extra_info; the table's row is ours, held. Skipped when the variable is
unset or pyslvs does not import there.
"""
from __future__ import annotations

import json
import os
import statistics
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest

from core.linkage.geometry import synthesize
from core.linkage.kinematics import shape, solve

PEER = Path(__file__).resolve().parent / "peers" / "pyslvs_positions.py"
ANGLES = np.radians(np.linspace(0, 360, 3601))
RPMS = [30, 40, 60, 80]


def pyslvs_python() -> str:
    python = os.environ.get("SHAPER_PYSLVS_PYTHON")
    if not python:
        pytest.skip("SHAPER_PYSLVS_PYTHON is not set: name a Python that has pyslvs 22.7 "
                    "(e.g. /work/peers/pyslvs-venv/bin/python) to compare with it")
    try:
        probe = subprocess.run([python, "-c", "import pyslvs; print(pyslvs.__version__)"],
                               capture_output=True, text=True, timeout=60)
    except OSError as error:
        pytest.skip(f"SHAPER_PYSLVS_PYTHON={python} cannot run: {error}")
    if probe.returncode != 0:
        last = (probe.stderr.strip().splitlines() or ["no message"])[-1]
        pytest.skip(f"pyslvs does not import in SHAPER_PYSLVS_PYTHON={python}: {last}")
    return python


def time_ours(design, held: bool, repeats: int) -> list[float]:
    """ms per ``solve`` of the cycle, ``repeats`` times; ``held`` keeps the previous result
    alive while the next is solved (see test_bench_core.py's ``…_rod_held``)."""
    times, keep = [], [solve(design, ANGLES, RPMS)]
    for _ in range(repeats):
        start = time.perf_counter()
        if held:
            keep[0] = solve(design, ANGLES, RPMS)
        else:
            solve(design, ANGLES, RPMS)
        times.append((time.perf_counter() - start) * 1000.0)
    return times


def test_kinematics_rod_against_pyslvs_positions(benchmark, tmp_path):
    python = pyslvs_python()
    design = synthesize(100, 1.4, 300, rod_ratio=0.3)
    quick = benchmark.disabled   # the normal test run: one short round
    rounds, repeats, expr_repeats, ours_repeats = (1, 3, 1, 20) if quick else (5, 50, 10, 200)
    np.save(tmp_path / "angles.npy", ANGLES)
    request = {"crank": design.crank, "frame": design.frame, "lever": design.lever,
               "guide": design.guide, "rod": design.rod, "rod_side": design.rod_side,
               "angles": str(tmp_path / "angles.npy"), "out": str(tmp_path / "pyslvs.npz"),
               "repeats": repeats, "expr_repeats": expr_repeats}
    (tmp_path / "request.json").write_text(json.dumps(request), encoding="utf-8")
    peer: list[dict] = []
    held: list[list[float]] = []
    dropped: list[list[float]] = []
    for _ in range(rounds):
        done = subprocess.run([python, str(PEER), str(tmp_path / "request.json")],
                              capture_output=True, text=True, check=True, timeout=600)
        peer.append(json.loads(done.stdout))
        held.append(time_ours(design, True, ours_repeats))
        dropped.append(time_ours(design, False, ours_repeats))

    at = shape(design, ANGLES)
    ours = np.concatenate([at.crank_pin, at.lever_tip, at.ram_joint]).T   # (n, 6): A, B, C
    positions = np.load(tmp_path / "pyslvs.npz")
    assert positions["tinycadlib"].shape == ours.shape
    worst = float(np.abs(positions["tinycadlib"] - ours).max())
    assert worst <= 1e-9, f"pyslvs's positions differ from ours by {worst:g} mm"
    expr_error = float(np.abs(positions["expr_solving"] - ours).max())

    def best_and_median(runs: list[list[float]]) -> tuple[float, float]:
        return min(min(r) for r in runs), statistics.median(statistics.median(r) for r in runs)

    figures: dict[str, object] = {"pyslvs": peer[0]["pyslvs"], "rounds": rounds,
                                  "pyslvs_tinycadlib_max_error_mm": worst,
                                  "pyslvs_expr_solving_max_error_mm": expr_error,
                                  "pyslvs_expr_stack": peer[0]["expr_stack"]}
    for key in ("tinycadlib", "expr_solving"):
        figures[f"pyslvs_{key}_min_ms"], figures[f"pyslvs_{key}_median_ms"] = \
            best_and_median([p[f"{key}_ms"] for p in peer])
    for key, runs in (("held", held), ("dropped", dropped)):
        figures[f"ours_{key}_min_ms"], figures[f"ours_{key}_median_ms"] = best_and_median(runs)
        for peer_key in ("tinycadlib", "expr_solving"):
            for stat in ("min", "median"):
                figures[f"{peer_key}_over_{key}_{stat}"] = (figures[f"pyslvs_{peer_key}_{stat}_ms"]
                                                            / figures[f"ours_{key}_{stat}_ms"])
    benchmark.extra_info.update(figures)
    print("\n" + ", ".join(f"{k} {v:.4g}" if isinstance(v, float) else f"{k} {v}"
                           for k, v in figures.items()))

    keep = [solve(design, ANGLES, RPMS)]

    def next_cycle():
        keep[0] = solve(design, ANGLES, RPMS)

    benchmark(next_cycle)
