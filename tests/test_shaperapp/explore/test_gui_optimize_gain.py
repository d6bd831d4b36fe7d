"""Optimize loads nothing that is not better (issue 34, item 6): with K and H fixed, L1
only scales the crank and the frame in proportion (L1/L2 = sin θ/2), so the lever, and
the ram with it, moves the same for every L1: max |a| does not depend on L1. Optimize
said "Proposal: 325.04 m/s² at L1 = 50.6838 (the design before: 325.04 m/s²)" and
loaded L1 = 50.68."""
from dataclasses import replace

import numpy as np
import pytest

from core.linkage.kinematics import solve
from shaperapp.widgets import i18n
from language_checks import english_words


def largest_accel(spec, crank: float, rpm: float) -> float:
    """max |a| on a fine grid of the closed-form kinematics, not the optimizer's peaks."""
    motion = solve(replace(spec, crank=crank).design(), np.radians(np.arange(0.0, 360.0, 0.01)),
                   [rpm])
    return float(np.max(np.abs(motion.ram_a)))


def optimize_l1_alone(qtbot, view, objective="accel"):
    view.box.free[0].setChecked(True)
    view.box.free[1].setChecked(False)
    view.box.objective.setCurrentIndex(view.box.objective.findData(objective))
    view.box.optimize.click()
    qtbot.waitUntil(lambda: view.runner.job is None and view.box.optimum.text() != "",
                    timeout=60_000)


def test_no_gain_loads_nothing_and_says_why(qtbot, view, model):
    view.axis_names[0].setCurrentIndex(view.axis_names[0].findData("crank"))
    spec, steps = model.valid_spec, model.undo_stack.count()
    low = view.lows[0].value()
    # The premise, independently: max |a| is the same at the range's low end and on screen.
    a_low, a_here = (largest_accel(spec, c, max(model.rpms)) for c in (low, spec.crank))
    assert low < 0.8 * spec.crank and a_low == pytest.approx(a_here, rel=1e-9)
    optimize_l1_alone(qtbot, view)
    assert model.valid_spec == spec
    assert model.undo_stack.count() == steps
    text = view.box.optimum.text()
    assert text.startswith("No better design within these bounds")
    assert "Proposal" not in text and "does not depend on Crank L1" in text
    assert not view.box.undo_proposal.isVisible()
    assert i18n.set_language("zh_CN")
    qtbot.waitUntil(lambda: view.box.optimum.text() != text, timeout=10_000)
    assert english_words(view.box.optimum.text(), {"br"}) == [], view.box.optimum.text()


def test_a_design_already_best_stays_and_the_bound_is_named(qtbot, view, model):
    """max |a| grows with K (a quicker return): from K = 1.4 in 1.4…1.6 nothing is better,
    and the best lies on the range's lower end."""
    view.axis_names[1].setCurrentIndex(view.axis_names[1].findData("crank"))
    view.axis_names[0].setCurrentIndex(view.axis_names[0].findData("time_ratio"))
    view.lows[0].setValue(1.4)
    view.highs[0].setValue(1.6)
    spec = model.valid_spec
    assert largest_accel(spec, spec.crank, max(model.rpms)) < largest_accel(
        replace(spec, time_ratio=1.41), spec.crank, max(model.rpms))
    view.box.free[0].setChecked(True)
    view.box.free[1].setChecked(False)
    view.box.objective.setCurrentIndex(view.box.objective.findData("accel"))
    view.box.optimize.click()
    qtbot.waitUntil(lambda: view.runner.job is None and view.box.optimum.text() != "",
                    timeout=60_000)
    text = view.box.optimum.text()
    assert model.valid_spec == spec
    assert text.startswith("No better design within these bounds") and "does not depend" not in text
    assert "is not better than the design before" in text
    assert "Time ratio K is at the lower end of its range" in text
