"""Crafted library contents in the Library pane: no crash, damaged rows marked, the rest usable.

An attacker (or a broken disk) can put any value in any column of the SQLite file:
a blob in a REAL column once ended the GUI with SIGSEGV in ``resizeColumnsToContents``
(the table model raised inside ``data()``). Each case runs in a subprocess, so a crash
fails the test instead of ending the test run.
"""
import sqlite3
import subprocess
import sys
import textwrap

import pytest

from core.library import Library
from core.linkage.spec import Spec

CASES = {
    "blob in a REAL column": "UPDATE entries SET theta_deg = X'00ff' WHERE name = 'a'",
    "text in a REAL column": "UPDATE entries SET K = 'abc' WHERE name = 'a'",
    "infinite figure": "UPDATE entries SET K = 1e999 WHERE name = 'a'",
    "blob as a name": "UPDATE entries SET name = X'00ff' WHERE name = 'a'",
    "blob in a speed": "UPDATE speeds SET a_max_m_s2 = X'01' "
                      "WHERE entry_id = (SELECT id FROM entries WHERE name = 'a')",
    "blob as notes": "UPDATE entries SET notes = X'00', modified = X'01' WHERE name = 'a'",
    "bad UTF-8 text": "UPDATE entries SET notes = CAST(X'ff80' AS TEXT) WHERE name = 'a'",
}

SCRIPT = textwrap.dedent("""
    import sys
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QApplication
    from shaperapp.library.pane import LibraryPane
    from shaperapp.design.model import DesignModel
    app = QApplication([])
    pane = LibraryPane(DesignModel(), settings=QSettings(sys.argv[2], QSettings.Format.IniFormat))
    pane.resize(1200, 400)
    pane.show()
    assert pane.open_library(sys.argv[1])
    app.processEvents()
    model = pane.table_model
    shown = [[model.data(model.index(r, c)) for c in range(model.columnCount())]
             for r in range(model.rowCount())]
    print(model.rowCount(), sum(model.damaged_at(r) for r in range(model.rowCount())))
    print(repr(shown))
""")


def make_library(path):
    with Library(path) as lib:
        for name in ("a", "b"):
            lib.add(name, {"spec": Spec(), "rpm": [40.0], "step_deg": 1.0, "masses": None})


@pytest.mark.parametrize("sql", CASES.values(), ids=list(CASES))
def test_crafted_value_neither_crashes_nor_hides_the_other_rows(tmp_path, sql):
    path = tmp_path / "lib.sqlite"
    make_library(path)
    with sqlite3.connect(path) as conn:
        conn.execute(sql)
    done = subprocess.run([sys.executable, "-c", SCRIPT, str(path), str(tmp_path / "s.ini")],
                          capture_output=True, text=True, timeout=120,
                          env={**__import__("os").environ, "QT_QPA_PLATFORM": "offscreen",
                               "SHAPER_LIBRARY": str(tmp_path / "default.sqlite")})
    assert done.returncode == 0, done.stderr[-2000:]
    assert "Traceback" not in done.stderr
    first, shown = done.stdout.splitlines()[:2]
    assert first == "2 1"                      # both rows listed, one marked damaged
    assert "inf" not in shown
    assert "'b'" in shown                      # the good row is shown as it is


def test_damaged_row_is_marked_in_the_pane(qtbot, tmp_path, monkeypatch):
    """In process (pytest-qt): the damaged row says why on hover; the good one opens."""
    from PySide6.QtCore import QSettings, Qt
    from PySide6.QtWidgets import QMessageBox
    from shaperapp.library.pane import LibraryPane
    from shaperapp.library.table import COLUMNS
    from shaperapp.design.model import DesignModel
    monkeypatch.setenv("SHAPER_LIBRARY", str(tmp_path / "default.sqlite"))
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: None)
    path = tmp_path / "lib.sqlite"
    make_library(path)
    with sqlite3.connect(path) as conn:
        conn.execute(CASES["blob in a REAL column"])
    model = DesignModel()
    pane = LibraryPane(model, settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    qtbot.addWidget(pane)
    assert pane.open_library(str(path))
    pane.show()
    table = pane.table_model
    assert [table.damaged_at(r) for r in range(2)] == [True, False]
    theta = table.data(table.index(0, COLUMNS.index("theta_deg")))
    assert theta == "—"
    tip = table.data(table.index(0, COLUMNS.index("theta_deg")), Qt.ItemDataRole.ToolTipRole)
    assert "theta_deg is not a number" in tip
    failures = []
    pane.actions.failed.connect(failures.append)
    assert not pane.actions.open_in_model("a") and "damaged" in failures[0]
    assert pane.actions.open_in_model("b")


def test_read_only_library_in_the_pane(qtbot, tmp_path, monkeypatch):
    """A read-only library is listed with the reason; the actions that change it are off,
    and a change tried anyway is refused with a message, the file unchanged."""
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QMessageBox
    from core.library import open as library_open
    from shaperapp.library.pane import LibraryPane
    from shaperapp.design.model import DesignModel
    monkeypatch.setenv("SHAPER_LIBRARY", str(tmp_path / "default.sqlite"))
    shown = []
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: shown.append(a[2]))
    path = tmp_path / "lib.sqlite"
    make_library(path)
    before = path.read_bytes()
    monkeypatch.setattr(library_open, "unwritable", lambda p: "simulated: root is not stopped by modes")
    pane = LibraryPane(DesignModel(), settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    qtbot.addWidget(pane)
    assert pane.open_library(str(path))
    pane.show()
    assert "read-only: simulated" in pane.path_label.text()
    pane.select_names(["a"])
    assert not pane.act_save.isEnabled() and not pane.act_delete.isEnabled() and pane.act_open.isEnabled()
    assert not pane.actions.delete(["a"])
    assert shown and "can only be read" in shown[-1]
    assert pane.actions.library.names() == ["a", "b"] and path.read_bytes() == before


def test_library_with_a_trigger_is_refused_in_the_pane(qtbot, model, tmp_path, monkeypatch):
    """Issue 33 item 2: a trigger another program added (it deleted every other design on
    the next save) makes the pane refuse the file, unchanged, and say what was added."""
    import hashlib
    import sqlite3

    from shaperapp.library import pane as library_pane
    from shaperapp.library.pane import LibraryPane

    path = tmp_path / "L.sqlite"
    with Library(path) as lib:
        for name in ("a", "b", "c"):
            lib.add(name, {"spec": Spec(), "rpm": [40.0], "step_deg": 1.0, "masses": None})
    conn = sqlite3.connect(path)
    conn.execute("PRAGMA journal_mode = DELETE")
    conn.execute("CREATE TRIGGER t AFTER INSERT ON entries BEGIN DELETE FROM entries WHERE id != NEW.id; END")
    conn.commit()
    conn.close()
    before = hashlib.sha256(path.read_bytes()).hexdigest()
    messages = []
    monkeypatch.setattr(library_pane, "ask_refused_library",
                        lambda parent, message: messages.append(message) or "cancel")
    widget = LibraryPane(model)
    qtbot.addWidget(widget)
    assert not widget.open_library(str(path))
    assert widget.actions.library is None
    assert len(messages) == 1 and "trigger t on entries" in messages[0] and "unchanged" in messages[0]
    assert hashlib.sha256(path.read_bytes()).hexdigest() == before


@pytest.mark.parametrize("case", ["text in a REAL column", "infinite figure", "blob in a speed",
                                  "blob as notes", "no document"])
def test_why_a_row_is_damaged_is_said_in_chinese(qtbot, tmp_path, monkeypatch, case):
    """Issue 32 item 4: the reason on hover and in the refusal was core's English
    ("K is not a number", "speeds: a_max_m_s2 is not a number") in the Chinese pane. Only
    the column's key (an identifier of the file format, as in JSON) stays as it is."""
    from PySide6.QtCore import QSettings, Qt
    from PySide6.QtWidgets import QMessageBox
    from shaperapp.library.pane import LibraryPane
    from shaperapp.library.table import COLUMNS
    from shaperapp.design.model import DesignModel
    from shaperapp.widgets import i18n
    from language_checks import assert_chinese_text
    monkeypatch.setenv("SHAPER_LIBRARY", str(tmp_path / "default.sqlite"))
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: None)
    path = tmp_path / "lib.sqlite"
    make_library(path)
    sql = "DELETE FROM documents WHERE entry_id = (SELECT id FROM entries WHERE name = 'a')" \
        if case == "no document" else CASES[case]
    with sqlite3.connect(path) as conn:
        conn.execute(sql)
    assert i18n.set_language("zh_CN")
    try:
        pane = LibraryPane(DesignModel(), settings=QSettings(str(tmp_path / "s.ini"),
                                                             QSettings.Format.IniFormat))
        qtbot.addWidget(pane)
        assert pane.open_library(str(path))
        table = pane.table_model
        rows = [r for r in range(table.rowCount()) if table.damaged_at(r)]   # the list reads no document
        tips = [table.data(table.index(r, COLUMNS.index("K")), Qt.ItemDataRole.ToolTipRole) for r in rows]
        failures = []
        pane.actions.failed.connect(failures.append)
        assert not pane.actions.open_in_model("a")
    finally:
        i18n.set_language("en")
    keys = {"K", "a_max_m_s2", "notes", "shaper", "library", "check"}   # the key and the command named
    assert len(tips) == (case != "no document")
    for text in (*tips, failures[0]):
        assert_chinese_text(text, keys, what=case)


def test_an_entry_stored_before_the_sample_limit_says_it_is_too_fine(qtbot, tmp_path, monkeypatch):
    """An entry whose step gives more samples than a design file holds (stored before the
    limit): Open says it is too fine, its samples, and the command's step that exports it
    (``shaper library export --step``, tests/test_core/cli/test_cli_library_too_fine.py),
    not the design file's "use a step of at least …", which no field of the pane takes."""
    import json

    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QMessageBox
    from shaperapp.library.pane import LibraryPane
    from shaperapp.design.model import DesignModel
    monkeypatch.setenv("SHAPER_LIBRARY", str(tmp_path / "default.sqlite"))
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: None)
    path = tmp_path / "lib.sqlite"
    make_library(path)
    with sqlite3.connect(path) as conn:
        entry_id, text = conn.execute("SELECT d.entry_id, d.text FROM documents d JOIN entries e "
                                      "ON e.id = d.entry_id WHERE e.name = 'a'").fetchone()
        doc = json.loads(text)
        doc["step_deg"] = 0.005                     # 72 001 angles at one speed
        conn.execute("UPDATE documents SET text = ? WHERE entry_id = ?", (json.dumps(doc), entry_id))
    pane = LibraryPane(DesignModel(), settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    qtbot.addWidget(pane)
    assert pane.open_library(str(path))
    failures = []
    pane.actions.failed.connect(failures.append)
    assert not pane.actions.open_in_model("a")
    assert "too fine: 72001 samples, limit 60000" in failures[0] and "--step 0.00601" in failures[0], failures
    assert not pane.actions.export("a", str(tmp_path / "a.shaper.json"))         # Export says the same
    assert "too fine: 72001 samples" in failures[1] and not (tmp_path / "a.shaper.json").exists(), failures
    assert pane.actions.export_all(str(tmp_path / "all"))                          # the others go out
    assert "not exported" in failures[2] and "a: too fine" in failures[2] and "damaged" not in failures[2]
    assert pane.actions.open_in_model("b")
