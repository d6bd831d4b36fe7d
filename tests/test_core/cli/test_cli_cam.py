"""``shaper cam`` (issue 23, items 2 and 5): the JSON keys, the CSV in the cam's frame, the
check mode, the DXF at 1:1, and one line naming the option for every bad input."""
from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

import ezdxf
import numpy as np
import pytest

from cli_runner import shaper_in_process
from core.linkage.cut import cutting
from core.linkage.spec import Spec

SHEET = ["--arm", "120", "--swing", "15", "--pressure", "40", "--rise", "60", "--dwell", "10",
         "--return", "60", "--law", "cosine", "--return-law", "parabolic"]
LINKAGE = ["--crank", "100", "--K", "1.4", "--stroke", "300"]
JSON_KEYS = {"base_radius_mm", "center_distance_mm", "arm_mm", "initial_angle_deg",
             "max_pressure_angle_rise_deg", "max_pressure_angle_return_deg",
             "min_curvature_radius_mm", "roller_mm"}
COLUMNS = ["cam_angle_deg", "follower_angle_deg", "follower_omega_rad_s", "follower_alpha_rad_s2",
           "pressure_angle_deg", "pitch_x_mm", "pitch_y_mm", "profile_x_mm", "profile_y_mm"]


def run_json(*words):
    status, out, err = shaper_in_process("cam", *words, "--json")
    assert status == 0 and err == "", err
    return json.loads(out)


def read_csv(path: Path):
    rows = list(csv.reader(io.StringIO(path.read_text())))
    return rows[0], np.array(rows[1:], dtype=float)


def test_json_has_the_issues_keys():
    doc = run_json(*SHEET)
    assert JSON_KEYS <= set(doc)
    a, l, r0, psi0 = (doc["center_distance_mm"], doc["arm_mm"], doc["base_radius_mm"],
                      math.radians(doc["initial_angle_deg"]))
    # the triangle O-A-B at the lowest position: the law of cosines ties the four figures
    assert r0 ** 2 == pytest.approx(a * a + l * l - 2 * a * l * math.cos(psi0), rel=1e-12)
    assert doc["max_pressure_angle_rise_deg"] == pytest.approx(40.0, abs=1e-6)
    assert doc["roller_mm"] == pytest.approx(min(0.8 * doc["min_curvature_radius_mm"],
                                                 doc["min_curvature_radius_mm"] - 3.0))


def test_csv_columns_and_the_cams_frame(tmp_path):
    target = tmp_path / "cam.csv"
    status, out, err = shaper_in_process("cam", *SHEET, "--csv", target, "--json", "--rpm", "30")
    doc = json.loads(out)
    names, data = read_csv(target)
    assert names == COLUMNS
    col = {n: data[:, i] for i, n in enumerate(names)}
    assert col["cam_angle_deg"][0] == 0 and col["cam_angle_deg"][-1] == 360 and len(data) == 361
    a, l, r0 = doc["center_distance_mm"], doc["arm_mm"], doc["base_radius_mm"]
    # every pitch point is the arm's length from the pivot, turned with the cam: at cam angle
    # δ the pivot seen from the (clockwise) cam is at a·(cos δ, sin δ)
    d = np.radians(col["cam_angle_deg"])
    pivot = np.stack([a * np.cos(d), a * np.sin(d)])
    reach = np.hypot(col["pitch_x_mm"] - pivot[0], col["pitch_y_mm"] - pivot[1])
    assert np.abs(reach - l).max() < 1e-6
    # at cam angle 0 the roller is on the base circle, and on the inner dwell it stays there
    inner = col["cam_angle_deg"] > 130
    assert np.abs(np.hypot(col["pitch_x_mm"], col["pitch_y_mm"])[inner] - r0).max() < 1e-6
    # the follower's ω at 30 r/min is the finite difference of its angle over time
    t = d / (30 * 2 * math.pi / 60)
    psi = np.radians(col["follower_angle_deg"])
    fd = np.gradient(psi, t)
    rise = (col["cam_angle_deg"] > 2) & (col["cam_angle_deg"] < 58)
    assert np.abs(fd - col["follower_omega_rad_s"])[rise].max() < 2e-3 * np.abs(fd).max()
    # the profile is one roller radius inside the pitch curve
    gap = np.hypot(col["pitch_x_mm"] - col["profile_x_mm"], col["pitch_y_mm"] - col["profile_y_mm"])
    assert np.abs(gap - doc["roller_mm"]).max() < 1e-6


def test_check_mode_reproduces_and_detects_a_smaller_base():
    doc = run_json(*SHEET)
    again = run_json(*SHEET, "--base", repr(doc["base_radius_mm"]),
                     "--distance", repr(doc["center_distance_mm"]))
    assert again["synthesized"] is False
    for key in ("initial_angle_deg", "max_pressure_angle_rise_deg", "min_curvature_radius_mm"):
        assert again[key] == pytest.approx(doc[key], rel=1e-9)
    small = run_json(*SHEET, "--base", repr(0.98 * doc["base_radius_mm"]),
                     "--distance", repr(doc["center_distance_mm"]))
    assert small["within_allowance"] is False


def test_timing_places_the_feed_outside_the_cut():
    doc = run_json(*SHEET, *LINKAGE, "--idle", "0.05")
    phi = math.radians(doc["phase_deg"]) + np.radians(np.linspace(0.0, 130.0, 1301))
    assert not cutting(Spec().design(), phi, 0.05).any()


def test_dxf_is_the_profile_at_full_scale(tmp_path):
    target = tmp_path / "cam.dxf"
    status, out, err = shaper_in_process("cam", *SHEET, "--dxf", target, "--json")
    assert status == 0, err
    doc = json.loads(out)
    dxf = ezdxf.readfile(target)
    assert dxf.header["$INSUNITS"] == 4
    assert not dxf.audit().has_errors
    msp = dxf.modelspace()
    outline = [e for e in msp.query("LWPOLYLINE") if e.dxf.layer == "OUTLINE"]
    pitch = [e for e in msp.query("LWPOLYLINE") if e.dxf.layer == "CENTER"]
    assert len(outline) == 1 and len(pitch) == 1 and outline[0].closed
    # the profile's points are the CSV's, at 1:1 (the DXF has a quarter-degree step)
    csv_target = tmp_path / "cam.csv"
    shaper_in_process("cam", *SHEET, "--csv", csv_target, "--step", "0.25")
    names, data = read_csv(csv_target)
    points = np.array([(x, y) for x, y, *_ in outline[0].get_points()])
    assert np.abs(points - data[:-1, 7:9]).max() < 1e-6
    base = [e for e in msp.query("CIRCLE") if e.dxf.layer == "CENTER"]
    assert base and base[0].dxf.radius == pytest.approx(doc["base_radius_mm"], rel=1e-12)
    dims = list(msp.query("DIMENSION"))
    assert dims and dims[0].get_measurement() == pytest.approx(doc["center_distance_mm"], rel=1e-9)


@pytest.mark.parametrize("words, option", [
    (["--rise", "200", "--dwell", "100", "--return", "100"], "--dwell"),
    (["--swing", "120"], "--swing"),
    (["--swing", "abc"], "--swing"),
    (["--pressure", "95"], "--pressure"),
    (["--return-pressure", "0"], "--return-pressure"),
    (["--arm", "-5"], "--arm"),
    (["--roller", "40"], "--roller"),
    (["--base", "30"], "--distance"),
    (["--base", "10", "--distance", "300"], "--base"),
    (["--rise", "150", "--return", "150", *LINKAGE], "--rise"),
    (["--phase", "90", *LINKAGE], "--phase"),
    (["--phase", "90"], "--phase"),
    (["--rpm", "0"], "--rpm"),
    (["--step", "0"], "--step"),
    (["--pressure", "5"], "--pressure"),
])
def test_bad_input_is_one_line_naming_the_option(words, option, tmp_path):
    merged = dict(zip(SHEET[::2], SHEET[1::2]))
    extra = []
    i = 0
    while i < len(words):
        if words[i] in merged:
            merged[words[i]] = words[i + 1]
        else:
            extra += words[i:i + 2]
        i += 2
    argv = [w for pair in merged.items() for w in pair] + extra
    status, out, err = shaper_in_process("cam", *argv, "--csv", tmp_path / "c.csv")
    assert status == 2 and out == ""
    assert err.startswith(f"shaper: error: {option}") and err.count("\n") == 1, err
    assert not (tmp_path / "c.csv").exists()


def test_a_design_files_cam_is_used_and_options_override_it(tmp_path):
    from core.cam import CamInputs, Program
    from core.cam.file import cam_to_dict
    from core.files.io import save_design
    inputs = CamInputs(arm_mm=120.0, program=Program(15.0, 60.0, 10.0, 60.0, "cosine", "parabolic"))
    save_design(tmp_path / "d.json", Spec(), [40.0], 1.0, extra={"cam": cam_to_dict(inputs, None)})
    from_file = run_json("--design", tmp_path / "d.json")
    assert from_file == run_json(*SHEET, *LINKAGE, "--rpm", "40")
    wider = run_json("--design", tmp_path / "d.json", "--swing", "20")
    assert wider["swing_deg"] == 20.0 and wider["rise_law"] == "cosine"
    save_design(tmp_path / "none.json", Spec(), [40.0], 1.0)
    status, out, err = shaper_in_process("cam", "--design", tmp_path / "none.json")
    assert status == 2 and err.startswith("shaper: error: --arm: required")
    save_design(tmp_path / "bad.json", Spec(), [40.0], 1.0, extra={"cam": {"arm_mm": -1}})
    status, out, err = shaper_in_process("cam", "--design", tmp_path / "bad.json")
    assert status == 2 and err.startswith("shaper: error: --design:") and err.count("\n") == 1
