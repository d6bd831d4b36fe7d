"""The gear pair in the design file, through the window (issue 35, item 4): Save writes the
Gear tab's pair even if the tab was never shown, Open reads it back, a file without one gets
the default pair, and a bad "gear" object (or one whose pair cannot be made) is refused
with nothing changed."""
from __future__ import annotations

import json

import pytest
from PySide6.QtCore import QSettings

from core.gear import GearPairInputs, design_pair
from core.gear.file import gear_to_dict
from shaperapp.design.document import Document
from shaperapp.design.model import DesignModel
from shaperapp.gear.model import GearModel

DEFAULT = gear_to_dict(GearPairInputs(13, 40, 6.0, centre_mm=162.0))


def saved_gear(window, path):
    assert window.document.save_to(str(path))
    return json.loads(path.read_text(encoding="utf-8"))["gear"]


def test_save_writes_the_default_pair_without_the_tab_ever_shown(window, tmp_path):
    assert not window._pages["gear"].is_built()
    assert saved_gear(window, tmp_path / "d.json") == DEFAULT
    assert not window._pages["gear"].is_built()


def test_an_edited_pair_goes_round_through_save_and_open(window, tmp_path):
    window.gear_model.set_fields(z1=15.0, z2=47.0, mode="shifts", x1=0.3, x2=-0.1, module=5.0)
    want = design_pair(GearPairInputs(15, 47, 5.0, x1=0.3, x2=-0.1))
    assert window.gear_model.pair == want
    path = tmp_path / "d.json"
    assert saved_gear(window, path) == gear_to_dict(want.inputs)
    window.model.load_state(window.model.valid_spec, window.model.rpms, window.model.step_deg)   # New
    assert window.gear_model.pair.inputs == GearPairInputs(13, 40, 6.0, centre_mm=162.0)
    assert window.document.open_path(str(path))
    assert window.gear_model.pair == want
    assert window.gear.form.fields["x1"].edit.text() == "0.3"       # the tab built now shows it
    assert window.gear.form.mode.currentData() == "shifts"


def test_a_file_without_a_gear_gets_the_default_pair(window, tmp_path):
    window.gear_model.set_fields(z1=17.0)
    path = tmp_path / "d.json"
    assert window.document.save_to(str(path))
    data = json.loads(path.read_text(encoding="utf-8"))
    del data["gear"]
    path.write_text(json.dumps(data), encoding="utf-8")
    assert window.document.open_path(str(path))
    assert gear_to_dict(window.gear_model.pair.inputs) == DEFAULT


@pytest.fixture
def gear_doc(qtbot, tmp_path):
    """A design model with the window's gear model and the file actions (no window: a
    refusal is a signal here, not a message box)."""
    model = DesignModel()
    gear_model = GearModel(model)
    return model, gear_model, Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))


@pytest.mark.parametrize("gear", [{"z1": 4, "z2": 40, "module_mm": 6},           # too few teeth
                                  {"z1": 13, "z2": 40},                            # no module
                                  {"z1": 13, "z2": 40, "module_mm": 6, "teeth": 3},  # not a field
                                  {"z1": 13, "z2": 40, "module_mm": 6, "centre_mm": 100.0},  # no pair fits
                                  [13, 40]])
def test_a_bad_gear_object_is_refused_and_nothing_changes(gear_doc, tmp_path, gear):
    model, gear_model, document = gear_doc
    gear_model.set_fields(z1=17.0)
    path = tmp_path / "d.json"
    assert document.save_to(str(path))
    model.set_spec(time_ratio=1.6)
    before = gear_model.pair
    data = json.loads(path.read_text(encoding="utf-8"))
    path.write_text(json.dumps({**data, "gear": gear}), encoding="utf-8")
    failures = []
    document.failed.connect(failures.append)
    assert not document.open_path(str(path))
    assert len(failures) == 1 and "d.json" in failures[0]
    assert gear_model.pair is before and gear_model.pair.gear1.teeth == 17
    assert model.spec.time_ratio == 1.6 and model.dirty      # the typed design as it was, not the file's


def test_an_opened_pair_shows_its_own_shifts_in_the_greyed_fields(window, tmp_path):
    """Issue 40: the greyed fields follow the pair the tables show after Open too. A file
    with a′ = 165 for z 10/40 opened over the tab built on another pair: x1, x2 are that
    file's pair's, to the 7 digits they show."""
    window.gear_model.set_fields(z1=10.0, centre=165.0)
    path = tmp_path / "d.json"
    assert window.document.save_to(str(path))
    window.model.load_state(window.model.valid_spec, window.model.rpms, window.model.step_deg)   # New
    form = window.gear.form
    assert window.document.open_path(str(path))
    want = design_pair(GearPairInputs(10, 40, 6.0, centre_mm=165.0))
    for name, value in (("x1", want.gear1.shift), ("x2", want.gear2.shift)):
        assert not form.fields[name].isEnabled()
        assert float(form.fields[name].edit.text()) == pytest.approx(value, rel=1e-6)
