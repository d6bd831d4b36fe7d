"""A task sheet states every input the answer key's figures follow from. A class whose table
set `delta` (or `idle`, a rotor, the cam's law, the gear's centre distance …) for a student
gave that student a task sheet without it: the key's J_F = ΔW_max/(ω²δ) (or M_m, r0, a′)
could not be reproduced from the sheet, which listed neither δ nor the idle margin at all."""
from __future__ import annotations

import copy
import json

import pytest

from cli_runner import shaper_in_process
from core.drawing.class_sheets import TASK_WORDS, data_rows
from core.linkage.spec import Spec

SCHEME_I = ("--dims", "110,380,540", "--rod-ratio", "0.25", "--rpm", "60", "--lever-weight", "200",
            "--lever-inertia", "1.1", "--ram-weight", "700", "--cut-force", "7000", "--cut-height", "80",
            "--arm", "125", "--swing", "15", "--pressure", "40", "--rise", "75", "--dwell", "10", "--return", "75",
            "--z1", "13", "--z2", "40", "--module", "6")
LABELS = {word: word for word in TASK_WORDS}

# (part of the design file, key, a value other than the default): each changes a figure of
# the answer key (J_F, M_m, M_max, r0, a_cam, r_r, x1, x2, a′, ε or the failed checks)
CHANGES = [("forces", "delta", 0.05), ("forces", "idle_fraction", 0.1), ("forces", "rod_mass_kg", 5.0),
           ("forces", "block_mass_kg", 2.0), ("forces", "crank_mass_kg", 3.0), ("forces", "gravity", False),
           ("forces", "rotors", [{"J_kg_m2": 0.5, "speed_ratio": 1.0}]),
           ("cam", "rise_law", "parabolic"), ("cam", "return_law", "cosine"),
           ("cam", "return_pressure_deg", 60.0), ("cam", "roller_mm", 5.0), ("cam", "base_mm", 40.0),
           ("cam", "distance_mm", 120.0), ("cam", "hub_mm", 15.0), ("cam", "boss_mm", 20.0),
           ("cam", "clearance_mm", 5.0), ("gear", "centre_mm", 162.0), ("gear", "pressure_angle_deg", 25.0),
           ("gear", "addendum", 0.8), ("gear", "clearance", 0.3), ("gear", "tip_limit", 0.4),
           ("gear", "contact_limit", 1.3)]


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    path = tmp_path_factory.mktemp("inputs") / "d.shaper.json"
    status, _, err = shaper_in_process("design", *SCHEME_I, "-o", path)
    assert status == 0, err
    doc = json.loads(path.read_text(encoding="utf-8"))
    return doc, Spec.from_dict(doc["spec"]).design()


def test_delta_and_the_idle_margin_are_always_stated(base):
    doc, design = base
    rows = {row[0]: row[2] for row in data_rows(doc, design, LABELS)}
    assert rows["Coefficient of speed fluctuation"] == "1/30"            # the default, 1/30
    assert rows["Idle margin at each end of the stroke"] == "0.05 H"
    assert rows["Rise law"] == rows["Return law"] == "sine (cycloidal)"


@pytest.mark.parametrize("part, key, value", CHANGES, ids=[c[1] for c in CHANGES])
def test_an_input_the_key_depends_on_changes_the_data_set(base, part, key, value):
    doc, design = base
    changed = copy.deepcopy(doc)
    changed[part][key] = value
    before, after = data_rows(doc, design, LABELS), data_rows(changed, design, LABELS)
    assert after != before, (key, after)


def test_shifts_given_are_stated(base):
    doc, design = base
    changed = copy.deepcopy(doc)
    changed["gear"].update(x1=0.3, x2=0.1)
    rows = {row[1]: row[2] for row in data_rows(changed, design, LABELS)}
    assert rows["x_1, x_2"] == "0.3, 0.1"
    delta = copy.deepcopy(doc)
    delta["forces"]["delta"] = 0.05
    assert {row[1]: row[2] for row in data_rows(delta, design, LABELS)}["[δ]"] == "0.05"
