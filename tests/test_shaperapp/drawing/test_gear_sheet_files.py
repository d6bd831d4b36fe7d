"""The meshing sheet from ``shaper drawing --content gear`` (issue 35, item 3): PDF, SVG and
DXF on A0–A3 (A2 by default) without a linkage, the pair of ``shaper gear``; the same DXF as
``shaper gear --dxf``; the Chinese sheet laid out like every sheet; bad input refused."""
import json
import re
import subprocess

import ezdxf
import pytest

from cli_runner import shaper_in_process
from output_checks import error_names
from sheet_checks import assert_laid_out

GEAR = ["--z1", "13", "--z2", "40", "--module", "6", "--centre", "162"]


def test_pdf_on_a2_by_default_and_the_numbers_of_shaper_gear(tmp_path):
    out = tmp_path / "gear.pdf"
    status, stdout, err = shaper_in_process("drawing", "--content", "gear", *GEAR, "-o", out)
    assert status == 0, err
    assert stdout.strip() == f"wrote {out} (A2, gear, PDF)"
    info = subprocess.run(["pdfinfo", str(out)], capture_output=True, text=True).stdout
    w, h = (float(v) * 25.4 / 72 for v in re.search(r"([\d.]+) x ([\d.]+) pts", info).groups())
    assert abs(w - 594.0) < 0.5 and abs(h - 420.0) < 0.5
    text = subprocess.run(["pdftotext", str(out), "-"], capture_output=True, text=True).stdout
    status, js, _ = shaper_in_process("gear", *GEAR, "--json")
    doc = json.loads(js)
    if text:
        assert f"{doc['gear1']['tip_diameter_mm']:.3f}" in text
        assert f"{doc['pair']['contact_ratio']:.4f}" in text and "4/4" in text


@pytest.mark.parametrize("size", ["A0", "A3"])
def test_svg_and_dxf_on_other_papers(size, tmp_path):
    for suffix in ("svg", "dxf"):
        out = tmp_path / f"gear.{suffix}"
        status, stdout, err = shaper_in_process("drawing", "--content", "gear", *GEAR, "--sheet", size,
                                                "-o", out)
        assert status == 0 and f"({size}, gear, {suffix.upper()})" in stdout, err


def test_drawing_and_shaper_gear_write_the_same_dxf(tmp_path):
    one, two = tmp_path / "one.dxf", tmp_path / "two.dxf"
    assert shaper_in_process("drawing", "--content", "gear", *GEAR, "-o", one)[0] == 0
    assert shaper_in_process("gear", *GEAR, "--dxf", two)[0] == 0

    def entities(path):
        msp = ezdxf.readfile(path).modelspace()
        return sorted((e.dxftype(), e.dxf.layer,
                       round(float(e.dxf.radius), 9) if e.dxftype() == "CIRCLE" else 0.0,
                       len(e) if e.dxftype() == "LWPOLYLINE" else 0) for e in msp
                      if e.dxf.layer != "TITLE")        # the drawing dates its title block
    texts = [t.dxf.text for t in ezdxf.readfile(one).modelspace().query("TEXT")]
    assert entities(one) == entities(two) and {"Gear", "meshing"} <= set(texts)   # the title, on two lines


def test_the_chinese_sheet_is_laid_out(qapp):
    from core.drawing.gear_sheet import gear_sheet
    from core.drawing.sheet import paper
    from core.gear import GearPairInputs, design_pair
    from shaperapp.drawing.gear_labels import gear_labels
    from shaperapp.widgets import i18n
    i18n.set_language("zh_CN")
    try:
        labels = gear_labels()
        pair = design_pair(GearPairInputs(z1=13, z2=40, module_mm=6.0, centre_mm=162.0))
        for size in ("A1", "A2", "A3"):
            drawn = gear_sheet(pair, paper(size), labels=labels)
            assert_laid_out(drawn.sheet, drawn.areas)
        texts = [t.text for t in drawn.sheet.items if hasattr(t, "text")]
        for term in ("齿轮啮合图", "啮合角 α′", "重合度 ε", "变位系数 x", "双齿啮合区", "单齿啮合区"):
            assert term in texts, term
    finally:
        i18n.set_language("en")


@pytest.mark.parametrize("words, option", [
    (["--content", "gear", "--z1", "4", "--z2", "40", "--module", "6"], "--z1"),
    (["--content", "gear", "--z2", "40", "--module", "6"], "--z1"),
    (["--content", "motion", "--crank", "100", "--K", "1.4", "--stroke", "300", "--z1", "13"], "--z1")])
def test_bad_input_names_the_option(words, option, tmp_path):
    status, out, err = shaper_in_process("drawing", *words, "-o", tmp_path / "g.pdf")
    assert status == 2 and error_names(err) == [option]
    assert not (tmp_path / "g.pdf").exists()


def test_shaper_gear_dxf_in_chinese(qapp, tmp_path):
    """``shaper gear --dxf --lang zh`` (issue 35, item 5): the Chinese sheet's words, no
    English word, the same drawing as the English DXF; on 55087ce --lang was unknown."""
    from language_checks import english_words
    from shaperapp.widgets import i18n
    zh, en = tmp_path / "zh.dxf", tmp_path / "en.dxf"
    try:
        status, _, err = shaper_in_process("gear", *GEAR, "--dxf", zh, "--lang", "zh")
    finally:
        i18n.set_language("en")
    assert status == 0, err
    assert shaper_in_process("gear", *GEAR, "--dxf", en)[0] == 0
    texts = [t.dxf.text for t in ezdxf.readfile(zh).modelspace().query("TEXT")]
    for term in ("齿轮啮合图", "啮合角 α′", "重合度 ε", "小齿轮 1", "大齿轮 2", "单齿啮合区"):
        assert term in texts, term
    assert english_words(" ".join(texts)) == []

    def drawn(path):
        return sorted((e.dxftype(), e.dxf.layer, round(float(e.dxf.radius), 9) if e.dxftype() == "CIRCLE" else 0.0,
                       len(e) if e.dxftype() == "LWPOLYLINE" else 0) for e in ezdxf.readfile(path).modelspace()
                      if e.dxftype() in ("CIRCLE", "LWPOLYLINE") and e.dxf.layer != "TITLE")
    assert drawn(zh) == drawn(en)


@pytest.mark.parametrize("words", [["--lang", "zh"], ["--dxf", "x.dxf", "--lang", "fr"]])
def test_shaper_gear_lang_needs_the_dxf_and_a_language(words, tmp_path):
    status, _, err = shaper_in_process("gear", *GEAR, *[str(tmp_path / w) if w.endswith(".dxf") else w
                                                        for w in words])
    assert status == 2 and error_names(err) == ["--lang"], err
    assert list(tmp_path.iterdir()) == []
