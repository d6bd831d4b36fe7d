"""Issue 12: whatever the user types, Save writes a file that reopens to the inputs on screen.

Sequences of edits are driven through the real form widgets (text typed into the
line edits, choices switched in the combo boxes and radio buttons, speeds added and
removed with the buttons) and the model's public load setter, with undo and redo in
between. After every action no field that Save would write may be invalid; at the
end, Save → Open gives back exactly the inputs on screen, in the GUI and in
``shaper analyze --design FILE``.
"""
import contextlib
import io
import json
from dataclasses import fields

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st
from PySide6.QtCore import QSettings

from core.cli import run as run_cli
from core.forces.masses import MassProperties
from core.files.io import load_design
from core.linkage.spec import NUMBER_FIELDS
from shaperapp.design.document import Document
from shaperapp.design.fields import parse_number
from shaperapp.design.form import DesignForm
from shaperapp.design.model import DesignModel

from cli_runner import shaper
from sweeps import examples

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

DESIGN_FIELDS = ("crank", "time_ratio", "stroke", "frame", "lever", "guide_height", "rod_length", "rod_ratio")
LOAD_FIELDS = ("lever_mass_kg", "lever_inertia_kg_m2", "ram_mass_kg", "cut_force_N", "cut_height_mm",
               "idle_fraction", "delta", "lever_cg_mm")
CHOICES = {"variant": ("block", "rod"), "guide_rule": ("chord", "sagitta", "height"),
           "rod_input": ("ratio", "length"), "rod_side": ("trailing", "leading")}
GARBAGE = ("ጼ", "", "abc", "1e999", "nan", "inf", "-5", "0", "1,5", "1e-320", " ", "--1", "0x10", "∞")

plausible = st.one_of(st.floats(0.5, 2000.0), st.floats(1.0, 5.0), st.floats(0.0, 3.0))
texts = st.one_of(plausible.map(lambda v: f"{v:.6g}"), st.sampled_from(GARBAGE),
                  st.text(max_size=4))
actions = st.one_of(
    st.tuples(st.just("type"), st.sampled_from(DESIGN_FIELDS), texts),
    st.tuples(st.just("mode"), st.sampled_from(("synthesis", "dimensions"))),
    st.tuples(st.just("choice"), st.sampled_from(sorted(CHOICES)), st.integers(0, 2)),
    st.tuples(st.just("step"), st.one_of(st.sampled_from(("1", "2", "5", "0", "x", "91", "0.5")), texts)),
    st.tuples(st.just("speed"), st.sampled_from(("add", "remove", "edit")), texts),
    st.tuples(st.just("load"), st.sampled_from(LOAD_FIELDS), texts),
    st.tuples(st.just("undo"),), st.tuples(st.just("redo"),),
)


@pytest.fixture(scope="module")
def rig(qapp, tmp_path_factory):
    """One model, form and document reused across examples (reset by File › New)."""
    folder = tmp_path_factory.mktemp("roundtrip")
    model = DesignModel()
    form = DesignForm(model)
    document = Document(model, QSettings(str(folder / "s.ini"), QSettings.Format.IniFormat))
    other = DesignModel()
    other_form = DesignForm(other)
    other_doc = Document(other, QSettings(str(folder / "o.ini"), QSettings.Format.IniFormat))
    yield model, form, document, other, other_form, other_doc, folder
    form.deleteLater()
    other_form.deleteLater()


def type_text(form: DesignForm, name: str, text: str) -> None:
    """What a user does: replace the text, then leave the field (Enter or Tab)."""
    edit = form.field(name)
    edit.setText(text)
    edit.textEdited.emit(text)
    edit.editingFinished.emit()


def perform(model, form, action) -> None:
    kind = action[0]
    if kind == "type":
        type_text(form, action[1], action[2])
    elif kind == "mode":
        (form._synth_radio if action[1] == "synthesis" else form._dims_radio).click()
    elif kind == "choice":
        combo = form._combo(action[1])
        combo.setCurrentIndex(action[2] % combo.count())
    elif kind == "step":
        type_text(form, "step", action[1])
    elif kind == "speed":
        if action[1] == "add":
            form._add_speed.click()
        elif action[1] == "remove":
            form._remove_speed.click()
        else:
            form._speeds.item(form._speeds.count() - 1).setText(action[2])
    elif kind == "load":
        value = None if action[1] == "lever_cg_mm" and not action[2].strip() else parse_number(action[2])
        model.set_masses(**{action[1]: value})
    elif kind == "undo":
        model.undo_stack.undo()
    else:
        model.undo_stack.redo()


def assert_nothing_invalid_is_kept(model) -> None:
    """What Save writes is valid field by field, and unused fields never hold raw text."""
    model.valid_spec.check_fields()
    spec = model.spec
    for name in set(NUMBER_FIELDS) - spec.active_fields():
        spec.check_field(name)
    MassProperties(**{f.name: getattr(model.masses, f.name) for f in fields(MassProperties)})


def shown_values(form: DesignForm) -> dict:
    values = {name: parse_number(form.field(name).text()) for name in DESIGN_FIELDS + ("step",)}
    values["speeds"] = [parse_number(form._speeds.item(i).text()) for i in range(form._speeds.count())]
    values["choices"] = {name: form._combo(name).currentData() for name in CHOICES}
    values["mode"] = "synthesis" if form._synth_radio.isChecked() else "dimensions"
    return values


@settings(max_examples=examples(300), deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture,
                                                                  HealthCheck.too_slow])
@given(st.lists(actions, max_size=10))
def test_any_edit_sequence_saves_a_file_that_reopens_to_the_screen(rig, sequence):
    model, form, document, other, other_form, other_doc, folder = rig
    document.new()
    for action in sequence:
        if action[0] in ("mode", "choice") and model.error is not None:
            event("switch while an input is invalid")
        perform(model, form, action)
        assert_nothing_invalid_is_kept(model)
    if not model.inputs_valid:
        model.revert_invalid()          # what Save does once the user agrees (Document.confirm_valid)
    assert model.inputs_valid and model.spec == model.valid_spec
    path = str(folder / "design.shaper.json")
    assert document.save_to(path) and not model.dirty

    assert other_doc.open_path(path), "a saved file must reopen"
    assert other.spec == model.spec and other.valid_spec == model.valid_spec
    assert other.rpms == model.rpms and other.step_deg == model.step_deg
    assert other.masses == model.masses and other.design == model.design
    assert shown_values(other_form) == shown_values(form)
    for name in DESIGN_FIELDS:          # what is on screen is exactly what was saved
        assert parse_number(form.field(name).text()) == getattr(model.spec, name)
    assert parse_number(form.field("step").text()) == model.step_deg
    assert other.error is None and other.forces_error is None

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert run_cli(["analyze", "--design", path, "--json"]) == 0
    assert json.loads(out.getvalue())["K"] == pytest.approx(model.metrics.time_ratio, rel=1e-9)


def test_issue_12_reproduction_saves_a_file_that_reopens(rig, tmp_path):
    """Dimensions mode, 'ጼ' typed as the frame, back to synthesis, Save: the file opens."""
    model, form, document, other, other_form, other_doc, _ = rig
    document.new()
    form._dims_radio.click()
    type_text(form, "frame", "ጼ")
    assert model.error is not None and model.error.parameter == "frame"
    form._synth_radio.click()
    assert model.error is None
    assert isinstance(model.spec.frame, float) and isinstance(model.valid_spec.frame, float)
    assert parse_number(form.field("frame").text()) == model.spec.frame
    path = tmp_path / "repro.shaper.json"
    assert document.save_to(str(path))
    assert load_design(path)["spec"] == model.valid_spec
    assert other_doc.open_path(str(path))
    result = shaper("analyze", "--design", path)      # the real command, in a subprocess
    assert result.returncode == 0, result.stderr
    assert "measured K" in result.stdout


def test_invalid_inactive_rod_and_guide_take_their_last_valid_value(rig):
    model, form, document, *_ = rig
    document.new()
    form._combo("variant").setCurrentIndex(1)                 # rod
    type_text(form, "rod_ratio", "-3")
    assert model.error.parameter == "rod_ratio"
    form._combo("variant").setCurrentIndex(0)                 # block: the rod is unused
    assert model.error is None and model.spec.rod_ratio == 0.3
    form._combo("guide_rule").setCurrentIndex(2)              # explicit height
    type_text(form, "guide_height", "x")
    assert model.error.parameter == "guide"
    form._combo("guide_rule").setCurrentIndex(0)
    assert model.error is None and model.spec.guide_height == 560.0
    assert form.field("guide_height").text() == "560"
