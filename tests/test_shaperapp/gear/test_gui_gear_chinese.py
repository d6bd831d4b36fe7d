"""The Gear tab in Chinese shows no English (issue 35, item 4): labels, lists, tables, the
checks with their advice, a refusal of core's and the module's note, the line over the
drawing; and in English the advice is core's own words."""
from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QTextDocument
from PySide6.QtWidgets import QAbstractButton, QComboBox, QLabel, QLineEdit, QWidget

from core.gear import pair_checks
from core.gear.table import MODE_TEXT
from shaperapp.widgets.gear_messages import check_advice, mode_text
from shaperapp.gear.tab import GearTab
from shaperapp.widgets import i18n
from shaperapp.widgets.result_table import ResultTable

from gui_helpers import shown
from cli_runner import shaper_in_process
from language_checks import english_words

SYMBOLS = {"zmin"}          # z_min of the rack, as the Drawing's x_min


@pytest.fixture
def chinese(qapp):
    i18n.set_language("zh_CN")
    yield
    i18n.set_language("en")


def texts(tab: GearTab) -> list[str]:
    out = [tab.view.caption(0.5)]
    for widget in tab.findChildren(QWidget):
        if not widget.isVisibleTo(tab):
            continue
        if isinstance(widget, QLabel) and widget.textFormat() == Qt.TextFormat.RichText:
            page = QTextDocument()
            page.setHtml(widget.text())
            out.append(page.toPlainText())
        elif isinstance(widget, (QLabel, QAbstractButton)):
            out.append(widget.text())
        if isinstance(widget, QLineEdit):
            out.append(widget.placeholderText())
        if isinstance(widget, QComboBox) and not widget.isEditable():
            out += [widget.itemText(i) for i in range(widget.count())]
        if isinstance(widget, ResultTable):
            for r in range(widget.rowCount()):
                out.append(widget.verticalHeaderItem(r).text())
                out.append(widget.verticalHeaderItem(r).toolTip())
                out += [widget.item(r, c).text() for c in range(widget.columnCount())]
            out += [widget.horizontalHeaderItem(c).text() for c in range(widget.columnCount())]
        out.append(widget.toolTip())
    return [t for t in out if t]


def english_in(tab: GearTab) -> list[str]:
    return [w for t in texts(tab) for w in english_words(t, SYMBOLS)]


def test_the_chinese_tab_shows_no_english(qtbot, model, chinese):
    tab = shown(qtbot, GearTab(model), 1000, 650)
    assert english_in(tab) == []
    gm = tab.gear_model
    gm.set_fields(mode="shifts", x1=0.0, x2=0.0)            # undercut: a failing check with advice
    assert not all(c.ok for c in pair_checks(gm.pair))
    assert english_in(tab) == []
    gm.set_fields(mode="centre", centre=162.0, module=5.5)  # the module's note; ε too small
    assert tab.form.note.isVisible()
    assert english_in(tab) == []
    for name, value in (("z1", 4.0), ("z1", 13.5), ("centre", 5.0), ("centre", 100.0)):
        gm.set_fields(**{name: value})                       # core's refusals, in words
        assert tab.form.error_label.isVisible(), name
        assert english_in(tab) == [], (name, value)
    gm.set_fields(mode="shifts", x1=3.0, x2=3.0, z1=13.0)
    assert english_in(tab) == []
    gm.set_fields(x1=5.0, x2=5.0)                           # teeth that never touch (hunt, 1 December)
    assert tab.form.error_label.isVisible()
    assert english_in(tab) == []
    gm.set_fields(mode="auto", module=6.0, z1=5.0, z2=6.0)
    assert english_in(tab) == []


def test_in_english_the_advice_and_the_rule_are_cores_words(model, qtbot):
    tab = shown(qtbot, GearTab(model), 1000, 650)
    assert "Teeth" in english_in(tab)                   # the harvest reads the tab's words
    for fields in ({"mode": "shifts", "x1": 0.0, "x2": 0.0}, {"mode": "centre", "module": 5.5},
                   {"mode": "shifts", "x1": 0.9, "x2": 0.9, "module": 6.0}):
        tab.gear_model.set_fields(**fields)
        for check in pair_checks(tab.gear_model.pair):
            assert check_advice(check) == check.advice
    for mode, text in MODE_TEXT.items():
        assert mode_text(mode) == text


@pytest.mark.parametrize("shifts", [(5.0, 5.0), (5.0, -1.0)], ids=["teeth never touch", "pointed tip"])
def test_a_design_files_refused_gear_pair_is_said_in_chinese(tmp_path, qapp, shifts):
    """File › Open of a file whose gear pair core refuses: the reason was core's English
    sentence inside the Chinese message (hunt, 1 December); now the Gear tab's words."""
    import json
    from core.base.errors import FileFormatError
    from core.files.design_file import load_design
    from core.gear.file import gear_to_dict
    from core.gear import GearPairInputs
    from shaperapp.widgets.file_messages import describe_file_error
    path = tmp_path / "g.shaper.json"
    status, _, err = shaper_in_process("design", "--crank", "100", "--K", "1.4", "--stroke", "300", "-o", path)
    assert status == 0, err
    doc = json.loads(path.read_text(encoding="utf-8"))
    doc["gear"] = gear_to_dict(GearPairInputs(z1=13, z2=40, module_mm=6.0, x1=shifts[0], x2=shifts[1]))
    path.write_text(json.dumps(doc), encoding="utf-8")
    with pytest.raises(FileFormatError) as info:
        load_design(path)
    i18n.set_language("zh_CN")              # after shaper_in_process, which sets English back
    try:
        text = describe_file_error(info.value)
    finally:
        i18n.set_language("en")
    assert "x1 ≤ " in text and english_words(text.replace(str(path), ""), SYMBOLS) == [], text
