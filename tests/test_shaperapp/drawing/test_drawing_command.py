"""``shaper drawing``: the files it writes measured, and bad input refused before writing."""
import math
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from cli_runner import shaper_in_process, shaper_run_in_process

pytestmark = pytest.mark.slow   # whole sheets: left out of the quick run

BLOCK = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40"]
ROD = ["--crank", "100", "--K", "1.46", "--stroke", "312", "--rod-ratio", "0.3", "--rpm", "40", "60"]
needs_poppler = pytest.mark.skipif(shutil.which("pdfinfo") is None or shutil.which("pdftoppm") is None,
                                   reason="poppler-utils not installed")


def pdf_page_mm(path) -> tuple[float, float]:
    info = subprocess.run(["pdfinfo", str(path)], capture_output=True, text=True).stdout
    w, h = re.search(r"Page size:\s+([\d.]+) x ([\d.]+) pts", info).groups()
    return float(w) * 25.4 / 72.0, float(h) * 25.4 / 72.0


@needs_poppler
@pytest.mark.parametrize("size, mm", [("A1", (841.0, 594.0)), ("A3", (420.0, 297.0))])
def test_pdf_page_is_the_paper_and_the_border_measures_true(size, mm, tmp_path):
    """The page size, and the border found in the page's pixels: its thick lines lie 25 mm
    (binding side) and c mm from the paper's edges, so a length on the page is paper mm."""
    out = tmp_path / "m.pdf"
    result = shaper_run_in_process("drawing", *BLOCK, "--sheet", size, "-o", out)
    assert result.returncode == 0, result.stderr
    w, h = pdf_page_mm(out)
    assert abs(w - mm[0]) < 0.5 and abs(h - mm[1]) < 0.5
    dpi = 50
    subprocess.run(["pdftoppm", "-r", str(dpi), "-gray", "-png", str(out), str(tmp_path / "p")], check=True)
    from PySide6.QtGui import QImage
    image = QImage(str(next(tmp_path.glob("p*.png"))))
    px_per_mm = dpi / 25.4
    row = image.height() // 3          # the trimmed edge at the paper's edges, then the border
    dark = [x for x in range(image.width()) if image.pixelColor(x, row).lightness() < 128
            and px_per_mm < x < image.width() - 1 - px_per_mm]
    c = 10.0 if size == "A1" else 5.0
    assert abs(min(dark) / px_per_mm - 25.0) < 1.0          # first dark column: the border
    assert abs(max(dark) / px_per_mm - (mm[0] - c)) < 1.0
    assert abs((max(dark) - min(dark)) / px_per_mm - (mm[0] - 25.0 - c)) < 1.0


@needs_poppler
def test_chinese_sheet_embeds_a_cjk_font(tmp_path):
    if shutil.which("pdffonts") is None:
        pytest.skip("pdffonts not installed")
    out = tmp_path / "运动.pdf"
    result = shaper_run_in_process("drawing", *ROD, "--lang", "zh", "--drawn-by", "张三", "-o", out)
    assert result.returncode == 0, result.stderr
    fonts = subprocess.run(["pdffonts", str(out)], capture_output=True, text=True).stdout
    rows = [line for line in fonts.splitlines()[2:] if line.strip()]
    assert any("CJK" in r or "Hei" in r or "Han" in r for r in rows), fonts
    assert all(" yes " in r for r in rows)                 # every font embedded
    text = subprocess.run(["pdftotext", str(out), "-"], capture_output=True, text=True).stdout
    assert "运动分析图" in text and "张三" in text


def test_svg_is_in_mm_and_the_lever_measures_true(tmp_path):
    """In the SVG (width in mm, the viewBox its user units): the thick lines are 0.5 mm and
    the thin 0.25 mm wide; the pairs of thick lines from one point are the crank from O2
    and the lever from O4 at the two limit positions: times the scale the caption states
    they are L1 and L3 long, and O2O4 is L2 (the numbers of shaper synth)."""
    out = tmp_path / "m.svg"
    result = shaper_run_in_process("drawing", *BLOCK, "--sheet", "A2", "-o", out)
    assert result.returncode == 0, result.stderr
    root = ET.parse(out).getroot()
    assert root.get("width") == "594mm" and root.get("height") == "420mm"
    vb = [float(v) for v in root.get("viewBox").split()]
    user_per_mm = vb[2] / 594.0
    assert vb[3] / user_per_mm == pytest.approx(420.0)
    ns = "{http://www.w3.org/2000/svg}"
    widths, segments, texts = set(), [], []
    for group in root.iter(f"{ns}g"):
        matrix = re.match(r"matrix\(([-\d.e]+),0,0,([-\d.e]+),", group.get("transform", ""))
        k = float(matrix.group(1)) if matrix else 1.0
        for poly in group.findall(f"{ns}polyline"):
            width = float(group.get("stroke-width")) * k / user_per_mm      # mm on paper
            widths.add(round(width, 3))
            points = np.array([[float(v) for v in p.split(",")] for p in poly.get("points").split()])
            if len(points) == 2 and width == pytest.approx(0.5):
                segments.append(points * k / user_per_mm)
        # Qt writes one <text> per font run ("…positions, ", "μ", "l = …"): join a group's
        texts.append("".join("".join(t.itertext()) for t in group.findall(f"{ns}text")))
    assert widths == {0.25, 0.5}
    scale = float(next(m.group(1) for t in texts if (m := re.search(r"[(（]1:([\d.]+)[)）]", t))))
    starts = {}
    for seg in segments:
        starts.setdefault(tuple(np.round(seg[0], 3)), []).append(float(np.hypot(*(seg[1] - seg[0]))))
    pairs = {start: lengths for start, lengths in starts.items() if len(lengths) == 2}
    assert len(pairs) == 2
    (o2, crank), (o4, lever) = sorted(pairs.items(), key=lambda kv: kv[1][0])
    # shaper synth --crank 100 --K 1.4 --stroke 300: frame O2O4 L2 386.370 mm, lever O4B L3 579.555 mm
    assert [length * scale for length in crank] == pytest.approx([100.0, 100.0], abs=0.01)
    assert [length * scale for length in lever] == pytest.approx([579.555, 579.555], abs=0.01)
    assert math.dist(o2, o4) * scale == pytest.approx(386.370, abs=0.01)


def test_dxf_written_and_measures_true(tmp_path):
    import ezdxf
    out = tmp_path / "m.dxf"
    result = shaper_run_in_process("drawing", *ROD, "--lang", "zh", "-o", out)
    assert result.returncode == 0, result.stderr
    doc = ezdxf.readfile(out)
    assert doc.header["$INSUNITS"] == 4
    texts = [t.dxf.text for t in doc.modelspace().query("TEXT")]
    scale = float(next(m.group(1) for t in texts if (m := re.search(r"[(（]1:([\d.]+)[)）]", t))))   # "μ", "l", "= … (1:n)"
    circle = doc.modelspace().query('CIRCLE[layer=="CENTER"]')[0]
    assert circle.dxf.radius * scale == pytest.approx(100.0, rel=1e-12)
    # no --title and no design file: the title block names the design by its inputs
    # (on two lines of the title block's name area, 50 mm wide)
    assert "L1 100 mm, K 1.46, H 312 mm, L4/L3 0.3" in {f"{a} {b}" for a, b in zip(texts, texts[1:])}


def test_user_text_stays_text_in_the_dxf_and_the_svg(tmp_path):
    """A title CAD would read as control codes (%%c is ⌀) or an SVG reader as markup is
    shown as typed."""
    import ezdxf
    title = '%%c50 <b>x</b> & "y" =1+1'
    for suffix in ("dxf", "svg"):
        result = shaper_run_in_process("drawing", *ROD, "--sheet", "A3", "--title", title,
                                       "-o", tmp_path / f"t.{suffix}")
        assert result.returncode == 0, result.stderr
    shown = [t.plain_text() for t in ezdxf.readfile(tmp_path / "t.dxf").modelspace().query("TEXT")]
    lines = {f"{a} {b}" for a, b in zip(shown, shown[1:])}       # on two lines in the title block
    assert title in shown or title in lines
    svg_texts = [e.text for e in ET.parse(tmp_path / "t.svg").iter() if e.text]
    assert title in svg_texts or title in {f"{a} {b}" for a, b in zip(svg_texts, svg_texts[1:])}


@pytest.mark.parametrize("words, option", [
    (["--sheet", "A5"], "--sheet"),
    (["--content", "cams"], "--content"),
    (["--content", "forces"], "--cut-force"),     # the forces sheet needs the loads
    (["--positions", "0"], "positions"),
    (["--positions", "73"], "positions"),
    (["--diagrams", "30"], "diagrams"),
    (["--date", "a\nb"], "--date"),
])
def test_bad_input_one_line_naming_the_option_nothing_written(words, option, tmp_path):
    out = tmp_path / "m.pdf"
    status, stdout, stderr = shaper_in_process("drawing", *BLOCK, *words, "-o", out)
    lines = stderr.strip().splitlines()
    assert status == 2 and len(lines) == 1 and option in lines[0], stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name", ["m.png", "m", "missing/m.pdf"])
def test_bad_output_name_refused(name, tmp_path):
    status, _, stderr = shaper_in_process("drawing", *BLOCK, "-o", tmp_path / name)
    lines = stderr.strip().splitlines()
    assert status == 2 and len(lines) == 1 and "--output" in lines[0], stderr
    assert list(tmp_path.iterdir()) == []


def test_a_folder_as_output_refused(tmp_path):
    (tmp_path / "m.dxf").mkdir()
    status, _, stderr = shaper_in_process("drawing", *BLOCK, "-o", tmp_path / "m.dxf")
    assert status == 2 and "--output" in stderr and "folder" in stderr
    assert [p.name for p in tmp_path.iterdir()] == ["m.dxf"] and not any((tmp_path / "m.dxf").iterdir())


def test_unwritable_folder_refused_and_old_file_kept(tmp_path):
    import os
    if os.geteuid() == 0:
        pytest.skip("root writes anywhere")
    folder = tmp_path / "ro"
    folder.mkdir()
    old = folder / "m.dxf"
    old.write_text("old")
    folder.chmod(0o500)
    try:
        status, _, stderr = shaper_in_process("drawing", *BLOCK, "-o", old)
    finally:
        folder.chmod(0o700)
    assert status == 2 and "--output" in stderr and len(stderr.strip().splitlines()) == 1
    assert old.read_text() == "old"
