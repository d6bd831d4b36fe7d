"""The Cam tab's slowest edits: a refusal whose advice designs many whole cams before it
names a value to type. How long the GUI thread is busy with the edit (the model's
recompute, the form's error line, ``processEvents()``), wall and the GUI thread's own CPU
(``time.thread_time``: a search on a worker thread is not counted in it), in the real tab
shown at 1000 × 650.

Target: no edit keeps the GUI thread busy for more than about 100 ms. Each round starts
from the form's default sheet with the case's other fields typed (valid or refused at
once) and every search ended, then core's cam caches emptied, as for a value typed for
the first time; the timed edit is the case's last field. The GUI thread's CPU of each
round goes into extra_info (median and largest).

Run with ``python -m pytest benchmarks/test_bench_cam_edits.py --benchmark-enable -n 0``.
"""
import statistics
import time

import pytest
from PySide6.QtWidgets import QApplication

from core.cam import extremes, synthesis
from core.cam.synthesis import import_solvers
from shaperapp.cam.model import DEFAULTS
from shaperapp.cam.tab import CamTab
from shaperapp.design.model import DesignModel

# (fields typed first, the timed edit); each timed edit is refused, the last one at once
CASES = {
    "boss-500": ({}, {"boss": 500.0}),                          # an arm of 687.0 mm (no swing …)
    "boss-90-roller-5": ({"roller": 5.0}, {"boss": 90.0}),       # a typed roller: an arm of 133.1 mm
    "allowance-5": ({}, {"pressure": 5.0}),                      # an allowance of 7.6°
    "both-allowances": ({"swing": 30.0, "rise": 40.0, "return": 40.0, "pressure": 10.0},
                        {"return_pressure": 5.0}),               # 15.1° on the rise and the return
    "hub-100": ({"arm": 65.0, "swing": 13.0, "rise": 130.0, "dwell": 8.0, "return": 60.0,
                 "return_law": "cosine", "pressure": 27.5, "boss": 35.0, "clearance": 5.0},
                {"hub": 100.0}),                                 # a swing of 4.3°
    "arm-15": ({"swing": 26.94, "rise": 97.56, "dwell": 36.63, "return": 45.13, "rise_law": "parabolic",
                "return_law": "parabolic", "pressure": 35.06}, {"arm": 15.0}),   # an arm of 32.3 mm
    "checked-hub": ({"base": 15.0}, {"distance": 110.0}),        # a base radius of 18.50 mm
}


def searched(tab: CamTab, limit_s: float = 30.0) -> None:
    """Events processed until no search for a refusal's advice runs (none on a tab that
    has no such search)."""
    busy = getattr(tab.cam_model, "searching", lambda: False)
    end = time.perf_counter() + limit_s
    while busy() and time.perf_counter() < end:
        QApplication.processEvents()
    assert not busy()
    QApplication.processEvents()


@pytest.fixture
def tab(qtbot):
    widget = CamTab(DesignModel())
    import_solvers()        # as the window does while idle once the tab is built (window/pages.py)
    qtbot.addWidget(widget)
    widget.resize(1000, 650)
    widget.show()
    qtbot.waitExposed(widget)
    yield widget
    searched(widget)


@pytest.mark.parametrize("case", list(CASES))
def test_a_refused_edit_of_the_cam_tab(benchmark, tab, case):
    before, edit = CASES[case]
    cpu = []

    def setup():
        searched(tab)
        tab.cam_model.set_fields(**DEFAULTS)
        tab.cam_model.set_fields(**before)
        searched(tab)
        for cached in (synthesis.synthesize, synthesis.admissible, synthesis._conditions, extremes.pressure_peaks,
                       extremes.min_convex_radius):
            cached.cache_clear()

    def typed():
        start = time.thread_time()
        tab.cam_model.set_fields(**edit)
        QApplication.processEvents()
        cpu.append(time.thread_time() - start)

    benchmark.pedantic(typed, setup=setup, rounds=5 if not benchmark.disabled else 1, iterations=1)
    assert tab.cam_model.error is not None
    benchmark.extra_info["gui_thread_cpu_median_s"] = statistics.median(cpu)
    benchmark.extra_info["gui_thread_cpu_max_s"] = max(cpu)
