"""The real ``shaper`` command in a subprocess: outputs, formats and refusals."""
import csv
import io
import json
import math

import numpy as np
import pytest

from core.linkage.geometry import synthesize
from core.linkage.kinematics import crank_angles, solve
from core.linkage.metrics import analyze

from cli_runner import shaper

REQUIRED = "rpm,crank_deg,time_s,ram_x_mm,ram_v_m_s,ram_a_m_s2,lever_deg,lever_omega_rad_s,lever_alpha_rad_s2"
SEED003 = ["--crank", "100", "--K", "1.4", "--stroke", "300"]


def test_synth_json_seed003():
    out = shaper("synth", *SEED003, "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["theta_deg"] == pytest.approx(30)
    assert data["frame_mm"] == pytest.approx(386.37, abs=0.005)
    assert data["lever_mm"] == pytest.approx(579.56, abs=0.005)
    assert data["h_mm"] == pytest.approx(173.44, abs=0.005)
    assert data["guide_mm"] == pytest.approx(data["h_mm"] + data["frame_mm"])
    assert data["rod_mm"] is None
    assert data["K"] == pytest.approx(1.4) and data["stroke_mm"] == pytest.approx(300)


def test_synth_rod_ratio_and_text_output():
    out = shaper("synth", *SEED003, "--rod-ratio", "0.25", "--guide", "sagitta", "--json")
    data = json.loads(out.stdout)
    assert data["rod_mm"] == pytest.approx(0.25 * data["lever_mm"])
    assert data["guide_mm"] == pytest.approx(data["lever_mm"] * (1 + math.cos(math.radians(15))) / 2)
    text = shaper("synth", *SEED003)
    assert text.returncode == 0 and "386.370 mm" in text.stdout and "173.437 mm" in text.stdout


def test_curves_csv_columns_and_values(tmp_path):
    target = tmp_path / "curves.csv"
    out = shaper("curves", *SEED003, "--rod-ratio", "0.3", "--rpm", "40", "60", "--step", "5",
                 "--csv", target)
    assert out.returncode == 0, out.stderr
    lines = target.read_text().splitlines()
    assert lines[0].startswith(REQUIRED + ",")
    rows = list(csv.DictReader(io.StringIO(target.read_text())))
    assert len(rows) == 2 * 73
    design = synthesize(100, 1.4, 300, rod_ratio=0.3)
    motion = solve(design, crank_angles(5), [40, 60])
    v = np.array([float(r["ram_v_m_s"]) for r in rows]).reshape(2, 73)
    x = np.array([float(r["ram_x_mm"]) for r in rows]).reshape(2, 73)
    assert np.allclose(v, motion.ram_v, rtol=1e-9, atol=1e-12)
    assert np.allclose(x[1], motion.ram_x, rtol=1e-9, atol=1e-9)
    assert [float(r["rpm"]) for r in rows[::73]] == [40.0, 60.0]


def test_curves_to_stdout_with_explicit_angles_and_dims():
    out = shaper("curves", "--dims", "125,275,600,150", "--guide", "575", "--rod-side", "leading",
                 "--angles", "0,90,180,270", "--rpm", "30")
    assert out.returncode == 0, out.stderr
    rows = list(csv.DictReader(io.StringIO(out.stdout)))
    assert [float(r["crank_deg"]) for r in rows] == [0, 90, 180, 270]
    assert float(rows[0]["ram_v_m_s"]) == pytest.approx(0, abs=1e-12)
    assert "rod_deg" in rows[0]


def test_analyze_json_matches_library():
    out = shaper("analyze", *SEED003, "--rpm", "40", "60", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    lib = analyze(synthesize(100, 1.4, 300), [40, 60])
    assert data["K"] == pytest.approx(1.4) and data["stroke_mm"] == pytest.approx(300)
    assert data["theta_deg"] == pytest.approx(30)
    for got, want in zip(data["speeds"], lib.speeds):
        assert got["rpm"] == want.rpm
        for key in ("v_work_max_m_s", "v_return_max_m_s", "a_max_m_s2"):
            assert got[key] == pytest.approx(getattr(want, key))
    # The return stroke is quicker: a quick-return mechanism.
    assert data["speeds"][0]["v_return_max_m_s"] > data["speeds"][0]["v_work_max_m_s"]


@pytest.mark.parametrize("args, option", [
    (["synth", "--crank", "100", "--K", "0.8", "--stroke", "300"], "--K"),
    (["synth", "--crank", "abc", "--K", "1.4", "--stroke", "300"], "--crank"),
    (["synth", "--crank", "-1", "--K", "1.4", "--stroke", "300"], "--crank"),
    (["synth", "--crank", "100", "--K", "1.4", "--stroke", "nan"], "--stroke"),
    (["synth", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod", "3"], "--rod"),
    (["synth", "--crank", "100", "--K", "1.4", "--stroke", "300", "--guide", "up"], "--guide"),
    (["curves", *SEED003, "--rpm", "0"], "--rpm"),
    (["curves", *SEED003, "--rpm", "-40"], "--rpm"),
    (["curves", *SEED003, "--rpm", "1e9"], "--rpm"),
    (["curves", *SEED003, "--step", "0"], "--step"),
    (["curves", *SEED003, "--step", "1e-9"], "--step"),
    (["curves", *SEED003, "--angles", "0,x"], "--angles"),
    (["curves", "--dims", "300,250,800"], "--dims (L1)"),
    (["curves", "--dims", "1,2"], "--dims"),
    (["curves", "--crank", "100"], "--K"),
    (["analyze", *SEED003, "--rod-ratio", "-0.3"], "--rod-ratio"),
    (["curves", *SEED003, "--rod-side", "up"], "--rod-side"),
    (["curves", *SEED003, "--csv", "/nonexistent-dir/x.csv"], "--csv"),
])
def test_bad_input_exits_2_with_one_line(args, option):
    out = shaper(*args)
    assert out.returncode == 2
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1, out.stderr
    assert option in lines[0]
    assert "Traceback" not in out.stderr and out.stdout == ""


def test_failed_csv_write_leaves_old_file(tmp_path):
    target = tmp_path / "keep.csv"
    target.write_text("old\n")
    out = shaper("curves", *SEED003, "--step", "0", "--csv", target)
    assert out.returncode == 2
    assert target.read_text() == "old\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keep.csv"]


def test_python_m_core_is_the_same_command():
    import subprocess
    import sys
    out = subprocess.run([sys.executable, "-m", "core", "synth", *SEED003, "--json"],
                         capture_output=True, text=True)
    assert json.loads(out.stdout)["lever_mm"] == pytest.approx(579.5554957734411)
