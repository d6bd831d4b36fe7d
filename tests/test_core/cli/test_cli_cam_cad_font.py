"""``shaper cam --dxf --cad-font gb|outline``: the cam's notes and its dimension's text as
GB-style TEXT (the default) or as filled outlines, which LibreCAD draws like every CAD;
``--cad-font`` without ``--dxf`` is one line naming it."""
from __future__ import annotations

import ezdxf

from tests.cli_runner import shaper_run_in_process as shaper

CAM = ("cam", "--arm", "120", "--swing", "15", "--pressure", "40", "--rise", "60", "--dwell", "10",
       "--return", "60")


def test_cad_font_without_dxf_is_one_line_naming_it(tmp_path):
    done = shaper(*CAM, "--cad-font", "outline", "--csv", str(tmp_path / "c.csv"))
    assert done.returncode == 2
    assert done.stderr.strip().splitlines() == ["shaper: error: --cad-font: only when a .dxf is written"]
    assert not list(tmp_path.iterdir())


def test_outline_writes_the_notes_and_the_dimension_as_hatches(tmp_path):
    for font in ("gb", "outline"):
        done = shaper(*CAM, "--dxf", str(tmp_path / f"{font}.dxf"), "--cad-font", font)
        assert done.returncode == 0, done.stderr
    gb, outline = (ezdxf.readfile(tmp_path / f"{font}.dxf") for font in ("gb", "outline"))
    notes = [t.dxf.text for t in gb.modelspace().query("TEXT")]
    assert len(notes) == 3 and notes[0].startswith("base radius r0 = ")
    assert len(gb.modelspace().query("HATCH")) == 0
    assert (tmp_path / "gb.dxf").read_bytes().count(b"base radius") == 1
    msp = outline.modelspace()
    assert len(msp.query("TEXT")) == len(msp.query("MTEXT")) == 0
    (dimension,) = msp.query("DIMENSION")
    assert dimension.dxf.text == " "
    assert not [e for e in outline.blocks[dimension.dxf.geometry] if e.dxftype() == "MTEXT"]
    assert len(msp.query("HATCH[layer=='TEXT']")) >= sum(len(t.replace(" ", "")) for t in notes)
    assert len(msp.query("HATCH[layer=='DIMENSIONS']")) >= 3         # "a = 1…"
