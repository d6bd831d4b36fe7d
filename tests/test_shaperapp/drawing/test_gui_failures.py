"""The drawing and report dialogs with zero loads, and with a sheet or report that cannot
be built: a result, or the reason in the dialog; never an exception for sys.excepthook
and never the wrong reason ("is none of them" for a .dxf) (issue 33, item 1)."""
import ezdxf
import export_faults
from export_faults import finished, in_child
import pytest
from PySide6.QtWidgets import QDialog, QFileDialog, QMessageBox

from shaperapp.drawing import dialog as drawing_dialog
from shaperapp.drawing.dialog import DrawingSheetDialog
from shaperapp.report import dialog as report_dialog

ZERO = dict(lever_mass_kg="0", lever_inertia_kg_m2="0", ram_mass_kg="0", cut_force_N="0")


@pytest.fixture
def unloaded(model):
    model.set_masses(**ZERO)
    assert model.masses.lever_mass_kg == model.masses.ram_mass_kg == model.masses.cut_force_N == 0.0
    return model


@pytest.fixture
def warnings(monkeypatch):
    shown = []
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: shown.append(a[2]))
    return shown


def test_forces_sheet_of_a_design_without_loads_previews_and_saves(unloaded, qtbot, tmp_path):
    dialog = DrawingSheetDialog(unloaded, "en")
    qtbot.addWidget(dialog)
    dialog.content.setCurrentIndex(dialog.content.findData("forces"))
    dialog.update_preview()
    assert not dialog.preview.pixmap().isNull() and dialog.message.text() == ""
    out = tmp_path / "zero-forces.dxf"
    dialog.export(str(out))
    texts = [t.dxf.text for t in ezdxf.readfile(out).modelspace().query("TEXT")]
    assert "0 N·m" in texts                    # the flywheel table: no torque without loads


def test_a_sheet_that_cannot_be_built_says_why_and_writes_nothing(model, qtbot, tmp_path, monkeypatch,
                                                                 warnings):
    dialog = DrawingSheetDialog(model, "en")
    qtbot.addWidget(dialog)

    def broken(*_args):
        raise ValueError("the loads do not add up")
    monkeypatch.setattr(drawing_dialog, "build_sheet", broken)
    dialog.update_preview()
    assert "the loads do not add up" in dialog.message.text()
    assert dialog.preview.pixmap().isNull()
    target = tmp_path / "sheet.dxf"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (str(target), ""))
    dialog._save_dialog()
    assert len(warnings) == 1 and "the loads do not add up" in warnings[0]
    assert "none of them" not in warnings[0]
    assert list(tmp_path.iterdir()) == []


def test_report_of_a_design_without_loads_is_written(unloaded, qtbot, tmp_path, monkeypatch, warnings):
    monkeypatch.setattr(report_dialog.ReportOptionsDialog, "exec", lambda self: QDialog.DialogCode.Accepted)
    target = tmp_path / "zero.html"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (str(target), ""))
    assert finished(report_dialog.export_report_dialog(unloaded, None, "en", str(tmp_path))) == str(target)
    assert warnings == []
    assert "Force polygon" in target.read_text(encoding="utf-8")


def test_a_report_that_cannot_be_built_says_why_and_writes_nothing(model, qtbot, tmp_path, monkeypatch,
                                                                  warnings):
    monkeypatch.setattr(report_dialog.ReportOptionsDialog, "exec", lambda self: QDialog.DialogCode.Accepted)
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (str(tmp_path / "r.pdf"), ""))

    in_child(monkeypatch, "shaperapp.report.dialog.write_report_of", export_faults.broken_report)
    assert finished(report_dialog.export_report_dialog(model, None, "en", str(tmp_path))) == ""
    assert len(warnings) == 1 and "the loads do not add up" in warnings[0]
    assert list(tmp_path.iterdir()) == []


CONTROL = "a\x01b\x1bc\x7fd"          # a file name may hold any of these


def test_a_file_name_with_control_characters_titles_the_sheet_printably(model, qtbot, tmp_path):
    """The SVG's <title> and the DXF's title block get U+FFFD for each control character: an
    XML parser read the raw 0x01 as an error, and DXF TEXT carried it."""
    import xml.etree.ElementTree as ET
    model.set_path(str(tmp_path / f"{CONTROL}.shaper.json"))
    dialog = DrawingSheetDialog(model, "en")
    qtbot.addWidget(dialog)
    shown = "a\ufffdb\ufffdc\ufffdd"
    assert dialog.choice().design_name == shown
    dialog.export(str(tmp_path / "s.svg"))
    assert ET.parse(tmp_path / "s.svg").getroot().find("{http://www.w3.org/2000/svg}title").text == shown
    dialog.export(str(tmp_path / "s.dxf"))
    texts = [t.dxf.text for t in ezdxf.readfile(tmp_path / "s.dxf").modelspace().query("TEXT")]
    assert shown in texts
    assert not any(ch in t for t in texts for ch in "\x01\x1b\x7f")


def test_the_report_dialog_names_the_design_printably(model, qtbot, tmp_path):
    model.set_path(str(tmp_path / f"{CONTROL}.shaper.json"))
    assert report_dialog.design_name(model) == "a\ufffdb\ufffdc\ufffdd"
    dialog = report_dialog.ReportOptionsDialog(model)
    qtbot.addWidget(dialog)
    dialog.design_name.setText("tab\there")
    assert dialog.name() == "tab\ufffdhere"
