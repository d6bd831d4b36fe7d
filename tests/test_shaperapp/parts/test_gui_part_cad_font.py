"""The Gear tab's meshing sheet and the Cam tab's DXF: the CAD texts (``--cad-font``) as the
scheme export's two DXF filters, remembered under the same setting; outlines without a font
refused in one message, nothing written."""
from __future__ import annotations

import ezdxf
import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QMessageBox

from shaperapp.cam.tab import CamTab
from shaperapp.gear.tab import GearTab
from shaperapp.widgets import file_dialogs
from shaperapp.widgets.cad_font import CAD_FONT_SETTING

from gui_helpers import shown


# (tab, export, index of the GB filter, of the outlines', filter first before any DXF:
# the gear sheet PDF's (Qt's first, ''), the cam's GB); the tabs share PartTab's dialog
PARTS = [(GearTab, "sheet", 2, 3, None), (CamTab, "dxf", 0, 1, 0)]


@pytest.mark.parametrize(("part", "kind", "gb", "outlines", "first"), PARTS)
def test_the_dxf_texts_are_the_filter_chosen_and_remembered(qtbot, model, tmp_path, monkeypatch,
                                                             part, kind, gb, outlines, first):
    tab = shown(qtbot, part(model), 1000, 650)
    asked = []

    def answer(parent, title, start, filters, selected=""):
        names = filters.split(";;")
        asked.append((names, selected))
        return str(tmp_path / f"g{len(asked)}.dxf"), names[outlines if len(asked) == 1 else gb]
    monkeypatch.setattr(file_dialogs, "save_file_and_filter", answer)
    tab.buttons[kind].click()
    (names, selected), = asked
    assert "GB style" in names[gb] and "outlines" in names[outlines] and len(names) == outlines + 1
    assert selected == ("" if first is None else names[first])
    msp = ezdxf.readfile(tmp_path / "g1.dxf").modelspace()
    assert len(msp.query("TEXT")) == 0 and len(msp.query("HATCH[layer=='TEXT']")) > 20
    assert QSettings().value(CAD_FONT_SETTING) == "outline"
    tab.buttons[kind].click()
    assert asked[1][1] == names[outlines]                   # the last DXF's filter first
    msp = ezdxf.readfile(tmp_path / "g2.dxf").modelspace()
    assert len(msp.query("TEXT")) >= 3 and len(msp.query("HATCH[layer=='TEXT']")) == 0
    assert QSettings().value(CAD_FONT_SETTING) == "gb"


@pytest.mark.parametrize(("part", "kind", "outlines"), [(p[0], p[1], p[3]) for p in PARTS])
def test_outlines_without_a_font_say_so_in_one_line_and_write_nothing(qtbot, model, tmp_path, monkeypatch,
                                                                      part, kind, outlines):
    tab = shown(qtbot, part(model), 1000, 650)
    from core.drawing import outline_text
    monkeypatch.setattr(outline_text, "OUTLINE_FONTS", (("no-such-font.ttf", 0, "None Such"),))
    outline_text.outline_font.cache_clear()
    said = []
    monkeypatch.setattr(QMessageBox, "warning", lambda parent, title, text: said.append(text))
    monkeypatch.setattr(file_dialogs, "save_file_and_filter",
                        lambda parent, title, start, filters, selected="":
                        (str(tmp_path / "g.dxf"), filters.split(";;")[outlines]))
    try:
        tab.buttons[kind].click()
    finally:
        outline_text.outline_font.cache_clear()
    assert len(said) == 1 and "No font with Chinese characters is installed" in said[0]
    assert "\n" not in said[0] and not (tmp_path / "g.dxf").exists()


@pytest.mark.parametrize(("part", "kind"), [(p[0], p[1]) for p in PARTS])
def test_the_export_shows_the_busy_cursor_while_it_writes(qtbot, model, tmp_path, monkeypatch, part, kind):
    """The gear sheet as DXF with outlined texts took 0.47 s of a quiet machine with the window
    frozen and the arrow shown: the wait cursor while the file is written, then the arrow."""
    from PySide6.QtCore import Qt
    from PySide6.QtGui import QGuiApplication

    def cursor():
        shape = QGuiApplication.overrideCursor()
        return None if shape is None else shape.shape()
    tab = shown(qtbot, part(model), 1000, 650)
    seen = []
    monkeypatch.setattr(tab, f"export_{kind}", lambda path, *options, **named: seen.append(cursor()))
    monkeypatch.setattr(file_dialogs, "save_file_and_filter",
                        lambda parent, title, start, filters, selected="":
                        (str(tmp_path / "g.dxf"), filters.split(";;")[0]))
    tab.buttons[kind].click()
    assert seen == [Qt.CursorShape.WaitCursor] and cursor() is None
