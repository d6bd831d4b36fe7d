"""``shaper class`` (issue 41): 30 students, A1 sheets, Chinese, with DXF, on 2 workers, against
one ``shaper course`` of the same kind (the unit): the class must cost at most 0.6 × 30
units, and at most 600 MB together (the parent and its workers) whatever --jobs.

Memory is the process tree's proportional set size (PSS, /proc/PID/smaps_rollup), sampled
every 0.1 s: the workers are forked from the parent and share its pages, which PSS
counts once (their resident sizes would count them three times); the peak of the
summed resident sizes is reported beside it. Run:
    python -m pytest benchmarks/test_bench_class.py --benchmark-enable -n 0 -s

The two modes differ in size and in what is asserted:
- measured (``--benchmark-enable``): the unit course, then 30 students
  (``SHAPER_BENCH_STUDENTS``); both bounds, time and memory.
- the suite's smoke run (benchmarks disabled): no unit course, and a class of 2 students
  with the same command and options; the 600 MB bound only. The tree's peak is its widest
  moment, the parent waiting while both workers write an A1 course with DXF, which 2
  students on ``--jobs 2`` reach as 30 do: 400 MB against 470 MB for 6 students
  (docs/performance.md). So the bound still fails if that moment grows by some 200 MB, by
  100 MB a worker: a course's own bloat, or the parent's pages no longer shared (Qt
  started, or the preload lost, before the fork). What the smoke run cannot see is a
  worker growing from one student to the next; the measured run, 15 students a worker,
  can. Time is not asserted: 2 students measure the class's fixed costs (forking, the task
  sheets, the answer key), not its parallel share, and on CI, next to the suite's other
  worker, the load. The 30-student smoke run took 149 s of the suite.
"""
from __future__ import annotations

import os
import subprocess
import sys
import threading
import time

import pytest


STUDENTS = int(os.environ.get("SHAPER_BENCH_STUDENTS", "30"))   # fewer for a quick look
SMOKE_STUDENTS = 2                 # the suite's run: both workers busy at once, nothing more
UNIT_SHARE = 0.6
TARGET_MB = 600.0
BASE = ("--arm", "125", "--swing", "15", "--pressure", "40", "--rise", "75", "--dwell", "10", "--return", "75",
        "--z1", "13", "--z2", "40", "--module", "6", "--rpm", "60", "--guide", "sagitta", "--rod-ratio", "0.3",
        "--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000",
        "--cut-height", "80", "--crank", "110", "--K", "1.46", "--stroke", "320")


def _tree(pid: int) -> list[int]:
    """``pid`` and its descendants."""
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        out.append(p)
        try:
            with open(f"/proc/{p}/task/{p}/children") as handle:
                todo += [int(c) for c in handle.read().split()]
        except OSError:
            pass
    return out


def _memory(pid: int) -> tuple[float, float]:
    """(PSS, RSS) of the tree in MB."""
    pss = rss = 0
    for p in _tree(pid):
        try:
            with open(f"/proc/{p}/smaps_rollup") as handle:
                for line in handle:
                    if line.startswith("Pss:"):
                        pss += int(line.split()[1])
                    elif line.startswith("Rss:"):
                        rss += int(line.split()[1])
        except OSError:
            pass
    return pss / 1024.0, rss / 1024.0


def run_measured(words: list[str]) -> tuple[float, float, float, str]:
    """(seconds, peak PSS MB, peak RSS MB, stdout) of ``shaper *words``."""
    start = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "core", *words], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    peaks = [0.0, 0.0]

    def sample():
        while proc.poll() is None:
            pss, rss = _memory(proc.pid)
            peaks[0], peaks[1] = max(peaks[0], pss), max(peaks[1], rss)
            time.sleep(0.1)
    watcher = threading.Thread(target=sample)
    watcher.start()
    out, err = proc.communicate(timeout=3600)
    watcher.join()
    assert proc.returncode == 0, err
    return time.perf_counter() - start, peaks[0], peaks[1], out


@pytest.mark.timeout(3600)         # 30 courses: some 5 minutes on a quiet machine, far more on a busy one
@pytest.mark.skipif(not hasattr(os, "sched_getaffinity") or len(os.sched_getaffinity(0)) < 2,
                    reason="needs 2 cores")
def test_a_class_costs_at_most_0_6_of_its_courses(benchmark, tmp_path):
    measured = not benchmark.disabled
    students = STUDENTS if measured else SMOKE_STUDENTS
    made = subprocess.run([sys.executable, "-m", "core", "design", *BASE, "-o", str(tmp_path / "base.json")],
                          capture_output=True, text=True)
    assert made.returncode == 0, made.stderr
    rows = ["student,student-number,crank,stroke"]
    rows += [f"学生{k},2026{k:03d},{100 + k % 10},{300 + 2 * k}" for k in range(students)]
    (tmp_path / "tasks.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    figures = {}

    def work():
        if measured:                # the unit the time is measured in: one course of the same kind
            unit = run_measured(["course", "--design", str(tmp_path / "base.json"), "-o", str(tmp_path / "one"),
                                 "--lang", "zh", "--sheet", "A1", "--dxf"])
            figures.update({"course s": unit[0], "course peak PSS MB": unit[1]})
        whole = run_measured(["class", "--tasks", str(tmp_path / "tasks.csv"), "--base", str(tmp_path / "base.json"),
                              "-o", str(tmp_path / "class"), "--lang", "zh", "--sheet", "A1", "--dxf",
                              "--jobs", "2"])
        figures.update({"class s": whole[0], "class peak PSS MB": whole[1], "class peak summed RSS MB": whole[2],
                        "students": students})
        if measured:
            figures["class / courses"] = whole[0] / (students * figures["course s"])
    benchmark.pedantic(work, rounds=1, iterations=1)
    shown = {k: round(v, 2) for k, v in figures.items()}
    benchmark.extra_info.update(shown)
    print(shown)
    assert figures["class peak PSS MB"] <= TARGET_MB, shown
    if measured:
        assert figures["class s"] <= UNIT_SHARE * students * figures["course s"], shown
