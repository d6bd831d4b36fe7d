"""``shaper dynamics`` run as the installed console script, in a subprocess."""
from __future__ import annotations

import csv
import io
import json
import math
import shutil
import subprocess
import sys

import numpy as np
import pytest

from core.forces.dynamics import solve_dynamics
from core.forces.masses import MassProperties

from core.forces.flywheel import summarize
from core.linkage.geometry import synthesize
from core.linkage.kinematics import crank_angles

COMMAND = [shutil.which("shaper")] if shutil.which("shaper") else [sys.executable, "-m", "core"]
DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300"]
LOADS = ["--lever-mass", "22", "--lever-inertia", "0.7", "--ram-mass", "55",
         "--cut-force", "2500", "--cut-height", "60", "--idle", "0.06", "--delta", "0.04"]


def shaper(*words: str) -> subprocess.CompletedProcess:
    return subprocess.run([*COMMAND, *words], capture_output=True, text=True, timeout=120)


def masses(**extra) -> MassProperties:
    values = dict(lever_mass_kg=22, lever_inertia_kg_m2=0.7, ram_mass_kg=55, cut_force_N=2500,
                  cut_height_mm=60, idle_fraction=0.06, delta=0.04)
    values.update(extra)
    return MassProperties(**values)


def read_csv(text: str) -> tuple[list[str], np.ndarray]:
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], np.array(rows[1:], dtype=float)


def test_csv_header_and_values_match_the_library():
    run = shaper("dynamics", *DESIGN, "--rod-ratio", "0.4", "--rpm", "40", "60", "--step", "5",
                 *LOADS, "--ram-cg=-12,30", "--rod-mass", "4", "--csv", "-")
    assert run.returncode == 0, run.stderr
    assert run.stderr == ""
    header, data = read_csv(run.stdout)
    assert header[:4] == ["rpm", "crank_deg", "crank_torque_N_m", "power_W"]
    for name in ("O2_x_N", "O2_y_N", "A_x_N", "A_y_N", "O4_x_N", "O4_y_N", "B_x_N", "B_y_N",
                 "C_x_N", "C_y_N", "guide_normal_N", "guide_offset_mm", "cut_force_N"):
        assert name in header
    design = synthesize(100, 1.4, 300, rod_ratio=0.4)
    dyn = solve_dynamics(design, crank_angles(5.0), [40, 60],
                         masses(ram_cg_mm=(-12, 30), rod_mass_kg=4))
    assert data.shape == (2 * 73, len(header))
    np.testing.assert_allclose(data[:, 0], np.repeat([40.0, 60.0], 73))
    np.testing.assert_allclose(data[:, 1], np.tile(np.arange(0, 361, 5.0), 2))
    scale = np.abs(dyn.crank_torque).max()
    np.testing.assert_allclose(data[:, 2], dyn.crank_torque.ravel(), rtol=1e-9, atol=1e-9 * scale)
    np.testing.assert_allclose(data[:, header.index("C_y_N")], dyn.c_y.ravel(), rtol=1e-9,
                               atol=1e-9 * np.abs(dyn.c_y).max())
    assert set(np.unique(data[:, header.index("cut_force_N")])) == {0.0, 2500.0}


def test_block_variant_csv_has_no_rod_columns(tmp_path):
    target = tmp_path / "forces.csv"
    run = shaper("dynamics", *DESIGN, "--rpm", "50", "--angles", "0,45,90", *LOADS, "--csv", str(target))
    assert run.returncode == 0, run.stderr
    assert run.stdout == ""
    header, data = read_csv(target.read_text())
    assert header[:4] == ["rpm", "crank_deg", "crank_torque_N_m", "power_W"]
    assert "C_x_N" not in header and data.shape[0] == 3


def test_json_keys_and_values_match_the_library():
    run = shaper("dynamics", *DESIGN, "--rpm", "30", "72", *LOADS, "--no-gravity", "--json")
    assert run.returncode == 0, run.stderr
    doc = json.loads(run.stdout)
    design = synthesize(100, 1.4, 300)
    expected = summarize(design, [30, 72], masses(gravity=False))
    assert doc["variant"] == "block"
    assert doc["inputs"]["gravity"] is False and doc["inputs"]["delta"] == 0.04
    assert doc["inputs"]["lever_cg_mm"] == pytest.approx(design.lever / 2)
    assert doc["equivalent_inertia_mean_kg_m2"] == pytest.approx(expected.equivalent_inertia_mean_kg_m2)
    assert [s["rpm"] for s in doc["speeds"]] == [30.0, 72.0]
    for got, want in zip(doc["speeds"], expected.speeds):
        for key in ("rpm", "mean_torque_N_m", "max_torque_N_m", "mean_power_W",
                    "energy_fluctuation_J", "flywheel_inertia_kg_m2", "flywheel_inertia_net_kg_m2"):
            assert key in got
        assert got["mean_torque_N_m"] == pytest.approx(want.mean_torque_N_m, rel=1e-12)
        assert got["max_torque_N_m"] == pytest.approx(want.max_torque_N_m, rel=1e-12)
        assert got["energy_fluctuation_J"] == pytest.approx(want.energy_fluctuation_J, rel=1e-12)
        assert got["flywheel_inertia_kg_m2"] == pytest.approx(want.flywheel_inertia_kg_m2, rel=1e-12)
        # Independent of the library: the mean torque is the cut work per radian.
        assert got["mean_torque_N_m"] == pytest.approx(2500 * 0.88 * 0.300 / (2 * math.pi), rel=1e-9)
        assert got["mean_power_W"] == pytest.approx(got["mean_torque_N_m"] * got["rpm"] * math.pi / 30)


def test_plain_summary_is_human_readable():
    run = shaper("dynamics", *DESIGN, "--rpm", "40", *LOADS)
    assert run.returncode == 0, run.stderr
    assert "40 r/min" in run.stdout and "flywheel" in run.stdout and "N·m" in run.stdout


@pytest.mark.parametrize("words,option", [
    (["--lever-mass", "-3"], "--lever-mass"),
    (["--ram-mass", "heavy"], "--ram-mass"),
    (["--lever-inertia", "nan"], "--lever-inertia"),
    (["--cut-force", "-1"], "--cut-force"),
    (["--delta", "0"], "--delta"),
    (["--delta", "1.5"], "--delta"),
    (["--idle", "0.5"], "--idle"),
    (["--ram-cg", "5"], "--ram-cg"),
    (["--lever-cg", "inf"], "--lever-cg"),
    (["--rod-mass", "2"], "--rod-mass"),       # the block variant has no rod
    (["--rpm", "-4"], "--rpm"),
    (["--step", "0"], "--step"),
])
def test_bad_input_exits_2_naming_the_option(words, option):
    base = dict(zip(LOADS[::2], LOADS[1::2]))
    for key, value in zip(words[::2], words[1::2]):
        base[key] = value
    argv = [w for pair in base.items() for w in pair]
    if "--rpm" not in base:
        argv += ["--rpm", "40"]
    run = shaper("dynamics", *DESIGN, *argv)
    assert run.returncode == 2
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0], run.stderr
    assert "Traceback" not in run.stderr


def test_missing_required_load_and_stdout_clash_are_usage_errors():
    run = shaper("dynamics", *DESIGN, "--rpm", "40", "--lever-mass", "1", "--lever-inertia", "0",
                 "--ram-mass", "1")
    assert run.returncode == 2 and "--cut-force" in run.stderr and len(run.stderr.strip().splitlines()) == 1
    run = shaper("dynamics", *DESIGN, "--rpm", "40", *LOADS, "--csv", "-", "--json")
    assert run.returncode == 2 and len(run.stderr.strip().splitlines()) == 1


def test_existing_subcommands_still_work():
    run = shaper("curves", *DESIGN, "--rpm", "40", "--step", "90")
    assert run.returncode == 0 and run.stdout.startswith("rpm,crank_deg,time_s,")
    run = shaper("analyze", *DESIGN, "--rpm", "40", "--json")
    assert run.returncode == 0 and json.loads(run.stdout)["K"] == pytest.approx(1.4, rel=1e-9)
