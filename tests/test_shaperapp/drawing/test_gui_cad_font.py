"""File › Export drawing sheet…: the CAD texts of a DXF (``--cad-font`` in the GUI, issue 40
item 7): the GB style by default, outlines when chosen (what ``shaper drawing --cad-font
outline`` writes, test_cad_font_option), offered for a DXF alone, remembered, and refused
in one line without a font for the outlines."""
import ezdxf
import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QFileDialog, QMessageBox

from core.drawing import outline_text
from shaperapp.drawing.dialog import DrawingSheetDialog
from shaperapp.widgets.cad_font import CAD_FONT_SETTING


@pytest.fixture
def settings(tmp_path):
    return QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)


@pytest.fixture
def dialog(model, qtbot, settings):
    """The dialog on the motion sheet, on A3 at one position: quick to write."""
    made = DrawingSheetDialog(model, "en", settings=settings)
    qtbot.addWidget(made)
    made.paper.setCurrentText("A3")
    made.count.setValue(1)
    return made


def save_as(dialog, monkeypatch, path) -> list[str]:
    """Press Save and answer the file dialog with ``path``; the warnings shown."""
    shown = []
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (str(path), ""))
    monkeypatch.setattr(QMessageBox, "warning", lambda parent, title, text: shown.append(text))
    dialog._save_dialog()
    return shown


def kinds(path) -> dict[str, int]:
    """How many TEXT entities and solid hatches on the TEXT layer the DXF holds."""
    msp = ezdxf.readfile(path).modelspace()
    return {"TEXT": len(msp.query("TEXT")),
            "outlines": sum(h.dxf.solid_fill for h in msp.query("HATCH[layer=='TEXT']"))}


def test_the_cad_texts_are_a_dxfs_alone_and_gb_by_default(dialog, monkeypatch, tmp_path):
    assert dialog.cad_font.value() == "gb"
    assert "LibreCAD" in dialog.cad_font.toolTip() and "editable" in dialog.cad_font.toolTip()
    for suffix, enabled in ((".pdf", False), (".svg", False), (".dxf", True), (".pdf", False)):
        dialog.file_type.setCurrentIndex(dialog.file_type.findData(suffix))
        assert dialog.cad_font.isEnabled() == enabled, suffix
    assert save_as(dialog, monkeypatch, tmp_path / "motion.dxf") == []    # the name's type wins
    assert dialog.file_type.currentData() == ".dxf" and dialog.cad_font.isEnabled()
    found = kinds(tmp_path / "motion.dxf")
    assert found["TEXT"] > 50 and found["outlines"] == 0
    # the GB fonts' two styles: GB, and wqy-unicode for the Greek and Chinese (LibreCAD's font)
    assert {t.dxf.style for t in ezdxf.readfile(tmp_path / "motion.dxf").modelspace().query("TEXT")} == \
        {"GB", "wqy-unicode"}


def test_outlines_chosen_are_written_and_remembered(dialog, model, qtbot, settings, monkeypatch,
                                                     tmp_path):
    dialog.file_type.setCurrentIndex(dialog.file_type.findData(".dxf"))
    dialog.cad_font.setCurrentIndex(dialog.cad_font.findData("outline"))
    assert dialog.message.text() == ""                      # the font is there
    assert save_as(dialog, monkeypatch, tmp_path / "motion") == []    # no suffix: the type chosen
    found = kinds(tmp_path / "motion.dxf")
    assert found["TEXT"] == 0 and found["outlines"] > 50
    assert settings.value(CAD_FONT_SETTING) == "outline"
    again = DrawingSheetDialog(model, "en", settings=settings)
    qtbot.addWidget(again)
    assert again.cad_font.value() == "outline"
    assert not again.cad_font.isEnabled()                   # a PDF until DXF is chosen


@pytest.fixture
def no_cjk_font(monkeypatch):
    """No font of core's outline list installed."""
    monkeypatch.setattr(outline_text, "OUTLINE_FONTS", (("no-such-font.ttf", 0, "None Such"),))
    outline_text.outline_font.cache_clear()
    yield
    outline_text.outline_font.cache_clear()


def test_outlines_without_a_font_say_so_in_one_line_and_write_nothing(dialog, no_cjk_font,
                                                                       monkeypatch, tmp_path):
    dialog.cad_font.setCurrentIndex(dialog.cad_font.findData("outline"))
    assert dialog.message.text() == ""                      # a PDF needs no outline font
    dialog.file_type.setCurrentIndex(dialog.file_type.findData(".dxf"))
    note = dialog.message.text()
    assert note.startswith("No font with Chinese characters is installed for the outlines")
    assert "fonts-noto-cjk" in note and "\n" not in note
    shown = save_as(dialog, monkeypatch, tmp_path / "motion.dxf")
    assert shown == [note + " Nothing was written."]
    assert not list(tmp_path.glob("motion*"))
    assert dialog.written == ""
