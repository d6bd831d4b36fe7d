"""``shaper optimize``'s table read as a designer reads it: each varied value typed back into
``shaper analyze`` or ``shaper dynamics`` gives the optimum it stands for, with its unit,
and the objective's row names the figure it prints."""
import json
import re

import pytest

from core.base.figure_text import figure_text

from cli_runner import shaper_run_in_process as shaper

ROD = ["--crank", "110", "--K", "1.46", "--stroke", "312.6", "--rod-ratio", "0.25", "--guide", "sagitta",
       "--rpm", "60"]
# the task book's 方案 I loads (G4, J_S4, G6, P, y_P)
LOADS = ["--lever-weight", "200", "--lever-inertia", "1.1", "--ram-weight", "700", "--cut-force", "7000",
         "--cut-height", "80"]


def row(text: str, name: str) -> str:
    """The value column of the table's first row called ``name``."""
    return re.search(rf"^{re.escape(name)} +(.+)$", text, re.M).group(1)


def test_an_optimum_on_the_edge_of_validity_is_printed_inside_it():
    """max |a| falls as K → 1 until the lever reaches 100 000 mm: the optimum K = 1.0019921 sits on
    that edge, and was printed as 1.00199 (6 digits), which shaper analyze refused ("--K: must
    be ≥ 1.002 …"). Typed as printed, it is a design, and as good as the optimum."""
    run = shaper("optimize", *ROD, "--objective", "accel", "--vary", "K=1:5")
    assert run.returncode == 0, run.stderr
    k = row(run.stdout, "K (input)")
    assert re.fullmatch(r"[0-9.]+", k), k
    optimum = row(run.stdout, "optimum")
    typed = [w if w != "1.46" else k for w in ROD]
    check = shaper("analyze", *typed, "--json")
    assert check.returncode == 0, check.stderr
    # the optimum at analyze's precision of an acceleration (one precision per kind)
    a_max = json.loads(check.stdout)["speeds"][0]["a_max_m_s2"]
    assert optimum == f"{figure_text('acceleration', a_max)} m/s²", (optimum, a_max)
    assert row(run.stdout, "a_max") == optimum                # the figure rows say the same


def test_the_flywheel_objective_is_j_f_not_the_flywheel_needed():
    """With other rotating parts (--rotor) `shaper dynamics` calls J_F − J_c "flywheel needed";
    the objective is J_F itself (the sweep's flywheel_inertia_kg_m2, the same argmin), and its
    row said "J_F needed" beside J_F."""
    args = ["optimize", "--dims", "110,380,540", "--rod-ratio", "0.25", "--guide", "sagitta", "--rpm", "60",
            *LOADS, "--rotor", "0.02:15", "--objective", "flywheel", "--vary", "rod=110:270"]
    doc = json.loads(shaper(*args, "--json").stdout)
    design = doc["design"]
    dims = f"{design['crank_mm']!r},{design['frame_mm']!r},{design['lever_mm']!r}"
    dynamics = shaper("dynamics", "--dims", dims, "--rod", repr(design["rod_mm"]), "--guide",
                      repr(design["guide_mm"]), "--rpm", "60", *LOADS, "--rotor", "0.02:15", "--json")
    speed = json.loads(dynamics.stdout)["speeds"][0]
    assert doc["objective_value"] == pytest.approx(speed["flywheel_inertia_kg_m2"], rel=1e-9)
    assert doc["objective_value"] != pytest.approx(speed["flywheel_inertia_needed_kg_m2"], rel=1e-6)
    text = shaper(*args).stdout
    objective = row(text, "objective")
    assert "J_F" in objective and "needed" not in objective
    assert re.match(r"[0-9.]+ mm\b", row(text, "rod (input)"))  # a varied length with its unit
