"""The Loads form takes the loads as the task book states them: a weight in N for the lever
and the ram (a kg/N choice), the rotating parts for the flywheel, the guide's length; and
the design file keeps a weight as a weight (issue 41 item 2, issue 40 item 3)."""
from __future__ import annotations

import json

import pytest

from core.files.design_file import masses_to_dict
from core.forces.masses import GRAVITY
from shaperapp.design.loads_form import LoadsForm

from gui_helpers import shown


@pytest.fixture
def form(qtbot, model) -> LoadsForm:
    return shown(qtbot, LoadsForm(model), 420, 900)


def type_into(qtbot, edit, text: str) -> None:
    edit.selectAll()
    qtbot.keyClicks(edit, text)


def choose(combo, data: str) -> None:
    combo.setCurrentIndex(combo.findData(data))
    combo.activated.emit(combo.currentIndex())


def test_the_lever_as_a_weight_of_200_N(form, model, qtbot):
    assert form.field("lever_mass_kg").isVisible() and not form.field("lever_weight_N").isVisible()
    choose(form.given_box("lever"), "weight")
    assert form.field("lever_weight_N").isVisible() and not form.field("lever_mass_kg").isVisible()
    assert model.masses.lever_weight_N == pytest.approx(20.0 * GRAVITY)   # the mass carried over
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, form.field("lever_weight_N"), "200")
    assert model.masses.lever_weight_N == 200.0
    assert model.masses.lever_mass_kg == 200.0 / GRAVITY
    saved = masses_to_dict(model.masses)
    assert saved["lever_weight_N"] == 200.0 and "lever_mass_kg" not in saved
    # and back to a mass: G/g carried, no weight left
    choose(form.given_box("lever"), "mass")
    assert model.masses.lever_weight_N is None
    assert model.masses.lever_mass_kg == pytest.approx(200.0 / GRAVITY, rel=1e-11)
    assert form.field("lever_mass_kg").isVisible()


def test_the_ram_as_a_weight_and_a_bad_weight_is_marked(form, model, qtbot):
    choose(form.given_box("ram"), "weight")
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, form.field("ram_weight_N"), "700")
    assert model.masses.ram_mass_kg == 700.0 / GRAVITY
    with qtbot.waitSignal(model.forcesErrorChanged, timeout=10_000):
        type_into(qtbot, form.field("ram_weight_N"), "-5")
    assert form.marked_fields() == ["ram_weight_N"]
    assert model.masses.ram_weight_N == 700.0             # the last valid loads stay


def test_rotating_parts_reach_the_flywheel(form, model, qtbot):
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, form.field("rotors"), "0.5:1; 0.02:15")
    assert model.masses.rotors == ((0.5, 1.0), (0.02, 15.0))
    summary = model.dynamics_summary
    assert summary.rotor_inertia_kg_m2 == pytest.approx(5.0)
    s = summary.speeds[0]
    assert s.flywheel_inertia_needed_kg_m2 == pytest.approx(s.flywheel_inertia_kg_m2 - 5.0)
    with qtbot.waitSignal(model.forcesErrorChanged, timeout=10_000):
        type_into(qtbot, form.field("rotors"), "0.5:x")
    assert form.marked_fields() == ["rotors"]
    assert model.masses.rotors == ((0.5, 1.0), (0.02, 15.0))


def test_guide_length_empty_is_the_stroke(form, model, qtbot):
    assert form.field("guide_length_mm").placeholderText().endswith("300")
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, form.field("guide_length_mm"), "450")
    assert model.masses.guide_length_mm == 450.0
    assert model.dynamics.guide_front_mm - model.dynamics.guide_rear_mm == pytest.approx(450.0)
    json.dumps(masses_to_dict(model.masses))     # what Save writes is plain JSON


def test_a_rotating_part_on_the_pinion_shaft_takes_the_gear_ratio(form, model, qtbot):
    model.parts.set_loaded({"gear": {"z1": 17, "z2": 68, "module_mm": 4}})
    with qtbot.waitSignal(model.forcesChanged, timeout=10_000):
        type_into(qtbot, form.field("rotors"), "0.03:gear")
    assert model.masses.rotors == ((0.03, 68 / 17),)
