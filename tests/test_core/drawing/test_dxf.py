"""The shared DXF document: millimetres, the standard's layers and linetypes, audited writes."""
from __future__ import annotations

import ezdxf
import pytest

from core.drawing import dxf


def test_document_is_in_millimetres_with_every_layer(tmp_path):
    doc = dxf.new_document()
    doc.modelspace().add_line((0, 0), (100, 0), dxfattribs={"layer": dxf.CENTER})
    path = tmp_path / "t.dxf"
    dxf.save_dxf(doc, path)
    back = ezdxf.readfile(path)
    assert back.header["$INSUNITS"] == 4 and back.header["$MEASUREMENT"] == 1
    for name, layer in dxf.LAYERS.items():
        read = back.layers.get(name)
        assert (read.dxf.linetype, read.dxf.lineweight, read.dxf.color) == \
            (layer.linetype, layer.lineweight, layer.color)
    assert not back.audit().has_errors


@pytest.mark.parametrize("name", sorted(dxf.LINETYPES))
def test_linetype_patterns_follow_gb_4457_4(name):
    """Dash 12d and gap 3d (dashed), long dash 24d, gap 3d, dot 0.5d (centre), d = 0.5 mm,
    and the total equal to the sum of the elements (a CAD program trusts the total)."""
    d = dxf.THICK_MM
    expected = {dxf.DASHED_LINETYPE: [12 * d, -3 * d], dxf.CENTER_LINETYPE: [24 * d, -3 * d, 0.5 * d, -3 * d]}
    total, *elements = dxf.LINETYPES[name][1]
    assert elements == pytest.approx(expected[name])
    assert total == pytest.approx(sum(abs(e) for e in elements))


def test_chinese_text_survives_the_round_trip(tmp_path):
    doc = dxf.new_document()
    doc.modelspace().add_text("曲柄 L1 = 100 mm", height=5,
                              dxfattribs={"layer": dxf.TEXT, "style": dxf.TEXT_STYLE})
    dxf.save_dxf(doc, tmp_path / "zh.dxf")
    back = ezdxf.readfile(tmp_path / "zh.dxf")
    assert [t.dxf.text for t in back.modelspace().query("TEXT")] == ["曲柄 L1 = 100 mm"]


def test_faulty_document_is_refused_before_anything_is_written(tmp_path):
    doc = dxf.new_document()
    line = doc.modelspace().add_line((0, 0), (1, 0))
    line.dxf.linetype = "NO_SUCH_LINETYPE"  # CAD would drop it: the audit "fixes" it
    path = tmp_path / "old.dxf"
    path.write_text("old")
    with pytest.raises(dxf.DxfAuditError):
        dxf.save_dxf(doc, path)
    assert path.read_text() == "old"


def test_texts_beyond_latin_1_name_the_font_librecad_has_for_them(tmp_path):
    """Every text of a Chinese sheet with a character beyond Latin-1 (Chinese, Greek, −) is in
    the style wqy-unicode, the rest in GB, all runs of one text alike; both styles name the GB
    fonts (what AutoCAD, ZWCAD and GstarCAD draw with), and so does the dimensions' text
    style. LibreCAD draws a text in its font named like the style: GB gave its standard
    font, without Chinese or Greek (test_cad_font_in_librecad.py prints both)."""
    from tests.cli_runner import shaper_run_in_process
    done = shaper_run_in_process("drawing", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40",
                                 "--lang", "zh", "--sheet", "A3", "-o", str(tmp_path / "m.dxf"))
    assert done.returncode == 0, done.stderr
    doc = ezdxf.readfile(tmp_path / "m.dxf")
    for name in (dxf.TEXT_STYLE, dxf.UNICODE_STYLE):
        style = doc.styles.get(name)
        assert (style.dxf.font, style.dxf.bigfont, style.dxf.width) == ("gbenor.shx", "gbcbig.shx", 0.7)
    from core.drawing.dimensions import DIMSTYLE
    assert doc.dimstyles.get(DIMSTYLE).dxf.dimtxsty == dxf.UNICODE_STYLE
    styles = {}
    for text in doc.modelspace().query("TEXT"):
        styles.setdefault(text.dxf.style, set()).add(text.dxf.text)
    wide = [t for t in styles[dxf.TEXT_STYLE] if any(ord(ch) > 0xFF for ch in t)]
    assert not wide, wide
    assert any("曲柄" in t for t in styles[dxf.UNICODE_STYLE])
    assert any("μ" in t for t in styles[dxf.UNICODE_STYLE])
    latin = {t for t in styles[dxf.UNICODE_STYLE] if all(ord(ch) <= 0xFF for ch in t)}
    assert latin, "a subscript run of a Chinese text keeps its text's style"
    assert len(styles[dxf.TEXT_STYLE]) > 20                    # the figures and the axes' ticks
