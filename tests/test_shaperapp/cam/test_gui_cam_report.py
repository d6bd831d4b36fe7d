"""The report carries the feed cam (issue 23, item 3): the figures ``shaper cam`` prints,
under the report's labels, and the cam to scale."""
from __future__ import annotations

import json

from cli_runner import shaper_in_process, shaper_run_in_process
from shaperapp.cam.tab import CamTab
from shaperapp.report.dialog import export_report

from gui_helpers import shown


def test_report_has_the_cam_of_the_tab(qtbot, model, tmp_path):
    tab = shown(qtbot, CamTab(model), 900, 600)
    tab.form.fields["arm"].edit.setText("140")
    tab.form.pending.typed("arm")
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
    assert f"{doc['phase_deg']:.3f}°" in text
    section = text[text.index("9 The feed cam"):]
    assert "<svg" in section


def test_shaper_report_takes_the_design_files_cam(tmp_path):
    from core.cam import CamInputs, Program
    from core.cam.file import cam_to_dict
    from core.files.io import save_design
    from core.linkage.spec import Spec
    inputs = CamInputs(arm_mm=160.0, program=Program(20.0, 70.0, 5.0, 80.0, "poly345", "cosine"))
    save_design(tmp_path / "d.json", Spec(), [40.0], 1.0, extra={"cam": cam_to_dict(inputs, None)})
    run = shaper_run_in_process("report", "--design", tmp_path / "d.json", "-o", tmp_path / "r.html")
    assert run.returncode == 0, run.stderr
    text = (tmp_path / "r.html").read_text(encoding="utf-8")
    status, out, err = shaper_in_process(
        "cam", "--arm", "160", "--swing", "20", "--pressure", "40", "--rise", "70", "--dwell", "5",
        "--return", "80", "--law", "poly345", "--return-law", "cosine", "--design", tmp_path / "d.json",
        "--json")
    doc = json.loads(out)
    assert "9 The feed cam" in text and f"{doc['base_radius_mm']:.3f} mm" in text
