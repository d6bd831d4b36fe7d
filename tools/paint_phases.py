"""Where the first paint's time goes, phase by phase, beside the floor's: ``python tools/paint_phases.py [ROUNDS]``.

Why: the benchmark (``benchmarks/test_bench_gui.py``) gives one ratio, app / floor, and
``tools/paint_instructions.py`` one count; neither says which part of the start-up the
app's excess is in. This exports HEAD (``git archive``) to a scratch folder, puts time
marks into that copy's ``shaperapp/app.py`` (between the engine's imports, Qt's and
pyqtgraph's, the application, the app's own imports, the model, the window, its show and
its first paint) and ``shaperapp/window/main_window.py`` (around each pane the window
builds), does the same to a copy of ``tools/first_paint_floor.py``, runs both ROUNDS times
in turn (offscreen, one BLAS thread, bytecode written first) and prints each phase's
median in ms. The marks are the only change to the copies; a mark whose line is no longer
in the source stops the tool with its name. Only a developer's tool.
"""
from __future__ import annotations

import os
import re
import statistics
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

# (line of shaperapp/app.py's main, the phase that ends there)
APP_MARKS = (
    ("    gc.disable()\n", "arguments"),
    ("    _import_engine_first()\n", "engine imports (numpy, core)"),
    ("    configure_plots()\n", "Qt and pyqtgraph imports"),
    ("    _install_error_hook(app)\n", "QApplication, fonts"),
    ("    from shaperapp.design.model import DesignModel\n", "the app's own imports"),
    ("    model = DesignModel()\n", "the design model"),
    ("    window = MainWindow(model, settings)\n", "  the window's saved state restored"),
    ("    window.show()\n", "show"),
)
WINDOW_MARKS = tuple((f"        self.{name} = {cls}({args})\n", f"  {label}") for name, cls, args, label in (
    ("document", "Document", "model, settings, self", "document"),
    ("inputs", "InputsPane", "model", "inputs pane"),
    ("metrics", "MetricsPanel", "model", "results pane"),
    ("scheme", "SchemeWidget", "model", "scheme"),
    ("animation", "AnimationBar", "model", "animation bar"),
    ("plots", "PlotsWidget", "model", "kinematics plots"),
    ("menus", "Menus", "self", "tabs, docks, actions, menus"),
)) + (("        self._retranslate()\n", "  the rest"),)
FLOOR_MARKS = (
    ("import numpy  # noqa: E402\n", "numpy import"),
    ("from PySide6.QtWidgets import QApplication, QMainWindow  # noqa: E402\n", "Qt and pyqtgraph imports"),
    ("watcher = _FirstPaint()\n", "QApplication, window, plot"),
    ("window.show()\n", "show"),
)
PHASE = re.compile(r"^PHASE (.+)=([0-9.]+)$")


def _marked(source: str, marks, clock: str, indent: str) -> str:
    for line, name in marks:
        if line not in source:
            raise SystemExit(f"paint_phases: no line {line.strip()!r} to mark {name!r} after")
        source = source.replace(line, f"{line}{indent}{clock}.append(({name!r}, time.perf_counter()))\n", 1)
    return source


def _patch(tree: Path) -> Path:
    app = tree / "shaperapp" / "app.py"
    source = _marked(app.read_text(encoding="utf-8"), APP_MARKS, "MARKS", "    ")
    source = source.replace("START = time.perf_counter()\n", "START = time.perf_counter()\nMARKS = []\n", 1)
    report = ("        MARKS.append(('paint', time.perf_counter()))\n"
              "        _previous = START\n"
              "        for _name, _at in MARKS + window.MARKS:\n"
              "            print(f'PHASE {_name}={(_at - _previous) * 1000:.2f}'); _previous = _at\n"
              "        sys.stdout.flush()\n")
    anchor = "        gc.freeze()\n"
    if anchor not in source:
        raise SystemExit("paint_phases: no gc.freeze() in app.main's painted()")
    # the window's own marks (indented) fall between the model's and its return: all in time order
    report = report.replace("MARKS + window.MARKS", "sorted(MARKS + window.MARKS, key=lambda m: m[1])")
    app.write_text(source.replace(anchor, anchor + report, 1), encoding="utf-8")
    window = tree / "shaperapp" / "window" / "main_window.py"
    source = _marked(window.read_text(encoding="utf-8"), WINDOW_MARKS, "self.MARKS", "        ")
    source = source.replace("        super().__init__(parent)\n",
                            "        super().__init__(parent)\n        import time\n        self.MARKS = []\n", 1)
    window.write_text(source, encoding="utf-8")
    floor = tree / "first_paint_floor.py"
    source = _marked((ROOT / "tools" / "first_paint_floor.py").read_text(encoding="utf-8"),
                     FLOOR_MARKS, "MARKS", "")
    source = source.replace("START = time.perf_counter()\n", "START = time.perf_counter()\nMARKS = []\n", 1)
    source = source.replace("def _done() -> None:\n", "def _done() -> None:\n"
                            "    MARKS.append(('paint', time.perf_counter())); _previous = START\n"
                            "    for _name, _at in MARKS:\n"
                            "        print(f'PHASE {_name}={(_at - _previous) * 1000:.2f}'); _previous = _at\n", 1)
    floor.write_text(source, encoding="utf-8")
    return floor


def _run(tree: Path, args: list[str], home: str) -> dict[str, float]:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env.update(QT_QPA_PLATFORM="offscreen", OPENBLAS_NUM_THREADS="1", PYTHONPATH=str(tree),
               XDG_CONFIG_HOME=home, XDG_DATA_HOME=home)
    out = subprocess.run([sys.executable, *args], capture_output=True, text=True, env=env, cwd=home,
                         stdin=subprocess.DEVNULL, timeout=120, check=True).stdout
    return {m.group(1): float(m.group(2)) for m in map(PHASE.match, out.splitlines()) if m}


def main(argv: list[str]) -> None:
    rounds = int(argv[0]) if argv else 11
    with tempfile.TemporaryDirectory() as scratch:
        tree, home = Path(scratch) / "tree", Path(scratch) / "home"
        tree.mkdir(), home.mkdir()
        archive = subprocess.run(["git", "-C", str(ROOT), "archive", "HEAD", "core", "shaperapp", "resources"],
                                 check=True, capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", str(tree)], input=archive, check=True)
        floor = _patch(tree)
        commands = {"app": ["-m", "shaperapp.app", "--lang", "en", "--quit-after-show"], "floor": [str(floor)]}
        phases: dict[str, dict[str, list[float]]] = {name: defaultdict(list) for name in commands}
        for name, args in commands.items():        # the bytecode written, the disk cache warm
            _run(tree, args, str(home))
        for k in range(rounds):
            for name in (("app", "floor") if k % 2 else ("floor", "app")):
                for phase, ms in _run(tree, commands[name], str(home)).items():
                    phases[name][phase].append(ms)
    for name, table in phases.items():
        total = statistics.median(map(sum, zip(*table.values())))
        print(f"{name}: first paint, median of {rounds}: {total:.1f} ms")
        for phase, values in table.items():
            print(f"  {phase:40s} {statistics.median(values):7.1f} ms")


if __name__ == "__main__":
    main(sys.argv[1:])
