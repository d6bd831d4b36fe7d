"""The PDFs' text layer holds the Chinese they print (issue 32, item 4): ``pdf_text``
maps the radicals Qt's PDF engine writes (the lowest code point of a shared glyph) back
to the unified ideographs, and leaves the pages as they were."""
import subprocess
import unicodedata

import pytest
from hypothesis import given, settings, strategies as st

from language_checks import control_characters, has_pdftotext, pdf_text, radicals
from shaperapp.widgets import pdf_text as repair

needs_poppler = pytest.mark.skipif(not has_pdftotext(), reason="poppler-utils not installed")

# The shape of the ToUnicode map QPdfWriter writes (Qt 6.11), with a radical in an array
# and a range that counts up.
QT_CMAP = b"""/CIDInit /ProcSet findresource begin
12 dict begin
begincmap
/CIDSystemInfo << /Registry (Adobe) /Ordering (UCS) /Supplement 0 >> def
/CMapName /Adobe-Identity-UCS def
/CMapType 2 def
1 begincodespacerange
<0000> <FFFF>
endcodespacerange
3 beginbfrange
<0000> <0000> <0000>
<0006> <000A> [<2F2F> <4F5C> <2F8F> <7A0B> <56DE> ]
<0010> <0012> <2F5C>
endbfrange
1 beginbfchar
<0020> <D835DC00>
endbfchar
endcmap
CMapName currentdict /CMap defineresource pop
end
end
"""
# Unicode's EquivalentUnifiedIdeograph.txt for the radicals the Chinese report printed
UNICODE_EQUIVALENTS = {"\u2F5C": "牛", "\u2F2F": "工", "\u2F8F": "行", "\u2EC6": "角", "\u2ED3": "长",
                       "\u2EDA": "页", "\u2EDC": "飞", "\u2EC9": "贝", "\u2F00": "一", "\u2F12": "力"}


def test_a_qt_tounicode_map_is_read_entry_by_entry():
    mapping, width = repair.parse_cmap(QT_CMAP)
    assert width == 2
    assert mapping == {0: "\x00", 6: "\u2F2F", 7: "作", 8: "\u2F8F", 9: "程", 10: "回",
                       0x10: "\u2F5C", 0x11: "\u2F5D", 0x12: "\u2F5E", 0x20: "\U0001D400"}


@settings(max_examples=60, deadline=None)
@given(st.dictionaries(st.integers(0, 0xFFFF), st.text(min_size=1, max_size=3).filter(
    lambda s: not any(0xD800 <= ord(c) <= 0xDFFF for c in s)), max_size=250))
def test_a_written_map_reads_back_as_it_was(mapping):
    assert repair.parse_cmap(repair.write_cmap(mapping, 2)) == (mapping, 2)


def test_radicals_become_the_ideographs_unicode_names_as_their_equivalents(qapp):
    for radical, ideograph in UNICODE_EQUIVALENTS.items():
        assert repair.ideograph_of(radical) == ideograph, radical
    assert repair.ideograph_of("牛") == "牛" and repair.ideograph_of("a") == "a"


def test_every_kangxi_radical_maps_to_its_compatibility_ideograph_or_one_drawn_alike(qapp):
    """NFKC is Unicode's own mapping of the Kangxi block; where the font draws the radical
    like another ideograph, that one (what is printed), and never a radical again."""
    from PySide6.QtGui import QFont, QRawFont

    from shaperapp.widgets.fonts import cjk_family
    if cjk_family() is None:
        pytest.skip("no Chinese font")
    raw = QRawFont.fromFont(QFont(cjk_family()))
    for code in range(0x2F00, 0x2FD6):
        radical = chr(code)
        mapped = repair.ideograph_of(radical)
        glyph = list(raw.glyphIndexesForString(radical))
        if mapped != radical:
            assert not repair.is_radical(mapped)
            assert mapped == unicodedata.normalize("NFKC", radical) \
                or list(raw.glyphIndexesForString(mapped)) == glyph, radical


def test_a_map_without_radicals_is_left_alone():
    assert repair.repaired_cmap(QT_CMAP.replace(b"<2F2F>", b"<5DE5>").replace(b"<2F8F>", b"<884C>")
                                .replace(b"<2F5C>", b"<725B>")) is None


def _qt_pdf(text: str, path) -> bytes:
    """``text`` painted by QPdfWriter in the Chinese report font, as Qt writes it (unrepaired)."""
    from PySide6.QtCore import QBuffer, QByteArray, QIODevice, QPointF
    from PySide6.QtGui import QPainter, QPdfWriter

    from shaperapp.widgets.fonts import report_font
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    writer = QPdfWriter(buffer)
    painter = QPainter(writer)
    painter.setFont(report_font("zh_CN", 14))
    painter.drawText(QPointF(200, 400), text)
    painter.end()
    buffer.close()
    return bytes(data.data())


@needs_poppler
def test_a_repaired_pdf_reads_as_printed_and_prints_as_before(qapp, tmp_path):
    import pikepdf
    text = "牛头刨床 导杆机构 工作行程 极位夹角 曲柄转角 页 飞轮 长度 力 大小"
    raw = _qt_pdf(text, tmp_path)
    (tmp_path / "raw.pdf").write_bytes(raw)
    assert radicals(pdf_text(tmp_path / "raw.pdf")) != []          # what Qt writes: ⽜头刨床
    (tmp_path / "fixed.pdf").write_bytes(repair.repair_text_layer(raw))
    read = pdf_text(tmp_path / "fixed.pdf")
    assert read.split() == text.split()
    assert radicals(read) == [] and control_characters(read) == []
    with pikepdf.open(tmp_path / "fixed.pdf") as doc:
        assert doc.check_pdf_syntax() == []
    for name in ("raw", "fixed"):
        subprocess.run(["pdftoppm", "-r", "100", "-gray", "-png", str(tmp_path / f"{name}.pdf"),
                        str(tmp_path / name)], check=True)
    assert (tmp_path / "raw-1.png").read_bytes() == (tmp_path / "fixed-1.png").read_bytes()


def test_a_pdf_without_radicals_comes_back_unchanged(qapp, tmp_path):
    raw = _qt_pdf("Shaper 100 mm", tmp_path)
    assert repair.repair_text_layer(raw) is raw
