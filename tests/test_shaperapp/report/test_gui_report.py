"""File › Export report… and the deliverable tabs in the assembled window."""
import os
import re
import shutil
import stat
import subprocess

from core.space.compare import Candidate
from export_faults import finished
from core.linkage.spec import Spec
from shaperapp.report.dialog import ReportOptionsDialog, export_report
from core.base.figure_text import figure_text


def test_window_has_the_deliverables(window, qtbot):
    texts = [window.tabs.tabText(i) for i in range(window.tabs.count())]
    assert texts[2] == "Positions"
    assert window.docks["polygons"].windowTitle() == "Vector diagrams"    # a pane beside the scheme
    assert window.docks.pane("polygons") is window.polygon_view
    assert window.act_report in window.menu_file.actions()
    window.set_language("zh_CN")
    qtbot.waitUntil(lambda: window.tabs.tabText(2) == "位置", timeout=10_000)
    assert window.docks["polygons"].windowTitle() == "矢量多边形"
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
        theta = f"{figure_text('angle', window.model.metrics.theta_deg)}°"   # one precision (issue 40)
        assert theta in text and "Untitled" not in text
        assert "L1 100 mm, K 1.6, H 300 mm" in text          # named by its inputs
    html = tmp_path / "r.html"
    assert export_report(window.model, str(html), "en") == 0
    assert "<svg" in html.read_text(encoding="utf-8")
    assert [p.name for p in tmp_path.iterdir() if re.match(r"\..*\.tmp$", p.name)] == []


def test_dialog_includes_the_compare_tabs_designs(window, qtbot, tmp_path):
    """The dialog offers the comparison only when the Compare tab has other designs; the
    design on screen itself (same inputs and loads) is not compared with itself."""
    dialog = ReportOptionsDialog(window.model, window)
    qtbot.addWidget(dialog)
    assert not dialog.include_comparison.isEnabled() and dialog.options().compare == ()
    model = window.model
    other = Candidate("K 1.6", Spec(time_ratio=1.6), model.masses)
    window.compare.set_candidates([Candidate("on screen", model.valid_spec, model.masses), other])
    dialog = ReportOptionsDialog(model, window)
    qtbot.addWidget(dialog)
    assert dialog.include_comparison.isEnabled() and dialog.include_comparison.isChecked()
    assert dialog.options().compare == (other,)
    pdf = tmp_path / "r.pdf"
    export_report(model, str(pdf), "en", dialog.options())
    if shutil.which("pdftotext"):
        text = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True).stdout
        assert "Comparison with other designs" in text and "K 1.6" in text
    dialog.include_comparison.setChecked(False)
    assert dialog.options().compare == ()
    window.compare.set_candidates([Candidate(f"K {k}", Spec(time_ratio=k), None)
                                   for k in (1.2, 1.3, 1.35, 1.45, 1.5, 1.55)])
    dialog = ReportOptionsDialog(model, window)
    qtbot.addWidget(dialog)
    assert not dialog.include_comparison.isEnabled()          # six others: one too many
    assert "at most 5" in dialog.include_comparison.toolTip()


def test_export_refuses_a_name_of_another_type(window, tmp_path):
    """A report named .docx was written as a PDF under that name: refused before anything
    is built, nothing written."""
    import pytest
    with pytest.raises(ValueError, match="must end in .pdf, .html or .htm"):
        export_report(window.model, str(tmp_path / "r.docx"), "en")
    assert list(tmp_path.iterdir()) == []


def test_dialog_adds_the_chosen_type_and_refuses_another(window, qtbot, tmp_path, monkeypatch):
    from PySide6.QtWidgets import QDialog, QFileDialog, QMessageBox
    from shaperapp.report import dialog as report_dialog
    monkeypatch.setattr(ReportOptionsDialog, "exec", lambda self: QDialog.DialogCode.Accepted)
    answers = []
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: answers.pop(0))
    warnings = []
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: warnings.append(a[2]))
    answers.append((str(tmp_path / "typed"), "PDF document (*.pdf)"))
    assert finished(report_dialog.export_report_dialog(window.model, window, "en", str(tmp_path))) \
        == str(tmp_path / "typed.pdf")
    assert (tmp_path / "typed.pdf").read_bytes().startswith(b"%PDF")
    answers.append((str(tmp_path / "page"), "HTML page (*.html)"))
    assert finished(report_dialog.export_report_dialog(window.model, window, "en", str(tmp_path))) \
        .endswith("page.html")
    answers.append((str(tmp_path / "r.txt"), "PDF document (*.pdf)"))
    assert report_dialog.export_report_dialog(window.model, window, "en", str(tmp_path)) is None
    assert len(warnings) == 1 and "r.txt" in warnings[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["page.html", "typed.pdf"]


def test_cover_fields_are_remembered_between_exports(window, qtbot, tmp_path, monkeypatch):
    """The student's fields come back in the next export's dialog (QSettings), the date is
    today's, and the design is named by its file; the report prints them all."""
    from PySide6.QtWidgets import QDialog, QFileDialog

    from shaperapp.report.dialog import export_report_dialog
    target = tmp_path / "r.html"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (str(target), ""))
    typed = {"student": "Li Ming", "number": "2021-07", "group": "ME 21", "school": "SME",
             "supervisor": "Prof. Wang"}

    def fill(dialog):
        for field, text in typed.items():
            dialog.cover[field].setText(text)
        return QDialog.DialogCode.Accepted
    monkeypatch.setattr(ReportOptionsDialog, "exec", fill)
    window.model.set_path(str(tmp_path / "bracket.shaper.json"))
    assert finished(export_report_dialog(window.model, window, "en", str(tmp_path), window.settings)) \
        == str(target)
    page = target.read_text(encoding="utf-8")
    for text in typed.values():
        assert f"<td>{text}</td>" in page
    assert '<td colspan="3">bracket</td>' in page               # the design, named by its file
    dialog = ReportOptionsDialog(window.model, window, window.settings)
    qtbot.addWidget(dialog)
    assert {f: dialog.cover[f].text() for f in typed} == typed
    assert dialog.name() == "bracket" and re.fullmatch(r"\d{4}-\d\d-\d\d", dialog.date())
    assert dialog.options().cover.student == "Li Ming"
