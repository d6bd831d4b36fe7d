"""Views built when first shown (shaperapp/widgets/lazy.py, issue 24): a LazyPage builds its
view on the first show or the first ``view()``, never twice; ViewTabs speaks of the views."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest
from PySide6.QtWidgets import QApplication, QLabel, QSpinBox, QVBoxLayout, QWidget

from shaperapp.widgets.lazy import LazyPage, ViewTabs, build_when_idle


def _counting_factory(made: list):
    def make() -> QWidget:
        view = QWidget()
        layout = QVBoxLayout(view)
        layout.addWidget(QSpinBox())
        view.setMinimumSize(300, 400)
        made.append(view)
        return view
    return make


def _hidden_pages(qtbot, made: list) -> tuple[QWidget, list[LazyPage]]:
    """Three pages, hidden, in a window on screen (as when the window has been painted)."""
    pages = [LazyPage(_counting_factory(made)) for _ in range(3)]
    holder = QWidget()
    qtbot.addWidget(holder)
    for page in pages:
        page.setParent(holder)
        page.hide()
    holder.show()
    return holder, pages


def test_a_page_is_built_when_first_shown_and_only_once(qtbot):
    made: list = []
    tabs = ViewTabs()
    qtbot.addWidget(tabs)
    first = QLabel("first")
    tabs.addTab(first, "first")
    page = LazyPage(_counting_factory(made))
    tabs.addTab(page, "lazy")
    tabs.resize(700, 700)
    tabs.show()
    qtbot.waitExposed(tabs)
    assert made == [] and not page.is_built()          # behind its tab: not built
    tabs.setCurrentIndex(1)
    # Built and shown at once, as an eagerly built view is (its showEvent may open a file).
    assert len(made) == 1 and page.built_view() is made[0] and made[0].isVisible()
    assert made[0].size() == page.size()               # and laid out to its page at once
    tabs.setCurrentIndex(0)
    tabs.setCurrentIndex(1)
    assert page.view() is made[0] and len(made) == 1
    # The tabs speak of the views themselves, as when every view was built at start-up.
    assert tabs.widget(1) is made[0] and tabs.currentWidget() is made[0]
    assert tabs.indexOf(made[0]) == 1 and tabs.indexOf(first) == 0 and tabs.indexOf(QWidget()) == -1
    tabs.setCurrentWidget(first)
    assert tabs.currentIndex() == 0
    # A choice or number built later is wheel-guarded as the window's others are.
    assert made[0].findChild(QSpinBox).property("shaperWheelGuard")


def test_asking_for_the_view_builds_it_and_the_minimum_size_counts_it(qtbot):
    made: list = []
    tabs = ViewTabs()
    qtbot.addWidget(tabs)
    tabs.addTab(QLabel("first"), "first")
    page = LazyPage(_counting_factory(made))
    tabs.addTab(page, "lazy")
    tabs.show()
    qtbot.waitExposed(tabs)
    assert tabs.minimumSizeHint().height() < 400
    view = page.view()                                  # e.g. a menu action that needs the view
    assert made == [view]
    QApplication.processEvents()
    assert tabs.minimumSizeHint().height() >= 400       # the hidden view's minimum reached the tabs


def test_a_deferred_page_shown_for_a_moment_is_not_built(qtbot):
    """A dock page shown while the window is laid out and hidden behind a tab in the same
    turn (the vector diagrams at 1366×768) builds nothing; one left on screen is built."""
    made = []
    holder = QWidget()
    qtbot.addWidget(holder)
    layout = QVBoxLayout(holder)
    brief = LazyPage(lambda: made.append("brief") or QLabel("b"), defer=True)
    stays = LazyPage(lambda: made.append("stays") or QLabel("s"), defer=True)
    layout.addWidget(brief)
    layout.addWidget(stays)
    holder.show()
    brief.hide()                                    # before the event loop turns
    qtbot.waitUntil(lambda: stays.is_built(), timeout=10_000)
    qtbot.wait(50)
    assert made == ["stays"] and not brief.is_built()


def test_idle_build_builds_every_page_one_per_turn(qtbot):
    made: list = []
    _, pages = _hidden_pages(qtbot, made)
    build_when_idle(pages)
    assert made == []                                   # nothing before the event loop turns
    qtbot.waitUntil(lambda: all(p.is_built() for p in pages), timeout=10_000)
    assert len(made) == 3


def test_idle_build_then_lets_each_hidden_view_catch_up_once(qtbot):
    """After every page is built, one per turn again, each hidden view does what its first
    show would (``catch_up``), so that the visit only paints; a page on screen does not
    (its show did), and nothing catches up twice."""
    events: list = []

    class Drawn(QWidget):
        def catch_up(self) -> None:
            events.append(("catch up", self))

    def make() -> QWidget:
        view = Drawn()
        events.append(("build", view))
        return view
    holder = QWidget()
    qtbot.addWidget(holder)
    layout = QVBoxLayout(holder)
    pages = [LazyPage(make) for _ in range(3)]
    for page in pages:
        layout.addWidget(page)
    pages[0].hide()
    pages[1].hide()
    holder.show()                                       # the third page's show builds it
    assert [e for e, _ in events] == ["build"]
    build_when_idle(pages)
    qtbot.waitUntil(lambda: all(p.is_ready() for p in pages), timeout=10_000)
    kinds = [e for e, _ in events]
    assert kinds == ["build"] * 3 + ["catch up"] * 2, kinds
    assert [v for e, v in events if e == "catch up"] == [pages[0].built_view(), pages[1].built_view()]
    pages[0].catch_up()
    build_when_idle(pages)
    qtbot.wait(50)
    assert len(events) == 5


def test_idle_build_leaves_a_closed_window_alone(qtbot):
    """A window closed before its turns come (a test's window, or one the user closed at
    once) gets no views built for it: they would serve a model that may be going away."""
    made: list = []
    holder, pages = _hidden_pages(qtbot, made)
    build_when_idle(pages)
    holder.close()
    qtbot.wait(200)
    assert made == []


def _run_probe(code: str, tmp_path, *args: str) -> list[str]:
    """Run ``code`` in a fresh interpreter, offscreen, with its settings under ``tmp_path``
    and no OPENBLAS_NUM_THREADS of ours; the lines it printed."""
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
    env.update(QT_QPA_PLATFORM="offscreen", XDG_CONFIG_HOME=str(tmp_path), XDG_DATA_HOME=str(tmp_path))
    out = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True,
                         env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    return out.stdout.strip().splitlines()


PROBE = """
import sys
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QApplication
app = QApplication(sys.argv[:1])
from shaperapp.app import _when_painted
from shaperapp.design.model import DesignModel
from shaperapp.window.main_window import MainWindow
window = MainWindow(DesignModel(), QSettings(sys.argv[1], QSettings.Format.IniFormat))
window.show()
def painted():
    print(sorted(m for m in sys.modules if m.startswith(WATCHED)))
    print(sorted(n for n, p in window._pages.items() if p.is_built()))
    app.quit()
WATCHED = ("shaperapp.explore", "shaperapp.compare", "shaperapp.vectors.view",
           "shaperapp.positions", "shaperapp.library", "shaperapp.plots.forces", "shaperapp.drawing", "core.library", "core.space.compare",
           "shaperapp.cam.tab", "shaperapp.cam.plots", "shaperapp.cam.profile_view", "core.drawing",
           "core.drawing.cam_dxf", "ezdxf", "numpy.ma.", "importlib.metadata",
           "core.cam.cam", "core.cam.build", "core.cam.synthesis", "core.cam.timing", "core.cam.file",
           "core.gear.checks", "core.gear.advice", "scipy", "core.forces.polygons", "core.files.dynamics_io",
           "shaperapp.widgets.image_export", "core.forces.flywheel", "core.forces.torque_peaks")
_when_painted(window, painted)
app.exec()
"""


def test_the_first_screen_imports_and_builds_only_what_it_shows(tmp_path):
    """At the window's first paint, the tabs behind Kinematics and the hidden library are
    neither built nor imported (issue 24: they cost a fifth of the start-up), nor the cam's
    solver and the gear's checks behind the Cam and Gear tabs, nor the forces' cycle
    summary (the flywheel and the torque peaks), whose table is below the Results pane's
    fold (issue 43 item 5)."""
    modules, built = _run_probe(PROBE, tmp_path, str(tmp_path / "s.ini"))[-2:]
    assert modules == "[]"
    assert built == "[]"       # the vector diagrams' dock, shown for a moment while tabbed, too


STARTED_PROBE = """
import gc, sys, shaperapp.app as app
collections, started, early = [], [], set()
gc.callbacks.append(lambda phase, info: phase == "stop" and started
                    and collections.append(info["generation"]))
engine_first = app._import_engine_first
def recorded():
    started.append(1)
    engine_first()
    early.update(m for m in sys.modules if m.startswith("core"))
app._import_engine_first = recorded
when_painted = app._when_painted
def painted(window, callback):
    def report():
        late = {m for m in sys.modules if m.startswith("core")}
        callback()
        print("engine", sorted(late - early), sorted(early - late))
        print("gc", collections, gc.isenabled(), gc.get_freeze_count() > 10_000)
    when_painted(window, report)
app._when_painted = painted
status = app.main(["--lang", "en", "--quit-after-show"])
after = (gc.isenabled(), gc.get_freeze_count())
import os, numpy.linalg
print("quit", status, os.environ.get("OPENBLAS_NUM_THREADS"), *after)
"""


@pytest.fixture(scope="module")
def started(tmp_path_factory) -> list[str]:
    """What one start of the app (``main --quit-after-show``) printed, watched three ways
    at once: the core modules imported before Qt and by the first paint, the collector's
    runs and state, and numpy's BLAS threads. Each only reads what start-up does, so one
    process serves the three tests that read them (a start costs some 0.6 s of CPU)."""
    return _run_probe(STARTED_PROBE, tmp_path_factory.mktemp("started"))


def printed(lines: list[str], word: str) -> str:
    """The line ``word`` begins in ``lines``, without the word."""
    found = [line.split(" ", 1)[1] for line in lines if line.split(" ", 1)[0] == word]
    assert len(found) == 1, lines
    return found[0]


def test_the_app_starts_numpy_with_one_blas_thread(started):
    """shaperapp's main asks OpenBLAS for one thread before numpy loads (core.base.blas):
    its idle worker threads spun for about 0.1 s of CPU at every start."""
    assert started[0].startswith("first window painted after ")
    assert printed(started, "quit").split()[:2] == ["0", "1"]


def test_the_engine_the_first_screen_uses_is_imported_before_qt(started):
    """shaperapp imports the core modules of the first screen before Qt (PySide6 reads
    the source of every module imported after it), and no more than those: a module
    the first screen comes to need, or no longer needs, shows here."""
    assert printed(started, "engine") == "[] []"


def test_start_up_runs_without_automatic_garbage_collection(started):
    """From main's first import to the first paint Python's collector does not run (its
    collections cost 35-55 ms of start-up, issue 24); at the first paint what start-up
    made is frozen, so that the timer's later full collections skip it; on quitting the
    collector is as main found it."""
    assert printed(started, "gc") == "[] False True"
    assert printed(started, "quit").split()[2:] == ["True", "0"]


IDLE_PROBE = """
import sys, time
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QApplication
app = QApplication(sys.argv[:1])
from shaperapp.design.model import DesignModel
from shaperapp.window.main_window import MainWindow
window = MainWindow(DesignModel(), QSettings(sys.argv[1], QSettings.Format.IniFormat))
window.show()
end = time.perf_counter() + 100
while not window._pages["cam"].is_built() and time.perf_counter() < end:
    app.processEvents()
print("scipy.optimize" in sys.modules, "scipy.spatial" in sys.modules)
app.processEvents()
print("scipy.optimize" in sys.modules, "scipy.spatial" in sys.modules, window.cam_model._value is None)
"""


def test_the_cam_tabs_scipy_is_imported_while_idle_once_the_tab_is_built(tmp_path):
    """The cam's synthesis imports scipy's linprog and half-plane intersection at first use
    (not at start-up); the window imports them on the turn after building the Cam tab while
    idle, so that the tab's first visit does not wait for them (issue 40 item 5), without
    computing a cam."""
    lines = _run_probe(IDLE_PROBE, tmp_path, str(tmp_path / "s.ini"))
    assert lines[-2:] == ["False False", "True True True"]
