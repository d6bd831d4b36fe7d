"""The sheets' width estimate against the fonts that draw them: each character's stored
advance (``core.drawing.advances``) is this machine's fonts' (``tools/text_advances.py``);
a text of the sheets' characters is never drawn squeezed, in the PDF's font nor in the
DXF's outline font, and its estimate is not much wider than the PDF draws it; the gear
sheet's "6 mm" and "78.0000 mm" come out unsqueezed (they were condensed beside their
neighbours)."""
import importlib.util
import string
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PySide6.QtGui import QFontInfo, QFontMetricsF

import shaperapp.drawing.render as render
from cli_runner import shaper_in_process
from core.drawing.advances import ADVANCES, KERNS
from core.drawing.sheet import Text, text_width
from shaperapp.widgets.fonts import PREFERRED_LATIN, latin_family, prefer_simplified_chinese, report_font
from shaperapp.widgets.sheet_paint import _drawn_width

TOOL = Path(__file__).resolve().parents[3] / "tools" / "text_advances.py"
GEAR = ["--z1", "13", "--z2", "40", "--module", "6", "--centre", "162"]
# what the sheets write besides letters and digits
SYMBOLS = " .,:;()/-+=*′°≥≤·×≈…−±αβγδεθλμπρστφωΔΣΩ"
LATIN = string.ascii_letters + string.digits + SYMBOLS


@pytest.fixture(scope="module")
def tool():
    spec = importlib.util.spec_from_file_location("text_advances", TOOL)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def fonts(qapp):
    """The PDF's font and its metrics as ``sheet_paint`` takes them; skipped where the font
    the table was measured in is not installed (another machine's fonts differ)."""
    prefer_simplified_chinese()
    if latin_family() != PREFERRED_LATIN[0]:
        pytest.skip(f"the table is measured in {PREFERRED_LATIN[0]}, not installed here")
    font = report_font("en")
    font.setPixelSize(100)
    metrics = QFontMetricsF(font)
    return metrics, metrics.capHeight()


@pytest.fixture(scope="module")
def outline(qapp):
    """The DXF's outline font, skipped where no CJK TrueType font is installed."""
    from core.drawing.outline_text import OutlineFontMissing, outline_font
    try:
        return outline_font()
    except OutlineFontMissing as missing:
        pytest.skip(str(missing))


def test_the_stored_table_is_this_machines_fonts(fonts, outline, tool):
    assert QFontInfo(report_font("en")).family() == PREFERRED_LATIN[0]
    advances, kerns = tool.measured()
    assert set(advances) == set(ADVANCES) and set(kerns) == set(KERNS)
    off = {ch: (ADVANCES[ch], value) for ch, value in advances.items()
           if abs(ADVANCES[ch] - value) > 0.002}
    off.update({pair: (KERNS[pair], value) for pair, value in kerns.items() if abs(KERNS[pair] - value) > 0.002})
    assert not off, f"run tools/text_advances.py again: {off}"


def test_the_table_holds_each_font_below_it(fonts, tool):
    """Independent of the tool's max: each character in the PDF's font, measured here, is no
    wider than its stored advance, and for the PDF's own font (DejaVu Sans) close to it."""
    metrics, cap = fonts
    for ch in LATIN:
        drawn = metrics.horizontalAdvance(ch) / cap
        assert drawn <= ADVANCES[ch] + 1e-9, ch
    assert ADVANCES["m"] == pytest.approx(metrics.horizontalAdvance("m") / cap, abs=0.002)
    assert ADVANCES["i"] < 0.5 < 1.2 < ADVANCES["m"] + ADVANCES["i"]


@settings(max_examples=300, deadline=None)
@given(text=st.text(alphabet=LATIN, min_size=1, max_size=40), height=st.sampled_from([2.5, 3.5, 5.0, 7.0]))
def test_a_text_is_never_drawn_squeezed_nor_estimated_much_wider(fonts, text, height):
    metrics, cap = fonts
    item = Text(text, (0.0, 0.0), height)
    natural = metrics.horizontalAdvance(text) * height / cap
    width, squeeze = _drawn_width(item, metrics, cap)
    assert squeeze >= 0.99, (text, squeeze)
    if text.strip():
        # the font kerns some pairs (T and r: 0.2 h closer), the estimate does not: one
        # such pair's room beside the 10 %
        assert item.width <= 1.10 * natural + 0.25 * height, (text, item.width, natural)


@settings(max_examples=100, deadline=None)
@given(text=st.text(alphabet=LATIN.replace("·", ""), min_size=1, max_size=40))
def test_the_dxf_outline_font_is_never_squeezed_either(outline, text):
    from core.drawing.dxf import TEXT_WIDTH
    from core.drawing.outline_text import squeeze
    assert squeeze(Text(text, (0.0, 0.0), 3.5), outline) >= 0.99 * TEXT_WIDTH


def test_the_outline_fonts_wide_dot_is_not_squeezed_among_letters(outline):
    """The CJK font's · is full width, the table's the PDF's (``tools/text_advances.py``
    leaves the outline's out): among the digits and letters of the gear table's row the
    outline's narrower Latin makes up for it."""
    from core.drawing.dxf import TEXT_WIDTH
    from core.drawing.outline_text import squeeze
    for text in ("≥ 0.25·m (= 1.5 mm)", "0.25·m", "m·s"):
        assert squeeze(Text(text, (0.0, 0.0), 3.5), outline) == pytest.approx(TEXT_WIDTH), text


def test_the_gear_sheets_values_are_drawn_unsqueezed(fonts, monkeypatch):
    metrics, cap = fonts
    built = []
    monkeypatch.setattr(render, "write_sheet", lambda sheet, *args, **kwargs: built.append(sheet))
    status, _, err = shaper_in_process("drawing", "--content", "gear", "--sheet", "A3", "--lang", "en",
                                       *GEAR, "-o", "unwritten.pdf")
    assert status == 0, err
    texts = {item.text: item for item in built[0].items if isinstance(item, Text)}
    for value in ("6 mm", "78.0000 mm", "Module m", "Shift factor x"):
        assert _drawn_width(texts[value], metrics, cap)[1] == pytest.approx(1.0), value
    # the table's values in one height: a value of the pair fills both gears' columns
    # ("162.0000 (159.0000) mm" was a size smaller in the pinion's column beside an empty one)
    values = ("6 mm", "78.0000 mm", "13", "162.0000 (159.0000) mm", "0.500000, 0.033475", "62.6124, 25.2166 mm")
    assert {texts[value].height for value in values} == {3.5}
    pinion, gear = texts["13"], texts["40"]
    assert texts["6 mm"].position[0] == pytest.approx((pinion.position[0] + gear.position[0]) / 2.0)


def test_the_chinese_sheets_letters_beside_chinese_are_unsqueezed(fonts, monkeypatch):
    """The Chinese characters are condensed to the square the sheet reckons them, the
    letters after them not ("模数 m" was one squeeze for the whole text, its m condensed)."""
    font = report_font("zh_CN")
    font.setPixelSize(100)
    metrics = QFontMetricsF(font)
    cap = metrics.capHeight()
    built = []
    monkeypatch.setattr(render, "write_sheet", lambda sheet, *args, **kwargs: built.append(sheet))
    status, _, err = shaper_in_process("drawing", "--content", "gear", "--sheet", "A3", "--lang", "zh",
                                       *GEAR, "-o", "unwritten.pdf")
    assert status == 0, err
    texts = {item.text: item for item in built[0].items if isinstance(item, Text)}
    for value in ("模数 m", "变位系数 x", "齿数 z"):
        width, squeeze = _drawn_width(texts[value], metrics, cap)
        assert squeeze == pytest.approx(1.0) and width <= texts[value].width + 1e-9, value
