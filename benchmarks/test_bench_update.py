"""How long from a changed input to the motion plots redrawn on screen.

One edit runs the model's recomputation (core solve + metrics), the plots'
setData through resultsChanged, and the repaint in processEvents; the target
is about 20 ms with 4 speeds at a 1° step. The lead extends this to the scheme
and metrics widgets.
"""
from __future__ import annotations

import numpy as np
from PySide6.QtWidgets import QApplication

from shaperapp.design.model import DesignModel
from shaperapp.plots.kinematics import LEVER_PLOTS, PlotsWidget

RPMS = [30, 40, 60, 80]


def _shown_plots(qtbot) -> tuple[DesignModel, PlotsWidget]:
    model = DesignModel()
    model.set_rpms(RPMS)
    model.set_step(1.0)
    widget = PlotsWidget(model)
    qtbot.addWidget(widget)
    for name in LEVER_PLOTS:          # the worst case: all six plots drawn
        widget.set_plot_visible(name, True)
    widget.resize(900, 700)
    widget.show()
    qtbot.waitExposed(widget)
    QApplication.processEvents()
    return model, widget


def test_bench_spec_change_to_plots_redrawn(benchmark, qtbot):
    model, widget = _shown_plots(qtbot)
    ratios = [1.5, 1.4]               # the default is 1.4: every call is a real change
    calls = [0]

    def edit() -> None:
        model.set_spec(time_ratio=ratios[calls[0] % 2])
        calls[0] += 1
        QApplication.processEvents()

    benchmark(edit)
    assert model.error is None
    shown = widget.curve_data("ram_v")
    assert len(shown) == len(RPMS)
    np.testing.assert_array_equal(shown[-1][1], model.motion.ram_v[-1])


def test_bench_angle_change_moves_cursor(benchmark, qtbot):
    model, widget = _shown_plots(qtbot)
    step = [0]

    def move() -> None:
        step[0] = (step[0] + 7) % model.angle_count
        model.set_angle_index(step[0])
        QApplication.processEvents()

    benchmark(move)
    assert widget.cursor_value() == np.degrees(model.motion.crank_angle[model.angle_index])
