"""Opening is all or nothing: every hostile file is refused through the open action,
the design on screen stays exactly as it was, and the next Save writes that design."""
import json

import pytest
from PySide6.QtCore import QSettings

from core.base.errors import FileFormatError
from core.files.io import load_design
from core.linkage.limits import MAX_FILE_SAMPLES
from shaperapp.design.document import Document
from shaperapp.design.model import DesignModel
from shaperapp.window.main_window import MainWindow

from gui_helpers import main_window
from hostile_files import CASES, VALID, build_case


@pytest.fixture(scope="module")
def window(qapp, tmp_path_factory):
    # The window shows each failure in a modal box; here the message is read from the signal.
    mp = pytest.MonkeyPatch()
    mp.setattr(MainWindow, "_show_failure", lambda self, message: None)
    with main_window(tmp_path_factory.mktemp("hostile")) as win:
        # The mechanism pane is closed: a hidden scheme does no work per edit (issue 8 item 8),
        # and its label search after each test's edits was most of the module's time; what
        # these tests compare (the model, the title, the form, the results) is all still shown.
        win.docks["mechanism"].hide()
        yield win
    mp.undo()


def state(win: MainWindow):
    m = win.model
    return (m.spec, m.valid_spec, m.design, m.rpms, m.step_deg, m.masses, m.path, m.dirty,
            m.error, m.forces_error, m.angle_index, win.windowTitle(), win.form.field("time_ratio").text(),
            win.metrics.value_text("frame"))


def refused(win: MainWindow, path, tmp_path, qtbot) -> None:
    """Open ``path``: refused with a message, nothing changed, Save writes the old design."""
    before = state(win)
    messages = []
    win.document.failed.connect(messages.append)
    try:
        with qtbot.assertNotEmitted(win.model.resultsChanged), qtbot.assertNotEmitted(win.model.specChanged):
            assert not win.document.open_path(str(path))
    finally:
        win.document.failed.disconnect(messages.append)
    assert len(messages) == 1 and str(path) in messages[0]
    assert state(win) == before
    saved = tmp_path / "after.shaper.json"
    assert win.document.save_to(str(saved))
    doc = load_design(saved)
    assert doc["spec"] == before[1] and tuple(doc["rpm"]) == before[3] and doc["masses"] == before[5]


def edited(win: MainWindow) -> None:
    """A design on screen that differs from the defaults and from the corpus' base."""
    m = win.model
    win.document.new()
    m.set_spec(time_ratio=1.6, variant="rod", rod_ratio=0.35)
    m.set_rpms([35.0, 70.0, 90.0])
    m.set_masses(ram_mass_kg=55.0)
    m.set_angle_index(40)


@pytest.mark.parametrize("name", sorted(CASES))
def test_hostile_file_is_refused_and_nothing_changes(window, tmp_path, qtbot, name):
    edited(window)
    refused(window, build_case(name, tmp_path), tmp_path, qtbot)


def test_file_that_cannot_be_computed_in_the_window_is_refused(window, tmp_path, qtbot):
    """16 speeds at 0.0002° exceed what a design file holds, what the window computes in
    half a second: refused by core's reader, before anything changes (issue 7: a 47 s
    freeze at 9.3 GB)."""
    edited(window)
    doc = dict(VALID, rpm=[float(10 + i) for i in range(16)], step_deg=0.0002)
    path = tmp_path / "fine.shaper.json"
    path.write_text(json.dumps(doc))
    assert 16 * 360 / 0.0002 > MAX_FILE_SAMPLES
    with pytest.raises(FileFormatError, match="more than a design file holds"):
        load_design(path)
    refused(window, path, tmp_path, qtbot)


def test_failure_in_the_recomputation_changes_nothing(window, tmp_path, qtbot, monkeypatch):
    """Issue 7: a file that passes the checks but fails in the recomputation used to
    replace the inputs and keep the old design, path and title; Save then wrote the mix."""
    edited(window)
    good = tmp_path / "good.shaper.json"
    good.write_text(json.dumps(dict(VALID, rpm=[20.0])))

    def broken(*args, **kwargs):
        raise RuntimeError("the ram does not have exactly two dead points")

    monkeypatch.setattr("shaperapp.design.results.analyze", broken)
    refused(window, good, tmp_path, qtbot)
    monkeypatch.undo()
    assert window.document.open_path(str(good))
    assert window.model.rpms == (20.0,) and not window.model.dirty
    assert window.model.undo_stack.count() == 0


def test_open_resets_undo_and_new_resets_it_too(window, tmp_path):
    edited(window)
    assert window.model.undo_stack.canUndo()
    path = tmp_path / "ok.shaper.json"
    path.write_text(json.dumps(VALID))
    assert window.document.open_path(str(path))
    assert not window.model.undo_stack.canUndo() and not window.model.dirty
    window.model.set_spec(time_ratio=1.7)
    window.document.new()
    assert not window.model.undo_stack.canUndo() and not window.model.dirty


def test_document_alone_refuses_like_the_window(qtbot, tmp_path):
    model = DesignModel()
    document = Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    model.set_spec(stroke=250.0)
    before = (model.spec, model.design, model.rpms)
    assert not document.open_path(str(build_case("version_true", tmp_path)))
    assert (model.spec, model.design, model.rpms) == before
