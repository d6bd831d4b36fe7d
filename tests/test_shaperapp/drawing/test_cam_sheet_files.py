"""The feed cam's sheet from the command line and the dialog: files of the right size, the
cam of ``shaper cam`` (options or the design file's cam) measured on it, bad input refused."""
import json
import re
import shutil
from types import SimpleNamespace

import ezdxf
import pytest

from cli_runner import shaper_in_process, shaper_run_in_process
from sheet_checks import assert_pdf_sheet
from core.cam import CamInputs, Program
from core.cam.file import cam_to_dict
from core.base.errors import DesignError
from core.files.io import save_design
from core.linkage.spec import Spec
from shaperapp.drawing.dialog import DrawingSheetDialog

BLOCK = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40"]
CAM = ["--arm", "120", "--swing", "15", "--pressure", "40", "--rise", "60", "--dwell", "10",
       "--return", "60", "--law", "cosine", "--return-law", "parabolic"]


def cam_json(*words) -> dict:
    status, out, err = shaper_in_process("cam", *words, "--json")
    assert status == 0, err
    return json.loads(out)


def dxf_scale_and_base_circle(path) -> tuple[float, float, list[str]]:
    """The drawn scale (cam mm per paper mm) from the caption, the base circle's radius on
    the paper (the THIN circle about the centre of the line of centres), the texts."""
    doc = ezdxf.readfile(path)
    assert doc.header["$INSUNITS"] == 4 and not doc.audit().has_errors
    texts = [t.dxf.text for t in doc.modelspace().query("TEXT")]
    caption = next(t for t in texts if re.search(r"\(([\d.]+):([\d.]+)\)", t))   # "μ", "l", " = … (a:b)"
    a, b = (float(v) for v in re.search(r"\(([\d.]+):([\d.]+)\)", caption).groups())
    circles = doc.modelspace().query('CIRCLE[layer=="THIN"]')
    return b / a, [c.dxf.radius for c in circles], texts        # a:b, so b/a cam mm per mm


def test_cli_dxf_carries_shaper_cams_cam_at_its_scale(tmp_path):
    out = tmp_path / "cam.dxf"
    status, stdout, err = shaper_in_process("drawing", *BLOCK, *CAM, "--content", "cam", "-o", out)
    assert status == 0, err
    assert stdout.strip() == f"wrote {out} (A1, cam, DXF)"
    figures = cam_json(*CAM, *BLOCK)
    mu, radii, texts = dxf_scale_and_base_circle(out)
    assert any(r * mu == pytest.approx(figures["base_radius_mm"], rel=1e-9) for r in radii), (mu, radii)
    assert f"{figures['center_distance_mm']:.3f} mm" in texts
    assert f"{figures['base_radius_mm']:.3f} mm" in texts
    assert "3/4" in texts and "Feed cam" in texts


def test_cli_takes_the_design_files_cam_and_options_override_it(tmp_path):
    inputs = CamInputs(arm_mm=120.0, program=Program(15.0, 60.0, 10.0, 60.0, "cosine", "parabolic"))
    save_design(tmp_path / "d.json", Spec(), [40.0], 1.0, extra={"cam": cam_to_dict(inputs, None)})
    out = tmp_path / "cam.dxf"
    status, _, err = shaper_in_process("drawing", "--design", tmp_path / "d.json", "--content", "cam",
                                       "--swing", "20", "-o", out)
    assert status == 0, err
    figures = cam_json("--design", tmp_path / "d.json", "--swing", "20")
    assert figures != cam_json("--design", tmp_path / "d.json")
    _, _, texts = dxf_scale_and_base_circle(out)
    assert f"{figures['base_radius_mm']:.3f} mm" in texts and "20°" in texts


@pytest.mark.parametrize("words, option", [
    ([w for w in CAM if w not in ("--arm", "120")], "--arm"),
    ([*CAM, "--swing", "100"], "--swing"),
    ([*CAM, "--pressure", "3"], "--pressure"),
    ([*CAM, "--rise", "0.5"], "--rise"),
    ([*CAM, "--roller", "500"], "--roller"),
    ([*CAM, "--phase", "0"], "--phase"),
    ([*CAM, "--base", "40"], "--distance"),
])
def test_bad_cam_input_one_line_naming_the_option_nothing_written(words, option, tmp_path):
    out = tmp_path / "cam.pdf"
    status, stdout, stderr = shaper_in_process("drawing", *BLOCK, *words, "--content", "cam", "-o", out)
    lines = stderr.strip().splitlines()
    assert status == 2 and len(lines) == 1 and option in lines[0], stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("word", ["--arm", "--law", "--phase"])
def test_a_cam_option_without_the_cam_sheet_is_refused(word, tmp_path):
    """A cam option with another content would be silently unused: one line naming it."""
    value = {"--law": "sine"}.get(word, "100")
    status, _, stderr = shaper_in_process("drawing", *BLOCK, word, value, "-o", tmp_path / "m.pdf")
    assert status == 2 and stderr.strip().splitlines() == [
        f"shaper: error: {word}: a cam option, only with --content cam"], stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("pdfinfo") is None, reason="poppler-utils not installed")
def test_cli_pdf_is_the_paper_and_chinese_embeds_a_cjk_font(tmp_path):
    out = tmp_path / "凸轮.pdf"
    result = shaper_run_in_process("drawing", *BLOCK, *CAM, "--content", "cam", "--sheet", "A2", "--lang", "zh",
                                   "-o", out)
    assert result.returncode == 0, result.stderr
    text = assert_pdf_sheet(out, (594.0, 420.0))
    if text:
        assert "进给凸轮" in text and "理论廓线基圆半径" in text


def test_dialog_offers_the_cam_sheet_of_the_cam_tab(model, qtbot, tmp_path):
    """With a cam source the dialog lists the cam sheet and draws that cam (a different arm
    than the default, so the default cam would fail the check)."""
    from core.cam import design_cam
    cam = design_cam(CamInputs(arm_mm=150.0, program=Program(20.0, 70.0, 10.0, 70.0)), model.design)
    plain = DrawingSheetDialog(model, "en")
    qtbot.addWidget(plain)
    assert plain.content.findData("cam") == -1           # no cam to draw: not offered
    source = SimpleNamespace(cam=cam, error=None)
    dialog = DrawingSheetDialog(model, "en", cam=source)
    qtbot.addWidget(dialog)
    assert dialog.count.isEnabled()
    dialog.content.setCurrentIndex(dialog.content.findData("forces"))   # draws two positions only
    assert not dialog.count.isEnabled() and all(box.isEnabled() for box in dialog.angles)
    dialog.content.setCurrentIndex(dialog.content.findData("cam"))
    assert dialog.choice().cam is cam
    assert not dialog.count.isEnabled() and not any(box.isEnabled() for box in dialog.angles)
    dialog.paper.setCurrentText("A2")
    out = tmp_path / "cam.dxf"
    dialog.export(str(out))
    mu, radii, texts = dxf_scale_and_base_circle(out)
    assert any(r * mu == pytest.approx(cam.base_radius_mm, rel=1e-9) for r in radii)
    assert "3/4" in texts and "150.000 mm" in texts
    assert dialog.message.text() == ""
    source.error = DesignError("swing", 100.0, "must be ≤ 60 °")        # typed wrong in the tab
    dialog.update_preview()
    assert "last valid cam" in dialog.message.text()
    dialog.content.setCurrentIndex(dialog.content.findData("motion"))
    dialog.update_preview()
    assert dialog.message.text() == ""


def test_window_gives_the_dialog_the_cam_tabs_cam(window, qtbot, monkeypatch):
    import shaperapp.drawing.dialog as dialog_module
    seen = {}

    def fake(model, parent, language, start_dir, settings=None, cam=None, gear=None):
        seen["cam"] = cam.cam
        return ""
    monkeypatch.setattr(dialog_module, "export_sheet_dialog", fake)
    window.cam.cam_model.set_fields(arm=140.0)
    window._export_sheet()
    assert seen["cam"] is window.cam.cam_model.cam and seen["cam"].follower.arm_mm == 140.0


def test_the_four_sheets_are_numbered_one_to_four(qapp):
    """The title blocks say 1/4 … 4/4: the course design's four sheets, in order (the gear
    pair's meshing sheet, issue 35, is the fourth)."""
    from core.cam import design_cam
    from core.forces.masses import MassProperties
    from core.drawing.sheet import Text
    from shaperapp.drawing.content import CONTENTS, SheetChoice, build_sheet
    spec = Spec()
    loads = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                           cut_force_N=7000.0, cut_height_mm=80.0)
    cam = design_cam(CamInputs(), spec.design())
    from core.gear import GearPairInputs, design_pair
    gear = design_pair(GearPairInputs(z1=13, z2=40, module_mm=6.0))
    numbers = []
    for content in CONTENTS:
        sheet = build_sheet(spec, [40.0], loads, SheetChoice(content, "A3", cam=cam, gear=gear))
        numbers.append([t.text for t in sheet.items if isinstance(t, Text) and re.fullmatch(r"\d/\d", t.text)])
    assert CONTENTS == ("motion", "forces", "cam", "gear")
    assert numbers == [["1/4"], ["2/4"], ["3/4"], ["4/4"]]


def test_the_cam_sheet_of_a_design_whose_cam_cannot_be_made_is_not_drawn(model, qtbot, tmp_path):
    """After opening a design whose cam its linkage refuses, the Cam tab still holds the cam
    of the design opened before (``own_value`` False); the dialog drew and wrote that cam
    as this design's cam sheet, under "shows its last valid cam". Now the preview says why
    there is none and Save writes nothing (hunt s13-hunt2)."""
    from core.cam import design_cam
    earlier = design_cam(CamInputs(arm_mm=150.0, program=Program(20.0, 70.0, 10.0, 70.0)), model.design)
    source = SimpleNamespace(cam=earlier, own_value=False,
                             error=DesignError("phase", 90.0, "feeds during the cut"))
    dialog = DrawingSheetDialog(model, "en", cam=source)
    qtbot.addWidget(dialog)
    dialog.content.setCurrentIndex(dialog.content.findData("cam"))
    dialog.update_preview()
    assert "cannot be drawn" in dialog.message.text() and "feeds during the cut" in dialog.message.text()
    out = tmp_path / "cam.pdf"
    with pytest.raises(DesignError):
        dialog.export(str(out))
    assert not out.exists()
