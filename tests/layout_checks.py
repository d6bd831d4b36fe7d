"""Layout measurements shared by the layout tests: the window built in a fresh process on a
screen of a given size (``layout_probe.py``), and rectangle overlap."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from locations import TESTS

PROBE = TESTS / "layout_probe.py"


def probe(tmp_path: Path, width: int, height: int, *args: str, settings: str = "s.ini") -> dict:
    screen = tmp_path / f"screen-{width}x{height}.json"
    screen.write_text(json.dumps({"screens": [{"name": "probe", "x": 0, "y": 0, "width": width,
                                               "height": height, "logicalDpi": 96,
                                               "logicalBaseDpi": 96, "dpr": 1}]}))
    env = dict(os.environ, QT_QPA_PLATFORM=f"offscreen:configfile={screen}",
               XDG_CONFIG_HOME=str(tmp_path), SHAPER_LIBRARY=str(tmp_path / "library.sqlite"))
    out = subprocess.run([sys.executable, str(PROBE), "--settings", str(tmp_path / settings), *args],
                         capture_output=True, text=True, env=env, timeout=180)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


def overlap(a: list[float], b: list[float]) -> bool:
    return a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and a[1] < b[1] + b[3] and b[1] < a[1] + a[3]
