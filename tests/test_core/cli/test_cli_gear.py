"""``shaper gear`` (issue 35, item 2): the JSON keys other tools read, its numbers against
independent involute geometry, the CSV, --design's gear object, and bad input as one line
naming the option (exit 2)."""
from __future__ import annotations

import csv
import io
import json
import math

import pytest
from scipy.optimize import brentq

from core.files.io import design_document
from core.linkage.spec import Spec

from cli_runner import shaper_in_process
from output_checks import error_names

PAIR_KEYS = {"centre_mm", "working_pressure_angle_deg", "centre_shift_factor",
             "addendum_reduction_factor", "contact_ratio"}
GEAR_KEYS = {"teeth", "shift_factor", "reference_diameter_mm", "base_diameter_mm",
             "tip_diameter_mm", "root_diameter_mm", "working_diameter_mm",
             "reference_thickness_mm", "tip_thickness_mm", "undercut"}


def _json(*words):
    status, out, err = shaper_in_process("gear", *words, "--json")
    assert status == 0, err
    return json.loads(out)


def test_json_keys_and_values_against_involute_geometry():
    doc = _json("--z1", "10", "--z2", "36", "--module", "5", "--x1", "0.45", "--x2", "0.2")
    assert PAIR_KEYS <= set(doc["pair"]) and GEAR_KEYS <= set(doc["gear1"]) <= set(doc["gear2"]) | GEAR_KEYS
    alpha, m, z1, z2, x1, x2 = math.radians(20), 5.0, 10, 36, 0.45, 0.2
    target = 2 * math.tan(alpha) * (x1 + x2) / (z1 + z2) + math.tan(alpha) - alpha
    alpha_w = brentq(lambda a: math.tan(a) - a - target, 1e-6, 1.5, xtol=1e-16, rtol=1e-15)
    centre = m * (z1 + z2) / 2 * math.cos(alpha) / math.cos(alpha_w)
    pair = doc["pair"]
    assert pair["working_pressure_angle_deg"] == pytest.approx(math.degrees(alpha_w), rel=1e-9)
    assert pair["centre_mm"] == pytest.approx(centre, rel=1e-9)
    # tip diameters from the standard clearance at a′: da1 = 2 (a′ − rf2 − c* m)
    rf2 = m * z2 / 2 - (1.25 - x2) * m
    assert doc["gear1"]["tip_diameter_mm"] == pytest.approx(2 * (centre - rf2 - 0.25 * m), rel=1e-9)
    assert doc["gear1"]["working_diameter_mm"] == pytest.approx(2 * centre * z1 / (z1 + z2), rel=1e-9)
    assert doc["gear1"]["undercut"] is False and doc["gear1"]["teeth"] == 10


def test_table_by_default_and_the_rule_named():
    status, out, err = shaper_in_process("gear", "--z1", "13", "--z2", "40", "--module", "6")
    assert status == 0 and err == ""
    assert "x2 = −x1" in out and "159.0000 mm" in out and "contact ratio ε" in out


def test_csv_holds_the_json_values(tmp_path):
    target = tmp_path / "g.csv"
    words = ("--z1", "12", "--z2", "12", "--module", "10", "--centre", "130")
    doc = _json(*words)
    status, _, err = shaper_in_process("gear", *words, "--csv", str(target))
    assert status == 0, err
    rows = {r["quantity"]: r for r in csv.DictReader(io.StringIO(target.read_text()))}
    assert float(rows["centre_mm"]["pair_or_gear1"]) == doc["pair"]["centre_mm"] == 130.0
    assert float(rows["tip_diameter_mm"]["gear2"]) == doc["gear2"]["tip_diameter_mm"]


def test_design_file_gear_object(tmp_path):
    path = tmp_path / "d.shaper.json"
    doc = design_document(Spec(), [60.0], 1.0, {"gear": {"z1": 12, "z2": 12, "module_mm": 10.0,
                                                            "centre_mm": 130.0}})
    path.write_text(json.dumps(doc), encoding="utf-8")
    assert _json("--design", str(path))["pair"]["centre_mm"] == 130.0
    # a shift pair on the command line replaces the file's centre distance
    assert _json("--design", str(path), "--x1", "0", "--x2", "0")["pair"]["centre_mm"] == 120.0
    doc["gear"]["z1"] = 4
    path.write_text(json.dumps(doc), encoding="utf-8")
    status, _, err = shaper_in_process("gear", "--design", str(path))
    assert status == 2 and error_names(err) == ["--design"]


@pytest.mark.parametrize("words, option", [
    (("--z1", "4", "--z2", "40", "--module", "2"), "--z1"),
    (("--z1", "12", "--z2", "40.5", "--module", "2"), "--z2"),
    (("--z1", "12", "--z2", "40", "--module", "0"), "--module"),
    (("--z1", "12", "--z2", "40", "--module", "-2"), "--module"),
    (("--z1", "12", "--z2", "40", "--module", "2", "--centre", "49"), "--centre"),
    (("--z1", "12", "--z2", "40", "--module", "2", "--centre", "46"), "--centre"),
    (("--z1", "12", "--z2", "12", "--module", "2", "--centre", "40"), "--centre"),
    (("--z1", "12", "--z2", "40", "--module", "2", "--x1", "1.4", "--x2", "0"), "--x1"),
    (("--z1", "12", "--z2", "40", "--module", "2", "--x1", "0.4"), "--x2"),
    (("--z1", "12", "--z2", "40", "--module", "2", "--pressure-angle", "90"), "--pressure-angle"),
    (("--z2", "40", "--module", "2"), "--z1")])
def test_bad_input_is_one_line_naming_the_option(words, option):
    status, out, err = shaper_in_process("gear", *words)
    assert status == 2 and out == ""
    assert error_names(err) == [option]
