"""GUI speed targets: start-up, input-to-screen update, one animation frame.

The update benchmark drives the whole window (form → model → scheme, metrics,
plots, forces) with 4 speeds at 1°, the case the GUI issue names.
"""
import os
import re
import statistics
import subprocess
import sys
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QApplication

from shaperapp.design.model import DesignModel
from shaperapp.window.main_window import MainWindow


@pytest.fixture
def window(qtbot, tmp_path):
    win = MainWindow(DesignModel(), QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    win.resize(1560, 940)
    win.show()
    win.model.set_rpms([30, 40, 60, 80])
    QApplication.processEvents()
    yield win
    win.model.set_clean("")
    win.close()


EDIT_BUDGET_S = 0.030       # edit → every visible view updated (issue 8, item 8)
FRAME_BUDGET_S = 0.008      # one animation frame of the whole window


# "nudge": a new K every round (1.40, 1.41 … 1.64, all valid): every number and label
# changes, and the plots and the scheme keep their ranges while the drawing still fits
# them. "jump": the stroke alternates 300 ↔ 450 mm, so every plot range changes and the
# scheme is fitted again each round (the worst case of an edit).
EDITS = {"nudge": ("time_ratio", lambda i: 1.4 + 0.01 * (i % 25)),
         "jump": ("stroke", lambda i: 300.0 if i % 2 else 450.0)}


@pytest.mark.parametrize("edit", ["nudge", "jump"])
@pytest.mark.parametrize("tab", ["kinematics", "forces"])
def test_input_to_all_views_updated(benchmark, window, tab, edit):
    """An edit redraws every visible view (scheme, metrics, animation bar, the front tab);
    the tab behind waits until it is shown."""
    window.tabs.setCurrentIndex(0 if tab == "kinematics" else 1)
    QApplication.processEvents()
    field, value = EDITS[edit]
    rounds = iter(range(10**6))

    def change():
        window.model.set_spec(**{field: value(next(rounds))})
        QApplication.processEvents()  # every view repaints

    # Fixed rounds: calibration ran this ~15 000 times (10 minutes) on a loaded machine.
    benchmark.pedantic(change, rounds=80, iterations=1, warmup_rounds=5)
    assert window.model.error is None
    front = window.plots if tab == "kinematics" else window.forces
    assert front.stack().is_current()
    # EDIT_BUDGET_S is not asserted: the shared 2-core machine varies by ±40 %; the
    # measured medians are in docs/performance.md.


def test_animation_frame_whole_window(benchmark, window):
    """Scheme (with force arrows), cursors of all plots and the read-out, repainted."""
    window.scheme.set_forces_visible(True)
    index = iter(range(10**9))

    def frame():
        window.model.set_angle_index(next(index) % window.model.angle_count)
        QApplication.processEvents()

    benchmark(frame)
    # FRAME_BUDGET_S: reported in docs/performance.md (measured medians) rather than asserted, as
    # the shared machine's load varies.


def _start(home, command=("-m", "shaperapp.app", "--lang", "en", "--quit-after-show")):
    # settings and library in ``home``: never the user's own, never an earlier run's. Python
    # keeps the modules' bytecode as an installed app has it (pip compiles it at install):
    # without it every start compiles the project's hundred-odd modules again (about 0.4 s
    # quiet), which the floor's installed packages never pay.
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env.update(XDG_CONFIG_HOME=str(home), XDG_DATA_HOME=str(home), OPENBLAS_NUM_THREADS="1")
    out = subprocess.run([sys.executable, *command], capture_output=True, text=True, timeout=120, env=env)
    assert out.returncode == 0, out.stderr
    return out.stdout


FLOOR = str(Path(__file__).resolve().parents[1] / "tools" / "first_paint_floor.py")
PAINT_OVER_FLOOR = 1.3      # issue 43 item 5: the first paint at most 1.3 × the floor's


def test_first_paint_against_the_floor(benchmark, tmp_path):
    """The window's first paint against ``tools/first_paint_floor.py`` (the same imports,
    PySide6, numpy and pyqtgraph, and one plot in a window), each started in turn, the
    order swapped every round, so that the shared machine's load falls on both alike. The
    median ratio app / floor is at most PAINT_OVER_FLOOR; in the ordinary test run (one
    round, beside the other tests) it is only recorded."""
    app_ms, floor_ms = [], []
    if not benchmark.disabled:      # measured: the bytecode written, the disk cache warm first
        _start(tmp_path), _start(tmp_path, (FLOOR,))   # (the one recorded round needs neither)

    def pair():
        starts = [(app_ms, None), (floor_ms, (FLOOR,))]
        for times, command in starts[::1 if len(app_ms) % 2 else -1]:
            out = _start(tmp_path) if command is None else _start(tmp_path, command)
            times.append(int(re.search(r"first (?:window )?paint(?:ed)? after (\d+) ms", out).group(1)))

    benchmark.pedantic(pair, rounds=1 if benchmark.disabled else 11, iterations=1)
    ratio = statistics.median(a / f for a, f in zip(app_ms, floor_ms))
    benchmark.extra_info.update(app_ms=app_ms, floor_ms=floor_ms, median_ratio=round(ratio, 3),
                                ratio_of_medians=round(statistics.median(app_ms) / statistics.median(floor_ms), 3))
    if not benchmark.disabled:
        assert ratio <= PAINT_OVER_FLOOR, (app_ms, floor_ms)


def test_startup_to_first_window(benchmark, tmp_path):
    """The whole process: start, first paint of the window, quit. The time from the app
    module's import to the first paint, as the app prints it, goes into extra_info."""
    painted = []

    def run():
        stdout = _start(tmp_path)
        painted.append(int(re.search(r"first window painted after (\d+) ms", stdout).group(1)))
        return stdout

    benchmark.pedantic(run, rounds=5, iterations=1)
    benchmark.extra_info["first_paint_ms_min"] = min(painted)
    benchmark.extra_info["first_paint_ms_median"] = sorted(painted)[len(painted) // 2]
    assert painted
