"""Issue 7: a fixed-seed run of a few thousand random user actions on the whole window.

Random text goes into every field (design, speeds, step, loads), every choice is
switched, speeds are added and removed, the animation is played and stepped, maps and
optimizations are started, cancelled and clicked on the Explore tab (its worker runs on), the
language switched, edits undone and redone, images and CSV exported to tmp_path,
good and hostile files opened, the design saved; the Cam and Gear tabs typed into, their
choices switched and their exports clicked; the library pane's actions run on a library in
tmp_path (save, open, compare, rename, duplicate, delete, undo, redo, import, export).
Dialogs answer at random. No exception may
reach ``sys.excepthook``; after every action what Save would write is valid, the window
never holds more samples than it redraws in half a second, a part's error is what its
typed fields give, the pair a valid Gear tab shows is its typed fields' and the Gear tab
on screen shows that pair in its tables and greyed fields (the Gear tab's fields follow
the pair its tables show, issue 40 item 1), and the library pane lists the library's
designs; at the end the library has no damaged entry.
"""
import json
import os
import random
import sys
import time

import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QApplication, QDialog, QFileDialog, QInputDialog, QMessageBox

from core.cam import design_cam
from core.files.io import load_design
from core.library import Library
from core.linkage.spec import NUMBER_FIELDS
from shaperapp.design.model import DesignModel
from shaperapp.cam.model import cam_inputs
from shaperapp.cam.tab import CamTab
from shaperapp.gear.model import check_part
from shaperapp.gear.tab import GearTab
from shaperapp.library.dialogs import SaveDialog
from core.linkage.limits import MAX_FILE_SAMPLES
from shaperapp.widgets import file_dialogs
from shaperapp.widgets import i18n
from shaperapp.window.main_window import MainWindow

from gear_checks import assert_fields_follow, assert_table_is
from hostile_files import VALID, build_case
from sweeps import examples

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

SEED = int(os.environ.get("SHAPER_GUI_FUZZ_SEED", "20240611"))
# 2000 actions took 9.5-12 s on the 2-core machine (ten runs, 24 Nov 2026), 58 s in the suite
# of 29 Nov (its longest test), and 20000 took 210 s beside a busy loop. A slow random sweep:
# CI draws a share of the 2000 (tests/sweeps.py), HYPOTHESIS_PROFILE=thorough all of them, and
# SHAPER_GUI_FUZZ_ACTIONS runs any number (e.g. 20000 before a release).
ACTIONS = int(os.environ.get("SHAPER_GUI_FUZZ_ACTIONS", str(examples(2000))))
DESIGN_FIELDS = ("crank", "time_ratio", "stroke", "frame", "lever", "guide_height", "rod_length", "rod_ratio", "step")
LOAD_FIELDS = ("lever_mass_kg", "lever_cg_mm", "lever_inertia_kg_m2", "ram_mass_kg", "ram_cg_dx", "ram_cg_dy",
               "rod_mass_kg", "block_mass_kg", "cut_force_N", "cut_height_mm", "idle_percent", "delta")
GARBAGE = ("", " ", "abc", "ጼ", "nan", "inf", "-inf", "1e999", "1e-320", "5e-324", "-0", "0", "1,5", "1/30",
           "1/0", "0x1F", "--3", "1e308", "١٢٣", "∞", "1.2.3", "1e", "+", "NaN", "3 4", "\t7")
HOSTILE = ("fifo", "link_to_dev_zero", "folder", "version_true", "spec_missing", "rpm_strings", "deep_arrays",
           "int_400_digits", "nan", "bad_utf8", "sparse_5_GB", "rpm_denormal", "inactive_frame_text")


def random_text(rng: random.Random, default: float) -> str:
    roll = rng.random()
    if roll < 0.55:
        return f"{default * rng.uniform(0.5, 2.0):.{rng.randint(1, 8)}g}"
    if roll < 0.8:
        return rng.choice(GARBAGE)
    if roll < 0.9:
        return f"{rng.uniform(-1e6, 1e6):g}"
    return "".join(rng.choice("0123456789.-e,/ xé") for _ in range(rng.randint(1, 6)))


class Fuzzer:
    def __init__(self, window: MainWindow, rng: random.Random, folder) -> None:
        self.w, self.rng, self.folder = window, rng, folder
        self.files = self._files()
        self.counts: dict[str, int] = {}
        self.seconds: dict[str, float] = {}

    def _files(self) -> list[str]:
        good = self.folder / "good.shaper.json"
        good.write_text(json.dumps(dict(VALID, rpm=[30.0, 50.0, 70.0], step_deg=2.0)))
        paths = [str(good)]
        for name in HOSTILE:
            paths.append(str(build_case(name, self.folder)))
        return paths

    def save_name(self) -> str:
        rng, f = self.rng, self.folder
        return rng.choice([str(f / "out.png"), str(f / "out.svg"), str(f / "out.csv"), str(f / "d.shaper.json"),
                           str(f / "missing" / "out.png"), str(f / "out.xyz"), str(f / "noext"), ""])

    # ---- actions -------------------------------------------------------
    def type_design(self) -> None:
        name = self.rng.choice(DESIGN_FIELDS)
        edit = self.w.form.field(name)
        default = {"time_ratio": 1.4, "rod_ratio": 0.3, "step": 1.0}.get(name, 300.0)
        text = random_text(self.rng, default)
        if name == "step" and self.rng.random() < 0.7:
            text = self.rng.choice(("1", "2", "5", "0.5", "0.05", "0.001", "0.0002", "45", text))
        edit.setFocus()
        edit.setText(text)
        edit.textEdited.emit(text)
        edit.editingFinished.emit()

    def type_load(self) -> None:
        name = self.rng.choice(LOAD_FIELDS)
        edit = self.w.loads.field(name)
        text = random_text(self.rng, {"delta": 0.0333, "idle_percent": 5.0}.get(name, 50.0))
        edit.setText(text)
        edit.textEdited.emit(text)
        edit.editingFinished.emit()

    def choice(self) -> None:
        form = self.w.form
        pick = self.rng.randrange(6)
        if pick == 0:
            self.rng.choice((form._synth_radio, form._dims_radio)).click()
        elif pick == 1:
            self.w.loads.gravity_box().click()
        else:
            combo = form._combo(("variant", "guide_rule", "rod_input", "rod_side")[pick - 2])
            combo.setCurrentIndex(self.rng.randrange(combo.count()))

    def speeds(self) -> None:
        form, rng = self.w.form, self.rng
        pick = rng.randrange(4)
        if pick == 0:
            form._add_speed.click()
        elif pick == 1:
            form._speeds.setCurrentRow(rng.randrange(form._speeds.count()))
            form._remove_speed.click()
        else:
            row = rng.randrange(form._speeds.count())
            form._speeds.item(row).setText(random_text(rng, 60.0))

    def animation(self) -> None:
        w, rng = self.w, self.rng
        pick = rng.randrange(6)
        if pick == 0:
            w.act_play.trigger()
        elif pick == 1:
            w.act_step.trigger()
        elif pick == 2:
            w.act_back.trigger()
        elif pick == 3:
            w.act_goto.trigger()
        elif pick == 4:
            w.model.set_angle_index(rng.randrange(10_000))
        else:
            w.form.field("crank").setFocus()
            key = rng.choice((Qt.Key.Key_Left, Qt.Key.Key_Right, Qt.Key.Key_Space))
            mods = Qt.KeyboardModifier.ControlModifier if key != Qt.Key.Key_Space else Qt.KeyboardModifier.NoModifier
            focus = QApplication.focusWidget() or w
            from pytestqt.qtbot import QtBot
            QtBot.keyClick(focus, key, mods)

    def view(self) -> None:
        w, rng = self.w, self.rng
        rng.choice((w.act_fit, w.act_dims, w.act_forces)).trigger()
        w.scheme.set_force_speed(rng.randrange(len(w.model.rpms)))
        w.tabs.setCurrentIndex(rng.randrange(w.tabs.count()))

    def explore(self) -> None:
        """The Explore tab: maps and optimizations run on the worker while the fuzz goes on."""
        view, rng = self.w.explore, self.rng
        pick = rng.randrange(6)
        if pick == 0:
            view.count.setValue(rng.choice((3, 8, 20, 60)))
            view.compute.click()
        elif pick == 1:
            view.box.optimize.click()
        elif pick == 2:
            view.cancel.click()
        elif pick == 3:
            combo = rng.choice((view.figure, *view.axis_names, view.box.objective))
            combo.setCurrentIndex(rng.randrange(combo.count()))
        elif pick == 4 and view.result is not None:
            view._clicked(rng.randrange(view.result.y.size), rng.randrange(view.result.x.size))
        else:
            self.w.tabs.setCurrentWidget(view)

    def part(self) -> None:
        """The Cam or the Gear tab: a field typed (the typed value scaled, or garbage), a
        choice switched (the gear's module typed), or one of its exports clicked."""
        w, rng = self.w, self.rng
        tab, part = (w.cam, w.cam_model) if rng.random() < 0.5 else (w.gear, w.gear_model)
        if rng.random() < 0.6:                  # mostly typed on screen, where its checks look
            w.tabs.setCurrentWidget(tab)
        form, pick = tab.form, rng.random()
        if pick < 0.7:
            name = rng.choice(list(form.fields))
            edit = form.fields[name].edit
            if not edit.isEnabled():            # a gear shift its mode derives
                return
            typed = part.typed.dict[name]
            if rng.random() < 0.7:                  # near what is typed: mostly a part it can make
                text = (str(rng.randint(8, 60)) if name in ("z1", "z2") else
                        f"{(typed if isinstance(typed, (int, float)) and typed else 10.0) * rng.uniform(0.8, 1.25):.4g}")
            else:
                text = random_text(rng, typed if isinstance(typed, (int, float)) and typed else 10.0)
            edit.setFocus()
            edit.setText(text)
            edit.textEdited.emit(text)
            edit.editingFinished.emit()
            if rng.random() < 0.7:              # the typing pause ends (else a later action's turn)
                form.commit()
        elif pick < 0.9:
            combo = rng.choice(list(form.combos.values()))
            if combo.isEditable() and rng.random() < 0.5:
                text = random_text(rng, 6.0)
                combo.setEditText(text)
                combo.lineEdit().textEdited.emit(text)
                form.commit()
            else:
                index = rng.randrange(combo.count())
                combo.setCurrentIndex(index)
                combo.activated.emit(index)
        else:
            tab.buttons[rng.choice(list(tab.buttons))].click()

    def library(self) -> None:
        """The library pane: some rows selected, then one of its actions (those enabled)."""
        pane, rng = self.w.library, self.rng
        names = pane.actions.library.names() if pane.actions.library is not None else []
        if names and rng.random() < 0.7:
            pane.select_names(rng.sample(names, rng.randint(1, min(3, len(names)))))
        action = rng.choice((pane.act_save, pane.act_save, pane.act_open, pane.act_compare, pane.act_rename,
                             pane.act_duplicate, pane.act_delete, pane.act_undo, pane.act_redo,
                             pane.act_import, pane.act_export, pane.act_export_all))
        if action.isEnabled():
            action.trigger()

    def undo_redo(self) -> None:
        (self.w.act_undo if self.rng.random() < 0.6 else self.w.act_redo).trigger()

    def language(self) -> None:
        self.w.lang_actions[self.rng.choice(("en", "zh_CN"))].trigger()

    def export(self) -> None:
        w = self.w
        self.rng.choice((w.act_csv, w.act_forces_csv, w.act_plots_img, w.act_scheme_img)).trigger()

    def files_action(self) -> None:
        w = self.w
        self.rng.choice((w.act_open, w.act_open, w.act_save, w.act_save_as, w.act_new)).trigger()

    def run(self, count: int) -> float:
        table = [(self.type_design, 30), (self.type_load, 12), (self.choice, 14), (self.speeds, 8),
                 (self.animation, 14), (self.view, 4), (self.undo_redo, 10), (self.language, 1),
                 (self.export, 3), (self.files_action, 4), (self.explore, 3), (self.part, 25),
                 (self.library, 10)]
        actions, weights = zip(*table)
        slowest = 0.0
        for _ in range(count):
            action = self.rng.choices(actions, weights)[0]
            self.counts[action.__name__] = self.counts.get(action.__name__, 0) + 1
            start = time.perf_counter()
            action()
            QApplication.processEvents()
            took = time.perf_counter() - start
            self.seconds[action.__name__] = self.seconds.get(action.__name__, 0.0) + took
            slowest = max(slowest, took)
            self.check()
        return slowest

    def check(self) -> None:
        model = self.w.model
        model.valid_spec.check_fields()
        for name in set(NUMBER_FIELDS) - model.spec.active_fields():
            model.spec.check_field(name)
        assert model.angle_count * len(model.rpms) <= MAX_FILE_SAMPLES
        for name in ("cam", "gear"):
            if self.w._part_models[name].made():
                self.check_part(name)
        pane = self.w.library
        if pane.actions.library is not None:
            table = pane.table_model
            assert sorted(table.name_at(r) for r in range(table.rowCount())) == sorted(pane.actions.library.names())

    def check_part(self, name: str) -> None:
        """A part's error is its typed fields' (with the linkage on screen); a gear pair made
        from this design's fields is the last valid typed fields' pair, and the Gear tab on
        screen shows it. (A hidden Cam tab's cam waits for the tab after a linkage edit: its
        error is compared while the tab is on screen.)"""
        part = self.w._part_models[name].model
        if name == "cam" and not isinstance(self.w.tabs.currentWidget(), CamTab):
            return
        try:
            if name == "cam":       # core's cam, as CamModel.compute asks it (which keeps the refusal's advice)
                inputs, phase = cam_inputs(part.typed)
                model = self.w.model
                design_cam(inputs, model.design, model.masses.idle_fraction, phase, advice_later=True)
            else:
                part.compute(part.typed)
            refused = None
        except Exception as exc:                # noqa: BLE001 - whatever the model catches
            refused = exc
        assert (refused is None) == (part.error is None), (name, refused, part.error)
        if name != "gear" or not part.own_value:
            return
        if part.error is None:
            assert part.pair == part.compute(part.typed)
        tab = self.w.tabs.currentWidget()
        if isinstance(tab, GearTab) and not any(n in tab.form.pending for n in (*tab.form.fields, "module")):
            assert_table_is(tab, part.pair)
            assert_fields_follow(tab, part.pair)


@pytest.fixture
def patched_dialogs(monkeypatch, tmp_path):
    """Every modal dialog answers at once, at random (the seed makes it repeatable)."""
    rng = random.Random(SEED + 1)
    state = {}

    def ask(*args, **kwargs):
        return rng.choice((QMessageBox.StandardButton.Yes, QMessageBox.StandardButton.Cancel,
                           QMessageBox.StandardButton.Save, QMessageBox.StandardButton.Discard))

    for name in ("warning", "critical", "information"):
        monkeypatch.setattr(QMessageBox, name, lambda *a, **k: QMessageBox.StandardButton.Ok)
    monkeypatch.setattr(QMessageBox, "question", ask)
    monkeypatch.setattr(QMessageBox, "about", lambda *a, **k: None)
    monkeypatch.setattr(file_dialogs, "save_file_name", lambda *a, **k: state["fuzzer"].save_name())
    def save_with_filter(parent, title, start, filters, selected=""):
        path = state["fuzzer"].save_name()
        return path, rng.choice(filters.split(";;")) if path else ""

    monkeypatch.setattr(file_dialogs, "save_file_and_filter", save_with_filter)
    monkeypatch.setattr(file_dialogs, "open_file_name", lambda *a, **k: rng.choice(state["fuzzer"].files + [""]))
    monkeypatch.setattr(QInputDialog, "getDouble", lambda *a, **k: (rng.uniform(-10, 370), rng.random() < 0.8))
    # the library pane's: a name (some refused: empty, a slash, 200 characters), files, folders
    names = ("a", "b", "seed 003", "长名字" * 3, " x ", "a/b", "", "d" * 200)
    folders = (str(tmp_path), "", str(tmp_path / "missing"))

    def save_dialog_exec(dialog):
        dialog.name_edit.setText(rng.choice(names))
        dialog.notes_edit.setPlainText(rng.choice(("", "note", "x" * 5000)))
        dialog.tags_edit.setText(rng.choice(("", "final, rod", ",,,", "a,a")))
        return rng.choice((QDialog.DialogCode.Accepted, QDialog.DialogCode.Accepted, QDialog.DialogCode.Rejected))

    monkeypatch.setattr(SaveDialog, "exec", save_dialog_exec)
    monkeypatch.setattr(QInputDialog, "getText", lambda *a, **k: (rng.choice(names), rng.random() < 0.8))
    monkeypatch.setattr(QFileDialog, "getOpenFileNames",
                        lambda *a, **k: (rng.sample(state["fuzzer"].files, rng.randint(0, 3)), ""))
    monkeypatch.setattr(QFileDialog, "getExistingDirectory", lambda *a, **k: rng.choice(folders))
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (state["fuzzer"].save_name(), ""))
    monkeypatch.setenv("SHAPER_LIBRARY", str(tmp_path / "library.sqlite"))
    return state


def test_random_user_actions_raise_nothing(qtbot, tmp_path, monkeypatch, patched_dialogs):
    caught = []
    monkeypatch.setattr(sys, "excepthook", lambda kind, value, tb: caught.append((kind, value)))
    settings = QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat)
    window = MainWindow(DesignModel(), settings)
    qtbot.addWidget(window)
    window.resize(1100, 700)
    window.show()
    qtbot.waitExposed(window)
    fuzzer = Fuzzer(window, random.Random(SEED), tmp_path)
    patched_dialogs["fuzzer"] = fuzzer
    window.library.open_library(None)            # $SHAPER_LIBRARY: tmp_path's
    start = time.perf_counter()
    try:
        slowest = fuzzer.run(ACTIONS)
        assert window.explore.runner.wait(30_000)           # the last map or optimization ended
    finally:
        window.animation.play_action.setChecked(False)
        i18n.set_language("en")
    elapsed = time.perf_counter() - start
    assert caught == [], caught[:3]
    assert sum(fuzzer.counts.values()) == ACTIONS and len(fuzzer.counts) == 13
    print(f"\nGUI fuzz: {ACTIONS} actions in {elapsed:.1f} s, slowest {slowest:.2f} s; {fuzzer.counts}; "
          f"seconds {({k: round(v, 1) for k, v in fuzzer.seconds.items()})}")
    # What is on screen still saves and reopens.
    window.model.revert_invalid()
    path = tmp_path / "final.shaper.json"
    assert window.document.save_to(str(path))
    with Library(tmp_path / "library.sqlite") as library:
        assert library.damaged() == []
    saved = load_design(path)
    assert saved["spec"] == window.model.valid_spec
    if window._part_models["gear"].made() and window.gear_model.own_value:
        assert check_part(saved["gear"]) == window.gear_model.pair
    window.model.set_clean(window.model.path)
