"""Options every subcommand shares: --design, --version, help, negative numbers, encodings."""
import json
import os
import subprocess

import pytest

from core.io import save_design
from core.spec import Spec

from cli_runner import shaper

SEED003 = ["--crank", "100", "--K", "1.4", "--stroke", "300"]


def test_bare_shaper_prints_usage_and_version_is_known():
    out = shaper()
    assert out.returncode == 0 and "COMMAND" in out.stdout and "synth" in out.stdout
    version = shaper("--version")
    assert version.returncode == 0 and version.stdout.startswith("shaper ")


@pytest.mark.parametrize("command", ["synth", "curves", "analyze", "dynamics"])
def test_every_subcommand_help_has_a_description_and_an_example(command):
    out = shaper(command, "--help")
    assert out.returncode == 0
    assert "example:" in out.stdout and f"shaper {command}" in out.stdout.split("example:")[1]
    assert "--design" in out.stdout


def test_design_file_stands_for_the_design_options(tmp_path):
    path = tmp_path / "d.shaper.json"
    spec = Spec(crank=110.0, time_ratio=1.5, stroke=320.0, variant="rod", rod_ratio=0.3)
    save_design(path, spec, [35.0], 2.0)
    from_file = json.loads(shaper("analyze", "--design", path, "--json").stdout)
    direct = json.loads(shaper("analyze", "--crank", "110", "--K", "1.5", "--stroke", "320",
                               "--rod-ratio", "0.3", "--rpm", "35", "--json").stdout)
    assert from_file == direct
    # The file's step is the curves' default step.
    rows = shaper("curves", "--design", path).stdout.splitlines()
    assert len(rows) == 1 + 181


def test_design_file_and_design_options_exclude_each_other(tmp_path):
    path = tmp_path / "d.shaper.json"
    save_design(path, Spec(), [40.0], 1.0)
    out = shaper("analyze", "--design", path, "--crank", "100")
    assert out.returncode == 2 and "--design" in out.stderr and len(out.stderr.splitlines()) == 1


def test_bad_design_file_exits_2_with_one_line(tmp_path):
    path = tmp_path / "bad.json"
    path.write_text("{not json")
    out = shaper("analyze", "--design", path)
    assert out.returncode == 2 and out.stderr.startswith("shaper: error: --design:")
    assert len(out.stderr.splitlines()) == 1


def test_negative_speed_gets_a_range_message():
    out = shaper("curves", *SEED003, "--rpm", "-1e5")
    assert out.returncode == 2 and "--rpm" in out.stderr and "1000" in out.stderr


def test_step_and_angles_exclude_each_other():
    out = shaper("curves", *SEED003, "--step", "1", "--angles", "0,1")
    assert out.returncode == 2 and "--angles" in out.stderr and "--step" in out.stderr


def test_k_near_one_names_k_in_synth():
    out = shaper("synth", "--crank", "100", "--K", "1.000000000001", "--stroke", "300")
    assert out.returncode == 2 and "--K" in out.stderr and "--dims" not in out.stderr


@pytest.mark.parametrize("command", [["synth"], ["analyze"]])
def test_ascii_console_gets_spelled_out_symbols(command):
    env = dict(os.environ, PYTHONIOENCODING="ascii")
    exe = [a for a in [__import__("shutil").which("shaper")] if a]
    out = subprocess.run(exe + command + SEED003, capture_output=True, text=True, env=env,
                         encoding="ascii")
    assert out.returncode == 0, out.stderr
    assert "theta" in out.stdout or "m/s^2" in out.stdout
