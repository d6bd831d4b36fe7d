"""``shaper sweep`` and ``shaper optimize`` run as a user would: formats, values, refusals."""
import csv
import io
import json
import math

import pytest

from core.forces.masses import MassProperties

from core.forces.flywheel import summarize
from core.linkage.geometry import synthesize
from core.linkage.metrics import analyze

# What the commands write, run in this process (each process costs its start-up); the first
# sweep and the optimizer's text run as the real command.
from cli_runner import shaper as real_shaper
from cli_runner import shaper_run_in_process as shaper

BASE = ["--crank", "100", "--K", "1.46", "--stroke", "312"]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000"]


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_sweep_csv_columns_and_values():
    out = real_shaper("sweep", *BASE, "--rod-ratio", "0.3", "--vary", "rod-ratio=0.2:1:3",
                 "--vary", "guide=400:700:3", "--rpm", "40", "60")
    assert out.returncode == 0, out.stderr
    table = rows(out.stdout)
    header = out.stdout.splitlines()[0].split(",")
    assert header == ["rod-ratio", "guide", "valid", "reason", "K", "stroke_mm", "theta_deg",
                      "v_work_max_m_s@40", "v_work_max_m_s@60", "v_return_max_m_s@40",
                      "v_return_max_m_s@60", "a_max_m_s2@40", "a_max_m_s2@60",
                      "pressure_angle_max_deg"]
    assert len(table) == 9
    assert [r["rod-ratio"] for r in table[:3]] == ["0.2"] * 3        # first name varies slowest
    for r in table:
        if r["valid"] == "true":
            assert r["reason"] == ""
            design = synthesize(100, 1.46, 312, rod_ratio=float(r["rod-ratio"]), guide=float(r["guide"]))
            m = analyze(design, [40, 60])
            assert float(r["K"]) == pytest.approx(1.46, rel=1e-9)
            assert float(r["stroke_mm"]) == pytest.approx(312, rel=1e-9)
            assert float(r["a_max_m_s2@60"]) == pytest.approx(m.speeds[1].a_max_m_s2, rel=1e-9)
            assert float(r["pressure_angle_max_deg"]) == pytest.approx(m.pressure_angle_max_deg, rel=1e-9)
        else:
            assert r["valid"] == "false" and r["K"] == "" and r["reason"].startswith("--")
    # The reason is the single design's own error line.
    bad = next(r for r in table if r["valid"] == "false")
    single = shaper("analyze", *BASE, "--rod-ratio", bad["rod-ratio"], "--guide", bad["guide"])
    assert single.returncode == 2
    assert single.stderr.strip() == "shaper: error: " + bad["reason"]


def test_sweep_json_with_loads_one_speed():
    out = shaper("sweep", *BASE, "--vary", "crank=80:120:3", "--rpm", "40", *LOADS, "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert [d["crank"] for d in data] == [80.0, 100.0, 120.0]
    first = data[0]
    assert list(first)[:3] == ["crank", "valid", "reason"]
    assert first["pressure_angle_max_deg"] is None                     # block variant
    assert "v_work_max_m_s" in first and "max_torque_N_m" in first      # no @RPM suffix
    masses = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70,
                            cut_force_N=7000)
    for d in data:
        if d["valid"]:
            s = summarize(synthesize(d["crank"], 1.46, 312), [40], masses).speeds[0]
            assert d["max_torque_N_m"] == pytest.approx(s.max_torque_N_m, rel=1e-9)
            assert d["flywheel_inertia_kg_m2"] == pytest.approx(s.flywheel_inertia_kg_m2, rel=1e-9)
        else:
            assert d["K"] is None and d["reason"]


def test_sweep_varies_k_beside_the_measured_k(tmp_path):
    target = tmp_path / "sweep.csv"
    out = shaper("sweep", *BASE, "--vary", "K=1.2:2:3", "--rpm", "40", "--csv", target)
    assert out.returncode == 0 and out.stdout == ""
    table = rows(target.read_text())
    assert [float(r["K_nominal"]) for r in table] == [1.2, 1.6, 2.0]
    assert [r["valid"] for r in table] == ["true", "true", "false"]   # guide below the crank at K = 2
    for r in table[:2]:
        assert float(r["K"]) == pytest.approx(float(r["K_nominal"]), rel=1e-9)
    # the chord rule places the guide 270 mm high, below L2 + L1 = 300 mm: the stroke that raises it
    # (300 mm / cos 30° · 2 sin 30°), not the guide, which the rule sets
    assert table[2]["reason"].startswith("--stroke: must be > 346.411 mm for this crank and K, so that the ram "
                                         "guide its rule places clears the crank")


@pytest.mark.parametrize("args, option", [
    (["--vary", "bogus=1:2:3"], "--vary"),
    (["--vary", "crank=1:2"], "--vary"),
    (["--vary", "crank=2:1:3"], "--vary"),
    (["--vary", "crank=1:2:0"], "--vary"),
    (["--vary", "crank=100:100:5"], "--vary"),            # five copies of one design (GUI: one-value range refused)
    (["--vary", "crank=1:x:3"], "--vary"),
    (["--vary", "frame=300:400:3"], "--vary"),            # synthesis mode has no frame
    (["--vary", "crank=1:2:3", "--vary", "crank=1:2:3"], "--vary"),
    (["--vary", "crank=80:120:3", "--rpm", "-5"], "--rpm"),
    (["--vary", "crank=80:120:3", "--json", "--csv", "-"], "--csv"),
    (["--vary", "crank=1:2:2000", "--vary", "guide=1:2:2000"], "--vary"),
])
def test_sweep_refuses_bad_input_in_one_line(args, option):
    out = shaper("sweep", *BASE, *args)
    assert out.returncode == 2
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0] and "Traceback" not in out.stderr


def test_optimize_json_beats_the_sweep_and_reports_the_design():
    out = shaper("optimize", *BASE, "--rod-ratio", "0.3", "--objective", "pressure-angle",
                 "--vary", "rod-ratio=0.2:1", "--vary", "guide=450:700", "--rpm", "40", "--json")
    assert out.returncode == 0, out.stderr
    doc = json.loads(out.stdout)
    assert doc["objective"] == "pressure-angle"
    sweep = json.loads(shaper("sweep", *BASE, "--rod-ratio", "0.3", "--vary", "rod-ratio=0.2:1:41",
                              "--vary", "guide=450:700:41", "--rpm", "40", "--json").stdout)
    best = min(d["pressure_angle_max_deg"] for d in sweep if d["valid"])
    assert doc["objective_value"] <= best
    start = synthesize(100, 1.46, 312, rod_ratio=0.3)
    assert doc["start_value"] == pytest.approx(analyze(start, [40]).pressure_angle_max_deg, rel=1e-9)
    synth_keys = json.loads(shaper("synth", *BASE, "--rod-ratio", "0.3", "--json").stdout).keys()
    assert doc["design"].keys() == synth_keys
    design = doc["design"]
    assert design["K"] == pytest.approx(1.46) and design["stroke_mm"] == pytest.approx(312)
    assert design["rod_mm"] == pytest.approx(doc["vary"]["rod-ratio"] * design["lever_mm"])
    assert design["guide_mm"] == pytest.approx(doc["vary"]["guide"])
    assert doc["figures"]["pressure_angle_max_deg"] == pytest.approx(doc["objective_value"])


@pytest.mark.parametrize("args, option", [
    (["--objective", "pressure-angle", "--vary", "crank=80:120"], "--objective"),   # block variant
    (["--objective", "flywheel", "--vary", "crank=80:120"], "--objective"),         # no loads
    (["--objective", "speed", "--vary", "crank=80:120"], "--objective"),
    (["--objective", "accel", "--vary", "crank=80:120:3"], "--vary"),
    (["--objective", "accel", "--vary", "guide=100:200"], "--vary"),                # nothing valid
])
def test_optimize_refuses_bad_input_in_one_line(args, option):
    out = shaper("optimize", *BASE, *args)
    assert out.returncode == 2, out.stdout
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0] and "Traceback" not in out.stderr


def test_optimize_text_output():
    # K, not L1 alone: with K and H fixed max |a| does not depend on L1 (no proposal, see
    # test_optimize_gain.py)
    out = real_shaper("optimize", *BASE, "--objective", "accel", "--vary", "K=1.3:1.6", "--rpm", "40")
    assert out.returncode == 0, out.stderr
    assert "optimum" in out.stdout and "m/s²" in out.stdout and "design as given" in out.stdout
    value = float(out.stdout.split("optimum")[1].split()[0])
    assert value <= analyze(synthesize(100, 1.46, 312), [40]).speeds[0].a_max_m_s2 * (1 + 1e-5)
    assert math.isfinite(value)


@pytest.mark.parametrize("fmt", [["--csv", "-"], ["--json"]])
def test_blocks_give_the_same_output(monkeypatch, capsys, fmt):
    """A large sweep is evaluated and written in blocks; the output does not depend on them."""
    from core.cli import cmd_sweep, main

    argv = ["sweep", *BASE, "--rod-ratio", "0.3", "--vary", "rod-ratio=0.1:1:5",
            "--vary", "guide=400:700:5", "--rpm", "40", "60", *fmt]
    assert main(argv) == 0
    whole = capsys.readouterr().out
    monkeypatch.setattr(cmd_sweep, "BLOCK", 7)
    assert main(argv) == 0
    assert capsys.readouterr().out == whole
    if fmt == ["--json"]:
        assert len(json.loads(whole)) == 25
    else:
        assert len(whole.splitlines()) == 26


def test_refusal_reason_names_the_option_as_analyze_does():
    """A value of --dims is named '--dims (L3)' as in analyze's error (it was '--dims')."""
    run = shaper("sweep", "--dims", "100,300,350", "--vary", "crank=100:150:2", "--rpm", "40")
    assert run.returncode == 0, run.stderr
    rows = list(csv.DictReader(io.StringIO(run.stdout)))
    assert [r["reason"].split(":")[0] for r in rows] == ["--dims (L3)"] * 2
    for row in rows:
        alone = shaper("analyze", "--dims", f"{row['crank']},300,350", "--rpm", "40")
        assert alone.returncode == 2
        assert alone.stderr.strip() == "shaper: error: " + row["reason"]


def test_optimize_says_when_the_optimum_sits_on_a_bound():
    """The pressure angle keeps falling as the rod grows: with rod-ratio up to 1 the optimum
    is rod-ratio = 1, the end of the range, and was printed as if it were a true optimum
    (issue 20 item 4). A guide height has an interior optimum and is not flagged."""
    args = ["optimize", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod-ratio", "0.3",
            "--objective", "pressure-angle"]
    wide = json.loads(shaper(*args, "--vary", "rod-ratio=0.2:1", "--json").stdout)
    assert wide["vary"]["rod-ratio"] == pytest.approx(1.0, abs=1e-4)
    assert wide["on_bound"] == {"rod-ratio": "upper"}
    narrow = json.loads(shaper(*args, "--vary", "rod-ratio=0.2:0.8", "--json").stdout)
    assert narrow["on_bound"] == {"rod-ratio": "upper"}
    assert narrow["objective_value"] > wide["objective_value"]          # beyond the bound is better
    text = shaper(*args, "--vary", "rod-ratio=0.2:1").stdout
    assert "upper bound" in text and "widen the range" in text
    inside = json.loads(shaper(*args, "--vary", "guide=450:700", "--json").stdout)
    assert inside["on_bound"] == {} and 460 < inside["vary"]["guide"] < 690


def test_a_crank_longer_than_the_frame_warns_nothing(tmp_path):
    """Designs whose crank is not shorter than the frame are refused with a reason and no θ;
    stderr stays empty (numpy's 'invalid value encountered in arcsin' was printed)."""
    target = tmp_path / "s.csv"
    run = shaper("sweep", "--dims", "100,300,350", "--vary", "crank=50:400:8", "--rpm", "40",
                 "--csv", target)
    assert run.returncode == 0 and run.stderr == ""
    rows = list(csv.DictReader(target.open(encoding="utf-8")))
    long = [r for r in rows if float(r["crank"]) >= 300.0]
    assert long and all(r["valid"] == "false" and r["theta_deg"] == "" and "frame" in r["reason"]
                        for r in long)
