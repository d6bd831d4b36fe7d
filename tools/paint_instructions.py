"""Instructions to the first paint, counted: ``python tools/paint_instructions.py [app|floor] [TREE]``.

Why: on the shared 2-core machine the first paint's time moves by ±10 % with the load,
more than a start-up cut of a few ms, and an A/B run alternating the two trees
(``tools/perf_alternate.py``) needs a quiet machine. The CPU instructions a start executes
up to its first paint do not depend on the load: this runs the app (or
``tools/first_paint_floor.py``) under valgrind's callgrind, ends the process at the first
paint, and prints the count. A run takes 25–60 s (callgrind is some 50 times slower);
two runs of one tree agree to 0.1 %. Instructions are not time (a cache miss, a system call,
the disk): read them as a ratio between trees, next to a timed run.

``TREE`` (default: this checkout) is put first on ``PYTHONPATH``, e.g. a commit exported by
``git archive REV | tar -x -C /tmp/rev`` (its bytecode is written by a first plain run).
The app's pyqtgraph garbage-collection timer is left out (under callgrind its 1 s period
comes before the paint). Only a developer's tool; needs valgrind.
"""
from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

APP = """
import os, sys
import pyqtgraph.util.garbage_collector as collector
class Idle:
    def __init__(self, *args, **kwargs):
        self.timer = type("Timer", (), {"stop": lambda self: None})()
collector.GarbageCollector = Idle
import shaperapp.app as app
when_painted = app._when_painted
app._when_painted = lambda window, callback: when_painted(window, lambda: os._exit(0))
app.main(["--lang", "en", "--quit-after-show"])
"""

FLOOR = """
import os, sys
source = open(sys.argv[1], encoding="utf-8").read()
source = source.replace("    QApplication.instance().quit()", "    os._exit(0)")
exec(compile(source, sys.argv[1], "exec"), {"__name__": "__main__", "os": os})
"""


def count(which: str, tree: Path) -> int:
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "OPENBLAS_NUM_THREADS": "1",
           "PYTHONHASHSEED": "0", "PYTHONPATH": str(tree)}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    code = APP if which == "app" else FLOOR
    args = [sys.executable, "-c", code] + ([] if which == "app" else [str(ROOT / "tools" / "first_paint_floor.py")])
    subprocess.run(args, env=env, capture_output=True, cwd="/tmp", check=False)     # the bytecode written
    out = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *args],
                         env=env, capture_output=True, text=True, cwd="/tmp", check=False)
    found = re.search(r"Collected\s*:\s*(\d+)", out.stderr)
    if not found:
        raise SystemExit(f"no count in valgrind's output:\n{out.stderr[-2000:]}")
    return int(found.group(1))


def main(argv: list[str]) -> None:
    which = argv[0] if argv else "app"
    if which not in ("app", "floor"):
        raise SystemExit("usage: paint_instructions.py [app|floor] [TREE]")
    tree = Path(argv[1]).resolve() if len(argv) > 1 else ROOT
    print(f"{which} ({tree}): {count(which, tree):,} instructions to the first paint")


if __name__ == "__main__":
    main(sys.argv[1:])
