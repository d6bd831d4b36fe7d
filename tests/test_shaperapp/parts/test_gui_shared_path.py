"""Every input form edits its model through the one shared path (issue 43, item 2): the
keystrokes wait for the pause (``PendingEdits``), the commit is one undoable step, undo and
redo bring the field and the model back, and a refused value is marked while the last
valid input stays: the linkage and loads forms, and the cam's and gear's part forms."""
from __future__ import annotations

import pytest

from shaperapp.cam.form import CamForm
from shaperapp.cam.model import CamModel
from shaperapp.design.fields import PendingEdits
from shaperapp.design.form import DesignForm
from shaperapp.design.loads_form import LoadsForm
from shaperapp.gear.form import GearForm
from shaperapp.gear.model import GearModel


def linkage(model):
    form = DesignForm(model)
    return form, form.field("crank"), lambda: model.valid_spec.crank, lambda: model.error


def loads(model):
    form = LoadsForm(model)
    return form, form.field("cut_force_N"), lambda: model.masses.cut_force_N, lambda: model.forces_error


def cam(model):
    part = CamModel(model)
    form = CamForm(part)
    form._part = part       # kept alive with the form
    return form, form.fields["swing"].edit, lambda: part.cam.program.swing_deg, lambda: part.error


def gear(model):
    part = GearModel(model)
    form = GearForm(part)
    form._part = part
    return form, form.fields["z1"].edit, lambda: part.pair.gear1.teeth, lambda: part.error


# form, its field, the value the model starts from (the defaults of DesignModel, CamModel,
# GearModel), the value typed (valid), and its field's name in the refusal
CASES = {"linkage": (linkage, 100.0, "110", 110.0, "crank"),
         "loads": (loads, 7000.0, "5000", 5000.0, "cut_force_N"),
         "cam": (cam, 15.0, "20", 20.0, "swing"),
         "gear": (gear, 13, "14", 14, "z1")}


def type_text(qtbot, edit, text):
    edit.selectAll()
    qtbot.keyClicks(edit, text)


@pytest.mark.parametrize("kind", list(CASES))
def test_each_form_edits_through_the_shared_path(qtbot, model, kind):
    build, start, text, typed, name = CASES[kind]
    form, edit, valid, error = build(model)
    qtbot.addWidget(form)
    form.show()
    assert isinstance(form.pending, PendingEdits)
    assert valid() == start
    steps = model.undo_stack.count()

    type_text(qtbot, edit, text)                       # typed, not yet sent: the pause
    assert name in form.pending and valid() == start and model.undo_stack.count() == steps
    qtbot.waitUntil(lambda: valid() == typed, timeout=10_000)
    assert name not in form.pending
    assert model.undo_stack.count() == steps + 1       # the keystrokes are one step

    model.undo_stack.undo()
    assert valid() == start and float(edit.text()) == float(start)
    model.undo_stack.redo()
    assert valid() == typed and float(edit.text()) == float(typed)

    type_text(qtbot, edit, "abc")                      # refused: marked, the last valid kept
    form.pending.commit()
    assert error() is not None and error().parameter == name
    assert form.marked_fields() == [name]
    assert valid() == typed and edit.text() == "abc"
    # typing on in the same field merges into the redone step (one step per field typed
    # into, in every form): its undo clears the mark and goes back to the start
    assert model.undo_stack.count() == steps + 1
    model.undo_stack.undo()
    assert error() is None and form.marked_fields() == []
    assert valid() == start and float(edit.text()) == float(start)


def _other(combo):
    """The index of an entry other than the one shown."""
    return (combo.currentIndex() + 1) % combo.count()


def pick(combo):
    """Another entry chosen as a user's choice is signalled (``activated``, which the part
    forms follow; the linkage form follows ``currentIndexChanged``)."""
    index = _other(combo)
    combo.setCurrentIndex(index)
    combo.activated.emit(index)


# a choice beside each form's typed field: (form, part) → (the choice's widget, how to make
# the other choice, the model's value of the choice)
CHOICE_CASES = {
    "linkage": lambda form, model: (form._combo("guide_rule"), pick,
                                    lambda: model.spec.guide_rule),
    "linkage mode": lambda form, model: (form._dims_radio, lambda r: r.setChecked(True),
                                         lambda: model.spec.mode),
    "loads": lambda form, model: (form._given["ram"], pick,
                                  lambda: model.mass_inputs.get("ram_weight_N") is not None),
    "cam": lambda form, model: (form.laws["return_law"], pick,
                                lambda: form._part.typed.dict["return_law"]),
    "gear": lambda form, model: (form.mode, pick,
                                 lambda: form._part.typed.dict["mode"]),
}


@pytest.mark.parametrize("kind", list(CHOICE_CASES))
def test_a_choice_made_while_a_field_waits_keeps_both(qtbot, model, kind):
    """A choice made while a typed field still waits for its pause (no focus change: a
    shortcut, an accessibility tool, a platform whose combo boxes take no focus on a click)
    sends the field, then the choice: the form shows the model after the field's commit,
    which must not turn the choice back before it is read."""
    build, start, text, typed, name = CASES[kind.split()[0]]
    form, edit, valid, error = build(model)
    qtbot.addWidget(form)
    form.show()
    widget, choose, chosen = CHOICE_CASES[kind](form, model)
    before = chosen()
    type_text(qtbot, edit, text)
    assert name in form.pending
    choose(widget)
    assert valid() == typed and name not in form.pending
    assert chosen() != before
