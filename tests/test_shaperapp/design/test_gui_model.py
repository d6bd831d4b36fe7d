"""The model's signal discipline: emit once per real change, keep the last valid design."""
import numpy as np
import pytest

from core.linkage.geometry import synthesize
from core.linkage.kinematics import crank_angles, solve
from core.linkage.metrics import analyze


def test_default_design_is_seed003(model):
    assert model.design == synthesize(100, 1.4, 300)
    assert model.rpms == (40.0, 60.0)
    assert model.error is None and not model.dirty


def test_valid_change_recomputes_once(model, qtbot):
    with qtbot.waitSignal(model.resultsChanged, timeout=10_000):
        model.set_spec(time_ratio=1.6, stroke=320)
    expected = synthesize(100, 1.6, 320)
    assert model.design == expected
    assert np.allclose(model.motion.ram_v, solve(expected, crank_angles(1), [40, 60]).ram_v)
    assert model.metrics.time_ratio == pytest.approx(analyze(expected, [40]).time_ratio)
    assert model.dirty


def test_same_value_emits_nothing(model, qtbot):
    with qtbot.assertNotEmitted(model.resultsChanged), qtbot.assertNotEmitted(model.specChanged):
        model.set_spec(time_ratio=1.4)
        model.set_rpms([40, 60])
        model.set_angle_index(0)


def test_invalid_change_keeps_last_valid(model, qtbot):
    before = model.motion
    with qtbot.assertNotEmitted(model.resultsChanged):
        with qtbot.waitSignal(model.errorChanged, timeout=10_000):
            model.set_spec(time_ratio=0.7)
    assert model.error.parameter == "time_ratio"
    assert model.motion is before and model.design.time_ratio == pytest.approx(1.4)
    assert model.spec.time_ratio == 0.7 and model.valid_spec.time_ratio == 1.4
    with qtbot.waitSignal(model.errorChanged, timeout=10_000):
        model.set_spec(time_ratio=1.5)
    assert model.error is None and model.design.time_ratio == pytest.approx(1.5)


def test_speeds_and_step(model, qtbot):
    model.set_rpms([20, 40, 60, 80])
    assert model.motion.ram_v.shape == (4, 361)
    model.set_rpms([40, "fast"])
    assert model.error.parameter == "rpm" and model.rpms == (20, 40, 60, 80)
    model.set_step(0.5)       # the typed speeds are still invalid: nothing is applied
    assert model.error.parameter == "rpm" and model.angle_count == 361
    model.set_rpms([40, 50])
    assert model.error is None and model.angle_count == 721 and model.rpms == (40, 50)
    model.set_step(0)
    assert model.error.parameter == "step" and model.angle_count == 721


def test_angle_index_wraps_and_snaps(model, qtbot):
    with qtbot.waitSignal(model.angleChanged, timeout=10_000) as blocker:
        model.set_angle_deg(90.4)
    assert blocker.args == [90] and model.crank_deg == pytest.approx(90)
    model.set_angle_index(361 + 5)
    assert model.angle_index == 5
