"""``--cad-font gb|outline`` (issue 40, item 7): the words checked before any work, and what
each writes. LibreCAD's print of both is tested in test_cad_font_in_librecad."""
from __future__ import annotations

import ezdxf

from core.cli.output import UsageError, cad_font_from_args
from core.drawing import outline_text

# In this process (a drawing's process costs ~2.5 s of CPU to start); test_scheme_command.py's
# test_real_process runs the real command.
from tests.cli_runner import shaper_run_in_process as shaper

GEAR = ("gear", "--z1", "13", "--z2", "40", "--module", "6")


def test_cad_font_without_a_dxf_is_one_line_naming_it(tmp_path):
    for args in (("drawing", "--crank", "100", "--K", "1.4", "--stroke", "300", "--cad-font", "outline",
                  "-o", str(tmp_path / "s.pdf")), (*GEAR, "--cad-font", "outline")):
        done = shaper(*args)
        assert done.returncode == 2
        assert done.stderr.strip().splitlines() == ["shaper: error: --cad-font: only when a .dxf is written"]
    assert not list(tmp_path.iterdir())


SCHEME = ("drawing", "--crank", "100", "--K", "1.4", "--stroke", "300", "--content", "scheme")


def test_the_scheme_in_outline_has_no_text_of_its_own(tmp_path):
    """--content scheme --cad-font outline: the joints' names and every dimension's text are
    HATCH entities; each DIMENSION keeps its points, its text blank and its block without
    one, so CAD draws no text over the outline. The default keeps TEXT and CAD's "<>"."""
    for font in ("gb", "outline"):
        done = shaper(*SCHEME, "--cad-font", font, "-o", str(tmp_path / f"{font}.dxf"))
        assert done.returncode == 0, done.stderr
    gb, outline = (ezdxf.readfile(tmp_path / f"{font}.dxf") for font in ("gb", "outline"))
    names = {t.dxf.text for t in gb.modelspace().query("TEXT")}
    assert names == {"O2", "O4", "A", "B"}
    assert {d.dxf.text for d in gb.modelspace().query("DIMENSION")} == {
        f"{name} = <>" for name in ("L1", "L2", "L3", "h", "H", "θ")}
    msp = outline.modelspace()
    assert len(msp.query("TEXT")) == len(msp.query("MTEXT")) == 0
    dimensions = msp.query("DIMENSION")
    assert len(dimensions) == 6 and {d.dxf.text for d in dimensions} == {" "}
    assert not [e for d in dimensions for e in outline.blocks[d.dxf.geometry] if e.dxftype() == "MTEXT"]
    assert len(msp.query("HATCH[layer=='TEXT']")) >= len(names)
    measured = [e.plain_text() for d in gb.modelspace().query("DIMENSION")
                for e in gb.blocks[d.dxf.geometry] if e.dxftype() == "MTEXT"]    # "θ = 30°" …
    assert len(measured) == 6      # a glyph is one hatch or more (its holes inside it)
    assert len(msp.query("HATCH[layer=='DIMENSIONS']")) >= sum(len(t.replace(" ", "")) for t in measured)
    for font in ("gb", "outline"):      # the scheme is DXF alone, whatever the font
        done = shaper(*SCHEME, "--cad-font", font, "-o", str(tmp_path / "s.pdf"))
        assert done.returncode == 2 and "--output: the scheme is written as DXF" in done.stderr


def test_outline_writes_no_text_and_gb_writes_gb_text(tmp_path):
    """The meshing sheet (in the model's mm, scaled round the pair): with outline its texts are
    HATCH entities on the TEXT layer and no TEXT is left; the default keeps TEXT in the GB
    fonts' two styles (GB, and wqy-unicode, LibreCAD's font name, for the Greek letters)."""
    for font in ("gb", "outline"):
        done = shaper(*GEAR, "--dxf", str(tmp_path / f"{font}.dxf"), "--cad-font", font)
        assert done.returncode == 0, done.stderr
    gb = ezdxf.readfile(tmp_path / "gb.dxf").modelspace()
    outline = ezdxf.readfile(tmp_path / "outline.dxf").modelspace()
    assert len(gb.query("TEXT")) > 50 and {t.dxf.style for t in gb.query("TEXT")} == {"GB", "wqy-unicode"}
    assert len(outline.query("TEXT")) == 0
    hatches = outline.query("HATCH[layer=='TEXT']")
    assert len(hatches) > len(gb.query("TEXT")) and all(h.dxf.solid_fill for h in hatches)


def test_no_cjk_font_is_one_line_naming_the_option(monkeypatch):
    """Without a font with Chinese glyphs, --cad-font outline is refused before any work."""
    monkeypatch.setattr(outline_text, "OUTLINE_FONTS", (("no-such-font.ttf", 0, "None Such"),))
    outline_text.outline_font.cache_clear()
    try:
        args = type("Args", (), {"cad_font": "outline"})()
        try:
            cad_font_from_args(args, True)
        except UsageError as exc:
            assert str(exc).startswith("--cad-font: the outline font needs a font with Chinese glyphs")
        else:
            raise AssertionError("no UsageError")
    finally:
        outline_text.outline_font.cache_clear()
