"""The report written by a child process under a progress dialog (issue 40, item 5): the
window stays usable meanwhile (a click on a tab switches it), the bar moves with every
section and page, only forward, to its maximum; the cursor is busy meanwhile; Cancel
leaves no file (nor a temporary one) and no process behind; a failure in the child is
one translated line; the headless writers take the same progress (``core.base.progress``),
for ``shaper course`` and ``shaper class``."""
import os

import pytest
from PySide6.QtCore import QProcess, Qt
from PySide6.QtGui import QGuiApplication
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QDialog, QFileDialog, QMessageBox, QProgressDialog, QPushButton

import export_faults
from core.base.progress import Cancelled, Progress
from shaperapp.report import dialog as report_dialog
from shaperapp.report.dialog import ReportOptionsDialog, export_report
from shaperapp.widgets import export_process, i18n
from shaperapp.widgets.export_process import STEPS


@pytest.fixture
def bar(monkeypatch):
    """Every value the progress dialog is set to, with the override cursor's shape then."""
    seen = {"values": [], "cursors": [], "maximum": []}
    set_value = QProgressDialog.setValue

    def record(self, value):
        seen["values"].append(value)
        seen["maximum"].append(self.maximum())
        cursor = QGuiApplication.overrideCursor()
        seen["cursors"].append(None if cursor is None else cursor.shape())
        set_value(self, value)
    monkeypatch.setattr(QProgressDialog, "setValue", record)
    return seen


@pytest.fixture
def report_answers(monkeypatch, tmp_path):
    """The options dialog accepted as it opens, the file dialog answering out/report.pdf."""
    out = tmp_path / "out"
    out.mkdir()
    monkeypatch.setattr(ReportOptionsDialog, "exec", lambda self: QDialog.DialogCode.Accepted)
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (str(out / "report.pdf"), ""))
    warnings = []
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: warnings.append(a[2]))
    return out, warnings


def press_cancel(run) -> None:
    """A click on the progress dialog's Cancel."""
    run.dialog.findChild(QPushButton).click()


def test_the_headless_report_hears_of_every_section_and_page_in_order(model, tmp_path):
    model.set_rpms([40.0, 60.0])
    heard = []
    pages = export_report(model, str(tmp_path / "r.pdf"), "en", progress=Progress(heard.append))
    assert heard == sorted(heard) and heard[-1] == pytest.approx(1.0) and heard[0] > 0.0
    assert len(set(heard)) >= 7 + pages          # the sections and every page


def test_the_bar_moves_forward_and_the_window_takes_clicks_while_the_report_is_written(
        window, bar, report_answers, qtbot):
    """One report written by the child serves both (each was a test writing its own):
    the bar moves forward to its maximum under a busy cursor; a click on another tab
    switches to it while the child writes, and editing the design then does not change
    the report: the child works on the design as it was."""
    out, warnings = report_answers
    run = report_dialog.export_report_dialog(window.model, window, "en", str(out))
    assert run.dialog.windowModality() == Qt.WindowModality.NonModal
    qtbot.waitUntil(lambda: run.dialog.value() > 0, timeout=120_000)     # the child is writing
    tabs = window.tabs.tabBar()
    target = (window.tabs.currentIndex() + 1) % window.tabs.count()
    QTest.mouseClick(tabs, Qt.MouseButton.LeftButton, pos=tabs.tabRect(target).center())
    assert window.tabs.currentIndex() == target and run.state == "running"
    crank = window.model.valid_spec
    window.model.set_rpms([11.0])                 # an edit meanwhile: not in the report
    assert run.wait() and run.result == str(out / "report.pdf") and warnings == []
    assert (out / "report.pdf").read_bytes().startswith(b"%PDF")
    assert window.model.valid_spec == crank
    values = bar["values"]
    assert values == sorted(values) and values[-1] == STEPS and set(bar["maximum"]) == {STEPS}
    assert len(set(values)) >= 15                 # it moves: sections and pages, not one jump
    assert set(bar["cursors"]) == {Qt.CursorShape.BusyCursor}
    assert QGuiApplication.overrideCursor() is None          # given back
    from language_checks import has_pdftotext, pdf_text
    if has_pdftotext():
        assert "11 r/min" not in pdf_text(out / "report.pdf")


@pytest.mark.parametrize("stop_at", [1, 500, 900])        # building, the last section, the pages
def test_cancel_leaves_nothing_behind(window, report_answers, qtbot, stop_at):
    out, warnings = report_answers
    (out / "report.pdf").write_bytes(b"the old report")       # a report written before stays as it was
    run = report_dialog.export_report_dialog(window.model, window, "en", str(out))
    run.progressed.connect(lambda fraction: fraction * STEPS >= stop_at and press_cancel(run))
    assert run.wait() and run.state == "cancelled" and run.result == ""
    assert warnings == []                                     # Cancel is no failure to report
    assert os.listdir(out) == ["report.pdf"] and (out / "report.pdf").read_bytes() == b"the old report"
    assert run.process.state() == QProcess.ProcessState.NotRunning
    assert QGuiApplication.overrideCursor() is None


def test_a_child_that_will_not_stop_is_killed_and_its_temporary_file_removed(window, report_answers,
                                                                             monkeypatch):
    """A child deaf to Cancel (stuck in a long step) is killed; the temporary file it had
    begun is removed, the old report stays."""
    out, warnings = report_answers
    (out / "report.pdf").write_bytes(b"the old report")
    export_faults.in_child(monkeypatch, "shaperapp.report.dialog.write_report_of", export_faults.stuck_report)
    # the child never stops, so the kill comes after the whole grace (3 s): how long that is
    # is not what this tests, and the test would only wait it out
    monkeypatch.setattr(export_process, "KILL_AFTER_MS", 300)
    run = report_dialog.export_report_dialog(window.model, window, "en", str(out))
    run.progressed.connect(lambda fraction: press_cancel(run))
    assert run.wait() and run.state == "cancelled" and warnings == []
    assert os.listdir(out) == ["report.pdf"] and (out / "report.pdf").read_bytes() == b"the old report"
    assert run.process.state() == QProcess.ProcessState.NotRunning


def test_a_child_that_cannot_write_says_why_in_the_ui_language(window, report_answers, qtbot):
    """The child fails (the name is taken by a folder): one line in Chinese, no traceback."""
    out, warnings = report_answers
    (out / "report.pdf").mkdir()
    i18n.set_language("zh_CN")
    try:
        run = report_dialog.export_report_dialog(window.model, window, "zh_CN", str(out))
        assert run.wait() and run.state == "failed" and run.result == ""
    finally:
        i18n.set_language("en")
    assert len(warnings) == 1 and "\n" not in warnings[0] and "Traceback" not in warnings[0]
    assert warnings[0].startswith("无法写入") and str(out / "report.pdf") in warnings[0]
    assert os.listdir(out) == ["report.pdf"] and os.listdir(out / "report.pdf") == []


def test_a_cancelled_headless_report_raises_and_writes_nothing(model, tmp_path):
    heard = []
    with pytest.raises(Cancelled):
        export_report(model, str(tmp_path / "r.pdf"), "en",
                      progress=Progress(heard.append, lambda: len(heard) >= 3))
    assert os.listdir(tmp_path) == [] and len(heard) == 3
