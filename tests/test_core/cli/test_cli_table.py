"""``shaper table`` run as a real subprocess: its rows equal ``shaper curves`` and
``shaper dynamics`` at the same angles, byte for byte."""
import csv
import io
import json

import pytest

from cli_runner import shaper

DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300"]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70",
         "--cut-force", "7000", "--cut-height", "80"]


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


@pytest.mark.parametrize("variant", [[], ["--rod-ratio", "0.3"]])
def test_csv_rows_equal_curves_and_dynamics(variant):
    table = shaper("table", *DESIGN, *variant, "--rpm", "40", "60", *LOADS, "--positions", "12",
                   "--at", "45,100", "--csv", "-")
    assert table.returncode == 0, table.stderr
    got = rows(table.stdout)
    assert len(got) == 2 * (12 + 6 + 2)
    angles = ",".join(str(30 * i) for i in range(12)) + ",45,100"
    curves = rows(shaper("curves", *DESIGN, *variant, "--rpm", "40", "60", "--angles", angles).stdout)
    forces = rows(shaper("dynamics", *DESIGN, *variant, "--rpm", "40", "60", *LOADS,
                         "--angles", angles, "--csv", "-").stdout)
    numbered = [r for r in got if r["position"] or (r["name"] == "")]
    assert len(numbered) == len(curves) == len(forces)
    for mine, ref, force in zip(numbered, curves, forces):
        for key, value in ref.items():
            assert mine[key] == value, key
        for key, value in force.items():
            assert mine[key] == value, key
    assert [r["name"] for r in got[12:18]] == ["limit_work_start", "limit_work_end", "cut_start",
                                                "cut_end", "v_work_max", "v_return_max"]


def test_json_objects_and_special_rows_match_analyze(tmp_path):
    result = shaper("table", *DESIGN, "--rpm", "40", *LOADS, "--json")
    assert result.returncode == 0, result.stderr
    records = json.loads(result.stdout)
    assert len(records) == 18
    assert {"position", "name", "crank_deg", "rpm", "ram_v_m_s", "crank_torque_N_m",
            "O4_x_N"} <= set(records[0])
    analyzed = json.loads(shaper("analyze", *DESIGN, "--rpm", "40", "--json").stdout)
    special = {r["name"]: r for r in records if r["name"]}
    assert special["limit_work_end"]["crank_deg"] == pytest.approx(
        analyzed["limit_positions"]["work_end_crank_deg"], abs=1e-12)
    assert special["v_work_max"]["ram_v_m_s"] == pytest.approx(
        analyzed["speeds"][0]["v_work_max_m_s"], rel=1e-6)
    assert -special["v_return_max"]["ram_v_m_s"] == pytest.approx(
        analyzed["speeds"][0]["v_return_max_m_s"], rel=1e-6)
    assert special["cut_start"]["cut_force_N"] in (0.0, 7000.0)


def test_kinematics_only_without_loads_and_text_output():
    result = shaper("table", *DESIGN, "--rpm", "40")
    assert result.returncode == 0, result.stderr
    assert "40 r/min" in result.stdout and "v_work_max" in result.stdout
    assert "crank_torque_N_m" not in result.stdout
    assert "0.49913" in result.stdout          # the hand-checked max cutting speed


def test_design_file_with_loads_gives_force_columns(tmp_path):
    from core.forces.masses import MassProperties
    from core.files.io import masses_to_dict, save_design
    from core.linkage.spec import Spec
    path = tmp_path / "d.shaper.json"
    save_design(path, Spec(), [50.0], 1.0,
                extra={"forces": masses_to_dict(MassProperties(ram_mass_kg=70, cut_force_N=100))})
    records = json.loads(shaper("table", "--design", str(path), "--positions", "4", "--json").stdout)
    assert len(records) == 10 and records[0]["rpm"] == 50.0 and "crank_torque_N_m" in records[0]


@pytest.mark.parametrize("words, option", [
    (["--positions", "0"], "--positions"), (["--positions", "2.5"], "--positions"),
    (["--at", "1,nan"], "--at"), (["--idle", "0.5"], "--idle"), (["--rpm", "0"], "--rpm"),
    (["--json", "--csv", "-"], "--json"),
])
def test_bad_input_is_one_line_naming_the_option(words, option):
    result = shaper("table", *DESIGN, *words)
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0]


def test_csv_to_file(tmp_path):
    target = tmp_path / "t.csv"
    assert shaper("table", *DESIGN, "--rpm", "40", "--csv", target).returncode == 0
    assert target.read_text().startswith("position,name,rpm,crank_deg,time_s,")


def test_json_writes_the_tilt_flag_as_true_or_false_where_the_csv_has_1_or_0():
    """A JSON flag is true/false: ``guide_tilted`` was 0.0/1.0. The CSV keeps 1/0 (its
    header's documented form), row for row the same."""
    from cli_runner import shaper_in_process
    args = ("table", *DESIGN, "--rpm", "40", *LOADS)
    status, out, err = shaper_in_process(*args, "--json")
    assert status == 0, err
    flags = [r["guide_tilted"] for r in json.loads(out)]
    assert all(type(f) is bool for f in flags) and True in flags and False in flags, flags
    status, out, err = shaper_in_process(*args, "--csv", "-")
    assert status == 0, err
    assert [r["guide_tilted"] for r in rows(out)] == ["1" if f else "0" for f in flags]
