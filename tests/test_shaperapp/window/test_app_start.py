"""What ``shaperapp.app.main`` spares at start-up: PySide6's reading of every module's
source (issue 43 item 5), and that sparing it changes nothing the app relies on."""
import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).parents[3]


def _started(code: str, tmp_path) -> str:
    """What ``code`` (which starts the app) printed, run in a fresh interpreter, offscreen,
    with its settings under ``tmp_path``."""
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "XDG_CONFIG_HOME": str(tmp_path),
           "XDG_DATA_HOME": str(tmp_path)}
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    return out.stdout

# Counts the modules whose source PySide6's import hook reads (``_mod_uses_pyside``)
# from the app's start to its first paint.
CHECKS_PROBE = """
import sys, shaperapp.app as app
read = []
skip = app._skip_pyside_source_checks
def counted():
    feature = sys.modules["PySide6.support.feature"]
    check = feature._mod_uses_pyside
    feature._mod_uses_pyside = lambda module: read.append(module.__name__) or check(module)
    skip()
app._skip_pyside_source_checks = counted
when_painted = app._when_painted
def at_paint(window, callback):
    def report():
        print("read", len(read), sorted(read)[:8])
        callback()
    when_painted(window, report)
app._when_painted = at_paint
app.main(["--lang", "en", "--quit-after-show"])
"""


def test_pyside_reads_no_module_source_before_the_first_paint(tmp_path):
    """PySide6 read the source of some 300 modules (60-75 ms of CPU at each start) to
    find the ones that might use its ``__feature__`` switches; the app marks every module
    as using none, so it reads none."""
    out = _started(CHECKS_PROBE, tmp_path)
    assert re.search(r"^read 0 \[\]$", out, re.M), out


def test_no_module_of_the_app_selects_a_pyside_feature():
    """Marking every module "uses no feature" is only right while none selects one
    (``from __feature__ import snake_case``): PySide6 would then switch that module's
    Qt names, and the modules marked -1 would follow whichever module ran last."""
    sources = [path for folder in ("shaperapp", "core", "tools") for path in (ROOT / folder).rglob("*.py")]
    assert len(sources) > 100
    selecting = [str(path.relative_to(ROOT)) for path in sources
                 if re.search(r"^\s*(from|import)\s+__feature__", path.read_text(encoding="utf-8"), re.M)]
    assert selecting == []


STARTED_PROBE = """
import sys, shaperapp.app as app
when_painted = app._when_painted
def at_paint(window, callback):
    def report():
        print("numtext", "core.files.numtext" in sys.modules)
        print("parts", sorted(name for name in sys.modules if name.split(".")[:2] in
                              (["core", "cam"], ["core", "gear"], ["shaperapp", "cam"], ["shaperapp", "gear"])))
        print("loads form", "shaperapp.design.loads_form" in sys.modules)
        callback()
    when_painted(window, report)
app._when_painted = at_paint
app.main(["--lang", "en", "--quit-after-show"])
"""


def test_the_first_screen_builds_no_csv_tables(tmp_path):
    """The CSV number formatter's tables (``core.files.numtext``, 4-5 ms to build at its
    import) wait for the first CSV: the first screen writes none."""
    out = _started(STARTED_PROBE, tmp_path)
    assert "numtext False" in out.splitlines(), out


def test_the_first_screen_makes_no_cam_or_gear_model_and_no_loads_form(tmp_path):
    """The cam's and the gear pair's models (and ``core.cam``, ``core.gear``, the default
    pair) wait until their tab, Save or an export asks, and the Loads form until its tab is
    shown or the window is idle: the first screen shows none of them, and they were some
    8 ms of every start (issue 43 item 5)."""
    out = _started(STARTED_PROBE, tmp_path)
    assert "parts []" in out.splitlines(), out
    assert "loads form False" in out.splitlines(), out


SEARCHES_PROBE = """
import sys, shaperapp.app as app
from shaperapp.scheme.labels import LabelLayout
sizes = []
place_still = LabelLayout.place_still
def counted(self, mm_per_px, bounds, window):
    sizes.append(round(max(mm_per_px), 6))
    return place_still(self, mm_per_px, bounds, window)
LabelLayout.place_still = counted
when_painted = app._when_painted
def at_paint(window, callback):
    def report():
        print("searches", len(sizes), len(set(sizes)))
        callback()
    when_painted(window, report)
app._when_painted = at_paint
app.main(["--lang", "en", "--quit-after-show"])
"""


def test_a_first_start_searches_the_schemes_labels_once_before_the_first_paint(tmp_path):
    """With fresh settings the window gives its docks their sizes after the scheme is shown
    (``Docks.apply_sizes``): the labels searched at the show were searched again for the
    taller view in the paint, 40-50 ms each (issue 43 item 5). They wait for the paint now."""
    out = _started(SEARCHES_PROBE, tmp_path)
    assert "searches 1 1" in out.splitlines(), out


FILTER_PROBE = """
import sys, shaperapp.app as app
from shaperapp.widgets import dialog_titles
seen = []
filtered = dialog_titles._TitleFitter.eventFilter
def counted(self, watched, event):
    seen.append(1)
    return filtered(self, watched, event)
dialog_titles._TitleFitter.eventFilter = counted
when_painted = app._when_painted
def at_paint(window, callback):
    def report():
        print("before the paint", len(seen))
        callback()
        from PySide6.QtWidgets import QApplication, QInputDialog
        dialog = QInputDialog(window)
        dialog.setWindowTitle("Go to crank angle, a title longer than the dialog's own width")
        dialog.show()
        QApplication.processEvents()
        print("fitted", dialog.width() >= dialog_titles.title_width(dialog), len(seen) > 0)
        dialog.close()
    when_painted(window, report)
app._when_painted = at_paint
app.main(["--lang", "en", "--quit-after-show"])
"""


def test_the_dialog_filter_waits_for_the_first_paint(tmp_path):
    """The dialogs' title fitter (``dialog_titles``) filters every event of the application:
    it saw about 3 000 while the first window was built and painted, 5-10 ms of the first
    paint (issue 43 item 5). It is installed at that paint, and fits a dialog shown after it."""
    out = _started(FILTER_PROBE, tmp_path)
    assert "before the paint 0" in out.splitlines(), out
    assert "fitted True True" in out.splitlines(), out


def test_the_phase_tools_marks_are_still_in_the_sources(tmp_path):
    """``tools/paint_phases.py`` marks lines of app.py, main_window.py and the floor by their
    text: a refactor that moves one must change the tool too (it would stop with the mark's
    name). The marked copies must still be Python."""
    import ast
    import importlib.util
    spec = importlib.util.spec_from_file_location("paint_phases", ROOT / "tools" / "paint_phases.py")
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    for part in ("shaperapp/app.py", "shaperapp/window/main_window.py"):
        (tmp_path / part).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / part).write_text((ROOT / part).read_text(encoding="utf-8"), encoding="utf-8")
    floor = tool._patch(tmp_path)
    for path, marks in ((tmp_path / "shaperapp/app.py", tool.APP_MARKS),
                        (tmp_path / "shaperapp/window/main_window.py", tool.WINDOW_MARKS),
                        (floor, tool.FLOOR_MARKS)):
        source = path.read_text(encoding="utf-8")
        ast.parse(source)
        assert all(f"({name!r}, time.perf_counter())" in source for _, name in marks), path
