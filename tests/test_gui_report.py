"""File › Export report… and the deliverable tabs in the assembled window."""
import os
import re
import shutil
import stat
import subprocess


from shaperapp.report.dialog import ReportOptionsDialog, export_report


def test_window_has_the_deliverables(window, qtbot):
    texts = [window.tabs.tabText(i) for i in range(window.tabs.count())]
    assert texts[2:4] == ["Positions", "Vector diagrams"]
    assert window.act_report in window.menu_file.actions()
    window.set_language("zh_CN")
    qtbot.waitUntil(lambda: window.tabs.tabText(2) == "位置")
    assert [window.tabs.tabText(i) for i in (2, 3)] == ["位置", "矢量多边形"]
    assert window.act_report.text().startswith("导出设计说明书")


def test_dialog_defaults_one_position_in_each_stroke(window, qtbot):
    dialog = ReportOptionsDialog(window.model, window)
    qtbot.addWidget(dialog)
    work, back = dialog.options().diagram_deg
    assert 0 < work < window.model.metrics.work_angle_deg < back < 360
    dialog.count.setValue(24)
    assert dialog.options().count == 24


def test_export_writes_pdf_and_html_of_the_design_on_screen(window, tmp_path):
    window.model.set_spec(time_ratio=1.6)
    pdf = tmp_path / "r.pdf"
    pages = export_report(window.model, str(pdf), "en")
    assert pages >= 8 and pdf.read_bytes().startswith(b"%PDF")
    assert stat.S_IMODE(os.stat(pdf).st_mode) != 0o600          # a normal file, not mkstemp's mode
    if shutil.which("pdftotext"):
        text = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True).stdout
        theta = f"{window.model.metrics.theta_deg:.4f} °"
        assert theta in text and "Untitled design" in text
    html = tmp_path / "r.html"
    assert export_report(window.model, str(html), "en") == 0
    assert "<svg" in html.read_text(encoding="utf-8")
    assert [p.name for p in tmp_path.iterdir() if re.match(r"\..*\.tmp$", p.name)] == []
