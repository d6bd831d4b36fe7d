"""The Chinese report is Chinese text (issue 32, items 4 and 5): its text layer holds the
ideographs it prints, its plots are set in the Simplified Chinese font, and it has no
untranslated English word. A real ``shaper report`` run of a design with loads, a cam and a
gear pair."""
import re
import shutil
import subprocess

import pytest

from cli_runner import shaper_run_in_process
from language_checks import (control_characters, english_words, han, has_pdftotext, pdf_text,
                             radicals)

pytestmark = [pytest.mark.slow,      # a real process: left out of the quick run
              pytest.mark.skipif(not has_pdftotext() or shutil.which("pdffonts") is None,
                                 reason="poppler-utils not installed")]
# Notation the report writes in Latin letters: functions, subscripted symbols (J_e, P_m,
# T_m, ΔW_max, v_slide, the Coriolis acceleration a^k, the rotating parts' J_c and J_i) and
# the command line's name.
SYMBOLS = {"sin", "cos", "tan", "Je", "Pm", "Tm", "Wmax", "vslide", "ak", "Jc", "Ji", "shaper"}
# Words of the plots' axes and bands (resources/glossary.tsv: 工作行程), which the plots
# drawn in Noto Sans CJK JP lost from the text layer or wrote with radicals (⼯作⾏程).
PLOT_WORDS = ("滑枕位移", "滑枕速度", "滑枕加速度", "工作行程", "回程", "曲柄转角")


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    from core.cam import CamInputs, Program
    from core.cam.file import cam_to_dict
    from core.forces.masses import MassProperties
    from core.files.io import masses_to_dict, save_design
    from core.linkage.spec import Spec
    folder = tmp_path_factory.mktemp("zh")
    cam = CamInputs(arm_mm=160.0, program=Program(20.0, 70.0, 5.0, 80.0, "poly345", "cosine"))
    loads = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                           cut_force_N=7000.0, cut_height_mm=80.0,
                           rotors=((0.5, 1.0), (0.02, 4.0)))     # the inputs' row "at 1·ω2" was English
    save_design(folder / "d.json", Spec(), [40.0, 60.0], 1.0,
                extra={"cam": cam_to_dict(cam, None), "forces": masses_to_dict(loads),
                       "gear": {"z1": 10, "z2": 14, "module_mm": 5.0}})
    run = shaper_run_in_process("report", "--design", folder / "d.json", "--lang", "zh", "--title", "牛头刨床",
                                "-o", folder / "zh.pdf")
    assert run.returncode == 0, run.stderr
    return folder / "zh.pdf"


def test_the_text_layer_holds_the_printed_ideographs(report):
    text = pdf_text(report)
    assert radicals(text) == [], "".join(sorted(set(radicals(text))))
    assert control_characters(text) == []
    assert len(han(text)) > 2000
    squashed = re.sub(r"\s+", "", text)
    assert [w for w in PLOT_WORDS if w not in squashed] == []


def test_every_chinese_font_is_the_simplified_chinese_one(report):
    fonts = subprocess.run(["pdffonts", str(report)], capture_output=True, text=True).stdout
    cjk = [line.split()[0] for line in fonts.splitlines()[2:] if "CJK" in line]
    assert cjk and all("CJKsc" in name for name in cjk), cjk


def test_no_english_word(report):
    assert english_words(pdf_text(report), SYMBOLS) == []


def test_the_design_files_gear_pair_has_its_section(report):
    """``shaper report --design`` reads the file's "gear" (issue 35, item 5): its section, the
    pair in mesh and its caption's scale."""
    squashed = re.sub(r"\s+", "", pdf_text(report))
    assert "10齿轮机构" in squashed and "齿轮机构" in squashed
    assert re.search(r"比例1:[\d.]+（μl=[\d.]+m/mm）", squashed)
