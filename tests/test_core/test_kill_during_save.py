"""A save killed at a random moment leaves the complete old or the complete new file,
and the next save leaves no temporary file behind.

A helper process imports core once and, on each request, forks a writer that
saves a curves CSV (about 1 MB, via ``atomic_write``) and a design file (via
``save_design``) over and over, alternating two versions. The test kills the
writer with SIGKILL after a random delay, so the kill lands anywhere: before
the first write, while a temp file is being filled, between fsync and
rename, or after it. Forking from the helper keeps each iteration to a few
milliseconds instead of a fresh interpreter's start-up.
"""
import json
import os
import random
import signal
import subprocess
import sys
import time

import pytest

from core.files.atomic import atomic_write, temp_pattern
from core.files.io import load_design, save_design
from core.linkage.spec import Spec

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

ITERATIONS = 60

HELPER = r"""
import os, sys
from core.files.atomic import atomic_write
from core.files.io import save_design
from core.linkage.spec import Spec

csv_path, design_path, version_a, version_b = sys.argv[1:5]
texts = [open(version_a).read(), open(version_b).read()]
specs = [(Spec(crank=100.0), [40.0]), (Spec(crank=90.0), [60.0])]
print("ready", flush=True)
for line in sys.stdin:
    pid = os.fork()
    if pid == 0:
        i = 0
        while True:
            atomic_write(csv_path, texts[i % 2])
            spec, rpm = specs[i % 2]
            save_design(design_path, spec, rpm, 1.0)
            i += 1
    print(pid, flush=True)
    os.waitpid(pid, 0)
    print("reaped", flush=True)
"""


def version(tag: str) -> str:
    """About 1 MB of CSV whose every line says which version it belongs to."""
    return "".join(f"{tag},{i},{i * 0.5:.6f}\n" for i in range(40_000))


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs fork")
def test_a_save_killed_at_random_is_old_or_new_and_leaves_no_temp(tmp_path):
    rng = random.Random(20240607)
    csv_path, design_path = tmp_path / "curves.csv", tmp_path / "design.json"
    a, b, base = version("A"), version("B"), version("P")
    (tmp_path / "a.txt").write_text(a)
    (tmp_path / "b.txt").write_text(b)
    helper = subprocess.Popen(
        [sys.executable, "-c", HELPER, str(csv_path), str(design_path),
         str(tmp_path / "a.txt"), str(tmp_path / "b.txt")],
        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
    seen = {"P": 0, "A": 0, "B": 0}
    left_temps = 0
    try:
        assert helper.stdout.readline().strip() == "ready"
        for _ in range(ITERATIONS):
            # The "next save" of the previous iteration: no temp file may survive it.
            atomic_write(csv_path, base)
            save_design(design_path, Spec(crank=80.0), [30.0], 2.0)
            assert not [p for p in tmp_path.iterdir()
                        if temp_pattern(csv_path).match(p.name) or temp_pattern(design_path).match(p.name)]

            helper.stdin.write("go\n")
            helper.stdin.flush()
            writer = int(helper.stdout.readline())
            time.sleep(rng.uniform(0.0, 0.08))
            os.kill(writer, signal.SIGKILL)
            assert helper.stdout.readline().strip() == "reaped"

            text = csv_path.read_text()
            assert text in (a, b, base), "a killed save left a partial or mixed file"
            seen[text[0]] += 1
            doc = load_design(design_path)         # complete and valid, whichever version
            assert (doc["spec"].crank, doc["rpm"]) in ((100.0, [40.0]), (90.0, [60.0]), (80.0, [30.0]))
            assert json.loads(design_path.read_text())["format"] == "shaper-design"
            left_temps += sum(1 for p in tmp_path.iterdir() if p.name.endswith(".tmp"))
        atomic_write(csv_path, base)
        assert not [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp") and "curves" in p.name]
    finally:
        helper.stdin.close()
        helper.kill()
        helper.wait()
    # The kills really interrupted saves: temp files were left behind and cleaned up,
    # and both new versions were seen complete.
    assert left_temps >= ITERATIONS // 5, seen
    assert seen["A"] + seen["B"] >= ITERATIONS // 5, seen
