"""A Chinese sheet's DXF as LibreCAD 2.2 prints it (issue 40, item 7).

LibreCAD has neither the GB style's gbenor.shx/gbcbig.shx nor reads a style's font files: it
draws a text in its font named like the text's *style*. In the style GB (its standard font)
it drew every Chinese character as a small dot and left every Greek letter out. The
``--cad-font gb`` DXF now writes every text beyond Latin-1 in the style ``wqy-unicode`` (the
same fonts for AutoCAD), the font with Chinese and Greek that LibreCAD's own Windows and macOS
builds ship; Debian's LibreCAD lacks it, so the tests print with a stand-in made from Noto
Sans CJK SC in ``$HOME/.librecad/fonts`` (``tests/librecad_font.py``), and with an empty
``$HOME``, where the dots remain. With ``--cad-font outline`` the texts are their glyphs'
filled outlines. The test prints an A3 motion sheet in Chinese through ``librecad dxf2pdf``
and looks at the ink where the sheet put its texts (known from the same sheet's GB DXF, whose
TEXT entities carry each text's place, height and alignment): a character is as tall as the
text and fills its cell as a glyph does, not as a dot.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import unicodedata

import numpy as np
import pytest

from core.drawing.sheet import text_width

from tests.cli_runner import shaper_run_in_process
from tests.librecad_font import have_noto_cjk, install_font

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(shutil.which("librecad") is None or shutil.which("pdftoppm") is None,
                                 reason="librecad or poppler-utils not installed "
                                        "(apt-get install librecad poppler-utils)"),
              pytest.mark.skipif(not have_noto_cjk(), reason="no Noto Sans CJK (fonts-noto-cjk)")]
SHEET = ("--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40", "--lang", "zh",
         "--sheet", "A3", "--positions", "6")
PAPER = (420.0, 297.0)           # A3 landscape, mm
DPI = 150
GREEK = set("αδεθμρφψωΔ")


def _wide(ch: str) -> bool:
    return unicodedata.east_asian_width(ch) in "WF"


def printed(tmp_path, name: str, home, label: str | None = None) -> np.ndarray:
    """``name``.dxf printed by LibreCAD with ``home`` as $HOME (a user's fonts are in its
    .librecad/fonts), as ``label``.pdf, and rasterized: dark pixels, rows from the top, cut
    to the sheet's trimmed edge (its outermost lines), so that paper mm map to pixels."""
    label = label or name
    if label != name:
        shutil.copyfile(tmp_path / f"{name}.dxf", tmp_path / f"{label}.dxf")
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "HOME": str(home)}
    subprocess.run(["librecad", "dxf2pdf", "-a", f"{label}.dxf"], cwd=tmp_path, env=env, check=True,
                   capture_output=True, timeout=120)
    subprocess.run(["pdftoppm", "-r", str(DPI), "-gray", "-png", "-singlefile", f"{label}.pdf", label],
                   cwd=tmp_path, check=True, timeout=120)
    from PIL import Image
    ink = np.asarray(Image.open(tmp_path / f"{label}.png").convert("L")) < 160
    rows, cols = np.flatnonzero(ink.any(axis=1)), np.flatnonzero(ink.any(axis=0))
    return ink[rows[0]:rows[-1] + 1, cols[0]:cols[-1] + 1]


def texts(path) -> list[tuple[str, float, float, float, str]]:
    """The upright TEXT entities of the GB DXF: (text, x, y, height, alignment) in paper mm,
    (x, y) the left end of the baseline (by the sheet's width estimate)."""
    import ezdxf
    found = []
    for e in ezdxf.readfile(path).modelspace().query("TEXT"):
        if e.dxf.rotation:
            continue
        align, p1, _ = e.get_placement()
        x, y = p1.x, p1.y
        h, text = e.dxf.height, e.dxf.text
        w = text_width(text, h)
        x -= {"LEFT": 0.0, "CENTER": w / 2.0, "RIGHT": w}.get(align.name.split("_")[-1], 0.0)
        y -= {"MIDDLE": h / 2.0, "TOP": h}.get(align.name.split("_")[0], 0.0)
        found.append((text, x, y, h, align.name))
    return found


def cell(ink: np.ndarray, x0: float, x1: float, y: float, h: float) -> np.ndarray:
    """The pixels of the paper box [x0, x1] × [y, y + h] mm."""
    sy, sx = (ink.shape[0] - 1) / PAPER[1], (ink.shape[1] - 1) / PAPER[0]
    top, bottom = int((PAPER[1] - y - h) * sy), int(np.ceil((PAPER[1] - y) * sy)) + 1
    return ink[top:bottom, int(x0 * sx):int(np.ceil(x1 * sx)) + 1]


GREEK_LINE = "μ φ Δ δ ω θ"


@pytest.fixture(scope="module")
def sheet_files(tmp_path_factory):
    """The A3 Chinese motion sheet as GB and outline DXF, in one folder."""
    folder = tmp_path_factory.mktemp("librecad")
    for name, font in (("gb", "gb"), ("outline", "outline")):
        done = shaper_run_in_process("drawing", *SHEET, "--cad-font", font, "-o", str(folder / f"{name}.dxf"))
        assert done.returncode == 0, done.stderr
    return folder


@pytest.fixture(scope="module")
def homes(tmp_path_factory, sheet_files):
    """$HOME for LibreCAD: ``bare`` without fonts of a user's (Debian's LibreCAD as it is),
    ``wqy`` with the stand-in wqy-unicode.lff of the sheet's characters and the Greek line's."""
    bare, wqy = tmp_path_factory.mktemp("bare-home"), tmp_path_factory.mktemp("wqy-home")
    install_font(wqy, "".join(t[0] for t in texts(sheet_files / "gb.dxf")) + GREEK_LINE + "θ°")
    return {"bare": bare, "wqy": wqy}


@pytest.fixture(scope="module")
def sheets(sheet_files, homes):
    """The sheet's texts, and its prints: the outline DXF, and the GB DXF with and without
    wqy-unicode.lff."""
    folder = sheet_files
    ink = {"outline": printed(folder, "outline", homes["bare"]),
           "gb": printed(folder, "gb", homes["bare"]),
           "gb-wqy": printed(folder, "gb", homes["wqy"], "gb-wqy")}
    return texts(folder / "gb.dxf"), ink


def chinese_coverage(ink: np.ndarray, found) -> tuple[int, list[str]]:
    """For each text of Chinese characters alone (the table's and the title block's words):
    does its box hold glyphs? A glyph's ink spans most of the text's height, a dot about
    half of it. (A text's ink lies within its estimated box in either font: both are drawn
    no wider than the estimate, the outline aligned within it.)"""
    checked, dotted = 0, []
    for text, x, y, h, _ in found:
        if not text or not all(_wide(ch) for ch in text):
            continue
        box = cell(ink, x, x + text_width(text, h), y - 0.1 * h, 1.2 * h)
        rows = np.flatnonzero(box.any(axis=1))
        span = (rows[-1] - rows[0] + 1) / box.shape[0] if rows.size else 0.0
        checked += 1
        if span < 0.65 or box.mean() < 0.08:
            dotted.append(f"{text} (height {span:.2f}, ink {box.mean():.2f})")
    return checked, dotted


@pytest.mark.parametrize("print_", ["outline", "gb-wqy"])
def test_chinese_texts_print_as_glyphs_in_librecad(sheets, print_):
    """The outline DXF anywhere; the GB DXF where LibreCAD has wqy-unicode.lff (its style
    GB printed every one of these texts as dots)."""
    found, ink = sheets
    checked, dotted = chinese_coverage(ink[print_], found)
    assert checked >= 8, checked            # the table's and the title block's words
    assert not dotted, dotted


def test_without_wqy_unicode_the_gb_dxf_prints_dots_in_librecad(sheets):
    """The measure tells dots from glyphs: the GB DXF in a LibreCAD without wqy-unicode.lff
    (Debian's; it falls back to its standard font) fails it."""
    found, ink = sheets
    checked, dotted = chinese_coverage(ink["gb"], found)
    assert checked >= 8 and len(dotted) >= 0.9 * checked, (checked, dotted)


def little_sheet(tmp_path, cad_font: str, home) -> np.ndarray:
    """An A3 sheet of two texts at known places, printed by LibreCAD: the Greek letters of
    the sheets (7 mm, left at x = 40, baseline y = 200) and μ with the index l (μ_l, 7 mm,
    at x = 40, y = 150), the way the sheets write a scale's name."""
    from core.drawing.sheet import PAPERS, Sheet, Text, frame_items, symbol
    from core.drawing.sheet_dxf import save_sheet_dxf
    paper = PAPERS["A3"]
    text, spans = symbol(("μ", "l"))
    items = frame_items(paper) + [Text(GREEK_LINE, (40.0, 200.0), 7.0),
                                  Text(text, (40.0, 150.0), 7.0, subscripts=spans)]
    save_sheet_dxf(Sheet(paper, tuple(items)), tmp_path / f"{cad_font}.dxf", cad_font)
    return printed(tmp_path, cad_font, home)


@pytest.mark.parametrize("cad_font", ["outline", "gb"])
def test_greek_letters_print_in_librecad(tmp_path, homes, cad_font):
    """Each Greek letter of the sheets has ink where it stands, in the GB DXF where LibreCAD
    has wqy-unicode.lff too: it left every one out of the GB DXF when they were in the style
    GB (its line printed no ink at all)."""
    ink = little_sheet(tmp_path, cad_font, homes["wqy"])
    line = cell(ink, 30.0, 150.0, 198.0, 11.0)
    columns = np.flatnonzero(line.any(axis=0))
    letters = np.split(columns, np.flatnonzero(np.diff(columns) > 3) + 1) if columns.size else []
    mm_per_px = 25.4 / DPI
    heights = [np.ptp(np.flatnonzero(line[:, g].any(axis=1))) * mm_per_px for g in letters]
    glyphs = [h for h in heights if h > 0.6 * 7.0]        # a dot is a fraction of the height
    assert len(glyphs) == len(GREEK_LINE.split()), heights


def test_a_subscript_sits_by_its_letter_in_librecad(tmp_path, homes):
    """μ_l: the index begins within a quarter of the text's height after μ's ink ends (the
    runs are closed up by the outline font's own widths, as in the PDF)."""
    ink = little_sheet(tmp_path, "outline", homes["bare"])
    word = cell(ink, 30.0, 80.0, 146.0, 12.0)
    columns = np.flatnonzero(word.any(axis=0))
    gaps = np.diff(columns)
    assert columns.size and (gaps > 1).sum() == 1, gaps     # two glyphs: μ and l
    mm_per_px = 25.4 / DPI
    assert gaps.max() * mm_per_px < 0.25 * 7.0, gaps.max() * mm_per_px


SCHEME = ("drawing", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40",
          "--content", "scheme")


def leftmost_glyph(path) -> tuple[float, float, float, float]:
    """The box (x0, y0, x1, y1, model mm) of the first glyph of the angular dimension's text
    (θ of "θ = 30°", the scheme's only angle) in the scheme's outline DXF: the leftmost of
    the HATCH entities on the DIMENSIONS layer round that DIMENSION's text point."""
    import ezdxf
    from ezdxf import bbox
    msp = ezdxf.readfile(path).modelspace()
    (dim,) = [d for d in msp.query("DIMENSION") if d.dimtype == 2]     # the angle of two lines
    mid = dim.dxf.text_midpoint
    boxes = [bbox.extents([h]) for h in msp.query("HATCH[layer=='DIMENSIONS']")]
    near = [b for b in boxes if abs(b.center.y - mid.y) < 20.0 and abs(b.center.x - mid.x) < 80.0]
    first = min(near, key=lambda b: b.extmin.x)
    return first.extmin.x, first.extmin.y, first.extmax.x, first.extmax.y


def test_the_schemes_theta_prints_in_librecad(tmp_path, homes):
    """``--content scheme --cad-font outline``: LibreCAD prints the θ of the swing's angle
    dimension where the outline DXF has it (a glyph as tall as the outline's, filling its
    box); the default GB file, CAD's own "θ = <>", has no glyph there in a LibreCAD without
    wqy-unicode.lff (LibreCAD drew a dot elsewhere for θ; with the font it draws θ, centred
    by its own widths, left of the outline's: seen in the print, and the dimension style's
    text style is wqy-unicode, test_dxf.py). Model mm map to the print's pixels by the
    drawing's height (the hatching over the guide way to the ground under O4, no text) and
    its right end."""
    import ezdxf
    from ezdxf import bbox
    for font in ("gb", "outline"):
        done = shaper_run_in_process(*SCHEME, "--cad-font", font, "-o", str(tmp_path / f"{font}.dxf"))
        assert done.returncode == 0, done.stderr
    extents = bbox.extents(ezdxf.readfile(tmp_path / "outline.dxf").modelspace())
    x0, y0, x1, y1 = leftmost_glyph(tmp_path / "outline.dxf")
    assert 0.6 * 20.0 < y1 - y0 < 1.2 * 20.0, (y0, y1)          # a glyph of the 5 mm × 4 text
    found = {}
    for font in ("gb", "outline"):
        ink = printed(tmp_path, font, homes["bare"])
        scale = (ink.shape[0] - 1) / extents.size.y             # px per model mm
        if font == "outline":
            assert abs((ink.shape[1] - 1) / extents.size.x / scale - 1.0) < 0.01
        right, top = ink.shape[1] - 1, 0

        def px(x: float, y: float) -> tuple[int, int]:
            return round(right - (extents.extmax.x - x) * scale), round(top + (extents.extmax.y - y) * scale)
        (left, up), (end, down) = px(x0 - 1.0, y1 + 1.0), px(x1 + 1.0, y0 - 1.0)
        box = ink[up:down + 1, left:end + 1]
        rows = np.flatnonzero(box.any(axis=1))
        found[font] = ((rows[-1] - rows[0] + 1) / box.shape[0] if rows.size else 0.0, box.mean())
    span, fill = found["outline"]
    assert span > 0.8 and fill > 0.15, found
    span, fill = found["gb"]
    assert span < 0.5 and fill < 0.05, found
