"""The forces sheet from the command line and the dialog: files of the right size, its
figures those of ``shaper dynamics``, and bad input refused."""
import shutil

import ezdxf
import pytest

from cli_runner import shaper_run_in_process
from sheet_checks import assert_pdf_sheet
from core.cli.cmd_dynamics import speed_rows
from core.forces.masses import masses_for_design
from core.forces.flywheel import summarize
from shaperapp.drawing.dialog import DrawingSheetDialog

BLOCK = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40"]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000",
         "--cut-height", "80"]


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("pdfinfo") is None, reason="poppler-utils not installed")
def test_cli_pdf_is_the_paper_and_chinese_embeds_a_cjk_font(tmp_path):
    out = tmp_path / "动态静力.pdf"
    result = shaper_run_in_process("drawing", *BLOCK, *LOADS, "--content", "forces", "--lang", "zh", "-o", out)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == f"wrote {out} (A1, forces, PDF)"
    text = assert_pdf_sheet(out, (841.0, 594.0))
    if text:
        assert "动态静力分析图" in text and "滑枕杆组" in text


@pytest.mark.slow
def test_cli_without_loads_exits_2_naming_the_cutting_force(tmp_path):
    out = tmp_path / "f.pdf"
    result = shaper_run_in_process("drawing", *BLOCK, "--content", "forces", "-o", out)
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 2 and len(lines) == 1 and "--cut-force" in lines[0], result.stderr
    assert list(tmp_path.iterdir()) == []


def test_dialog_writes_the_forces_sheet_of_the_design_on_screen(model, qtbot, tmp_path):
    model.set_spec(time_ratio=1.6)
    dialog = DrawingSheetDialog(model, "en")
    qtbot.addWidget(dialog)
    dialog.content.setCurrentIndex(dialog.content.findData("forces"))
    assert dialog.choice().content == "forces"
    out = tmp_path / "forces.dxf"
    dialog.export(str(out))
    doc = ezdxf.readfile(out)
    assert doc.header["$INSUNITS"] == 4 and not doc.audit().has_errors
    texts = [t.dxf.text for t in doc.modelspace().query("TEXT")]
    assert "Kinetostatic analysis" in " ".join(texts)       # on two lines in the title block
    masses = masses_for_design(model.design, model.masses)
    cli = dict(speed_rows(summarize(model.design, model.rpms[:1], masses).speeds[0]))
    assert cli["flywheel J_F"] in texts and cli["energy fluctuation ΔW_max"] in texts
