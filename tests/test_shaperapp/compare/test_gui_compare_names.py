"""Compare's entries are named for what they are (issue 34, item 7): "Design on screen"
was a frozen snapshot under a live-sounding name. Added at K = 1.4, it still said "Design
on screen" after K became 1.6, and adding again gave "Design on screen (2)" although the
design had a file name by then. Now an entry of the screen's design is a snapshot: named
after its file or library entry while the screen shows it unchanged, else "Design on
screen" with the inputs that tell it apart and the snapshot's time."""
import re

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QMessageBox

from shaperapp.compare.view import CompareView
from shaperapp.design.document import Document
from shaperapp.library.pane import LibraryPane

SNAPSHOT = r" \(snapshot \d\d:\d\d:\d\d\)$"


@pytest.fixture
def view(qtbot, model):
    widget = CompareView(model)
    qtbot.addWidget(widget)
    return widget


def labels(view):
    return [view.list.item(i).text() for i in range(view.list.count())]


def test_issue_case_snapshot_then_file(view, model, tmp_path):
    assert view.add_current()
    first = labels(view)[0]
    assert re.fullmatch(r"Design on screen, K 1\.4" + SNAPSHOT, first), first
    model.set_spec(time_ratio=1.6)
    assert labels(view) == [first]                          # frozen, and says so
    assert view.candidates()[0].spec.time_ratio == 1.4
    document = Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    assert document.save_to(str(tmp_path / "mine.shaper.json"))
    assert view.add_current()
    assert labels(view) == [first, "mine"]
    k_row = [r.key for r in view.comparison.rows].index("K")
    assert view.table.item(k_row, 0).text().startswith("1.4")
    assert view.table.item(k_row, 1).text().startswith("1.6")
    model.set_spec(crank=90.0)                              # edited after saving
    assert view.add_current()
    third = labels(view)[2]
    assert re.fullmatch(r"mine modified, K 1\.6, L1 90 mm" + SNAPSHOT, third), third


def test_the_same_design_again_is_refused_not_named_alike(view, model):
    assert view.add_current()
    assert not view.add_current()
    assert len(view.candidates()) == 1
    assert view.hint.text().startswith("This design is already compared, as “Design on screen, K 1.4")
    model.set_spec(stroke=320.0)                            # differs in H only: H in the label
    assert view.add_current()
    first, second = labels(view)
    assert first != second and "H 320 mm" in second and "H " not in first


def test_a_library_entry_keeps_its_name(qtbot, model, tmp_path, monkeypatch):
    monkeypatch.setenv("SHAPER_LIBRARY", str(tmp_path / "default.sqlite"))
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: None)
    pane = LibraryPane(model, settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    qtbot.addWidget(pane)
    assert pane.open_library(str(tmp_path / "lib.sqlite"))
    model.set_spec(time_ratio=1.5)
    assert pane.actions.save_current("quick return", notes="", tags=[])
    model.set_spec(time_ratio=1.45)
    assert pane.actions.open_in_model("quick return")
    view = CompareView(model)
    qtbot.addWidget(view)
    assert view.add_current()
    assert labels(view) == ["quick return"]


def test_designs_that_differ_in_no_number_are_told_apart(view, model):
    model.set_spec(variant="rod", rod_ratio=0.3)
    assert view.add_current()
    model.set_spec(rod_side="leading")
    assert view.add_current()
    first, second = labels(view)
    assert re.fullmatch(r"Design on screen, K 1\.4, leading rod" + SNAPSHOT, second), second
    assert "(2)" not in second and "leading" not in first
