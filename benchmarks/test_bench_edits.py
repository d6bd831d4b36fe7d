"""Issue 40, item 5: an edit in each form reaching the screen, and each lazy tab's first
visit, with 16 speeds in the whole window at 1366 × 768.

Targets (on a quiet machine): an edit within 50 ms, a tab's first visit within 300 ms.
A Design edit reaches the screen when the scheme has painted the new mechanism; its
labels are placed in the turn after that paint, and the edit until they are settled
(placed and painted) is measured beside it. Between two rounds the window is left to
settle, as between a user's keystrokes.
A Gear edit recomputes the gear alone: the design model's kinematics and dynamics are
not run again (asserted, not timed). In the ordinary test run (benchmarks disabled) each
runs once, briefly: instead of the idle waits, events are processed until every view is
built (a condition, reached in a fraction of a second), and the report is of 2 speeds.
"""
import time

import pytest
from PySide6.QtCore import QEvent, QObject, QSettings
from PySide6.QtWidgets import QApplication

from shaperapp.design.model import DesignModel
from shaperapp.window.main_window import MainWindow

SPEEDS = [20.0 + 5.0 * i for i in range(16)]
TABS = {"design": "plots", "loads": "forces", "cam": "cam", "gear": "gear"}
EDIT_BUDGET_S = 0.050       # issue 40 item 5, on a quiet machine: asserted on the median
VISIT_BUDGET_S = 0.300


def drained(seconds: float = 4.0) -> None:
    """Events processed for ``seconds``: the views built while idle, as a user meets the
    window a few seconds after start."""
    end = time.perf_counter() + seconds
    while time.perf_counter() < end:
        QApplication.processEvents()


def open_window(tmp_path) -> MainWindow:
    tmp_path.mkdir(exist_ok=True)
    win = MainWindow(DesignModel(), QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    win.resize(1366, 768)
    win.show()
    win.model.set_rpms(SPEEDS)
    QApplication.processEvents()
    return win


class Paints(QObject):
    """Counts a widget's paint events (the scheme's plot viewport: the last view an edit
    repaints)."""

    def __init__(self, widget) -> None:
        super().__init__(widget)
        self.count = 0
        widget.installEventFilter(self)

    def eventFilter(self, watched, event) -> bool:
        if event.type() == QEvent.Type.Paint:
            self.count += 1
        return False


def until(done, limit_s: float = 30.0) -> None:
    """Events processed until ``done()`` (a condition, not a time: at most ``limit_s``)."""
    end = time.perf_counter() + limit_s
    while not done() and time.perf_counter() < end:
        QApplication.processEvents()
    assert done()


def painted(win: MainWindow, paints: Paints) -> None:
    """The labels settled (placed in the turn after the edit's paint) and painted: events
    processed until two turns in a row paint nothing more."""
    until(win.scheme.labels_settled)
    quiet = 0
    while quiet < 2:
        count = paints.count
        QApplication.processEvents()
        quiet = quiet + 1 if paints.count == count else 0


def built(win: MainWindow) -> None:
    """Events processed until every lazy view is built and has caught up while hidden
    (``LazyPage.is_ready``), then one turn more: what the idle waits below are for,
    reached as a condition, not a time."""
    until(lambda: all(page.is_ready() for page in win._pages.values()), 60.0)
    QApplication.processEvents()


def idle(win: MainWindow, benchmark, seconds: float) -> None:
    """The window left idle for ``seconds`` when timed, as between a user's keystrokes; in
    the ordinary run (benchmarks disabled) only until its views are built."""
    if benchmark is not None and not benchmark.disabled:
        drained(seconds)
    built(win)


@pytest.fixture
def window(qtbot, tmp_path, request):
    win = open_window(tmp_path)
    # the gear's check waits for every view: one built meanwhile must not count as its work
    timed = request.getfixturevalue("benchmark") if "benchmark" in request.fixturenames else None
    idle(win, timed, 4.0)
    yield win
    win.model.set_clean("")
    win.close()


# each form's edit: a new value every round, always valid
EDITS = {
    "design": lambda w, i: w.model.set_spec(time_ratio=1.4 + 0.01 * (i % 25)),
    "loads": lambda w, i: w.model.set_masses(cut_force_N=7000.0 + 10.0 * (i % 50)),
    "cam": lambda w, i: w.cam_model.set_fields(rise=60.0 + 0.5 * (i % 20)),
    "gear": lambda w, i: w.gear_model.set_fields(z1=13.0 + (i % 3)),
}


@pytest.mark.parametrize("form", list(EDITS))
def test_an_edit_reaches_the_screen(benchmark, window, form):
    """The form's tab in front (the Kinematics plots for the design form): the edit, the
    model's recompute and every visible view repainted."""
    window.tabs.setCurrentWidget(getattr(window, TABS[form]))
    idle(window, benchmark, 1.0)
    rounds = iter(range(1, 10**6))

    def edit():
        EDITS[form](window, next(rounds))
        QApplication.processEvents()

    if form == "design":
        paints = Paints(window.scheme.plot_widget().viewport())

        def edit():
            count = paints.count
            EDITS[form](window, next(rounds))
            QApplication.processEvents()
            until(lambda: paints.count > count)      # the scheme painted the new mechanism

        benchmark.pedantic(edit, setup=lambda: painted(window, paints), rounds=20, iterations=1,
                           warmup_rounds=2)
    else:
        benchmark.pedantic(edit, rounds=20, iterations=1, warmup_rounds=2)
    if not benchmark.disabled:
        assert benchmark.stats.stats.median <= EDIT_BUDGET_S


@pytest.mark.parametrize("step", [1.0, 0.1])
def test_a_design_edit_settles_its_labels(benchmark, window, step):
    """The Design edit above until its labels are placed (in the turn after the scheme's
    paint) and painted: what a user sees last. Reported beside the edit, no budget. Also
    at a crank-angle step of 0.1° (3601 angles), whose label search took the moving
    bodies at ten times the angles of 1° until 44c0794."""
    window.model.set_step(step)
    assert window.model.error is None
    window.tabs.setCurrentWidget(window.plots)
    idle(window, benchmark, 1.0)
    rounds = iter(range(1, 10**6))
    paints = Paints(window.scheme.plot_widget().viewport())

    def edit():
        EDITS["design"](window, next(rounds))
        QApplication.processEvents()
        painted(window, paints)

    benchmark.pedantic(edit, setup=lambda: painted(window, paints), rounds=20, iterations=1,
                       warmup_rounds=2)
    assert window.scheme.labels_settled()


def test_a_gear_edit_recomputes_the_gear_alone(window, monkeypatch):
    """No kinematics, no dynamics, no metrics: the design model's recompute is not run."""
    window.tabs.setCurrentWidget(window.gear)
    built(window)
    runs = []
    for name in ("_recompute", "_recompute_forces"):
        original = getattr(DesignModel, name)
        monkeypatch.setattr(DesignModel, name, lambda self, *a, _o=original, _n=name, **k:
                            runs.append(_n) or _o(self, *a, **k))
    pair = window.gear_model.pair
    window.gear_model.set_fields(z1=14.0)
    QApplication.processEvents()
    assert window.gear_model.pair != pair and runs == []


@pytest.mark.parametrize("tab", ["explore", "forces", "cam", "gear"])
def test_a_tabs_first_visit(benchmark, qtbot, tmp_path, tab):
    """A fresh window, left idle until its views are built and have drawn what they can
    while hidden, then the tab shown for the first time: what is left for the visit (what
    the tab computes and draws only when shown) and its first paint."""
    windows = []

    def setup():
        win = open_window(tmp_path / str(len(windows)))
        windows.append(win)
        # as the docstring says: until every view is built and has caught up while hidden,
        # and the Cam tab's scipy imported (on a loaded machine 4 s idle are not enough, and
        # the visit then measured those)
        idle(win, benchmark, 4.0)
        if not benchmark.disabled:
            drained(0.2)
        return (win,), {}

    def visit(win):
        win.tabs.setCurrentWidget(getattr(win, tab))
        QApplication.processEvents()

    benchmark.pedantic(visit, setup=setup, rounds=3, iterations=1)
    if not benchmark.disabled:
        assert benchmark.stats.stats.median <= VISIT_BUDGET_S
    for win in windows:
        win.model.set_clean("")
        win.close()


def test_the_reports_longest_slice(benchmark, qtbot, tmp_path):
    """The report of 16 speeds written as File › Export report writes it: the time between
    two of its progress steps is how long the window waits to repaint or to hear Cancel
    (the longest and the total go into extra_info)."""
    from core.base.progress import Progress
    from shaperapp.report.dialog import export_report
    model = DesignModel()
    model.set_rpms(SPEEDS if not benchmark.disabled else SPEEDS[:2])
    slices = []

    def run():
        last = [time.perf_counter()]

        def heard(_fraction: float) -> None:
            now = time.perf_counter()
            slices.append(now - last[0])
            last[0] = now
        export_report(model, str(tmp_path / "r.pdf"), "en", progress=Progress(heard))

    benchmark.pedantic(run, rounds=2, iterations=1)
    benchmark.extra_info["longest_slice_s"] = max(slices)
    benchmark.extra_info["steps"] = len(slices) // 2
