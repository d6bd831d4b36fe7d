"""File › Export drawing sheet…: the preview and the files written from the design on screen."""
import re
import shutil
import subprocess

import ezdxf
import pytest

from shaperapp.drawing.dialog import DrawingSheetDialog


def test_file_menu_has_the_drawing_sheet(window, qtbot):
    assert window.act_sheet in window.menu_file.actions()
    assert "drawing sheet" in window.act_sheet.text()
    window.set_language("zh_CN")
    qtbot.waitUntil(lambda: window.act_sheet.text() != "Export &drawing sheet (PDF/SVG/DXF)…", timeout=10_000)
    assert re.search(r"[\u4e00-\u9fff]", window.act_sheet.text())


def test_preview_shows_the_sheet_and_follows_the_choices(model, qtbot):
    dialog = DrawingSheetDialog(model, "en")
    qtbot.addWidget(dialog)
    first = dialog.preview.pixmap().toImage()
    assert not first.isNull()
    assert first.width() / first.height() == pytest.approx(841.0 / 594.0, rel=0.01)
    work, back = dialog.choice().diagram_deg
    assert 0 < work < model.metrics.work_angle_deg < back < 360
    dialog.count.setValue(6)
    dialog.update_preview()
    assert dialog.preview.pixmap().toImage() != first


def test_export_writes_the_design_on_screen(model, qtbot, tmp_path):
    model.set_spec(time_ratio=1.6)
    dialog = DrawingSheetDialog(model, "en")
    qtbot.addWidget(dialog)
    dialog.paper.setCurrentText("A2")
    out = tmp_path / "sheet.dxf"
    dialog.export(str(out))
    doc = ezdxf.readfile(out)
    texts = [t.dxf.text for t in doc.modelspace().query("TEXT")]
    assert f"{model.design.time_ratio:.4f}" in texts
    scale = float(next(m.group(1) for t in texts if (m := re.search(r"[(（]1:([\d.]+)[)）]", t))))   # "μ", "l", "= … (1:n)"
    circle = doc.modelspace().query('CIRCLE[layer=="CENTER"]')[0]
    assert circle.dxf.radius * scale == pytest.approx(model.design.crank, rel=1e-12)
    assert doc.header["$LIMMAX"][0] == pytest.approx(594.0)
    pdf = tmp_path / "sheet.pdf"
    dialog.export(str(pdf))
    assert pdf.read_bytes().startswith(b"%PDF")
    if shutil.which("pdfinfo"):
        info = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True).stdout
        w, h = (float(v) * 25.4 / 72 for v in re.search(r"([\d.]+) x ([\d.]+) pts", info).groups())
        assert abs(w - 594.0) < 0.5 and abs(h - 420.0) < 0.5


def test_export_refuses_another_type_and_writes_nothing(model, qtbot, tmp_path):
    dialog = DrawingSheetDialog(model, "en")
    qtbot.addWidget(dialog)
    with pytest.raises(ValueError):
        dialog.export(str(tmp_path / "sheet.png"))
    assert list(tmp_path.iterdir()) == []


def test_typing_in_a_field_redraws_the_preview_once_after_a_pause(model, qtbot, monkeypatch):
    """The choices restarted the preview's 150 ms timer with their own value as its interval
    (A0, the paper's index 0: 0 ms), so after choosing A0 each key typed into the title
    block re-drew the whole sheet (0.2 s a key on this machine): typing lagged."""
    from shaperapp.drawing import dialog as dialog_module
    painted = []
    real = dialog_module.paint_sheet
    monkeypatch.setattr(dialog_module, "paint_sheet", lambda *a, **k: (painted.append(1), real(*a, **k))[1])
    dialog = DrawingSheetDialog(model, "en")
    qtbot.addWidget(dialog)
    dialog.paper.setCurrentText("A0")
    dialog.count.setValue(24)
    dialog._timer.stop()                # those two choices' preview is not the test's
    painted.clear()
    field = dialog.fields["student"]
    for key in "Zhang":                 # a quick typist: 30 ms a key
        qtbot.keyClick(field, key)
        qtbot.wait(30)
    assert painted == []
    qtbot.waitUntil(lambda: painted == [1], timeout=2000)
    qtbot.wait(200)
    assert painted == [1] and dialog._timer.interval() == 150
