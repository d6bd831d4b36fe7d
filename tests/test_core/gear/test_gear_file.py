"""The design file's "gear" object (issue 35, item 4's last sentence): read all or nothing,
like the cam's; a bad one refuses the whole file, naming the key."""
from __future__ import annotations

import json

import pytest

from core.files.design_file import load_design
from core.base.errors import DesignError, FileFormatError
from core.gear import GearPairInputs
from core.gear.file import gear_from_dict, gear_to_dict
from core.files.io import design_document
from core.linkage.spec import Spec


def test_round_trip():
    inputs = GearPairInputs(z1=13, z2=40, module_mm=6.0, centre_mm=160.0, clearance=0.28)
    assert gear_from_dict(json.loads(json.dumps(gear_to_dict(inputs)))) == inputs


@pytest.mark.parametrize("change, key", [({"teeth": 3}, "teeth"), ({"z1": True}, "z1"),
                                         ({"z1": 12.5}, "z1"), ({"z1": 3}, "z1"),
                                         ({"module_mm": "6"}, "module_mm"),
                                         ({"module_mm": -1}, "module"), ({"x1": 0.3}, "x2")])
def test_a_bad_value_is_named(change, key):
    data = {"z1": 13, "z2": 40, "module_mm": 6.0, **change}
    with pytest.raises(DesignError) as info:
        gear_from_dict(data)
    assert info.value.parameter == key


def test_required_keys():
    with pytest.raises(DesignError) as info:
        gear_from_dict({"z1": 13, "z2": 40})
    assert info.value.parameter == "module_mm"


def _file(tmp_path, gear):
    doc = design_document(Spec(), [60.0], 1.0)
    doc["gear"] = gear
    path = tmp_path / "d.shaper.json"
    path.write_text(json.dumps(doc), encoding="utf-8")
    return path


def test_a_design_file_keeps_a_good_gear_and_refuses_a_bad_one(tmp_path):
    good = {"z1": 13, "z2": 40, "module_mm": 6.0, "x1": None, "x2": None, "centre_mm": None}
    assert load_design(_file(tmp_path, good))["gear"] == good
    with pytest.raises(FileFormatError) as info:
        load_design(_file(tmp_path, {"z1": 13, "z2": 40, "module_mm": 6.0, "pinion": 1}))
    assert "pinion" in str(info.value)


@pytest.mark.parametrize("gear, key", [
    ({"centre_mm": 1e-300}, "centre"),          # below a cos α = 159 cos 20° = 149.41 mm
    ({"centre_mm": 200.0}, "centre"),           # a tip of gear 1 pointed
    ({"x1": -3.0, "x2": -3.0}, "x1")])          # α′ ≤ 0: the gears do not mesh
def test_a_pair_that_cannot_be_made_refuses_the_file(tmp_path, gear, key):
    """Each key in range alone, but no pair: the GUI's File › Open refused such a file
    (``shaperapp.gear.model.check_part``) while every ``--design`` and ``shaper library add``
    read it, so the library kept a design its pane could not open (hunt s13-hunt2)."""
    with pytest.raises(FileFormatError) as info:
        load_design(_file(tmp_path, {"z1": 13, "z2": 40, "module_mm": 6.0, **gear}))
    assert info.value.cause.parameter == key
