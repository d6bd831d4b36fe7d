"""Every test runs headless (Qt draws offscreen, so no screen is needed) and away from
the user's own files."""
import atexit
import gc
import os
import shutil
import tempfile

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
# The per-user library (platformdirs' data folder) and the window's settings (Qt's
# config folder) go to a private folder for this run, children included: a test must
# neither change a user's files nor depend on what an earlier run left there.
_PRIVATE_HOME = tempfile.mkdtemp(prefix="shaper-tests-")
atexit.register(shutil.rmtree, _PRIVATE_HOME, True)
for _name in ("XDG_DATA_HOME", "XDG_CONFIG_HOME"):
    os.environ[_name] = os.path.join(_PRIVATE_HOME, _name.lower())

from typing import Iterator  # noqa: E402

import pytest  # noqa: E402
from hypothesis import settings  # noqa: E402

from shaperapp.design.model import DesignModel  # noqa: E402
from shaperapp.scheme.view import SchemeWidget  # noqa: E402
from shaperapp.window.main_window import MainWindow  # noqa: E402

from gui_helpers import main_window, shown  # noqa: E402
from modal_watchdog import ModalWatchdog  # noqa: E402

pytest_plugins = ["hang_guard", "qt_exit"]

# Hypothesis profiles (HYPOTHESIS_PROFILE, "ci" unless set): "ci" draws a share of each
# slow random sweep's examples (tests/sweeps.py), "thorough" all of them. Both print the
# blob that replays a failing example, since a CI run's examples are not the database's.
settings.register_profile("ci", print_blob=True)
settings.register_profile("thorough", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


def pytest_collection_finish(session) -> None:
    """What collection made (the modules, their tests, hypothesis's strategies) lives as long
    as the run: it is frozen out of the garbage collector's walks. The collection after
    every Qt test (below) then walks what tests made since, not this too (only the one every
    FULL_COLLECTION_EVERY Qt tests thaws and walks everything, then freezes it again):
    docs/performance.md, "The test suite's time (29 November)"."""
    gc.collect()
    gc.freeze()


# A modal dialog open this long in a test is one nobody will answer (see modal_watchdog).
MODAL_LIMIT_S = 60.0


@pytest.fixture(autouse=True)
def unanswered_modals_fail(request) -> Iterator[None]:
    """In every test that uses Qt: a modal dialog left unanswered is closed after
    MODAL_LIMIT_S and fails the test, naming it, instead of hanging the suite."""
    if not {"qtbot", "qapp"} & set(request.fixturenames):
        yield
        return
    request.getfixturevalue("qapp")
    watchdog = ModalWatchdog(MODAL_LIMIT_S)
    watchdog.start()
    yield
    watchdog.stop()
    if watchdog.closed:
        pytest.fail("unanswered modal dialog, closed by the watchdog: " + "; ".join(watchdog.closed))


@pytest.fixture(autouse=True)
def no_worker_outlives_its_test(request) -> Iterator[None]:
    """A job a test leaves running (a window closed mid-map) ends before the next test:
    its thread would hold garbage collection off there, and a test of the collector run
    after it (another order, another xdist worker) saw collection still held."""
    yield
    if "qtbot" in request.fixturenames or "qapp" in request.fixturenames:
        from shaperapp.widgets.worker import COLLECTOR
        assert COLLECTOR.join(60.0), "a worker thread still runs 60 s after its test"
        # The test's widgets are closed: collect their reference cycles now, between tests.
        # Left to Python's automatic collection they went at a random point of a later test;
        # once that was inside QObject::disconnect, which holds Qt's connection lock, and the
        # QMenu being destroyed waited for the same lock: the worker hung (seen with py-spy
        # in test_gui_scheme's first test, near the end of the parallel suite).
        _collect_what_the_test_left()


# Qt tests between two collections that walk everything alive (see below).
FULL_COLLECTION_EVERY = 50
_qt_tests_ended = 0


def _collect_what_the_test_left() -> None:
    """Collect the cycles a Qt test left, then freeze what survives out of later walks.

    Why frozen: what earlier tests keep alive grows through a worker's run (windows closed
    with ``deleteLater`` where no event loop runs again, module-scoped views, Qt's
    wrappers), and a full collection walks all of it: one after each test took 35 ms at
    the start of ``test_gui_hostile_settings.py`` and 134 ms at its end, and 17-20 s over
    the 407 tests of ``tests/test_shaperapp/window`` and ``design`` in one process
    (2.5 s frozen; docs/performance.md, "The collection after each Qt test"). Frozen, a
    collection walks only what the last test made. A cycle that reaches frozen objects is
    not collected then: every FULL_COLLECTION_EVERY Qt tests everything is thawed and
    collected once, here between tests as before, so no garbage outlives that many tests
    and none is collected at a random point inside a Qt call (above). Automatic
    collections skip frozen objects too."""
    global _qt_tests_ended
    _qt_tests_ended += 1
    if _qt_tests_ended % FULL_COLLECTION_EVERY == 0:
        gc.unfreeze()
    gc.collect()
    gc.freeze()


@pytest.hookimpl(wrapper=True, tryfirst=True)
def pytest_runtest_teardown(item):
    """A test's own window (the function-scoped ``window`` fixture) is hidden as soon as
    the test has ended, before pytest-qt's teardown processes the pending events (its
    hook runs after this one's first half).

    Why: a shown window builds one of its hidden views per turn of the event loop from
    its first paint (``build_when_idle``), and stops for a hidden window. The views built
    in those turns, after the test's last check, were CPU spent for nothing: 4-13 % of
    the window tests' (docs/performance.md, 30 November). A window a whole module
    shares is left as it is: the module's next test uses it."""
    info = getattr(item, "_fixtureinfo", None)          # test functions only (pytest's own record)
    fixtures = info.name2fixturedefs.get("window", ()) if info is not None else ()
    window = getattr(item, "funcargs", {}).get("window")
    if fixtures and fixtures[-1].scope == "function" and isinstance(window, MainWindow):
        window.hide()
    return (yield)


@pytest.fixture
def window(qtbot, tmp_path) -> Iterator[MainWindow]:
    """The assembled window (see :func:`main_window`), settings under ``tmp_path``."""
    with main_window(tmp_path) as win:
        yield win


@pytest.fixture
def model(qtbot) -> DesignModel:
    """A fresh model on the default design (L1 = 100 mm, K = 1.4, H = 300 mm); qtbot
    makes sure a QApplication exists for its signals."""
    return DesignModel()


@pytest.fixture
def scheme(qtbot, model) -> SchemeWidget:
    """The scheme widget shown at a realistic size."""
    return shown(qtbot, SchemeWidget(model), 900, 650)
