"""The report and the course design written under a progress dialog (issue 40, item 5):
the bar moves with every section and page, only forward, to its maximum; the cursor is
busy meanwhile; Cancel leaves no file (nor a temporary one) behind; the headless writers
take the same progress (``core.base.progress``), for ``shaper course`` and ``shaper class``."""
import os

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QDialog, QFileDialog, QMessageBox, QProgressDialog

from core.base.progress import Cancelled, Progress
from shaperapp.report import dialog as report_dialog
from shaperapp.report.dialog import ReportOptionsDialog, export_report
from shaperapp.widgets.progress_dialog import STEPS


@pytest.fixture
def bar(monkeypatch):
    """Every value the progress dialog is set to, with the override cursor's shape then;
    ``stop_at`` (a value of the bar) makes Cancel pressed once the bar has passed it."""
    seen = {"values": [], "cursors": [], "stop_at": None, "maximum": []}
    set_value = QProgressDialog.setValue

    def record(self, value):
        seen["values"].append(value)
        seen["maximum"].append(self.maximum())
        cursor = QGuiApplication.overrideCursor()
        seen["cursors"].append(None if cursor is None else cursor.shape())
        set_value(self, value)
    monkeypatch.setattr(QProgressDialog, "setValue", record)
    monkeypatch.setattr(QProgressDialog, "wasCanceled", lambda self: seen["stop_at"] is not None
                        and bool(seen["values"]) and seen["values"][-1] >= seen["stop_at"])
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


def test_the_headless_report_hears_of_every_section_and_page_in_order(model, tmp_path):
    model.set_rpms([40.0, 60.0])
    heard = []
    pages = export_report(model, str(tmp_path / "r.pdf"), "en", progress=Progress(heard.append))
    assert heard == sorted(heard) and heard[-1] == pytest.approx(1.0) and heard[0] > 0.0
    assert len(set(heard)) >= 7 + pages          # the sections and every page


def test_the_bar_moves_forward_to_its_maximum_under_a_busy_cursor(window, bar, report_answers):
    out, warnings = report_answers
    assert report_dialog.export_report_dialog(window.model, window, "en", str(out)) == str(out / "report.pdf")
    assert warnings == [] and (out / "report.pdf").read_bytes().startswith(b"%PDF")
    values = bar["values"]
    assert values == sorted(values) and values[-1] == STEPS and set(bar["maximum"]) == {STEPS}
    assert len(set(values)) >= 15                 # it moves: sections and pages, not one jump
    assert set(bar["cursors"]) == {Qt.CursorShape.BusyCursor}
    assert QGuiApplication.overrideCursor() is None          # given back


@pytest.mark.parametrize("stop_at", [1, 500, 900])        # building, the last section, the pages
def test_cancel_leaves_nothing_behind(window, bar, report_answers, stop_at):
    out, warnings = report_answers
    (out / "report.pdf").write_bytes(b"the old report")       # a report written before stays as it was
    bar["stop_at"] = stop_at
    assert report_dialog.export_report_dialog(window.model, window, "en", str(out)) == ""
    assert warnings == []                                     # Cancel is no failure to report
    assert os.listdir(out) == ["report.pdf"] and (out / "report.pdf").read_bytes() == b"the old report"
    assert max(bar["values"]) < STEPS and QGuiApplication.overrideCursor() is None


def test_a_cancelled_headless_report_raises_and_writes_nothing(model, tmp_path):
    heard = []
    with pytest.raises(Cancelled):
        export_report(model, str(tmp_path / "r.pdf"), "en",
                      progress=Progress(heard.append, lambda: len(heard) >= 3))
    assert os.listdir(tmp_path) == [] and len(heard) == 3
