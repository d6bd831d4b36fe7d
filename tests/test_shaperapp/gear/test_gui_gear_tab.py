"""The Gear tab (issue 35, item 4): the table is core's pair of what was typed, a bad value
marks its field and keeps the last valid pair, edits undo on the design's stack, the
drawing turns with the animation's crank angle, and the exports write core's numbers."""
from __future__ import annotations

import math

import ezdxf
import numpy as np
import pytest

from core.gear import GearPairInputs, design_pair, pair_checks
from core.gear.mesh import gear_outline
from core.gear.table import MODE_TEXT, gear_summary, summary_csv
from shaperapp.gear.model import MODE_FIELDS
from shaperapp.gear.tab import GearTab
from cli_runner import shaper_in_process

from gear_checks import assert_fields_follow, assert_table_is
from gui_helpers import shown


@pytest.fixture
def tab(qtbot, model):
    return shown(qtbot, GearTab(model), 1000, 650)


def type_into(qtbot, tab, name, text):
    edit = tab.form.module.lineEdit() if name == "module" else tab.form.fields[name].edit
    edit.selectAll()
    qtbot.keyClicks(edit, text)
    tab.form.commit()


def test_the_default_pair_and_what_is_typed_are_cores(qtbot, tab):
    assert_table_is(tab, design_pair(GearPairInputs(13, 40, 6.0, centre_mm=162.0)))
    type_into(qtbot, tab, "z1", "15")
    type_into(qtbot, tab, "z2", "47")
    type_into(qtbot, tab, "centre", "5")            # refused (below a cos α): the pair stays
    assert tab.form.marked_fields() == ["centre"]
    type_into(qtbot, tab, "centre", "186")
    assert tab.form.marked_fields() == []
    assert_table_is(tab, design_pair(GearPairInputs(15, 47, 6.0, centre_mm=186.0)))


def test_each_mode_gives_cores_pair(qtbot, tab):
    form = tab.form
    form.mode.setCurrentIndex(form.mode.findData("shifts"))
    form.mode.activated.emit(form.mode.currentIndex())
    assert tab.gear_model.pair.centre_mm == 162.0          # the switch alone changes nothing
    assert form.fields["x1"].isEnabled() and not form.fields["centre"].isEnabled()
    type_into(qtbot, tab, "x1", "0.45")
    type_into(qtbot, tab, "x2", "0.2")
    assert_table_is(tab, design_pair(GearPairInputs(13, 40, 6.0, x1=0.45, x2=0.2)))
    form.mode.setCurrentIndex(form.mode.findData("auto"))
    form.mode.activated.emit(form.mode.currentIndex())
    want = design_pair(GearPairInputs(13, 40, 6.0))
    assert_table_is(tab, want)
    assert tab.results.rule.text() == "Shifts: " + MODE_TEXT[want.mode]


@pytest.mark.parametrize("name, text", [("z1", "4"), ("z1", "abc"), ("z1", "13.5"), ("z2", "2000"),
                                        ("module", "0"), ("pressure_angle", "50"), ("contact_limit", "x")])
def test_a_bad_value_marks_its_field_and_keeps_the_pair(qtbot, tab, name, text):
    before = tab.gear_model.pair
    saved = tab.gear_model.document()
    type_into(qtbot, tab, name, text)
    assert tab.form.marked_fields() == [name]
    assert tab.form.error_label.isVisible()
    assert "The last valid gear pair stays on screen." in tab.form.error_label.text()
    assert tab.gear_model.pair is before and tab.gear_model.document() == saved


def test_a_bad_teeth_count_is_named_in_words(qtbot, tab):
    type_into(qtbot, tab, "z1", "4")
    assert tab.form.error_label.text().startswith("⚠ Teeth z1: must be at least 5 and at most 1000 teeth")


def test_edits_undo_and_redo_on_the_designs_stack(qtbot, tab, model):
    type_into(qtbot, tab, "z1", "17")
    assert tab.gear_model.pair.gear1.teeth == 17
    model.undo_stack.undo()
    assert tab.gear_model.pair.gear1.teeth == 13 and tab.form.fields["z1"].edit.text() == "13"
    model.undo_stack.redo()
    assert tab.gear_model.pair.gear1.teeth == 17
    assert model.dirty


def test_a_module_outside_the_first_series_is_taken_with_the_note(qtbot, tab):
    assert not tab.form.note.isVisible()
    type_into(qtbot, tab, "module", "5.5")
    assert tab.gear_model.pair.inputs.module_mm == 5.5
    assert tab.form.note.isVisible()
    assert tab.form.note.text() == tab.gear_model.pair.inputs.module_note
    tab.form.module.setCurrentIndex(tab.form.module.findText("6"))
    tab.form.module.activated.emit(tab.form.module.currentIndex())
    assert tab.gear_model.pair.inputs.module_mm == 6.0 and not tab.form.note.isVisible()


def test_failing_checks_say_what_to_change_in_cores_words(qtbot, tab):
    tab.gear_model.set_fields(mode="shifts", x1=0.0, x2=0.0)      # z1 = 13 < 17 uncut: undercut
    checks = pair_checks(tab.gear_model.pair)
    failing = [c for c in checks if not c.ok]
    assert any(c.name == "undercut1" for c in failing)
    text = tab.results.checks.text()
    assert text.count("✗") == len(failing) and text.count("✓") == len(checks) - len(failing)
    for check in failing:
        assert check.advice in text


def test_the_drawing_turns_with_the_crank(qtbot, tab, model):
    """The gear z2 turns with the crank (clockwise about O2), the pinion i = z2/z1 times as
    fast the other way about O1; the outlines are core's."""
    pair = tab.gear_model.pair
    model.set_angle_index(0)
    one0, two0 = tab.view.placed_outlines(tab.gear_model.crank_turn())
    model.set_angle_deg(37.0)
    phi = tab.gear_model.crank_turn()
    assert math.degrees(phi) == pytest.approx(37.0, abs=0.51)
    one, two = tab.view.placed_outlines(phi)

    def turned(points, angle, centre):
        c, s = math.cos(angle), math.sin(angle)
        rel = points - centre
        return np.column_stack([c * rel[:, 0] - s * rel[:, 1], s * rel[:, 0] + c * rel[:, 1]]) + centre
    assert np.abs(two - turned(two0, -phi, np.array([pair.centre_mm, 0.0]))).max() < 1e-9
    assert np.abs(one - turned(one0, phi * 40 / 13, np.zeros(2))).max() < 1e-9
    assert np.abs(tab.view.outlines()[1] - gear_outline(pair, 2)).max() == 0.0


def test_the_view_repaints_when_the_crank_moves(qtbot, tab, model):
    before = tab.view.grab().toImage()
    model.set_angle_deg(90.0)
    qtbot.wait(20)
    assert tab.view.grab().toImage() != before


def test_csv_export_is_shaper_gears(tab, tmp_path):
    path = tmp_path / "g.csv"
    tab.export_csv(str(path))
    assert path.read_text() == summary_csv(gear_summary(design_pair(GearPairInputs(13, 40, 6.0, centre_mm=162.0))))


def test_the_meshing_sheet_exports_as_dxf_with_the_pair_at_one_to_one(tab, tmp_path):
    path = tmp_path / "g.dxf"
    tab.export_sheet(str(path))
    doc = ezdxf.readfile(str(path))
    pair = tab.gear_model.pair
    radii = {round(c.dxf.radius, 6) for c in doc.modelspace().query("CIRCLE")}
    assert round(pair.gear1.rb, 6) in radii and round(pair.gear1.ra, 6) in radii
    # the pair on its own: sheet 1 of 1 (it said 4/4, the course design's fourth of four sheets)
    texts = {t.dxf.text for t in doc.modelspace().query("TEXT[layer=='TITLE']")}
    assert "1/1" in texts and "4/4" not in texts, texts
    with pytest.raises(ValueError):
        tab.export_sheet(str(tmp_path / "g.txt"))


def test_the_close_up_fits_the_line_of_action(qtbot, tab):
    from core.gear.mesh import line_points
    from shaperapp.gear.pair_view import pair_span
    pair = tab.gear_model.pair
    lo, hi = pair_span(pair, close_up=True)
    full_lo, full_hi = pair_span(pair)
    for name in ("N1", "N2", "P"):
        assert np.all(line_points(pair)[name] > lo) and np.all(line_points(pair)[name] < hi)
    assert np.all(hi - lo < (full_hi - full_lo) / 2)
    before = tab.view.grab().toImage()
    tab.close_up.setChecked(True)
    assert tab.view.close_up and tab.view.grab().toImage() != before


def test_a_pair_the_closed_forms_cannot_compute_is_said_not_raised(qtbot, tab, monkeypatch):
    before = tab.gear_model.pair
    monkeypatch.setattr("shaperapp.gear.model.design_pair", lambda inputs: 1 / 0)
    type_into(qtbot, tab, "z1", "14")
    assert tab.gear_model.pair is before
    assert tab.form.error_label.text().startswith("⚠ Design: cannot be computed for these inputs")


# ---- issue 40: The Gear tab's greyed fields follow the pair the tables show (issue 40, item 1): with a′
# typed, x1 and x2 are the pair's after every edit, undo, redo and refusal (they showed the
# shifts of the pair before z1 changed: 0.2396/0.2938 beside a table of 0.415/2.069); with x1
# and x2 typed, a′ is; a shift field shows 7 significant digits of a value it was not typed,
# the exact value its tooltip and the model's.

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


def cli_pair_texts(*options) -> tuple[str, str, str]:
    """x1, x2 and a′ as ``shaper gear OPTIONS`` prints them (run in this process)."""
    status, out, _ = shaper_in_process("gear", *options)
    assert status == 0
    rows = {line[:40].strip(): line[40:].strip() for line in out.splitlines()}
    x1, x2 = rows["shift factor x1 / x2"].split(" / ")
    return x1, x2, rows["centre distance a′ (a)"].split(" mm")[0]


@pytest.mark.parametrize("mode, typed, options", [
    ("centre", (("z1", "13"),), ("--centre", "162")),
    ("auto", (("z1", "9"),), ()),
    ("shifts", (("z1", "11"), ("x1", "0.3"), ("x2", "-0.1")), ("--x1", "0.3", "--x2", "-0.1"))])
def test_the_greyed_fields_read_as_shaper_gear_prints_them(qtbot, tab, mode, typed, options):
    """A greyed x1, x2 or a′ is the figure ``shaper gear`` prints for the same pair, digit for
    digit (x1 showed 7 significant digits beside the table's and the CLI's 6 decimals)."""
    tab.form.mode.setCurrentIndex(tab.form.mode.findData(mode))
    tab.form.mode.activated.emit(tab.form.mode.currentIndex())
    for name, text in typed:
        type_into(qtbot, tab, name, text)
    z1 = dict(typed)["z1"]
    want = dict(zip(("x1", "x2", "centre"), cli_pair_texts("--z1", z1, "--z2", "40", "--module", "6", *options)))
    greyed = [name for name in want if not tab.form.fields[name].isEnabled()]
    assert greyed == [name for name in want if name not in MODE_FIELDS[mode]]
    for name in greyed:
        assert tab.form.fields[name].edit.text() == want[name], name


def test_an_export_while_a_field_is_refused_asks_first(qtbot, tab, tmp_path, monkeypatch):
    """With z1 typed as 4 (refused, the last valid pair on screen) the CSV button wrote the
    last valid pair without a word, a sheet whose z1 the fields no longer show; now it asks
    first, as File › Export does for the design's inputs, and Cancel writes nothing
    (hunt s13-hunt2)."""
    from PySide6.QtWidgets import QMessageBox
    from shaperapp.widgets import file_dialogs
    path = tmp_path / "g.csv"
    monkeypatch.setattr(file_dialogs, "save_file_and_filter", lambda *a, **k: (str(path), ""))
    asked: list[str] = []

    def answer(button):
        return lambda *a, **k: asked.append(a[2]) or button
    monkeypatch.setattr(QMessageBox, "question", answer(QMessageBox.StandardButton.Cancel))
    tab._export_dialog("csv")                 # every field valid: no question
    assert asked == [] and path.exists()
    path.unlink()
    type_into(qtbot, tab, "z1", "4")
    tab._export_dialog("csv")
    assert not path.exists() and len(asked) == 1
    assert asked[0].startswith("Teeth z1: must be at least 5") and "last valid gear pair" in asked[0]
    monkeypatch.setattr(QMessageBox, "question", answer(QMessageBox.StandardButton.Yes))
    tab._export_dialog("csv")
    assert path.read_text() == summary_csv(gear_summary(tab.gear_model.pair))
