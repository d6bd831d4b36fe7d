"""File › Export report carries the design's gear pair (issue 35, item 5): the section with the
figures ``shaper gear`` prints for the same inputs, and the pair in mesh as a figure. On
55087ce the GUI's report had no gear section."""
from __future__ import annotations

import json

import pytest

from cli_runner import shaper_in_process
from core.linkage.spec import Spec
from shaperapp.report.dialog import export_report

pytestmark = pytest.mark.slow       # a whole report (about 5 s)
GEAR = {"z1": 13, "z2": 40, "module_mm": 6.0, "centre_mm": 162.0}


def test_report_has_the_gear_of_the_design(model, tmp_path):
    model.load_state(Spec(), [40.0], 1.0, parts={"gear": GEAR})
    html = tmp_path / "r.html"
    assert export_report(model, str(html), "en") == 0
    text = html.read_text(encoding="utf-8")
    status, out, err = shaper_in_process("gear", "--z1", "13", "--z2", "40", "--module", "6",
                                         "--centre", "162", "--json")
    assert status == 0, err
    pair = json.loads(out)["pair"]
    section = text[text.rindex("9 The gear pair"):]
    for value in (f"{pair['contact_ratio']:.6f}", f"{pair['working_pressure_angle_deg']:.6f}°",
                  f"{pair['centre_mm']:.4f} mm"):
        assert value in section, value
    assert "<svg" in section and "to scale 1:" in section

