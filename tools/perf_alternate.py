"""Time a command in two trees in turn: ``python tools/perf_alternate.py REV ROUNDS [FILE…] -- ARGS…``.

The shared 2-core machine runs the same code up to 40 % slower from one minute to the
next, so a before/after comparison is only fair when both are timed in one run,
alternating. This exports commit REV (``git archive``) to a temporary folder and runs
``python ARGS…`` ROUNDS times in each tree in turn (``PYTHONPATH`` set to the tree, in
a scratch folder, with bytecode cached per tree as an installed package has it; one
run each first to write that cache). It prints the min and median whole-process time
(and CPU time, user + system, which varies less with the load) of each tree and, when the command prints "first window painted after N ms" (the GUI's
``--quit-after-show``) or "measured N ms" (``tools/report_cpu.py``: one report built in
process), the min and median of N. Each FILE named before ``--`` is
copied from the work tree into REV's (e.g. ``shaperapp/app.py``, to time an older commit
with the work tree's way of measuring).

Example (issue 24): ``python tools/perf_alternate.py b1fd494 10 -- -m core curves
--crank 100 --K 1.4 --stroke 300 --rpm 40 60 --step 0.01 --csv out.csv``.
"{run}" in ARGS is replaced by a number of its own for every run (a command that skips
work already done, such as ``shaper class``, then writes into a fresh folder each time):
``… -- -m core class --tasks tasks.csv --base base.json -o class-{run} --jobs 2``.
Only a developer's tool.
"""
from __future__ import annotations

import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PAINTED = re.compile(r"(?:first window painted after|measured) (\d+) ms")


def export_commit(rev: str, target: Path) -> None:
    """Commit ``rev``'s files (``git archive``) unpacked into the folder ``target``."""
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", rev], check=True,
                             capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(target)], input=archive, check=True)


def main(argv: list[str]) -> int:
    if "--" not in argv or argv.index("--") < 2:
        print(__doc__.splitlines()[0], file=sys.stderr)
        return 2
    split = argv.index("--")
    rev, rounds, overlay, args = argv[0], int(argv[1]), argv[2:split], argv[split + 1:]
    with tempfile.TemporaryDirectory() as scratch:
        base = Path(scratch) / "base"
        base.mkdir()
        export_commit(rev, base)
        for name in overlay:
            (base / name).write_bytes((ROOT / name).read_bytes())
        trees = {rev: base, "work tree": ROOT}
        envs = {}
        for name, tree in trees.items():
            env = dict(os.environ, PYTHONPATH=str(tree), QT_QPA_PLATFORM="offscreen",
                       XDG_CONFIG_HOME=str(Path(scratch) / f"home-{len(envs)}"),
                       PYTHONPYCACHEPREFIX=str(Path(scratch) / f"pyc-{len(envs)}"))
            env["XDG_DATA_HOME"] = env["XDG_CONFIG_HOME"]
            env.pop("PYTHONDONTWRITEBYTECODE", None)
            envs[name] = env
            subprocess.run([sys.executable, *_numbered(args, f"warm-{len(envs)}")], env=env, cwd=scratch,
                           capture_output=True)
        whole: dict[str, list[float]] = {name: [] for name in trees}
        cpu: dict[str, list[float]] = {name: [] for name in trees}
        painted: dict[str, list[float]] = {name: [] for name in trees}
        for turn in range(rounds):
            for k, name in enumerate(trees):
                used = resource.getrusage(resource.RUSAGE_CHILDREN)
                start = time.perf_counter()
                done = subprocess.run([sys.executable, *_numbered(args, f"{turn}-{k}")], env=envs[name],
                                      cwd=scratch, capture_output=True, text=True)
                whole[name].append(time.perf_counter() - start)
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu[name].append(after.ru_utime + after.ru_stime - used.ru_utime - used.ru_stime)
                if done.returncode != 0:
                    print(f"{name}: exit status {done.returncode}: {done.stderr[-300:]}", file=sys.stderr)
                    return 1
                found = PAINTED.search(done.stdout)
                if found:
                    painted[name].append(int(found.group(1)) / 1000)
    for name in trees:
        line = (f"{name}: min {min(whole[name]):.3f} s, median {statistics.median(whole[name]):.3f} s"
                f" (CPU time min {min(cpu[name]):.3f} s, median {statistics.median(cpu[name]):.3f} s)")
        if painted[name]:
            line += (f"; first paint or measured min {min(painted[name]):.3f} s, "
                     f"median {statistics.median(painted[name]):.3f} s")
        print(line + f" ({rounds} runs each, alternating)")
    return 0


def _numbered(args: list[str], run: str) -> list[str]:
    """``args`` with "{run}" replaced by ``run``."""
    return [a.replace("{run}", run) for a in args]


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
