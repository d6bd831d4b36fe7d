"""The report carries the feed cam (issue 23, item 3): the figures ``shaper cam`` prints,
under the report's labels, and the cam to scale."""
from __future__ import annotations

import json

from cli_runner import shaper_in_process
from shaperapp.cam.tab import CamTab
from shaperapp.report.dialog import export_report

from gui_helpers import shown


def test_report_has_the_cam_of_the_tab(qtbot, model, tmp_path):
    tab = shown(qtbot, CamTab(model), 900, 600)
    tab.form.fields["arm"].edit.setText("140")
    tab.form._typed("arm")
    tab.form.commit()
    html = tmp_path / "r.html"
    assert export_report(model, str(html), "en") == 0
    text = html.read_text(encoding="utf-8")
    status, out, err = shaper_in_process(
        "cam", "--arm", "140", "--swing", "15", "--pressure", "40", "--rise", "60", "--dwell", "10",
        "--return", "60", "--crank", "100", "--K", "1.4", "--stroke", "300", "--json")
    doc = json.loads(out)
    assert "9 The feed cam" in text
    assert f"{doc['base_radius_mm']:.3f} mm" in text and f"{doc['center_distance_mm']:.3f} mm" in text
    assert f"{doc['phase_deg']:.3f} °" in text
    section = text[text.index("9 The feed cam"):]
    assert "<svg" in section
