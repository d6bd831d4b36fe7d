"""Layout measurements shared by the layout tests: the window built in a fresh process on a
screen of a given size (``layout_probe.py``), and rectangle overlap."""
from __future__ import annotations

import copy
import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Callable, Sequence

from locations import TESTS

PROBE = TESTS / "layout_probe.py"

Screen = tuple[int, int]


def probes(tmp_path: Path, width: int, height: int, jobs: Sequence[Sequence[str]]) -> list[dict]:
    """The reports of ``jobs`` (each the probe's arguments, ``--settings`` first), run in
    turn in one process on a ``width`` × ``height`` screen, each in a fresh window."""
    screen = tmp_path / f"screen-{width}x{height}.json"
    screen.write_text(json.dumps({"screens": [{"name": "probe", "x": 0, "y": 0, "width": width,
                                               "height": height, "logicalDpi": 96,
                                               "logicalBaseDpi": 96, "dpr": 1}]}))
    env = dict(os.environ, QT_QPA_PLATFORM=f"offscreen:configfile={screen}",
               XDG_CONFIG_HOME=str(tmp_path), SHAPER_LIBRARY=str(tmp_path / "library.sqlite"))
    argv = [arg for i, job in enumerate(jobs) for arg in (["--next"] if i else []) + list(job)]
    out = subprocess.run([sys.executable, str(PROBE), *argv],
                         capture_output=True, text=True, env=env, timeout=180)
    assert out.returncode == 0, out.stderr
    lines = out.stdout.strip().splitlines()[-len(jobs):]
    assert len(lines) == len(jobs), out.stdout
    return [json.loads(line) for line in lines]


def probe(tmp_path: Path, width: int, height: int, *args: str, settings: str = "s.ini") -> dict:
    """One probe in a process of its own, its settings file ``tmp_path / settings``."""
    return probes(tmp_path, width, height, [("--settings", str(tmp_path / settings), *args)])[0]


class SharedProbes:
    """The probes a module's tests read, run on first use, all of one screen in one process
    (``plan``: screen → every job of it the module asks for, without ``--settings``; each
    job gets a settings file of its own). A test calls it with its screen and job and gets
    its own copy of the report, so no test sees another's changes.

    Why one process a screen: a probe process costs about 1 s of CPU before its window is
    measured, a further window in it about 0.35 s (docs/performance.md)."""

    def __init__(self, folder: Callable[[], Path], plan: dict[Screen, Sequence[tuple[str, ...]]]) -> None:
        self._folder, self._plan, self._reports = folder, plan, {}

    def __call__(self, width: int, height: int, *args: str) -> dict:
        key = (width, height, args)
        if key not in self._reports:
            jobs = list(self._plan[width, height])
            assert args in jobs, f"{args} is not in the plan for {width}x{height}"
            folder = self._folder()
            settings = [("--settings", str(folder / f"s{i}.ini"), *job) for i, job in enumerate(jobs)]
            for job, report in zip(jobs, probes(folder, width, height, settings)):
                self._reports[width, height, job] = report
        return copy.deepcopy(self._reports[key])


def overlap(a: list[float], b: list[float]) -> bool:
    return a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and a[1] < b[1] + b[3] and b[1] < a[1] + a[3]
