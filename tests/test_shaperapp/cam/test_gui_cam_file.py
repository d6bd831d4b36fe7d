"""Open then Save gives back the file's cam, also when that cam cannot be made against the
file's linkage (the Cam tab shows why): the user's inputs are theirs to mend, never lost."""
from __future__ import annotations

import json

import pytest
from PySide6.QtCore import QSettings

from core.files.io import design_document
from core.linkage.spec import Spec
from shaperapp.cam.model import CamModel
from shaperapp.design.document import Document

GOOD = {"arm_mm": 100.0, "swing_deg": 20.0, "rise_deg": 60.0, "dwell_deg": 10.0, "return_deg": 60.0,
        "pressure_deg": 40.0}
FEEDS_IN_THE_CUT = {**GOOD, "arm_mm": 110.0, "swing_deg": 18.0, "phase_deg": 90.0}


def _file(tmp_path, name, cam):
    path = tmp_path / name
    path.write_text(json.dumps({**design_document(Spec(), [40.0], 1.0), "cam": cam}), encoding="utf-8")
    return str(path)


@pytest.mark.parametrize("made_first", [True, False])
def test_a_cam_the_linkage_refuses_is_saved_as_opened(qtbot, model, tmp_path, made_first):
    """Opening a file whose cam feeds during the cut (phase 90°) showed the error, and Save
    wrote the cam the model last computed instead: the default (arm 120, swing 15), or the
    cam of the file opened before (hunt s13-hunt2). ``made_first``: the Cam tab's model made
    before the file is opened, or (the tab never shown) only when Save asks for the cam."""
    document = Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    cams = []
    if made_first:
        cams.append(CamModel(model))
        assert document.open_path(_file(tmp_path, "good.json", GOOD))
    assert document.open_path(_file(tmp_path, "bad.json", FEEDS_IN_THE_CUT))
    if not made_first:
        cams.append(CamModel(model))
    assert "feeds during the cut" in str(cams[0].error)
    target = tmp_path / "saved.json"
    assert document.save_to(str(target))
    saved = json.loads(target.read_text(encoding="utf-8"))["cam"]
    assert {k: saved[k] for k in FEEDS_IN_THE_CUT} == FEEDS_IN_THE_CUT


def test_a_cam_export_after_opening_a_refused_cam_writes_nothing(qtbot, model, tmp_path, monkeypatch):
    """After a file whose cam its linkage refuses, the tab still draws the cam of the file
    opened before; the CSV button offered to export it ("the last valid cam stays on
    screen") as if it were this design's. Now it says nothing was exported (hunt s13-hunt2)."""
    from PySide6.QtWidgets import QMessageBox
    from shaperapp.cam.tab import CamTab
    from shaperapp.widgets import file_dialogs
    document = Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    cam = CamModel(model)
    tab = CamTab(model, cam_model=cam)
    qtbot.addWidget(tab)
    path = tmp_path / "cam.csv"
    monkeypatch.setattr(file_dialogs, "save_file_and_filter", lambda *a, **k: (str(path), ""))
    said: list[str] = []
    monkeypatch.setattr(QMessageBox, "question", lambda *a, **k: said.append(a[2]) or QMessageBox.StandardButton.Yes)
    monkeypatch.setattr(QMessageBox, "warning", lambda *a, **k: said.append(a[2]))
    assert document.open_path(_file(tmp_path, "good.json", GOOD))
    tab._export_dialog("csv")
    assert path.exists() and said == []
    path.unlink()
    assert document.open_path(_file(tmp_path, "bad.json", FEEDS_IN_THE_CUT))
    tab._export_dialog("csv")
    assert not path.exists() and len(said) == 1 and "Nothing was exported" in said[0]
    cam.set_fields(phase="")             # mended in the tab: this design's cam, exported
    assert cam.error is None
    tab._export_dialog("csv")
    assert path.exists()


def _cam_pixels(view) -> int:
    """How many pixels of the view are the cam's fill (the profile drawn)."""
    from PySide6.QtGui import QColor
    from shaperapp.cam.profile_view import CAM_FILL
    image = view.grab().toImage()
    fill = QColor(CAM_FILL).rgb()
    return sum(image.pixel(x, y) == fill for x in range(0, image.width(), 3) for y in range(0, image.height(), 3))


def test_the_cam_tab_shows_no_cam_of_another_design(qtbot, model, tmp_path):
    """After a file whose cam its linkage refuses, the Cam tab drew the cam of the file opened
    before, with its figures and plots, under "The last valid cam stays on screen" (hunt
    s13-hunt2). Now the drawing and the form say why there is no cam, and no figure, curve or
    axis of the other design is shown; mending the field, or opening a good file, shows it."""
    from shaperapp.cam.tab import CamTab
    document = Document(model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    cam = CamModel(model)
    tab = CamTab(model, cam_model=cam)
    qtbot.addWidget(tab)
    tab.resize(1100, 700)
    tab.show()
    qtbot.waitExposed(tab)
    good, bad = _file(tmp_path, "good.json", GOOD), _file(tmp_path, "bad.json", FEEDS_IN_THE_CUT)

    def shown() -> tuple[int, str, bool, str]:
        return (_cam_pixels(tab.profile), tab.figures.text(), tab.plots._inner.isVisible(),
                tab.form.error_label.text())

    assert document.open_path(good)
    pixels, figures, plots, said = shown()
    assert pixels > 100 and "Base radius" in figures and plots and said == ""
    assert document.open_path(bad)
    pixels, figures, plots, said = shown()
    assert pixels == 0 and figures == "" and not plots
    assert "feeds during the cut" in said and "cannot be made" in said and "last valid" not in said
    assert document.open_path(good)             # the same cam as before: no new value, shown again
    assert shown()[0] > 100 and shown()[2]
    cam.set_fields(phase=90.0)                  # refused while this design's cam stays on screen
    pixels, figures, plots, said = shown()
    assert pixels > 100 and "Base radius" in figures and "last valid cam stays" in said
    assert document.open_path(bad)              # the same refusal's text, now no cam of this design
    pixels, figures, plots, said = shown()
    assert pixels == 0 and figures == "" and not plots and "last valid" not in said
    cam.set_fields(phase="")                    # mended: this design's cam
    pixels, figures, plots, said = shown()
    assert pixels > 100 and "Base radius" in figures and plots and said == ""
