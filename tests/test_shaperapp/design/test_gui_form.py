"""The form drives the model, marks the offending field, and mirrors the model."""
import pytest

from core.base.figure_text import figure_text   # one precision per kind (issue 40)

from core.linkage.geometry import synthesize
from shaperapp.design.form import DesignForm
from shaperapp.design.model import DesignModel
from shaperapp.results.panel import MetricsPanel


@pytest.fixture
def setup(qtbot):
    model = DesignModel()
    form = DesignForm(model)
    metrics = MetricsPanel(model)
    qtbot.addWidget(form)
    qtbot.addWidget(metrics)
    form.show()
    return model, form, metrics


def type_into(qtbot, edit, text):
    edit.selectAll()
    qtbot.keyClicks(edit, text)


def test_typing_k_updates_dimensions_and_metrics_after_debounce(setup, qtbot):
    model, form, metrics = setup
    edit = form.field("time_ratio")
    edit.clear()
    with qtbot.waitSignal(model.resultsChanged, timeout=10_000):
        type_into(qtbot, edit, "1.6")
    expected = synthesize(100, 1.6, 300)
    assert model.design == expected
    assert metrics.value_text("frame") == f"{expected.frame:.3f}"     # lengths to 3 decimals everywhere (issue 40)
    assert metrics.value_text("K") == "1.6000"
    assert form.marked_fields() == []


def test_invalid_value_marks_field_and_keeps_design(setup, qtbot):
    model, form, metrics = setup
    before = model.design
    shown = metrics.value_text("lever")
    edit = form.field("stroke")
    edit.clear()
    with qtbot.waitSignal(model.errorChanged, timeout=10_000):
        type_into(qtbot, edit, "120")
    assert form.marked_fields() == ["stroke"]
    assert "Stroke H" in form.error_text()
    assert model.design == before and metrics.value_text("lever") == shown
    with qtbot.waitSignal(model.errorChanged, timeout=10_000):
        type_into(qtbot, edit, "360")
    assert form.marked_fields() == [] and form.error_text() == ""
    assert model.design.stroke == pytest.approx(360)


def test_text_that_is_not_a_number(setup, qtbot):
    model, form, _ = setup
    edit = form.field("crank")
    edit.clear()
    with qtbot.waitSignal(model.errorChanged, timeout=10_000):
        type_into(qtbot, edit, "1o0")
    assert model.error.parameter == "crank" and form.marked_fields() == ["crank"]
    assert "number" in form.error_text()


def test_model_change_shows_in_form(setup, qtbot):
    model, form, _ = setup
    model.set_spec(crank=120.0, variant="rod", rod_ratio=0.4)
    assert form.field("crank").text() == "120"
    assert form.field("rod_ratio").text() == "0.4"
    assert form.field("rod_ratio").isVisible()
    model.set_spec(variant="block")
    assert not form.field("rod_ratio").isVisible()


def test_add_and_remove_speed(setup, qtbot):
    model, form, metrics = setup
    with qtbot.waitSignal(model.resultsChanged, timeout=10_000):
        qtbot.mouseClick(form._add_speed, __import__("PySide6.QtCore").QtCore.Qt.MouseButton.LeftButton)
    assert model.rpms == (40.0, 60.0, 80.0)
    assert metrics.table_text(0, 2) == f"{model.metrics.speeds[2].cycle_time_s:.4f}"
    form._speeds.setCurrentRow(0)
    form._remove_speed.click()
    assert model.rpms == (60.0, 80.0)


def test_direct_dimensions_mode(setup, qtbot):
    import math
    model, form, metrics = setup
    form._dims_radio.setChecked(True)
    assert model.spec.mode == "dimensions"
    assert form.field("frame").isVisible() and not form.field("stroke").isVisible()
    type_into(qtbot, form.field("frame"), "250")
    form.field("frame").editingFinished.emit()
    theta = 2 * math.asin(100 / 250)
    assert model.error is None
    assert metrics.value_text("K_nominal") == f"{(math.pi + theta) / (math.pi - theta):.4f}"
    assert metrics.value_text("K") == f"{(math.pi + theta) / (math.pi - theta):.4f}"
    type_into(qtbot, form.field("frame"), "90")
    form.field("frame").editingFinished.emit()
    assert model.error.parameter == "crank" and form.marked_fields() == ["crank"]


def test_metrics_show_flywheel_and_power_from_core(setup, qtbot):
    from core.forces.flywheel import summarize
    model, form, metrics = setup
    model.set_masses(cut_force_N=5000.0, delta=0.05)
    want = summarize(model.design, model.rpms, model.masses).speeds
    for col, s in enumerate(want):
        assert metrics.table_text(2, col, forces=True) == figure_text("power", s.mean_power_W / 1000)
        assert metrics.table_text(5, col, forces=True) == figure_text("inertia", s.flywheel_inertia_kg_m2)
    # Power is the cut work per cycle over the cycle time (gravity and inertia do no net work).
    h = model.metrics.stroke_mm / 1000
    assert want[0].mean_power_W == pytest.approx(5000 * h * (1 - 2 * 0.05) / model.metrics.speeds[0].cycle_time_s)
