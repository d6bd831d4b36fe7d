"""``shaper design`` (issue 41, item 4): a design file from the options, checked as every
subcommand checks them, readable by the design file's reader and the GUI's; laid over
--design; bad input one line naming the option and nothing written."""
from __future__ import annotations

import json
import math
import re

import pytest

from cli_runner import shaper_in_process
from core.files.design_file import load_design
from core.linkage.kinematics import angle_count

LOADS = ("--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000",
         "--cut-height", "80")
CAM = ("--arm", "125", "--swing", "15", "--pressure", "40", "--rise", "75", "--dwell", "10", "--return", "75")
GEAR = ("--z1", "13", "--z2", "40", "--module", "6")


def design(tmp_path, *words, name="d.shaper.json"):
    out = tmp_path / name
    status, stdout, err = shaper_in_process("design", *words, "-o", out)
    return status, out, err


def test_every_part_from_the_options_reads_back(tmp_path):
    status, out, err = design(tmp_path, "--dims", "110,380,540", "--rod-ratio", "0.25", "--guide", "sagitta",
                              "--rpm", "60", "72", "--step", "0.5", *LOADS, *CAM, *GEAR)
    assert status == 0, err
    doc = load_design(out)               # the GUI's and every --design's reader
    spec = doc["spec"]
    assert (spec.mode, spec.crank, spec.frame, spec.lever) == ("dimensions", 110.0, 380.0, 540.0)
    assert (spec.variant, spec.rod_input, spec.rod_ratio, spec.guide_rule) == ("rod", "ratio", 0.25, "sagitta")
    assert doc["rpm"] == [60.0, 72.0] and doc["step_deg"] == 0.5
    masses = doc["masses"]
    assert (masses.lever_mass_kg, masses.lever_inertia_kg_m2, masses.ram_mass_kg, masses.cut_force_N,
            masses.cut_height_mm) == (20.0, 1.1, 70.0, 7000.0, 80.0)
    assert {k: doc["cam"][k] for k in ("arm_mm", "swing_deg", "pressure_deg", "rise_deg", "dwell_deg",
                                        "return_deg")} == {"arm_mm": 125.0, "swing_deg": 15.0, "pressure_deg": 40.0,
                                                           "rise_deg": 75.0, "dwell_deg": 10.0, "return_deg": 75.0}
    assert (doc["gear"]["z1"], doc["gear"]["z2"], doc["gear"]["module_mm"]) == (13, 40, 6.0)
    # and the course can be made from it: every subcommand takes it
    for command in ("synth", "analyze", "dynamics", "cam", "gear"):
        status, _, err = shaper_in_process(command, "--design", out, "--json")
        assert status == 0, (command, err)


@pytest.mark.parametrize("words, named", [
    (("--crank", "100", "--K", "0.9", "--stroke", "300"), "--K:"),
    (("--dims", "110,380,-1"), "--dims (L3):"),
    (("--crank", "100", "--K", "1.4", "--stroke", "300", "--ram-mass", "-3"), "--ram-mass:"),
    (("--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "0"), "--rpm:"),
    (("--crank", "100", "--K", "1.4", "--stroke", "300", "--arm", "120"), "--swing: required"),
    (("--crank", "100", "--K", "1.4", "--stroke", "300", "--z1", "3", "--z2", "40", "--module", "5"), "--z1:"),
    (("--crank", "100", "--K", "1.4", "--stroke", "300", "--step", "0"), "--step:"),
    (("--K", "1.4", "--stroke", "300"), "--crank: required"),
])
def test_a_bad_value_is_one_line_naming_its_option_and_nothing_is_written(tmp_path, words, named):
    status, out, err = design(tmp_path, *words)
    assert status == 2 and err.startswith(f"shaper: error: {named}") and err.count("\n") == 1, err
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_options_change_the_files_values_and_keep_the_rest(tmp_path):
    status, base, err = design(tmp_path, "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod-ratio", "0.3",
                               "--rpm", "40", *LOADS, *CAM, *GEAR, name="base.json")
    assert status == 0, err
    status, out, err = design(tmp_path, "--design", base, "--crank", "110", "--cut-force", "9000", "--z1", "14")
    assert status == 0, err
    doc, was = load_design(out), load_design(base)
    # the synthesized base's K and H are kept when only L1 is given; the rod stays
    assert (doc["spec"].crank, doc["spec"].time_ratio, doc["spec"].stroke) == (110.0, 1.4, 300.0)
    assert (doc["spec"].variant, doc["spec"].rod_ratio) == ("rod", 0.3)
    assert doc["masses"].cut_force_N == 9000.0 and doc["masses"].ram_mass_kg == was["masses"].ram_mass_kg
    assert doc["gear"]["z1"] == 14 and doc["gear"]["z2"] == 40 and doc["cam"] == was["cam"]
    assert doc["rpm"] == [40.0]


def test_a_dimensions_base_refuses_part_of_a_synthesis(tmp_path):
    status, base, _ = design(tmp_path, "--dims", "110,380,540", name="base.json")
    status, out, err = design(tmp_path, "--design", base, "--K", "1.5")
    assert status == 2 and "--K: the design file gives its linkage by dimensions" in err
    assert not out.exists()


def test_the_classic_data_sets_give_the_hand_formulas(tmp_path):
    """孙桓《机械原理》课程设计指导书, 牛头刨床导杆机构, 方案 I–III (l_O2A, l_O2O4, l_O4B): for the
    crank and slotted lever θ = 2·asin(l_O2A/l_O2O4), H = 2·l_O4B·sin(θ/2), K = (180°+θ)/(180°−θ)."""
    for crank, frame, lever in ((110, 380, 540), (90, 350, 580), (110, 430, 810)):
        status, out, err = design(tmp_path, "--dims", f"{crank},{frame},{lever}", "--rod-ratio", "0.3")
        assert status == 0, err
        status, text, err = shaper_in_process("synth", "--design", out, "--json")
        got = json.loads(text)
        theta = 2 * math.asin(crank / frame)
        assert got["theta_deg"] == pytest.approx(math.degrees(theta), rel=1e-12)
        assert got["stroke_mm"] == pytest.approx(2 * lever * math.sin(theta / 2), rel=1e-12)
        assert got["K"] == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-12)


SEED = ("--crank", "100", "--K", "1.4", "--stroke", "300")
SIXTEEN = tuple(str(10 * (i + 1)) for i in range(16))      # 10 … 160 r/min


def test_a_step_over_the_design_files_limit_is_refused_and_its_advice_is_taken(tmp_path):
    """16 speeds at 0.05° are 16 × (360/0.05 + 1) = 115 216 samples, more than a design file
    holds (60 000, what the GUI recomputes on an edit): refused in one line naming --step,
    the limit and the coarsest step that fits; that step, typed, is accepted, and a step
    finer by one unit of its last digit is not (so it is the coarsest that fits)."""
    status, out, err = design(tmp_path, *SEED, "--rpm", *SIXTEEN, "--step", "0.05")
    assert status == 2 and err.count("\n") == 1 and not out.exists(), err
    assert err.startswith("shaper: error: --step: gives 115216 samples (angles × speeds) with 16 speeds")
    assert "more than a design file holds (60000)" in err and "(got 0.05)" in err
    advice = re.search(r"use a step of at least (\S+)°", err).group(1)
    status, out, err = design(tmp_path, *SEED, "--rpm", *SIXTEEN, "--step", advice)
    assert status == 0, err
    doc = load_design(out)
    assert doc["step_deg"] == float(advice) and 16 * angle_count(float(advice)) <= 60_000
    digits = len(advice.split(".")[1])
    finer = f"{float(advice) - 10.0 ** -digits:.{digits}f}"
    status, _, err = design(tmp_path, *SEED, "--rpm", *SIXTEEN, "--step", finer, name="finer.json")
    assert status == 2 and "--step:" in err


def over_the_limit(tmp_path):
    """A design file over the limit, as ``shaper design`` wrote it before the limit."""
    path = tmp_path / "fine.shaper.json"
    path.write_text(json.dumps({"format": "shaper-design", "version": 1,
                                "spec": {"crank": 100, "time_ratio": 1.4, "stroke": 300},
                                "rpm": [float(r) for r in SIXTEEN], "step_deg": 0.05}), encoding="utf-8")
    return path


def test_a_file_over_the_limit_is_refused_by_every_reader_and_the_library(tmp_path):
    path = over_the_limit(tmp_path)
    library = tmp_path / "lib.sqlite"
    for words in (("analyze", "--design", path), ("design", "--design", path, "-o", tmp_path / "o.json"),
                  ("library", "add", "--library", library, "--design", path, "--name", "fine")):
        status, out, err = shaper_in_process(*words)
        assert status == 2 and err.count("\n") == 1 and out == "", (words, err)
        assert err.startswith("shaper: error: --design: ") and "more than a design file holds (60000)" in err
    status, out, err = shaper_in_process("library", "add", "--library", library, *SEED, "--rpm", *SIXTEEN,
                                         "--step", "0.05", "--name", "fine")
    assert status == 2 and err.startswith("shaper: error: --step: ") and err.count("\n") == 1, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fine.shaper.json"]     # nothing written


def test_a_command_that_writes_no_design_file_keeps_its_own_limit(tmp_path):
    """``shaper curves`` computes up to core's 2 000 000 samples: 115 216 rows are written."""
    csv = tmp_path / "curves.csv"
    status, out, err = shaper_in_process("curves", *SEED, "--rpm", *SIXTEEN, "--step", "0.05", "--csv", csv)
    assert status == 0, err
    with open(csv, encoding="utf-8") as rows:
        assert sum(1 for _ in rows) == 1 + 115_216
