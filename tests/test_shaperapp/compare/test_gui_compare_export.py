"""The Compare tab's picture export with nothing to compare: refused, nothing written (as
the Explore tab refuses a map not yet computed); it drew an empty table frame below its
own canvas (issue 32, item 6)."""
import pytest

from shaperapp.compare.view import CompareView


@pytest.mark.parametrize("name", ["cmp.svg", "cmp.png"])
def test_export_image_with_nothing_to_compare_is_refused(model, qtbot, tmp_path, name):
    view = CompareView(model)
    qtbot.addWidget(view)
    assert view.comparison is None
    path = tmp_path / name
    with pytest.raises(ValueError, match="nothing to export"):
        view.export_image(str(path))
    assert list(tmp_path.iterdir()) == []


def test_one_design_is_still_nothing_to_compare(model, qtbot, tmp_path):
    view = CompareView(model)
    qtbot.addWidget(view)
    assert view.add_current() and view.comparison is None
    with pytest.raises(ValueError):
        view.export_image(str(tmp_path / "one.svg"))
    assert not (tmp_path / "one.svg").exists()


def test_the_window_shows_the_refusal_naming_the_file(model, qtbot, tmp_path, monkeypatch):
    """Through the export dialog: a message naming the file, no traceback, no file."""
    view = CompareView(model)
    qtbot.addWidget(view)
    shown = []
    monkeypatch.setattr(view, "_fail", shown.append)
    path = str(tmp_path / "cmp.svg")
    monkeypatch.setattr("shaperapp.compare.view.QFileDialog.getSaveFileName",
                        lambda *a, **k: (path, ""))
    view._export_dialog("image")
    assert len(shown) == 1 and path in shown[0] and "nothing to export" in shown[0]
    assert list(tmp_path.iterdir()) == []
