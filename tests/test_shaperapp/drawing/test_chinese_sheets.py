"""The Chinese sheets are Chinese text (issue 32, items 4 and 5): the PDF's text layer
holds the ideographs the DXF of the same sheet writes (no radicals, no control
characters), and neither file has an untranslated English word."""
from collections import Counter

import ezdxf
import pytest

from cli_runner import shaper_in_process
from language_checks import (assert_chinese_text, english_words, han, has_pdftotext, pdf_text,
                             words_of)

BLOCK = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40", "60"]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70",
         "--cut-force", "7000", "--cut-height", "80"]
CAM = ["--arm", "120", "--swing", "15", "--pressure", "40", "--rise", "60", "--dwell", "10",
       "--return", "60"]
GEAR = ["--z1", "13", "--z2", "40", "--module", "6", "--centre", "162"]
EXTRA = {"motion": [], "forces": LOADS, "cam": CAM, "gear": GEAR}
PEOPLE = ["--drawn-by", "张三", "--school", "机械工程学院"]


def sheet(content: str, suffix: str, folder) -> str:
    out = folder / f"{content}.{suffix}"
    linkage = [] if content == "gear" else BLOCK
    status, _, err = shaper_in_process("drawing", *linkage, *EXTRA[content], *PEOPLE, "--content",
                                       content, "--lang", "zh", "-o", out)
    assert status == 0, err
    return out


def dxf_texts(path) -> list[str]:
    doc = ezdxf.readfile(path)
    return [e.dxf.text if e.dxftype() == "TEXT" else e.plain_text()
            for e in doc.modelspace().query("TEXT MTEXT")]


@pytest.mark.skipif(not has_pdftotext(), reason="poppler-utils not installed")
@pytest.mark.parametrize("content", ["motion", "forces", "cam", "gear"])
def test_the_pdf_text_layer_holds_the_ideographs_the_sheet_prints(content, tmp_path):
    text = pdf_text(sheet(content, "pdf", tmp_path))
    assert_chinese_text(text, what=content)
    printed = "".join(dxf_texts(sheet(content, "dxf", tmp_path)))
    assert len(han(printed)) > 40
    assert Counter(han(text)) == Counter(han(printed))


@pytest.mark.parametrize("content", ["motion", "forces", "cam", "gear"])
def test_the_dxf_and_svg_texts_have_no_english_word(content, tmp_path):
    import xml.etree.ElementTree as ET
    texts = dxf_texts(sheet(content, "dxf", tmp_path))
    assert [(t, english_words(t)) for t in texts if english_words(t)] == []
    svg = ET.parse(sheet(content, "svg", tmp_path)).getroot()
    shown = ["".join(e.itertext()) for e in svg.iter("{http://www.w3.org/2000/svg}text")]
    assert len(shown) > 20
    assert [(t, english_words(t)) for t in shown if english_words(t)] == []


def test_the_scan_finds_english_and_keeps_symbols_and_units():
    """The scanner itself, on the phrases issue 32 found and on the notation that must pass."""
    found = english_words("凸轮 (allowed 40° / 70°) (largest 7.647 mm) is not a design file (not valid JSON)")
    assert found == ["allowed", "largest", "is", "not", "design", "file", "not", "valid"]
    assert english_words("L1 = 100 mm, K = 1.4, H, O4, vB3, aB3B2, J_F, ψmax, 40 r/min, N·m, kg·m², "
                         "PDF/SVG/DXF/CSV, rad/s², GB/T 14689") == []
    assert english_words("design.json 已保存", words_of("design.json")) == []


@pytest.mark.slow                  # two A1 sheets rendered: left out of the quick run
@pytest.mark.skipif(not has_pdftotext(), reason="poppler-utils not installed")
def test_the_repair_leaves_the_page_as_qt_painted_it(tmp_path, monkeypatch):
    """The cam sheet (the most radicals) with and without the text layer's repair: the same
    pixels (pdftoppm), and qpdf finds nothing wrong with the repaired file."""
    import subprocess

    import pikepdf
    repaired = sheet("cam", "pdf", tmp_path)
    monkeypatch.setattr("shaperapp.drawing.render.repair_text_layer", lambda data: data)
    (tmp_path / "raw").mkdir()
    raw = sheet("cam", "pdf", tmp_path / "raw")
    assert raw.read_bytes() != repaired.read_bytes()
    with pikepdf.open(repaired) as doc:
        assert doc.check_pdf_syntax() == []
    for pdf in (raw, repaired):
        subprocess.run(["pdftoppm", "-r", "40", "-gray", "-png", str(pdf), str(pdf.with_suffix(""))],
                       check=True)
    assert (tmp_path / "raw" / "cam-1.png").read_bytes() == (tmp_path / "cam-1.png").read_bytes()
