"""One figure, one precision (issue 40) in ``shaper library compare``, ``list``, ``show`` and
``shaper optimize``: they printed 6 significant digits (θ 33.6585, v 0.479993 m/s, J_F
1562.73) where ``analyze``, the GUI and the sheets write lengths and angles to 3 decimals, K,
speeds and accelerations to 4, loads to 4 significant digits. The reference is the rule
written out by hand, as in ``tests/test_shaperapp/results/test_gui_one_precision.py``.
``optimize`` also showed "K" twice, the input and the measured K: now "K (input)" and
"measured K", as ``analyze`` names it."""
from __future__ import annotations

import json
import math
import re

import pytest

from cli_runner import shaper_in_process

LOADS = ("--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000",
         "--cut-height", "80")


def fixed(value: float, decimals: int) -> str:
    return f"{value:.{decimals}f}"


def significant(value: float, digits: int) -> str:
    return f"{value:.{max(digits - 1 - math.floor(math.log10(abs(value))), 0)}f}"


RULE = {"K": lambda v: fixed(v, 4), "theta_deg": lambda v: fixed(v, 3), "frame_mm": lambda v: fixed(v, 3),
        "v_work_max_m_s": lambda v: fixed(v, 4), "a_max_m_s2": lambda v: fixed(v, 4),
        "max_torque_N_m": lambda v: significant(v, 4), "flywheel_inertia_kg_m2": lambda v: significant(v, 4)}


def run(*args) -> str:
    status, out, err = shaper_in_process(*args)
    assert status == 0, err
    return out


@pytest.fixture(scope="module")
def library(tmp_path_factory):
    path = str(tmp_path_factory.mktemp("lib") / "lib.sqlite")
    for name, k in (("a", "1.46"), ("b", "1.6")):
        run("library", "add", "--crank", "100", "--K", k, "--stroke", "300", "--rpm", "40", *LOADS,
            "--name", name, "--library", path)
    return path


def test_library_compare_writes_each_figure_at_its_kinds_precision(library):
    doc = json.loads(run("library", "compare", "a", "b", "--library", library, "--json"))
    values = {f["figure"]: [f["values"]["a"], f["values"]["b"]] for f in doc["figures"]}
    text = run("library", "compare", "a", "b", "--library", library)
    lines = {line.split()[0]: line for line in text.splitlines() if line.strip()}
    for key, rule in RULE.items():
        a, b = values[key]
        diff = b - a
        sign = "+" if diff > 0 else ""
        best = r"(?: \*)?"                        # the best value's mark
        expected = f"{key} +{re.escape(rule(a))}{best} +{re.escape(rule(b))} \\({re.escape(sign + rule(diff))}\\)"
        assert re.match(expected, lines[key]), (lines[key], expected)
    show = {line.split()[0]: line.split()[1] for line in run("library", "show", "a", "--library", library)
            .splitlines() if len(line.split()) == 2}
    for key in ("K", "theta_deg", "frame_mm"):
        assert show[key] == RULE[key](values[key][0]), (key, show[key])
    listed = run("library", "list", "--library", library).splitlines()[1].split()
    assert RULE["K"](values["K"][0]) in listed and fixed(values["stroke_mm"][0], 3) in listed
    assert significant(values["flywheel_inertia_kg_m2"][0], 4) in listed, listed


def test_optimize_names_the_input_k_and_the_measured_k_apart_each_at_its_precision():
    args = ("optimize", "--crank", "100", "--K", "1.46", "--stroke", "312", "--rod-ratio", "0.3",
            "--vary", "K=1.3:1.6", "--rpm", "40", *LOADS, "--objective", "flywheel")
    doc = json.loads(run(*args, "--json"))
    text = run(*args)
    rows = dict(re.match(r"(.+?)  +(.+)$", line).groups() for line in text.splitlines())
    assert "K" not in rows and {"K (input)", "measured K"} <= rows.keys(), list(rows)
    figures = doc["figures"]
    assert rows["measured K"] == RULE["K"](figures["K"])
    assert rows["θ"] == f"{fixed(figures['theta_deg'], 3)} °"
    assert rows["v_work_max"] == f"{fixed(figures['v_work_max_m_s'], 4)} m/s"
    assert rows["a_max"] == f"{fixed(figures['a_max_m_s2'], 4)} m/s²"
    assert rows["max_torque"] == f"{significant(figures['max_torque_N_m'], 4)} N·m"
    j_f = f"{significant(figures['flywheel_inertia_kg_m2'], 4)} kg·m²"
    assert rows["flywheel_inertia"] == j_f and rows["optimum"] == j_f
    assert rows["design as given"] == f"{significant(doc['start_value'], 4)} kg·m²"
