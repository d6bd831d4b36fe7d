"""The Gear tab's greyed fields follow the pair the tables show (issue 40, item 1): with a′
typed, x1 and x2 are the pair's after every edit, undo, redo and refusal (they showed the
shifts of the pair before z1 changed: 0.2396/0.2938 beside a table of 0.415/2.069); with x1
and x2 typed, a′ is; a shift field shows 7 significant digits of a value it was not typed,
the exact value its tooltip and the model's."""
from __future__ import annotations

import pytest

from core.gear import GearPairInputs, design_pair
from shaperapp.gear.tab import GearTab

from gui_helpers import shown


@pytest.fixture
def tab(qtbot, model):
    return shown(qtbot, GearTab(model), 1000, 650)


def type_into(qtbot, tab, name, text):
    edit = tab.form.fields[name].edit
    edit.selectAll()
    qtbot.keyClicks(edit, text)
    tab.form.commit()


def table_shift(tab, col):
    rows = [tab.results.gears.verticalHeaderItem(r).text() for r in range(tab.results.gears.rowCount())]
    return float(tab.results.gears.item(rows.index("x"), col).text())


def assert_fields_follow(tab, want):
    """The greyed fields read (to their 7 digits) the pair the table shows, which is ``want``."""
    f = tab.form.fields
    assert table_shift(tab, 0) == pytest.approx(want.gear1.shift, abs=5e-7)
    assert table_shift(tab, 1) == pytest.approx(want.gear2.shift, abs=5e-7)
    for name, value in (("x1", want.gear1.shift), ("x2", want.gear2.shift), ("centre", want.centre_mm)):
        if f[name].isEnabled():
            continue                                     # typed: shows what was typed
        assert float(f[name].edit.text()) == pytest.approx(value, rel=1e-6, abs=1e-6), name
        assert float(f[name].edit.toolTip()) == value, name


def test_with_a_typed_centre_the_greyed_shifts_are_the_tables(qtbot, tab, model):
    type_into(qtbot, tab, "z1", "10")
    pair10 = design_pair(GearPairInputs(10, 40, 6.0, centre_mm=162.0))
    assert not tab.form.fields["x1"].isEnabled()
    assert_fields_follow(tab, pair10)
    type_into(qtbot, tab, "centre", "5")                  # refused: the last valid pair stays
    assert tab.form.marked_fields() == ["centre"]
    assert_fields_follow(tab, pair10)
    type_into(qtbot, tab, "centre", "165")
    assert_fields_follow(tab, design_pair(GearPairInputs(10, 40, 6.0, centre_mm=165.0)))
    model.undo_stack.undo()                              # a′ 162 again (5 and 165: one step)
    assert_fields_follow(tab, pair10)
    model.undo_stack.undo()                              # z1 = 13
    assert_fields_follow(tab, design_pair(GearPairInputs(13, 40, 6.0, centre_mm=162.0)))
    model.undo_stack.redo()
    assert_fields_follow(tab, pair10)


def test_with_typed_shifts_the_greyed_centre_is_the_tables(qtbot, tab):
    tab.form.mode.setCurrentIndex(tab.form.mode.findData("shifts"))
    tab.form.mode.activated.emit(tab.form.mode.currentIndex())
    type_into(qtbot, tab, "x1", "0.3")
    type_into(qtbot, tab, "z1", "11")
    assert not tab.form.fields["centre"].isEnabled()
    want = design_pair(GearPairInputs(11, 40, 6.0, x1=0.3, x2=tab.gear_model.pair.gear2.shift))
    assert_fields_follow(tab, want)
    assert tab.form.fields["x1"].edit.text() == "0.3"     # a typed value stays as typed


def test_the_rule_greys_all_three_and_they_are_the_tables(qtbot, tab):
    tab.form.mode.setCurrentIndex(tab.form.mode.findData("auto"))
    tab.form.mode.activated.emit(tab.form.mode.currentIndex())
    type_into(qtbot, tab, "z1", "9")
    assert_fields_follow(tab, design_pair(GearPairInputs(9, 40, 6.0)))


def test_a_carried_over_shift_is_rounded_on_screen_and_exact_in_the_model(qtbot, tab):
    tab.form.mode.setCurrentIndex(tab.form.mode.findData("shifts"))
    tab.form.mode.activated.emit(tab.form.mode.currentIndex())
    exact = tab.gear_model.typed.dict["x1"]
    assert exact == design_pair(GearPairInputs(13, 40, 6.0, centre_mm=162.0)).gear1.shift
    edit = tab.form.fields["x1"].edit
    assert edit.text() == f"{exact:.7g}" and float(edit.toolTip()) == exact
    assert edit.fontMetrics().horizontalAdvance(edit.text()) <= edit.contentsRect().width() - 4
