"""The Library pane and the Compare view, driven as a user would (pytest-qt)."""
from dataclasses import replace

import numpy as np
import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtGui import QImage
from PySide6.QtWidgets import QApplication, QMessageBox

from core.space.compare import compare, table_csv
from core.files.io import load_design, save_design
from core.library import Library
from core.linkage.spec import Spec
from shaperapp.compare.plots import design_pen
from shaperapp.compare.view import CompareView
from shaperapp.library import pane as library_pane
from shaperapp.library.pane import LibraryPane
from shaperapp.library.table import COLUMNS


@pytest.fixture(autouse=True)
def no_dialogs(monkeypatch, tmp_path):
    """Never touch the user's library; record message boxes instead of showing them."""
    monkeypatch.setenv("SHAPER_LIBRARY", str(tmp_path / "default.sqlite"))
    shown = []
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: shown.append(a[2]))
    monkeypatch.setattr(QMessageBox, "information", lambda *a, **k: shown.append(a[2]))
    monkeypatch.setattr(QMessageBox, "question", lambda *a, **k: QMessageBox.StandardButton.Yes)
    return shown


@pytest.fixture
def pane(qtbot, model, tmp_path):
    widget = LibraryPane(model, settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    qtbot.addWidget(widget)
    assert widget.open_library(str(tmp_path / "lib.sqlite"))
    widget.resize(1200, 500)
    widget.show()
    return widget


def names(pane):
    return [pane.table_model.name_at(r) for r in range(pane.table_model.rowCount())]


def save(pane, model, name, **spec):
    model.set_spec(**spec)
    assert model.error is None
    assert pane.actions.save_current(name, notes=f"notes of {name}", tags=["t"])


def test_filter_takes_the_field_names_the_pane_shows(pane, model):
    """In Chinese the columns read 方案, 最大压力角 (°) …, but the filter took only core's
    English names: "方案=滑块" was refused (issue 20 item 7)."""
    from shaperapp.widgets import i18n
    from shaperapp.library.filter import core_filter
    save(pane, model, "a block")
    save(pane, model, "a rod", variant="rod", rod_input="ratio", rod_ratio=0.3)
    i18n.set_language("zh_CN")
    try:
        assert core_filter("方案=滑块") == "variant=block"
        assert core_filter(' 名称~"a, b", K>=1.4') == ' name~"a, b", K>=1.4'
        headers = [pane.table_model.headerData(c, Qt.Orientation.Horizontal)
                   for c in range(pane.table_model.columnCount())]
        variant = headers[1]
        rod_word = pane.table_model.index(names(pane).index("a rod"), 1).data()
        pane.filter_edit.setText(f"{variant}={rod_word}")
        assert names(pane) == ["a rod"] and pane.filter_edit.toolTip() == ""
        pane.filter_edit.setText(f"{variant} != {rod_word}, L1 (mm) > 50")
        assert names(pane) == ["a block"]
        pressure = next(h for h in headers if "压力角" in h)
        pane.filter_edit.setText(f"{pressure.split(' (')[0]}<90")   # the title without its unit
        assert names(pane) == ["a rod"]
        pane.filter_edit.setText("variant=rod")                       # core's names still work
        assert names(pane) == ["a rod"]
    finally:
        i18n.set_language("en")
    pane.filter_edit.setText("Variant=block")
    assert names(pane) == ["a block"]


def test_columns_fit_their_texts_after_an_add(pane, model):
    """Opened empty, the Name and K columns stayed as narrow as their titles after
    designs were added ("base K…", "1.…"; issue 20 item 3)."""
    save(pane, model, "base K 1.4 stroke 300 long name")
    save(pane, model, "second", time_ratio=1.6)
    view, metrics = pane.view, pane.view.fontMetrics()
    for row in range(pane.table_model.rowCount()):
        for col in range(pane.table_model.columnCount()):
            text = pane.table_model.index(row, col).data()
            if text:
                assert view.columnWidth(col) >= metrics.horizontalAdvance(str(text)), (row, col, text)


def test_save_current_design_and_list_it(pane, model):
    save(pane, model, "K1.4")
    save(pane, model, "K1.6 rod", time_ratio=1.6, variant="rod")
    assert names(pane) == ["K1.4", "K1.6 rod"]
    row = names(pane).index("K1.6 rod")
    col = COLUMNS.index("K")
    assert pane.table_model.data(pane.table_model.index(row, col)) == "1.6000"
    with Library(pane.actions.library.path) as lib:
        doc = lib.load("K1.6 rod")
    assert doc["spec"] == model.valid_spec and doc["masses"] == model.masses
    assert doc["rpm"] == list(model.rpms)


def test_search_filter_sort_and_speed(pane, model, qtbot):
    for k in (1.3, 1.5, 1.7):
        save(pane, model, f"K{k}", time_ratio=k, stroke=400.0)
    pane.filter_edit.setText("K>=1.45")
    assert names(pane) == ["K1.5", "K1.7"]
    pane.filter_edit.setText("K>=")                       # not understood: marked, rows kept
    assert pane.message_label.text() and names(pane) == ["K1.5", "K1.7"]
    pane.filter_edit.setText("")
    assert not pane.message_label.text() and len(names(pane)) == 3
    pane.search_edit.setText("notes of K1.3")
    assert names(pane) == ["K1.3"]
    pane.search_edit.setText("")
    pane.view.sortByColumn(COLUMNS.index("a_max_m_s2"), Qt.SortOrder.DescendingOrder)
    a = [pane.table_model.value(r, "a_max_m_s2") for r in range(3)]
    assert a == sorted(a, reverse=True)
    pane.speed_box.setCurrentText("60")
    assert pane.table_model.value(0, "rpm") == 60.0
    a60 = pane.table_model.value(0, "a_max_m_s2")
    assert a60 == pytest.approx(max(a) * (60 / 40) ** 2)   # a ∝ ω² (first speed is 40)


def test_open_from_library_is_all_or_nothing(pane, model, no_dialogs):
    save(pane, model, "rod", time_ratio=1.6, variant="rod")
    model.set_spec(time_ratio=1.3, variant="block")
    pane.select_names(["rod"])
    pane.open_selected()
    assert model.spec.time_ratio == 1.6 and model.spec.variant == "rod"
    # a document damaged in the database: refused, the design on screen stays
    pane.actions.library._conn.execute(
        "UPDATE documents SET text = replace(text, '\"crank\": 100.0', '\"crank\": -5')")
    model.set_spec(time_ratio=1.45)
    before = (model.spec, model.metrics)
    pane.open_selected()
    assert (model.spec, model.metrics) == before
    assert no_dialogs and "Could not open the design" in no_dialogs[-1]


def test_opening_an_entry_says_the_defaults_it_lacked(pane, model, no_dialogs):
    """An entry stored from a file saved before the cam had a hub, a boss and a clearance
    (tests/data/my.shaper.json) opens with them at their defaults, said in the pane as File ›
    Open says them in the status bar; an entry with every key says nothing."""
    from pathlib import Path
    from core.files.io import load_design
    old = load_design(Path(__file__).resolve().parents[2] / "data" / "my.shaper.json")
    pane.actions.library.add("old", old)
    save(pane, model, "new", time_ratio=1.5)
    pane.message_label.setText("")
    pane.select_names(["new"])
    pane.open_selected()
    assert pane.message_label.text() == ""
    pane.select_names(["old"])
    pane.open_selected()
    assert pane.message_label.text() == ("library entry “old” does not give cam.hub_mm = 12.5 mm, "
                                         "cam.boss_mm = 12.5 mm, cam.clearance_mm = 3 mm; these were taken.")
    assert no_dialogs == []


def test_rename_duplicate_delete_with_undo(pane, model):
    save(pane, model, "a")
    save(pane, model, "b", time_ratio=1.5)
    lib = pane.actions.library
    original = lib.get("a")
    assert pane.actions.rename("a", "c") and names(pane) == ["b", "c"]
    assert pane.actions.duplicate("c") and names(pane) == ["b", "c", "c (2)"]
    pane.select_names(["b", "c (2)"])
    assert pane.selected_names() == ["b", "c (2)"]
    pane.delete_selected()
    assert names(pane) == ["c"]
    stack = pane.actions.undo_stack
    stack.undo()                                         # delete undone
    assert names(pane) == ["b", "c", "c (2)"]
    stack.undo()                                         # duplicate undone
    stack.undo()                                         # rename undone
    assert names(pane) == ["a", "b"] and lib.get("a") == original
    stack.redo()
    assert names(pane) == ["b", "c"]
    assert not pane.actions.rename("c", "b")              # taken: refused, nothing changes
    assert names(pane) == ["b", "c"]


def test_save_over_an_existing_name_is_undoable(pane, model):
    save(pane, model, "x")
    first = pane.actions.library.get("x")
    model.set_spec(time_ratio=1.55)
    assert not pane.actions.save_current("x")             # exists: refused without replace
    assert pane.actions.save_current("x", replace_existing=True)
    assert pane.actions.library.get("x").figures.K == pytest.approx(1.55)
    pane.actions.undo_stack.undo()
    assert pane.actions.library.get("x") == first


def test_import_folder_and_export(pane, tmp_path, no_dialogs):
    folder = tmp_path / "designs"
    folder.mkdir()
    save_design(folder / "one.shaper.json", Spec(time_ratio=1.5), [40.0], 1.0)
    save_design(folder / "two.shaper.json", Spec(variant="rod"), [50.0], 2.0)
    (folder / "broken.json").write_text('{"format": "shaper-design", "version": 1, "spec": 3}')
    pane.import_paths([str(folder)])
    assert names(pane) == ["one", "two"]
    assert "broken.json" in no_dialogs[-1]
    out = tmp_path / "two-out.json"
    assert pane.actions.export("two", str(out))
    assert load_design(out)["spec"] == Spec(variant="rod") and load_design(out)["step_deg"] == 2.0
    export_dir = tmp_path / "all"
    export_dir.mkdir()
    assert pane.actions.export_all(str(export_dir))
    assert sorted(p.name for p in export_dir.iterdir()) == ["one.shaper.json", "two.shaper.json"]
    pane.actions.undo_stack.undo()                      # the import, as one step
    assert names(pane) == []


def test_changes_from_another_program_appear(pane, model):
    save(pane, model, "mine")
    with Library(pane.actions.library.path) as other:
        other.add("theirs", {"spec": Spec(time_ratio=1.5), "rpm": [40.0], "step_deg": 1.0, "masses": None})
    pane._poll()
    assert names(pane) == ["mine", "theirs"]


def test_damaged_library_is_refused_and_can_be_copied(qtbot, model, tmp_path, monkeypatch, no_dialogs):
    path = tmp_path / "bad.sqlite"
    path.write_bytes(b"SQLite format 3\x00" + bytes(range(256)) * 40)
    before = path.read_bytes()
    monkeypatch.setattr(library_pane, "ask_refused_library", lambda parent, message: "copy")
    widget = LibraryPane(model)
    qtbot.addWidget(widget)
    monkeypatch.setattr(widget, "choose_library_dialog", lambda: None)
    assert not widget.open_library(str(path))
    assert path.read_bytes() == before
    copies = list(tmp_path.glob("bad.sqlite.backup-*"))
    assert len(copies) == 1 and copies[0].read_bytes() == before
    assert "A copy was saved" in no_dialogs[-1]
    assert widget.actions.library is None


# ---- comparison ----------------------------------------------------------------------
def test_compare_selected_designs(pane, model, qtbot, tmp_path):
    save(pane, model, "block")
    save(pane, model, "rod", time_ratio=1.6, variant="rod")
    view = CompareView(model)
    qtbot.addWidget(view)
    view.resize(900, 800)
    view.show()
    pane.compareRequested.connect(view.set_candidates)
    pane.select_names(["block", "rod"])
    assert pane.act_compare.isEnabled()
    pane.compare_selected()
    assert [c.label for c in view.candidates()] == ["block", "rod"]
    expected = compare(view.candidates(), view.speed.value())
    result = view.comparison
    np.testing.assert_array_equal(result.ram_a_m_s2, expected.ram_a_m_s2)
    row = [r.key for r in result.rows].index("a_max_m_s2")
    assert view.table.item(row, 0).text().startswith("★")       # the block has the lower max |a|
    assert "(+" in view.table.item(row, 1).text()
    # every design its own colour and line style, in every plot
    curves = view.plots.item("ram_v_m_s").listDataItems()
    styles = {(c.opts["pen"].color().name(), c.opts["pen"].style()) for c in curves}
    assert len(curves) == 2 and len(styles) == 2
    assert design_pen(0).style() != design_pen(1).style()
    view.speed.setValue(60.0)
    assert view.comparison.rpm == 60.0
    assert not view.add_current()       # the screen shows "rod" itself: refused, not a look-alike
    model.set_spec(time_ratio=1.55)
    assert model.valid_spec.time_ratio == 1.55 and view.add_current() and len(view.candidates()) == 3
    csv_path = tmp_path / "cmp.csv"
    view.export_csv(str(csv_path))
    assert csv_path.read_text(encoding="utf-8") == table_csv(compare(view.candidates(), 60.0))
    png, svg = tmp_path / "cmp.png", tmp_path / "cmp.svg"
    view.export_image(str(png))
    view.export_image(str(svg))
    assert not QImage(str(png)).isNull() and QImage(str(png)).width() > 500
    assert "<svg" in svg.read_text(encoding="utf-8")


def test_compare_view_with_too_few_designs_and_files(model, qtbot, tmp_path):
    view = CompareView(model)
    qtbot.addWidget(view)
    assert view.comparison is None and view.hint.text()
    path = tmp_path / "f.shaper.json"
    save_design(path, Spec(time_ratio=1.5), [40.0], 1.0)
    assert view.add_file(str(path)) and view.add_current()
    assert view.comparison is not None and view.comparison.labels[0] == "f"
    for i in range(4):
        model.set_spec(time_ratio=1.41 + 0.01 * i)    # the same design again is refused
        view.add_current()
    assert len(view.candidates()) == 6 and not view.add_current()
    view.list.setCurrentRow(0)
    view.remove_selected()
    assert len(view.candidates()) == 5


def test_main_window_has_library_dock_and_compare_tab(qtbot, tmp_path):
    from shaperapp.window.main_window import MainWindow
    from shaperapp.design.model import DesignModel
    win = MainWindow(DesignModel(), QSettings(str(tmp_path / "w.ini"), QSettings.Format.IniFormat))
    qtbot.addWidget(win)
    win.show()
    assert not win.library_dock.isVisible()
    win.act_library.trigger()
    assert win.library_dock.isVisible()
    assert win.library.actions.library is not None          # opened when first shown ($SHAPER_LIBRARY)
    win.act_compare.trigger()
    assert win.tabs.currentWidget() is win.compare


def test_replace_in_dataclass_keeps_entry_equal(pane, model):
    save(pane, model, "e")
    entry = pane.actions.library.get("e")
    assert replace(entry) == entry


def test_large_library_is_fetched_page_by_page(pane, model):
    from shaperapp.library.table import PAGE
    save(pane, model, "template")
    lib = pane.actions.library
    template = lib.get("template")
    lib.add_entries([replace(template, name=f"n{i:04d}") for i in range(2 * PAGE + 10)])
    pane.table_model.refresh()
    assert pane.table_model.rowCount() == PAGE and pane.table_model.canFetchMore()
    pane.view.scrollToBottom()                      # the view asks for the next page itself
    assert pane.table_model.rowCount() == 2 * PAGE
    row = pane.table_model.row_of("template")       # the last entry: fetched on demand
    assert row == 2 * PAGE + 10 and not pane.table_model.canFetchMore()
    assert names(pane) == [f"n{i:04d}" for i in range(2 * PAGE + 10)] + ["template"]


def _age(path, name):
    """What an older program left: figures of version 0 that differ from this one's."""
    import sqlite3
    conn = sqlite3.connect(path)
    with conn:
        conn.execute("UPDATE entries SET figures_version = 0, K = 9.5 WHERE name = ?", (name,))
    conn.close()


def test_stale_figures_are_shown_and_recomputed(pane, model, no_dialogs, qtbot):
    save(pane, model, "K1.4")
    save(pane, model, "K1.6", time_ratio=1.6)
    assert pane.stale_bar.isHidden()
    path = pane.actions.library.path
    _age(path, "K1.6")
    pane._poll()                                 # another program's change is noticed
    assert pane.stale_bar.isVisible() and "1 design" in pane.stale_bar.label.text()
    col = COLUMNS.index("K")
    row = names(pane).index("K1.6")
    assert pane.table_model.data(pane.table_model.index(row, col)) == "9.5000"
    qtbot.mouseClick(pane.stale_bar.button, Qt.MouseButton.LeftButton)
    assert pane.stale_bar.isHidden() and no_dialogs == []
    assert pane.table_model.data(pane.table_model.index(row, col)) == "1.6000"
    with Library(path) as lib:
        assert lib.stale_names() == []


def test_stale_bar_in_chinese(pane, model, qtbot):
    from shaperapp.widgets import i18n
    save(pane, model, "K1.4")
    _age(pane.actions.library.path, "K1.4")
    pane._refresh()
    try:
        i18n.set_language("zh_CN")
        qtbot.waitUntil(lambda: pane.stale_bar.button.text() != "Recompute", timeout=10_000)
        assert "1" in pane.stale_bar.label.text() and "older" not in pane.stale_bar.label.text()
    finally:
        i18n.set_language("en")


def test_a_huge_note_is_not_held_by_the_list(pane, model):
    """Issue 33 item 7: a design with 50 MB of notes took the pane 2 GB and 9 s to open;
    the list now gets only the first NOTES_SHOWN + 1 characters of each note from SQLite
    (the cell shows 120 of them and its tooltip 500, each ending in …), and the note itself is stored whole."""
    from shaperapp.library.table import NOTES_CELL, NOTES_SHOWN
    model.set_spec(time_ratio=1.5)
    note = "n" * 5_000_000
    assert pane.actions.save_current("big", notes=note)
    row = names(pane).index("big")
    assert len(pane.table_model.value(row, "notes")) == NOTES_SHOWN + 1
    index = pane.table_model.index(row, COLUMNS.index("notes"))
    shown = pane.table_model.data(index)
    tip = pane.table_model.data(index, Qt.ItemDataRole.ToolTipRole)
    assert shown == "n" * NOTES_CELL + "…" and tip == "n" * NOTES_SHOWN + "…"
    assert pane.actions.library.get("big").notes == note
    assert pane.actions.library.query()[0]["notes"] == note         # the CLI's list is whole
    assert pane.actions.save_current("short", notes="line one\nline two")
    index = pane.table_model.index(names(pane).index("short"), COLUMNS.index("notes"))
    assert pane.table_model.data(index) == "line one"
    assert pane.table_model.data(index, Qt.ItemDataRole.ToolTipRole) == "line one\nline two"


def _cursor():
    from PySide6.QtGui import QGuiApplication
    cursor = QGuiApplication.overrideCursor()
    return None if cursor is None else cursor.shape()


def test_import_and_export_all_show_the_busy_cursor(pane, tmp_path, monkeypatch):
    """Import read every file and computed its figures with the window frozen and the arrow
    shown (1.5 s for a folder of 300 designs, 0.19 s to export them): the wait cursor now,
    the arrow again over a message said in the middle (a folder that is a file),
    and the cursor as it was afterwards."""
    from PySide6.QtWidgets import QFileDialog
    seen = []
    actions = pane.actions
    for step in ("import_paths", "export_all"):
        real = getattr(actions, step)
        monkeypatch.setattr(actions, step, lambda *a, real=real, step=step: (
            seen.append((step, _cursor())), real(*a))[1])
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: seen.append(("message", _cursor())))
    folder = tmp_path / "designs"
    folder.mkdir()
    save_design(folder / "one.shaper.json", Spec(time_ratio=1.5), [40.0], 1.0)
    pane.import_paths([str(folder)])
    assert names(pane) == ["one"]
    (tmp_path / "a file").write_text("")
    for target in (tmp_path / "out", tmp_path / "a file"):        # the second cannot be written
        monkeypatch.setattr(QFileDialog, "getExistingDirectory", lambda *a, target=target: str(target))
        pane.export_all_dialog()
    wait, arrow = Qt.CursorShape.WaitCursor, Qt.CursorShape.ArrowCursor
    assert seen == [("import_paths", wait), ("export_all", wait), ("export_all", wait), ("message", arrow)]
    assert (tmp_path / "out" / "one.shaper.json").exists() and _cursor() is None


def reachable(pane, action) -> bool:
    """``action`` is a button in view on one of the pane's toolbars, or in the menu of one
    (not behind a toolbar's », whose buttons are hidden)."""
    from PySide6.QtWidgets import QToolBar, QToolButton
    for bar in pane.findChildren(QToolBar):
        for button in bar.findChildren(QToolButton):
            if (not button.isVisible() or not bar.rect().contains(button.geometry())
                    or button.objectName() == "qt_toolbar_ext_button"):       # », the hidden ones' menu
                continue
            if button.defaultAction() is action or (button.menu() and action in button.menu().actions()):
                return True
    return False


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_every_button_is_in_view_at_a_laptops_width(pane, language):
    """The pane as a tab beside the Results at 1366 × 768 (414 px wide under openbox):
    Import, Import folder, Export and Export all were behind the toolbar's » there."""
    from shaperapp.widgets import i18n
    i18n.set_language(language)
    try:
        pane.resize(400, 500)
        QApplication.processEvents()
        actions = [pane.act_save, pane.act_open, pane.act_compare, pane.act_rename, pane.act_duplicate,
                   pane.act_delete, pane.act_undo, pane.act_redo, pane.act_import, pane.act_import_folder,
                   pane.act_export, pane.act_export_all]
        assert [a.text() for a in actions if not reachable(pane, a)] == []
    finally:
        i18n.set_language("en")


def test_an_entry_too_fine_for_a_design_file_is_compared(pane, model, no_dialogs):
    """An entry stored before the design file's sample limit was refused by Compare (the
    stored step does not enter a comparison; hunt, 1 December): it is a candidate now,
    and Open still refuses it (it would load that step)."""
    import json
    import sqlite3
    save(pane, model, "fine")
    save(pane, model, "coarse", time_ratio=1.6)
    with sqlite3.connect(pane.actions.library.path) as c:
        entry_id, text = c.execute("SELECT d.entry_id, d.text FROM documents d JOIN entries e ON e.id = d.entry_id "
                                   "WHERE e.name = 'fine'").fetchone()
        doc = dict(json.loads(text), step_deg=0.0002)                   # 1.8 million angles × the speeds
        c.execute("UPDATE documents SET text = ? WHERE entry_id = ?", (json.dumps(doc), entry_id))
    c.close()
    assert [c.label for c in pane.actions.candidates(["fine", "coarse"])] == ["fine", "coarse"]
    assert no_dialogs == []
    assert not pane.actions.open_in_model("fine")
