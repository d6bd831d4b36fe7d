"""An `export --all` killed mid-way leaves nothing that stays (hunt of 1 December).

The export writes into a hidden staging folder, `.shaper-export-<pid>-<8 hex>`, and moves
the files in when all are written: a kill leaves no partial export in FOLDER, but on
756ad63 it left the staging folder, a whole hidden copy of the library's designs, and no
later export removed it (20 kills at random moments left one each). The next export now
removes those whose process no longer runs. The kill here is at a chosen point, the third
staged file's fsync, so the test is deterministic."""
from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

from cli_runner import shaper_in_process
from core.files.design_file import load_design
from locations import DATA, ROOT

CHILD = """
import os, signal, sys
from core.library import Library
from core.library.files import export_entries
calls, real = [0], os.fsync
def fsync(fd):
    real(fd)
    calls[0] += 1
    if calls[0] == 3:                       # the third design staged: killed outright
        os.kill(os.getpid(), signal.SIGKILL)
os.fsync = fsync
with Library(sys.argv[1], create=False) as lib:
    export_entries(lib, sys.argv[2])
"""


def test_the_staging_folder_of_a_killed_export_is_removed_by_the_next(tmp_path):
    library, out = tmp_path / "lib.sqlite", tmp_path / "out"
    sources = tmp_path / "designs"
    sources.mkdir()
    for name in ("a", "b", "c", "d"):
        (sources / f"{name}.shaper.json").write_bytes((DATA / "my.shaper.json").read_bytes())
    status, _, err = shaper_in_process("library", "import", sources, "--library", library)
    assert status == 0, err
    out.mkdir()
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    child = subprocess.run([sys.executable, "-c", CHILD, str(library), str(out)], env=env, timeout=60)
    assert child.returncode == -9
    left = [p.name for p in out.iterdir()]
    assert len(left) == 1 and re.fullmatch(r"\.shaper-export-\d+-[0-9a-f]{8}", left[0]), left
    assert not any(p.suffix == ".json" for p in out.iterdir())          # nothing moved in: all or nothing
    live = out / f".shaper-export-{os.getppid()}-0123abcd"              # a live process's export: kept
    live.mkdir()
    status, text, err = shaper_in_process("library", "export", "--all", "-o", out, "--library", library)
    assert (status, err) == (0, ""), err
    names = sorted(p.name for p in out.iterdir())
    assert names == [live.name, "a.shaper.json", "b.shaper.json", "c.shaper.json", "d.shaper.json"], names
    assert all(load_design(out / n)["spec"] == load_design(DATA / "my.shaper.json")["spec"] for n in names[1:])
