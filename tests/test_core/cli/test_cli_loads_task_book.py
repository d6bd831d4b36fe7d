"""``shaper`` with the loads as the task book states them: weights in N, the rotating parts
reduced to the crank, the guide's length (issues 40 item 3 and 41 item 2)."""
from __future__ import annotations

import json

import pytest

from core.forces.masses import MassProperties
from core.files.io import load_design, masses_to_dict, save_design
from core.linkage.spec import Spec

from cli_runner import shaper_in_process

SEED = ("--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "60")
TASK_BOOK = ("--lever-weight", "200", "--lever-inertia", "1.1", "--ram-weight", "700",
             "--cut-force", "7000", "--cut-height", "80")


def test_weights_print_as_typed():
    status, out, err = shaper_in_process("dynamics", *SEED, *TASK_BOOK)
    assert status == 0, err
    rows = dict(line.split("  ", 1) for line in out.splitlines() if "  " in line)
    assert rows["lever weight G4"].strip() == "200 N"
    assert rows["ram weight G6"].strip() == "700 N"


@pytest.mark.parametrize("mass, weight", [("--lever-mass", "--lever-weight"), ("--ram-mass", "--ram-weight")])
def test_a_mass_and_a_weight_of_one_link_are_refused_naming_both(mass, weight):
    status, out, err = shaper_in_process("dynamics", *SEED, *TASK_BOOK, mass, "20")
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and mass in err and weight in err


def test_a_missing_lever_load_names_its_mass_and_its_weight():
    status, _, err = shaper_in_process("dynamics", *SEED, "--lever-inertia", "1.1", "--ram-weight",
                                       "700", "--cut-force", "7000")
    assert status == 2 and err.startswith("shaper: error: --lever-mass: required (or --lever-weight)")


def test_rotors_in_json_with_units_and_the_flywheel_needed():
    status, out, err = shaper_in_process("dynamics", *SEED, *TASK_BOOK, "--rotor", "0.5:1",
                                         "--rotor", "0.02:15", "--json")
    assert status == 0, err
    doc = json.loads(out)
    assert doc["inputs"]["rotors"] == [{"J_kg_m2": 0.5, "speed_ratio": 1.0},
                                       {"J_kg_m2": 0.02, "speed_ratio": 15.0}]
    assert doc["inputs"]["lever_weight_N"] == 200.0 and doc["inputs"]["ram_weight_N"] == 700.0
    assert doc["rotor_inertia_kg_m2"] == pytest.approx(0.5 + 0.02 * 225)
    speed = doc["speeds"][0]
    assert speed["flywheel_needed"] is True
    assert speed["flywheel_inertia_needed_kg_m2"] == pytest.approx(
        speed["flywheel_inertia_kg_m2"] - 5.0, rel=1e-12)


def test_rotating_parts_larger_than_j_f_print_no_negative_flywheel():
    status, out, err = shaper_in_process("dynamics", *SEED, *TASK_BOOK, "--rotor", "5000:1")
    assert status == 0, err
    line = next(x for x in out.splitlines() if x.startswith("flywheel needed"))
    assert "none needed" in line and "−" not in line.split("J_c", 1)[1].split("=")[0]
    assert "-" not in line


def test_rotor_gear_takes_the_design_files_gear_ratio(tmp_path):
    path = tmp_path / "d.shaper.json"
    save_design(path, Spec(), [60.0], 1.0,
                {"forces": masses_to_dict(MassProperties(lever_weight_N=200.0)),
                 "gear": {"z1": 17, "z2": 68, "module_mm": 4}})
    status, out, err = shaper_in_process("dynamics", "--design", str(path), "--lever-inertia", "1.1",
                                         "--ram-weight", "700", "--cut-force", "7000",
                                         "--rotor", "0.03:gear", "--json")
    assert status == 0, err
    assert json.loads(out)["inputs"]["rotors"] == [{"J_kg_m2": 0.03, "speed_ratio": 4.0}]
    status, _, err = shaper_in_process("dynamics", *SEED, *TASK_BOOK, "--rotor", "0.03:gear")
    assert status == 2 and err.startswith("shaper: error: --rotor:")


def test_rotor_gear_takes_the_gear_pair_the_design_is_given(tmp_path):
    """shaper design (and so a class's row) with gear options: J:gear is the pinion shaft of
    the pair it writes. Under a file's pair of 17/68 teeth, --z1 15 --z2 41 stored the
    file's ratio, 4, beside the 41/15 pair the file then held (a task sheet printed
    '0.02, 3.076923077' for a row of 15/41 teeth over a base of 13/40); without a file,
    --z1 13 --z2 40 --module 6 was refused as no gear pair."""
    path = tmp_path / "d.shaper.json"
    save_design(path, Spec(), [60.0], 1.0,
                {"forces": masses_to_dict(MassProperties(lever_weight_N=200.0)),
                 "gear": {"z1": 17, "z2": 68, "module_mm": 4}})
    over = tmp_path / "over.shaper.json"
    status, _, err = shaper_in_process("design", "--design", path, "--z1", "15", "--z2", "41",
                                       "--rotor", "0.03:gear", "-o", over)
    assert status == 0, err
    doc = json.loads(over.read_text(encoding="utf-8"))
    assert (doc["gear"]["z1"], doc["gear"]["z2"]) == (15, 41)
    assert doc["forces"]["rotors"] == [{"J_kg_m2": 0.03, "speed_ratio": pytest.approx(41 / 15, rel=1e-15)}]
    alone = tmp_path / "alone.shaper.json"
    status, _, err = shaper_in_process("design", *SEED, "--z1", "13", "--z2", "40", "--module", "6",
                                       "--rotor", "0.03:gear", "-o", alone)
    assert status == 0, err
    rotors = json.loads(alone.read_text(encoding="utf-8"))["forces"]["rotors"]
    assert rotors == [{"J_kg_m2": 0.03, "speed_ratio": pytest.approx(40 / 13, rel=1e-15)}]


def test_a_weight_typed_over_a_files_mass_replaces_it(tmp_path):
    path = tmp_path / "d.shaper.json"
    save_design(path, Spec(), [60.0], 1.0, {"forces": masses_to_dict(MassProperties(
        lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0, cut_force_N=7000.0))})
    assert load_design(path)["masses"].lever_weight_N is None
    status, out, err = shaper_in_process("dynamics", "--design", str(path), "--lever-weight", "300", "--json")
    assert status == 0, err
    assert json.loads(out)["inputs"]["lever_mass_kg"] == pytest.approx(300 / 9.81)


def test_guide_length_is_an_option_and_the_csv_has_the_end_forces():
    status, out, err = shaper_in_process("dynamics", *SEED, *TASK_BOOK, "--guide-length", "450",
                                         "--step", "30", "--csv", "-")
    assert status == 0, err
    header = out.splitlines()[0].split(",")
    assert {"guide_rear_N", "guide_front_N", "guide_tilted"} <= set(header)
    status, out, err = shaper_in_process("dynamics", *SEED, *TASK_BOOK, "--guide-length", "0")
    assert status == 2 and err.startswith("shaper: error: --guide-length:")


# ---- issue 40 item 8: what a student got stuck on ----------------------------------------

def test_course_help_names_the_gear_pair_it_requires():
    status, out, _ = shaper_in_process("course", "--help")
    assert status == 0
    text = " ".join(out.split())
    assert 'the gear pair ("gear"' in text and "cam and gear pair" in text


def test_cam_help_says_the_return_allowance_default_and_why():
    from core.cam import CamInputs
    status, out, _ = shaper_in_process("cam", "--help")
    assert status == 0
    text = " ".join(out.split())
    default = CamInputs().return_pressure_deg
    assert f"(default {default:g}: the follower returns unloaded" in text


def test_the_j_gear_refusal_says_where_the_gear_pair_goes_and_that_works(tmp_path):
    """``--rotor J:gear`` without a gear pair said only that none was given. It now says what
    to give: the ratio itself, or a design file with a "gear" object, which ``shaper design
    --design FILE --z1 --z2 --module`` adds; done as it says, the same command runs."""
    plain = tmp_path / "plain.shaper.json"
    status, _, err = shaper_in_process("design", *SEED, *TASK_BOOK, "-o", str(plain))
    assert status == 0, err
    for given in (("--design", str(plain)), SEED + TASK_BOOK):
        status, _, err = shaper_in_process("dynamics", *given, "--rotor", "0.03:gear")
        lines = err.strip().splitlines()
        assert status == 2 and len(lines) == 1 and lines[0].startswith("shaper: error: --rotor:"), err
        assert "J:RATIO" in err and "gear.z1, gear.z2, gear.module_mm" in err, err
        assert "shaper design --design FILE --z1 Z1 --z2 Z2 --module M -o FILE" in err, err
    geared = tmp_path / "geared.shaper.json"
    status, _, err = shaper_in_process("design", "--design", str(plain), "--z1", "17", "--z2", "68",
                                       "--module", "4", "-o", str(geared))
    assert status == 0, err
    status, out, err = shaper_in_process("dynamics", "--design", str(geared), "--rotor", "0.03:gear", "--json")
    assert status == 0, err
    assert json.loads(out)["inputs"]["rotors"] == [{"J_kg_m2": 0.03, "speed_ratio": 4.0}]


@pytest.mark.parametrize("rotor, said", [("nan:gear", "must be a finite number (got nan)"),
                                         ("2e6:gear", "must be ≥ 0 and ≤ 1e+06 kg·m² (got 2000000)")])
def test_a_bad_inertia_before_gear_is_named_not_copied_into_the_advice(rotor, said):
    """'nan:gear' without a gear pair was told to type 'nan:3.07692', which is refused again
    (hunt, 1 December): the J is checked first, as for J:RATIO."""
    status, _, err = shaper_in_process("dynamics", *SEED, *TASK_BOOK, "--rotor", rotor)
    assert status == 2 and err == f"shaper: error: --rotor: {said}\n"
