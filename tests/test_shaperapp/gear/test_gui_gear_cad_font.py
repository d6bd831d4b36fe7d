"""The Gear tab's meshing sheet as DXF: the CAD texts (``--cad-font``) as two DXF filters,
the scheme export's, remembered under the same setting; outlines without a font refused."""
from __future__ import annotations

import ezdxf
import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QMessageBox

from shaperapp.gear.tab import GearTab
from shaperapp.widgets import file_dialogs
from shaperapp.widgets.cad_font import CAD_FONT_SETTING

from gui_helpers import shown


@pytest.fixture
def tab(qtbot, model):
    return shown(qtbot, GearTab(model), 1000, 650)


def test_the_sheet_texts_are_the_dxf_filter_chosen_and_remembered(tab, tmp_path, monkeypatch):
    asked = []

    def answer(parent, title, start, filters, selected=""):
        names = filters.split(";;")
        asked.append((names, selected))
        return str(tmp_path / f"g{len(asked)}.dxf"), names[3 if len(asked) == 1 else 2]
    monkeypatch.setattr(file_dialogs, "save_file_and_filter", answer)
    tab.buttons["sheet"].click()
    (names, selected), = asked
    assert len(names) == 4 and "GB style" in names[2] and "outlines" in names[3]
    assert selected == ""                                   # PDF first until a DXF is written
    msp = ezdxf.readfile(tmp_path / "g1.dxf").modelspace()
    assert len(msp.query("TEXT")) == 0 and len(msp.query("HATCH[layer=='TEXT']")) > 20
    assert QSettings().value(CAD_FONT_SETTING) == "outline"
    tab.buttons["sheet"].click()
    assert asked[1][1] == names[3]                          # the last DXF's filter first
    msp = ezdxf.readfile(tmp_path / "g2.dxf").modelspace()
    assert len(msp.query("TEXT")) > 5 and len(msp.query("HATCH[layer=='TEXT']")) == 0
    assert QSettings().value(CAD_FONT_SETTING) == "gb"


def test_outlines_without_a_font_say_so_in_one_line_and_write_nothing(tab, tmp_path, monkeypatch):
    from core.drawing import outline_text
    monkeypatch.setattr(outline_text, "OUTLINE_FONTS", (("no-such-font.ttf", 0, "None Such"),))
    outline_text.outline_font.cache_clear()
    said = []
    monkeypatch.setattr(QMessageBox, "warning", lambda parent, title, text: said.append(text))
    monkeypatch.setattr(file_dialogs, "save_file_and_filter",
                        lambda parent, title, start, filters, selected="":
                        (str(tmp_path / "g.dxf"), filters.split(";;")[3]))
    try:
        tab.buttons["sheet"].click()
    finally:
        outline_text.outline_font.cache_clear()
    assert len(said) == 1 and "No font with Chinese characters is installed" in said[0]
    assert "\n" not in said[0] and not (tmp_path / "g.dxf").exists()
