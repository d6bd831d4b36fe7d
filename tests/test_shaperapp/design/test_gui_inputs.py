"""Issue 8, inputs without traps, and undo/redo of every design and load edit."""
import math

import pytest
from PySide6.QtCore import QPoint, QPointF, QSettings, Qt
from PySide6.QtGui import QWheelEvent
from PySide6.QtWidgets import QApplication, QMessageBox, QScrollArea

from core.base.errors import DesignError
from core.linkage.geometry import synthesize
from shaperapp.design.document import Document
from shaperapp.design.form import DesignForm
from shaperapp.design.inputs import MAX_SPEEDS
from shaperapp.design.model import DesignModel
from shaperapp.widgets.guards import guard_wheel, install_wheel_guard
from shaperapp.widgets.messages import describe


@pytest.fixture
def setup(qtbot, tmp_path):
    model = DesignModel()
    form = DesignForm(model)
    qtbot.addWidget(form)
    form.show()
    document = Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    return model, form, document


def type_text(form, name, text):
    edit = form.field(name)
    edit.setText(text)
    edit.textEdited.emit(text)
    edit.editingFinished.emit()


# ---- the error clears as soon as the value is valid again ------------------------
def test_retyping_the_old_step_clears_the_error(setup):
    """Issue 8: type an invalid angle step, then the old value: the error must go."""
    model, form, _ = setup
    type_text(form, "step", "0")
    assert model.error.parameter == "step" and form.marked_fields() == ["step"]
    type_text(form, "step", "1")
    assert model.error is None and form.marked_fields() == [] and form.error_text() == ""


def test_retyping_the_old_speed_clears_the_error(setup):
    model, form, _ = setup
    form._speeds.item(0).setText("fast")
    assert model.error.parameter == "rpm"
    form._speeds.item(0).setText("40")
    assert model.error is None and model.rpms == (40.0, 60.0)


# ---- switching mode carries the design over ---------------------------------------
def test_switching_to_dimensions_carries_the_synthesized_design(setup):
    """Issue 8: K = 1.6, H = 450 on screen, then Direct dimensions: the same mechanism."""
    model, form, _ = setup
    type_text(form, "time_ratio", "1.6")
    type_text(form, "stroke", "450")
    expected = synthesize(100, 1.6, 450)
    form._dims_radio.click()
    assert model.spec.mode == "dimensions" and model.error is None
    assert model.design.frame == pytest.approx(expected.frame, rel=1e-11)
    assert model.design.lever == pytest.approx(expected.lever, rel=1e-11)
    assert float(form.field("frame").text()) == model.spec.frame
    assert form._main_box.title() == "Link lengths"


def test_switching_to_synthesis_carries_the_k_and_h_the_dimensions_imply(setup):
    model, form, _ = setup
    form._dims_radio.click()
    type_text(form, "frame", "250")
    type_text(form, "lever", "500")
    design = model.design
    form._synth_radio.click()
    assert model.spec.mode == "synthesis" and model.error is None
    assert model.spec.time_ratio == pytest.approx(design.time_ratio, rel=1e-11)
    assert model.spec.stroke == pytest.approx(design.stroke, rel=1e-11)
    assert model.design.frame == pytest.approx(250, rel=1e-9) and model.design.lever == pytest.approx(500, rel=1e-9)
    assert form._main_box.title() == "Synthesis inputs"


def test_metrics_box_title_follows_the_mode(setup, qtbot):
    from shaperapp.results.panel import MetricsPanel
    model, form, _ = setup
    panel = MetricsPanel(model)
    qtbot.addWidget(panel)
    assert panel._dim_box.title() == "Synthesized dimensions"
    model.set_spec(mode="dimensions")
    assert panel._dim_box.title() == "Dimensions"


# ---- the wheel never changes what is not focused -----------------------------------
def wheel(widget, delta=-120):
    pos = QPointF(widget.rect().center())
    event = QWheelEvent(pos, QPointF(widget.mapToGlobal(pos.toPoint())), QPoint(), QPoint(0, delta),
                        Qt.MouseButton.NoButton, Qt.KeyboardModifier.NoModifier, Qt.ScrollPhase.NoScrollPhase,
                        False)
    QApplication.sendEvent(widget, event)


def test_wheel_over_an_unfocused_choice_scrolls_the_panel_instead(qtbot):
    """Issue 8: scrolling the side panel over "Ram drive" switched the rod to a block."""
    model = DesignModel()
    model.set_spec(variant="rod")
    form = DesignForm(model)
    scroll = QScrollArea()
    scroll.setWidget(form)
    scroll.resize(300, 200)
    qtbot.addWidget(scroll)
    guard_wheel(scroll)
    scroll.show()
    qtbot.waitExposed(scroll)
    combo = form._combo("variant")
    assert combo.focusPolicy() == Qt.FocusPolicy.StrongFocus
    start = scroll.verticalScrollBar().value()
    wheel(combo)
    assert model.spec.variant == "rod" and combo.currentData() == "rod"
    assert scroll.verticalScrollBar().value() > start            # the panel scrolled
    combo.setFocus()
    qtbot.waitUntil(combo.hasFocus, timeout=10_000)
    wheel(combo, 120)                                             # focused: the wheel chooses
    assert model.spec.variant == "block"


def test_a_window_that_gets_the_focus_has_its_choices_guarded(qtbot):
    """The guard sits on each choice, not on the application (which made every event of
    every widget pass through Python): a dialog's spin box is guarded as soon as a
    widget in its window gets the focus."""
    from PySide6.QtWidgets import QDialog, QPushButton, QSpinBox, QVBoxLayout
    install_wheel_guard()
    dialog = QDialog()
    qtbot.addWidget(dialog)
    layout = QVBoxLayout(dialog)
    button = QPushButton("OK")
    spin = QSpinBox()
    layout.addWidget(button)
    layout.addWidget(spin)
    spin.setValue(5)
    assert not spin.property("shaperWheelGuard")
    dialog.show()
    dialog.activateWindow()
    button.setFocus()
    qtbot.waitUntil(button.hasFocus, timeout=10_000)
    assert spin.property("shaperWheelGuard") and spin.focusPolicy() == Qt.FocusPolicy.StrongFocus
    wheel(spin, 120)
    assert spin.value() == 5                                      # unfocused: unchanged
    spin.setFocus()
    qtbot.waitUntil(spin.hasFocus, timeout=10_000)
    wheel(spin, 120)
    assert spin.value() == 6


# ---- Save or Export while a field is invalid asks ----------------------------------
def test_save_while_invalid_asks_and_cancel_saves_nothing(setup, tmp_path, monkeypatch):
    model, form, document = setup
    model.set_clean(str(tmp_path / "d.shaper.json"))
    type_text(form, "time_ratio", "0.9")
    asked = []
    monkeypatch.setattr(QMessageBox, "question", lambda *a, **k: asked.append(a[2]) or QMessageBox.StandardButton.Cancel)
    assert not document.save_dialog(None)
    assert asked and "Time ratio K" in asked[0]
    assert not (tmp_path / "d.shaper.json").exists() and model.dirty


def test_save_while_invalid_yes_saves_the_valid_design_and_shows_it(setup, tmp_path, monkeypatch):
    model, form, document = setup
    path = tmp_path / "d.shaper.json"
    model.set_clean(str(path))
    type_text(form, "time_ratio", "1.5")
    type_text(form, "time_ratio", "0.9")
    monkeypatch.setattr(QMessageBox, "question", lambda *a, **k: QMessageBox.StandardButton.Yes)
    assert document.save_dialog(None)
    assert form.field("time_ratio").text() == "1.5" and model.error is None and not model.dirty
    assert '"time_ratio": 1.5' in path.read_text()
    model.undo_stack.undo()                          # the revert is one undo step
    assert model.spec.time_ratio == 0.9


def test_export_while_invalid_asks(setup, tmp_path, monkeypatch):
    model, form, document = setup
    type_text(form, "crank", "abc")
    monkeypatch.setattr(QMessageBox, "question", lambda *a, **k: QMessageBox.StandardButton.Cancel)
    monkeypatch.setattr("shaperapp.widgets.file_dialogs.save_file_name",
                        lambda *a, **k: pytest.fail("no file dialog after Cancel"))
    assert not document.export_csv_dialog(None)
    assert not document.export_forces_csv_dialog(None)


def test_save_to_while_invalid_keeps_the_unsaved_mark(setup, tmp_path):
    model, form, document = setup
    type_text(form, "stroke", "-1")
    assert document.save_to(str(tmp_path / "x.json"))
    assert model.dirty and model.path.endswith("x.json")


# ---- controls can't go past their limits --------------------------------------------
def test_plus_disabled_at_sixteen_speeds_and_minus_at_one(setup):
    model, form, _ = setup
    while form._add_speed.isEnabled():
        form._add_speed.click()
    assert len(model.rpms) == MAX_SPEEDS and model.error is None
    form._add_speed.click()                  # disabled: nothing happens
    assert len(model.rpms) == MAX_SPEEDS
    while form._remove_speed.isEnabled():
        form._remove_speed.click()
    assert len(model.rpms) == 1 and not form._remove_speed.isEnabled()


def test_added_speed_never_exceeds_the_largest_allowed(setup):
    model, form, _ = setup
    model.set_rpms([990.0])
    form._add_speed.click()
    assert model.rpms == (990.0, 1000.0) and model.error is None


# ---- messages: the field's own unit, one wording, no internal names -----------------
def test_rod_ratio_error_speaks_in_ratio_not_mm(setup):
    """Issue 8: a rod given as L4/L3 that cannot reach the guide was blamed in mm."""
    model, form, _ = setup
    form._combo("variant").setCurrentIndex(1)
    type_text(form, "rod_ratio", "0.01")
    error = model.error
    assert error.parameter == "rod_ratio" and form.marked_fields() == ["rod_ratio"]
    text = form.error_text()
    assert "Rod ratio L4/L3" in text and "mm" not in text
    bound = float(text.split("more than ")[1].split()[0])
    # Hand check: with the chord rule the guide lies at the tip's lowest point L3·cos(θ/2),
    # so the rod must span the rise L3·(1 − cos(θ/2)); θ = 30° for K = 1.4.
    assert bound == pytest.approx(1 - math.cos(math.radians(15)), rel=1e-3)


@pytest.mark.parametrize("changes", [dict(time_ratio="x"), dict(time_ratio=float("nan")), dict(stroke=float("inf")),
                                     dict(crank="1o0"), dict(time_ratio=0.5), dict(time_ratio=1.0000001),
                                     dict(mode="dimensions", crank=100.0, frame=100.5),
                                     dict(variant="rod", rod_input="length", rod_length=1.0),
                                     dict(guide_rule="height", guide_height=1.0)])
def test_messages_have_no_internal_names_and_one_wording(model, changes):
    model.set_spec(**changes)
    text = describe(model.error)
    assert "_" not in text and "time_ratio" not in text
    assert "finite" not in text


def test_not_a_number_and_infinity_read_the_same(model):
    model.set_spec(time_ratio="x")
    first = describe(model.error)
    model.set_spec(time_ratio=float("inf"))
    assert describe(model.error) == first == "Time ratio K: must be a number"


def test_too_fine_a_step_for_the_speeds_is_refused_with_the_smallest_step(model):
    model.set_rpms([40.0 + i for i in range(16)])
    model.set_step(0.001)
    assert model.error.parameter == "step" and model.step_deg == 1.0
    assert "16 speeds" in describe(model.error)
    smallest = float(describe(model.error).split("at least ")[1].split("°")[0])
    model.set_step(smallest)
    assert model.error is None


def test_a_speed_too_small_to_compute_is_refused(model):
    model.set_rpms([5e-324])
    assert model.error.parameter == "rpm" and model.rpms == (40.0, 60.0)
    model.set_step(5e-324)
    assert model.error is not None


# ---- undo / redo -------------------------------------------------------------------
def test_keystrokes_in_one_field_are_one_undo_step(setup, qtbot):
    model, form, _ = setup
    edit = form.field("time_ratio")
    edit.setFocus()
    for text in ("1", "1.", "1.6"):             # three debounced commits while typing
        edit.setText(text)
        edit.textEdited.emit(text)
        form._commit()
    edit.editingFinished.emit()
    assert model.spec.time_ratio == 1.6
    assert model.undo_stack.count() == 1
    model.undo_stack.undo()
    assert model.spec.time_ratio == 1.4 and form.field("time_ratio").text() == "1.4" and not model.dirty
    model.undo_stack.redo()
    assert model.spec.time_ratio == 1.6 and form.field("time_ratio").text() == "1.6" and model.dirty


def test_leaving_the_field_starts_a_new_step(setup):
    model, form, _ = setup
    type_text(form, "stroke", "320")
    type_text(form, "stroke", "340")
    assert model.undo_stack.count() == 2
    model.undo_stack.undo()
    assert model.spec.stroke == 320


def test_undo_redo_every_kind_of_edit_both_ways(setup):
    model, form, _ = setup
    states = [(model.spec, model.rpm_inputs, model.step_input, model.mass_inputs, model.design)]
    edits = [lambda: type_text(form, "crank", "110"), lambda: form._dims_radio.click(),
             lambda: form._combo("variant").setCurrentIndex(1), lambda: form._combo("rod_side").setCurrentIndex(1),
             lambda: form._add_speed.click(), lambda: type_text(form, "step", "2"),
             lambda: model.set_masses(ram_mass_kg=50.0), lambda: model.set_masses(delta="x"),
             lambda: type_text(form, "lever", "nope")]
    for edit in edits:
        edit()
        states.append((model.spec, model.rpm_inputs, model.step_input, model.mass_inputs, model.design))
    assert model.undo_stack.count() == len(edits)
    for expected in reversed(states[:-1]):
        model.undo_stack.undo()
        assert (model.spec, model.rpm_inputs, model.step_input, model.mass_inputs, model.design) == expected
    assert not model.dirty and model.error is None and model.forces_error is None
    for expected in states[1:]:
        model.undo_stack.redo()
        assert (model.spec, model.rpm_inputs, model.step_input, model.mass_inputs, model.design) == expected
    assert model.error.parameter == "lever" and form.field("lever").text() == "nope"
    assert model.forces_error.parameter == "delta"


def test_clean_state_is_the_unsaved_mark(setup, tmp_path, qtbot):
    model, form, document = setup
    type_text(form, "crank", "90")
    assert document.save_to(str(tmp_path / "c.json")) and not model.dirty
    with qtbot.waitSignal(model.dirtyChanged, timeout=10_000) as blocker:
        model.undo_stack.undo()
    assert blocker.args == [True] and model.dirty
    with qtbot.waitSignal(model.dirtyChanged, timeout=10_000) as blocker:
        model.undo_stack.redo()
    assert blocker.args == [False] and not model.dirty


def test_invalid_edit_then_undo_restores_the_valid_state(model):
    model.set_spec(time_ratio=0.2)
    assert model.error is not None
    model.undo_stack.undo()
    assert model.error is None and model.spec.time_ratio == 1.4


def test_load_state_refuses_without_changing_anything(model):
    from core.linkage.spec import Spec
    model.set_spec(stroke=280.0)
    before = (model.spec, model.design, model.undo_stack.count(), model.dirty)
    with pytest.raises(DesignError):
        model.load_state(Spec(time_ratio=0.5), [40.0], 1.0, path="x.json")
    with pytest.raises(DesignError):
        model.load_state(Spec(mode="dimensions", time_ratio=0.5), [40.0], 1.0, path="x.json")
    assert (model.spec, model.design, model.undo_stack.count(), model.dirty) == before and model.path == ""


def test_a_design_core_cannot_compute_is_reported_not_ignored(model, monkeypatch):
    """Issue 7: a RuntimeError in the recomputation left no error on the form while the
    old design stayed on screen; now the form says so and nothing half-changes."""
    before = (model.design, model.motion, model.valid_spec)

    def broken(*args, **kwargs):
        raise RuntimeError("the ram does not have exactly two dead points")

    monkeypatch.setattr("shaperapp.design.results.analyze", broken)
    model.set_spec(stroke=310.0)
    assert model.error is not None and model.error.parameter == "design"
    assert describe(model.error) == "Design: cannot be computed for these inputs; try other values"
    assert (model.design, model.motion, model.valid_spec) == before
    monkeypatch.undo()
    model.set_spec(stroke=320.0)
    assert model.error is None and model.design.stroke == pytest.approx(320.0)
