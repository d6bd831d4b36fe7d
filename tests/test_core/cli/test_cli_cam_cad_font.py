"""``shaper cam --dxf --cad-font gb|outline``: the cam's notes and its dimension's text as
GB-style TEXT (the default) or as filled outlines, which LibreCAD draws like every CAD;
``--cad-font`` without ``--dxf`` is one line naming it."""
from __future__ import annotations

import ezdxf
import pytest

from tests.cli_runner import shaper_run_in_process as shaper
from dxf_checks import notes_of

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
    notes = [t.dxf.text for t in gb.modelspace().query("TEXT")]     # r_0 and ψ_0: a run each
    assert len(notes) == 7 + 2 * 2 and notes[:3] == ["Base radius r", "0", " (pitch curve) = 36.341 mm"]
    assert len(gb.modelspace().query("HATCH")) == 0
    assert (tmp_path / "gb.dxf").read_bytes().count(b"Base radius") == 1
    msp = outline.modelspace()
    assert len(msp.query("TEXT")) == len(msp.query("MTEXT")) == 0
    (dimension,) = msp.query("DIMENSION")
    assert dimension.dxf.text == " "
    assert not [e for e in outline.blocks[dimension.dxf.geometry] if e.dxftype() == "MTEXT"]
    assert len(msp.query("HATCH[layer=='TEXT']")) >= sum(len(t.replace(" ", "")) for t in notes)
    assert len(msp.query("HATCH[layer=='DIMENSIONS']")) >= 3         # "a = 1…"


def test_the_notes_follow_the_language_with_the_figures_of_shaper_cam(tmp_path):
    """The notes were English in both languages. With --lang zh they are the Chinese cam
    sheet's words, each with the figure shaper cam --json gives; without it, English."""
    import json
    import re
    status = shaper(*CAM, "--json")
    figures = json.loads(status.stdout)
    for lang in ("en", "zh"):
        done = shaper(*CAM, "--dxf", str(tmp_path / f"{lang}.dxf"), "--lang", lang)
        assert done.returncode == 0, done.stderr
    en, zh = notes_of(tmp_path / "en.dxf"), notes_of(tmp_path / "zh.dxf")
    assert en.splitlines()[0] == "Base radius r0 (pitch curve) = 36.341 mm"
    assert zh.splitlines()[0].startswith("理论廓线基圆半径 r0 = ") and "凸轮顺时针转动" in zh
    assert not re.search("[A-Za-z]{3,}", zh.replace(" mm", "")), zh    # no English word left
    for notes in (en, zh):
        numbers = [float(x) for x in re.findall(r"= (-?[0-9.]+)", notes)]
        expected = [figures["base_radius_mm"], figures["roller_mm"], figures["center_distance_mm"],
                    figures["arm_mm"], figures["initial_angle_deg"], figures["max_pressure_angle_rise_deg"],
                    figures["max_pressure_angle_return_deg"]]
        assert numbers[:6] + [float(notes.split(" / ")[-1].split("°")[0])] == pytest.approx(expected, abs=5e-4)
    done = shaper(*CAM, "--lang", "zh")
    assert done.returncode == 2 and done.stderr.strip() == "shaper: error: --lang: only with --dxf"
