"""The title block's course-design fields come from the report cover's options and the
report dialog's remembered fields (issue 32, item 6): ``shaper drawing`` takes the same
options as ``shaper report``, and the drawing dialog shows what the report dialog kept."""
import argparse

import ezdxf
import pytest

from cli_runner import shaper_in_process
from shaperapp.drawing import command as drawing_command
from shaperapp.drawing.dialog import DrawingSheetDialog
from shaperapp.report import command as report_command
from shaperapp.report.dialog import ReportOptionsDialog

BLOCK = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40"]
COVER = {"--student": "Zhang San", "--student-number": "2021001", "--class": "ME 2101",
         "--school": "SME", "--supervisor": "Li Si", "--date": "2026-11-27"}


def options(configure) -> set[str]:
    parser = argparse.ArgumentParser()
    configure(parser)
    return {o for action in parser._actions for o in action.option_strings}


def test_drawing_takes_the_reports_cover_options():
    cover = set(COVER)
    assert cover <= options(report_command.configure)
    assert cover <= options(drawing_command.configure)


def title_texts(path) -> list[str]:
    doc = ezdxf.readfile(path)
    return [t.dxf.text for t in doc.modelspace().query("TEXT") if t.dxf.layer == "TITLE"]


def test_cli_fills_the_title_block_with_the_cover_fields(tmp_path):
    out = tmp_path / "m.dxf"
    words = [w for pair in COVER.items() for w in pair]
    status, _, err = shaper_in_process("drawing", *BLOCK, "--sheet", "A2", *words, "-o", out)
    assert status == 0, err
    texts = title_texts(out)
    for value in COVER.values():
        assert value in texts, value
    # --drawn-by, the old name, is still the student's name
    status, _, err = shaper_in_process("drawing", *BLOCK, "--drawn-by", "Wang Wu", "-o", out)
    assert status == 0, err
    assert "Wang Wu" in title_texts(out)


@pytest.mark.parametrize("option", ["--student-number", "--class", "--supervisor"])
def test_a_cover_field_of_two_lines_is_refused_naming_its_option(option, tmp_path):
    out = tmp_path / "m.dxf"
    status, _, err = shaper_in_process("drawing", *BLOCK, option, "a\nb", "-o", out)
    lines = err.strip().splitlines()
    assert status == 2 and len(lines) == 1 and lines[0].startswith(f"shaper: error: {option}: must be one line")
    assert not out.exists()


def test_dialog_shows_the_report_dialogs_fields_and_keeps_them_there(model, qtbot, tmp_path):
    from PySide6.QtCore import QSettings
    settings = QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat)
    typed = {"student": "Li Ming", "number": "2021-07", "group": "ME 21", "school": "SME",
             "supervisor": "Prof. Wang"}
    report = ReportOptionsDialog(model, None, settings)
    qtbot.addWidget(report)
    for field, text in typed.items():
        report.cover[field].setText(text)
    report.remember()
    dialog = DrawingSheetDialog(model, "en", settings=settings)
    qtbot.addWidget(dialog)
    assert {f: dialog.fields[f].text() for f in typed} == typed
    choice = dialog.choice()
    assert (choice.drawn, choice.number, choice.group, choice.school, choice.supervisor) == \
        tuple(typed.values())
    dialog.fields["group"].setText("ME 22")
    out = tmp_path / "sheet.dxf"
    dialog.export(str(out))
    assert {"Li Ming", "2021-07", "ME 22", "SME", "Prof. Wang"} <= set(title_texts(out))
    again = ReportOptionsDialog(model, None, settings)          # the report sees the change
    qtbot.addWidget(again)
    assert again.cover["group"].text() == "ME 22"


LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000",
         "--cut-height", "80"]
CAM = ["--arm", "120", "--swing", "15", "--pressure", "40", "--rise", "60", "--dwell", "10", "--return", "60"]


@pytest.mark.parametrize("content, extra", [("motion", []), ("forces", LOADS), ("cam", CAM)])
def test_a_sheet_without_a_title_names_its_design_by_the_inputs(tmp_path, content, extra):
    """No --title, no design file: the title block's design cell names the design by its
    inputs on every sheet of the linkage, as the report's cover does (the kinetostatic
    sheet's cell was empty: 方案 I's forces sheet named no design)."""
    out = tmp_path / "s.dxf"
    status, _, err = shaper_in_process("drawing", "--dims", "110,380,540", "--rod-ratio", "0.25", "--rpm", "60",
                                       "--content", content, *extra, "-o", out)
    assert status == 0, err
    texts = title_texts(out)
    assert "L1 110 mm, L2 380 mm, L3 540 mm, L4/L3 0.25" in {f"{a} {b}" for a, b in zip(texts, texts[1:])}, texts
