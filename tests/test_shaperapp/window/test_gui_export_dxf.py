"""File › Export scheme as DXF…: the design on screen at the animation's crank angle, for CAD."""
import math

import ezdxf
import numpy as np
import pytest
from PySide6.QtCore import QSettings

from core.linkage.kinematics import shape
from shaperapp.design.document import Document
from shaperapp.design.model import DesignModel
from shaperapp.widgets import file_dialogs
from shaperapp.widgets.cad_font import CAD_FONT_SETTING


@pytest.fixture
def document(qtbot, tmp_path):
    """A document without a window: a failure is a signal, not a message box."""
    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    return Document(DesignModel(), settings)


def lever_tip(path) -> np.ndarray:
    """B as the file has it: the end of L3's dimension away from O4."""
    dim = next(d for d in ezdxf.readfile(path).modelspace().query("DIMENSION")
               if d.dxf.text.startswith("L3 ="))
    ends = [np.array(dim.dxf.defpoint2)[:2], np.array(dim.dxf.defpoint3)[:2]]
    return max(ends, key=lambda p: np.hypot(*p))


def test_menu_writes_the_design_on_screen_at_its_angle(window, tmp_path, monkeypatch, qtbot):
    assert window.act_scheme_dxf in window.menu_file.actions()
    window.model.set_spec(variant="rod", time_ratio=1.5)
    window.model.set_angle_deg(130.0)
    angle = window.model.crank_deg
    target = tmp_path / "scheme.dxf"
    monkeypatch.setattr(file_dialogs, "save_file_and_filter", lambda *args: (str(target), ""))
    window.act_scheme_dxf.trigger()
    design = window.model.design
    assert design.rod is not None and math.isclose(design.time_ratio, 1.5)
    doc = ezdxf.readfile(target)
    measured = {d.dxf.text.split(" = ")[0]: d.get_measurement() for d in doc.modelspace().query("DIMENSION")}
    assert measured["L4"] == pytest.approx(design.rod, abs=1e-6)
    assert measured["L1"] == pytest.approx(design.crank, abs=1e-6)
    expected = shape(design, np.radians([angle])).lever_tip[:, 0]
    assert lever_tip(target) == pytest.approx(expected, abs=1e-9)
    assert not np.allclose(expected, shape(design, np.zeros(1)).lever_tip[:, 0])  # not φ = 0


def test_a_name_without_suffix_gets_dxf(document, tmp_path):
    assert document.export_scheme_dxf_to(str(tmp_path / "scheme"))
    assert ezdxf.readfile(tmp_path / "scheme.dxf").header["$INSUNITS"] == 4


def test_another_suffix_or_an_unwritable_place_is_reported_and_nothing_written(document, tmp_path, qtbot):
    png = tmp_path / "scheme.png"
    with qtbot.waitSignal(document.failed, timeout=10_000) as blocker:
        assert not document.export_scheme_dxf_to(str(png))
    assert str(png) in blocker.args[0] and "DXF" in blocker.args[0] and not png.exists()
    missing = tmp_path / "missing-dir" / "s.dxf"
    with qtbot.waitSignal(document.failed, timeout=10_000) as blocker:
        assert not document.export_scheme_dxf_to(str(missing))
    assert str(missing) in blocker.args[0] and ".tmp" not in blocker.args[0]
    assert [p.name for p in tmp_path.iterdir() if p.suffix != ".ini"] == []


def test_menu_text_in_chinese(window, qtbot):
    window.set_language("zh_CN")
    qtbot.waitUntil(lambda: window.tabs.tabText(2) == "位置", timeout=10_000)
    assert window.act_scheme_dxf.text().startswith("导出机构简图为 DXF")


def test_the_cad_texts_are_the_filter_chosen_and_remembered(window, tmp_path, monkeypatch):
    """Two filters of DXF: the GB style (first, the default) and outlines, as ``shaper drawing
    --content scheme --cad-font``; the one chosen is offered first the next time."""
    asked = []

    def answer(parent, title, start, filters, selected=""):
        asked.append((filters.split(";;"), selected))
        return str(tmp_path / f"scheme{len(asked)}.dxf"), filters.split(";;")[1]
    monkeypatch.setattr(file_dialogs, "save_file_and_filter", answer)
    window.act_scheme_dxf.trigger()
    (names, selected), = asked
    assert len(names) == 2 and "GB style" in names[0] and "outlines" in names[1]
    assert selected == names[0]                             # nothing remembered: GB
    msp = ezdxf.readfile(tmp_path / "scheme1.dxf").modelspace()
    assert len(msp.query("TEXT")) == 0 and {d.dxf.text for d in msp.query("DIMENSION")} == {" "}
    assert len(msp.query("HATCH[layer=='DIMENSIONS']")) > 20
    assert window.settings.value(CAD_FONT_SETTING) == "outline"
    window.act_scheme_dxf.trigger()
    assert asked[1][1] == names[1]


def test_outlines_without_a_font_are_reported_and_nothing_written(document, tmp_path, qtbot, monkeypatch):
    from core.drawing import outline_text
    monkeypatch.setattr(outline_text, "OUTLINE_FONTS", (("no-such-font.ttf", 0, "None Such"),))
    outline_text.outline_font.cache_clear()
    try:
        with qtbot.waitSignal(document.failed, timeout=10_000) as blocker:
            assert not document.export_scheme_dxf_to(str(tmp_path / "s.dxf"), "outline")
    finally:
        outline_text.outline_font.cache_clear()
    assert "No font with Chinese characters is installed for the outlines" in blocker.args[0]
    assert "\n" not in blocker.args[0] and not (tmp_path / "s.dxf").exists()
