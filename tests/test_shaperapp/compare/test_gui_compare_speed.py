"""Compare's speed is the design on screen's first until the user chooses one. It was set
once, when the tab was built (the window builds it while idle, before a file is opened): two
design files at 60 r/min, opened and added, were compared at the default design's 40 r/min
while the screen and both files said 60, and `shaper library compare --file A --file B`
(the first design's first speed) printed other figures."""
from __future__ import annotations

import pytest

from cli_runner import shaper_run_in_process as shaper
from core.space.compare import Candidate
from shaperapp.compare.view import CompareView
from shaperapp.design.document import Document
from PySide6.QtCore import QSettings


def test_the_speed_follows_the_design_on_screen_until_chosen(qtbot, model, tmp_path):
    view = CompareView(model)
    qtbot.addWidget(view)
    assert view.speed.value() == model.rpms[0] == 40.0
    path = tmp_path / "a.shaper.json"
    status = shaper("design", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "60", "-o", str(path))
    assert status.returncode == 0, status.stderr
    document = Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    assert document.open_path(str(path))
    assert model.rpms == (60.0,) and view.speed.value() == 60.0
    assert view.add_file(str(path))
    assert view.add_candidate(Candidate("K 1.6", model.valid_spec.__class__(time_ratio=1.6), model.masses))
    assert view.comparison.rpm == 60.0
    view.speed.setValue(50.0)                 # the user's choice stays
    model.set_rpms([70.0])
    assert view.speed.value() == 50.0 and view.comparison.rpm == 50.0
