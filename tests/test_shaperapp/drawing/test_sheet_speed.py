"""The sheets drawn at one of the design's speeds (issue 40, item 4): ``shaper drawing
--rpm-index``, ``shaper course --rpm-index`` and the drawing dialog's speed choice; the
numbers are those of that speed and the title block names it."""
import json

import ezdxf
import pytest

from cli_runner import shaper_in_process
from core.forces.masses import MassProperties, masses_for_design
from core.forces.flywheel import summarize
from core.files.io import design_document, masses_to_dict
from core.linkage.spec import Spec
from shaperapp.drawing.dialog import DrawingSheetDialog

BLOCK = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40", "60"]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000",
         "--cut-height", "80"]
LOADS_KG = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                          cut_force_N=7000.0, cut_height_mm=80.0)
CAM = {"arm_mm": 120.0, "swing_deg": 15.0, "rise_deg": 60.0, "dwell_deg": 10.0, "return_deg": 60.0,
       "pressure_deg": 40.0, "return_pressure_deg": 70.0}
GEAR = {"z1": 13, "z2": 40, "module_mm": 6.0, "centre_mm": 162.0}


def texts(path, layer=None) -> list[str]:
    doc = ezdxf.readfile(path)
    return [t.dxf.text for t in doc.modelspace().query("TEXT") if layer is None or t.dxf.layer == layer]


def title_block(path) -> str:
    """The title block's texts in one (an index is a text of its own: n, 2, " = 60 r/min")."""
    return "".join(texts(path, "TITLE"))


def flywheel_texts(rpm_index: int) -> tuple[str, str]:
    """J_F and the mean power at the speed of ``rpm_index`` (0-based) of 40, 60 r/min, from core's
    summary of both speeds at once, as the sheet formats them."""
    design = Spec().design()
    speed = summarize(design, [40.0, 60.0], masses_for_design(design, LOADS_KG)).speeds[rpm_index]
    return f"{speed.flywheel_inertia_kg_m2:.4g} kg·m²", f"{speed.mean_power_W:.4g} W"


def test_the_forces_sheet_at_speed_2_carries_speed_2s_numbers_and_names_it(tmp_path):
    out = tmp_path / "f.dxf"
    status, _, err = shaper_in_process("drawing", *BLOCK, *LOADS, "--content", "forces",
                                       "--rpm-index", "2", "-o", out)
    assert status == 0, err
    drawn = texts(out)
    second, first = flywheel_texts(1), flywheel_texts(0)
    assert second[0] != first[0] and second[1] != first[1]      # the speeds do differ here
    assert set(second) <= set(drawn) and not set(first) & set(drawn)
    assert "n2 = 60 r/min" in title_block(out)


def test_the_first_speed_is_the_default_and_the_title_block_names_it(tmp_path):
    out = tmp_path / "m.dxf"
    status, _, err = shaper_in_process("drawing", *BLOCK, "-o", out)
    assert status == 0, err
    assert "n2 = 40 r/min" in title_block(out)


@pytest.mark.parametrize("value", ["3", "0", "-1", "1.5", "two"])
def test_a_speed_out_of_range_is_refused_naming_the_option_and_the_speeds(value, tmp_path):
    out = tmp_path / "m.dxf"
    status, _, err = shaper_in_process("drawing", *BLOCK, f"--rpm-index={value}", "-o", out)
    lines = err.strip().splitlines()
    assert status == 2 and len(lines) == 1, err
    assert lines[0].startswith("shaper: error: --rpm-index: ") and "2 speeds" in lines[0]
    assert not out.exists()


def test_the_gear_sheet_has_no_speed_to_choose(tmp_path):
    out = tmp_path / "g.dxf"
    status, _, err = shaper_in_process("drawing", "--content", "gear", "--z1", "13", "--z2", "40",
                                       "--module", "6", "--centre", "162", "--rpm-index", "1", "-o", out)
    assert status == 2 and err.strip().splitlines()[-1].startswith("shaper: error: --rpm-index:")
    assert not out.exists()


def test_the_dialog_draws_the_chosen_speed(model, qtbot, tmp_path):
    model.set_rpms([40.0, 60.0])
    dialog = DrawingSheetDialog(model, "en")
    qtbot.addWidget(dialog)
    assert [dialog.speed.itemText(i) for i in range(dialog.speed.count())] == ["40 r/min", "60 r/min"]
    assert dialog.speed.currentIndex() == 0
    dialog.speed.setCurrentIndex(1)
    out = tmp_path / "m.dxf"
    dialog.export(str(out))
    drawn = texts(out)
    assert "n2 = 60 r/min" in title_block(out)
    assert any("n = 60 r/min" in t for t in drawn) and not any("40 r/min" in t for t in drawn)
    dialog.content.setCurrentIndex(dialog.content.findData("gear"))
    assert not dialog.speed.isEnabled()


def test_the_course_draws_its_sheets_at_the_chosen_speed(tmp_path, monkeypatch):
    monkeypatch.setattr("shaperapp.course.write.write_report", lambda *args: None)
    monkeypatch.setattr("shaperapp.course.write._report", lambda *args: None)   # sheets only
    path = tmp_path / "d.shaper.json"
    path.write_text(json.dumps(design_document(Spec(), [40.0, 60.0], 1.0, {
        "forces": masses_to_dict(LOADS_KG), "cam": CAM, "gear": GEAR})), encoding="utf-8")
    out = tmp_path / "out"
    status, _, err = shaper_in_process("course", "--design", path, "--dxf", "--rpm-index", "2",
                                       "--sheet", "A3", "-o", out)
    assert status == 0, err
    for name in ("01-motion.dxf", "02-kinetostatic.dxf", "03-cam.dxf"):
        assert "n2 = 60 r/min" in title_block(out / name), name
    assert flywheel_texts(1)[0] in texts(out / "02-kinetostatic.dxf")
    refused = tmp_path / "refused"
    status, _, err = shaper_in_process("course", "--design", path, "--rpm-index", "3", "-o", refused)
    assert status == 2 and "--rpm-index" in err and "2 speeds" in err
    assert not refused.exists()
