"""``shaper library`` run as a real command in subprocesses."""
import csv
import io
import json
import os
import subprocess
import sys

import pytest

from core.files.io import load_design, save_design
from core.linkage.spec import Spec
from cli_runner import shaper, shaper_in_process

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

LOADS = ("--lever-mass", 20, "--lever-inertia", 1.1, "--ram-mass", 70, "--cut-force", 7000)


def lib_cmd(lib, *args):
    return shaper("library", *args, "--library", lib)


def one_error_line(run, option):
    assert run.returncode == 2, (run.stdout, run.stderr)
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"shaper: error: {option}"), run.stderr
    assert "Traceback" not in run.stderr


@pytest.fixture
def lib(tmp_path):
    """A library of two designs, added by ``shaper library add`` in this process: the tests
    run the commands they check as processes; this setup need not start two more each."""
    path = tmp_path / "lib.sqlite"
    for args in (("--crank", 100, "--K", 1.4, "--stroke", 300, "--name", "base",
                  "--notes", "seed 003", "--tags", "seed", "block"),
                 ("--crank", 100, "--K", 1.6, "--stroke", 300, "--rod-ratio", 0.35,
                  "--name", "rod 1.6", "--rpm", 40, 60, *LOADS)):
        status, _, err = shaper_in_process("library", "add", *args, "--library", path)
        assert status == 0, err
    return path


def test_add_list_show(lib):
    run = lib_cmd(lib, "list", "--json")
    rows = json.loads(run.stdout)
    assert [r["name"] for r in rows] == ["base", "rod 1.6"]
    for key in ("name", "K", "stroke_mm", "variant", "modified"):
        assert key in rows[0]
    assert rows[1]["variant"] == "rod" and rows[1]["K"] == pytest.approx(1.6)
    assert rows[0]["flywheel_inertia_kg_m2"] is None and rows[1]["flywheel_inertia_kg_m2"] > 0
    text = lib_cmd(lib, "list").stdout.splitlines()
    assert text[0].split()[:3] == ["name", "variant", "K"] and len(text) == 3
    show = json.loads(lib_cmd(lib, "show", "rod 1.6", "--json").stdout)
    assert show["document"]["format"] == "shaper-design"
    assert [s["rpm"] for s in show["speeds"]] == [40.0, 60.0]
    assert show["document"]["forces"]["cut_force_N"] == 7000.0
    assert "seed 003" in lib_cmd(lib, "show", "base").stdout


def test_duplicate_name_exits_2(lib):
    run = lib_cmd(lib, "add", "--crank", 100, "--K", 1.5, "--stroke", 300, "--name", "base")
    one_error_line(run, "--name")
    assert "already" in run.stderr


def test_filters_and_sorting(lib):
    lib_cmd(lib, "add", "--crank", 100, "--K", 1.5, "--stroke", 320, "--name", "cutter K1.5")
    names = lambda *a: [r["name"] for r in json.loads(lib_cmd(lib, "list", "--json", *a).stdout)]  # noqa: E731
    assert names("--where", "K>=1.45") == ["cutter K1.5", "rod 1.6"]
    assert names("--where", "K>=1.4,variant=block,name~CUT") == ["cutter K1.5"]
    assert names("--sort", "a_max", "--desc", "--rpm", 40) == ["rod 1.6", "cutter K1.5", "base"]
    assert names("--where", "tag=seed") == ["base"]
    assert names("--search", "seed") == ["base"]
    one_error_line(lib_cmd(lib, "list", "--where", "K>>1"), "--where")
    one_error_line(lib_cmd(lib, "list", "--sort", "colour"), "--sort")


def test_export_opens_with_design_and_import_round_trip(lib, tmp_path):
    out = tmp_path / "rod.shaper.json"
    assert lib_cmd(lib, "export", "rod 1.6", "-o", out).returncode == 0
    doc = load_design(out)
    assert doc["spec"].variant == "rod" and doc["rpm"] == [40.0, 60.0]
    analyzed = shaper("analyze", "--design", out, "--json")
    assert analyzed.returncode == 0
    assert lib_cmd(lib, "import", out).returncode == 0
    one_error_line(lib_cmd(lib, "import", out), "FILE")           # 'rod' is taken now
    assert lib_cmd(lib, "import", out, "--rename-duplicates").returncode == 0
    names = [r["name"] for r in json.loads(lib_cmd(lib, "list", "--json").stdout)]
    assert names == ["base", "rod", "rod (2)", "rod 1.6"]
    again = tmp_path / "again.json"
    assert lib_cmd(lib, "export", "rod (2)", "-o", again).returncode == 0
    assert again.read_text(encoding="utf-8") == out.read_text(encoding="utf-8")


def test_import_refuses_a_bad_file_and_imports_nothing(lib, tmp_path):
    good = tmp_path / "good.shaper.json"
    save_design(good, Spec(time_ratio=1.5), [40.0], 1.0)
    bad = tmp_path / "bad.json"
    bad.write_text("[1, 2")
    one_error_line(lib_cmd(lib, "import", good, bad), "FILE")
    assert "good" not in lib_cmd(lib, "list").stdout
    run = lib_cmd(lib, "import", good, bad, "--skip-invalid")
    assert run.returncode == 0 and "imported 1 design: good" in run.stdout and "bad.json" in run.stderr


def test_remove_and_missing_names(lib):
    assert lib_cmd(lib, "remove", "base").returncode == 0
    one_error_line(lib_cmd(lib, "remove", "base"), "NAME")
    one_error_line(lib_cmd(lib, "show", "nothing"), "NAME")


def test_compare_outputs(lib, tmp_path):
    run = lib_cmd(lib, "compare", "base", "rod 1.6", "--rpm", 60, "--json")
    doc = json.loads(run.stdout)
    assert doc["designs"] == ["base", "rod 1.6"] and doc["rpm"] == 60.0
    a = next(f for f in doc["figures"] if f["figure"] == "a_max_m_s2")
    analyzed = json.loads(shaper("analyze", "--crank", 100, "--K", 1.4, "--stroke", 300, "--rpm", 60,
                                 "--json").stdout)
    assert a["values"]["base"] == pytest.approx(analyzed["speeds"][0]["a_max_m_s2"], rel=1e-12)
    assert a["best"] == ["base"]
    table = tmp_path / "cmp.csv"
    curves = tmp_path / "curves.csv"
    assert lib_cmd(lib, "compare", "base", "rod 1.6", "--csv", table, "--curves-csv", curves).returncode == 0
    rows = list(csv.reader(io.StringIO(table.read_text(encoding="utf-8"))))
    assert rows[0][:5] == ["figure", "unit", "better", "base", "rod 1.6"]
    assert len(curves.read_text().splitlines()) == 1 + 2 * 361
    design = tmp_path / "file.shaper.json"
    save_design(design, Spec(time_ratio=1.5), [40.0], 1.0)
    text = lib_cmd(lib, "compare", "base", "--file", design).stdout
    assert "file" in text.splitlines()[0] and "*" in text
    one_error_line(lib_cmd(lib, "compare", "base"), "NAME")
    one_error_line(lib_cmd(lib, "compare", "base", "base"), "NAME")
    one_error_line(lib_cmd(lib, "compare", "base", "rod 1.6", "--rpm", -3), "--rpm")


def test_environment_variable_chooses_the_library(tmp_path):
    path = tmp_path / "env.sqlite"
    env = dict(os.environ, SHAPER_LIBRARY=str(path))
    cmd = [sys.executable, "-m", "core", "library", "add", "--crank", "100", "--K", "1.4", "--stroke",
           "300", "--name", "from env"]
    run = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=120)
    assert run.returncode == 0, run.stderr
    assert str(path) in run.stdout and path.exists()
    assert "from env" in lib_cmd(path, "list").stdout


def test_damaged_library_is_refused_with_a_backup_hint(lib, tmp_path):
    data = bytearray(lib.read_bytes())
    data[4096:] = b"\xa5" * (len(data) - 4096)
    lib.write_bytes(bytes(data))
    before = (lib.read_bytes(), lib.stat().st_mtime_ns)
    run = lib_cmd(lib, "list")
    one_error_line(run, "--library")
    assert "damaged" in run.stderr and "shaper library backup" in run.stderr
    assert (lib.read_bytes(), lib.stat().st_mtime_ns) == before
    one_error_line(lib_cmd(lib, "add", "--crank", 100, "--K", 1.4, "--stroke", 300, "--name", "x"),
                   "--library")
    assert (lib.read_bytes(), lib.stat().st_mtime_ns) == before
    backup = lib_cmd(lib, "backup", "-o", tmp_path / "saved.sqlite")
    assert backup.returncode == 0, backup.stderr
    assert (tmp_path / "saved.sqlite").read_bytes() == before[0]


def test_backup_of_a_healthy_library_opens(lib, tmp_path):
    copy = tmp_path / "copy.sqlite"
    assert lib_cmd(lib, "backup", "-o", copy).returncode == 0
    assert [r["name"] for r in json.loads(lib_cmd(copy, "list", "--json").stdout)] == ["base", "rod 1.6"]


def test_help_lists_every_action():
    run = shaper("library", "--help")
    for action in ("add", "list", "show", "remove", "export", "import", "compare", "backup"):
        assert action in run.stdout


def test_wrong_paths_are_usage_errors(lib, tmp_path):
    """Found by the library fuzz: a wrong path is the user's input (exit 2, naming the
    option), and an empty --library is refused rather than taken for the default library."""
    env_library = tmp_path / "env.sqlite"
    run = subprocess.run([sys.executable, "-m", "core", "library", "add", "--crank", "100", "--K", "1.4",
                          "--stroke", "300", "--name", "x", "--library", ""], capture_output=True,
                         text=True, env=dict(os.environ, SHAPER_LIBRARY=str(env_library)))
    one_error_line(run, "--library")
    assert not env_library.exists()
    one_error_line(lib_cmd(tmp_path, "list"), "--library")                     # a folder
    one_error_line(lib_cmd(tmp_path / "no" / "lib.sqlite", "add", "--crank", 100, "--K", 1.4,
                           "--stroke", 300, "--name", "x"), "--library")       # no such folder
    one_error_line(lib_cmd(lib, "backup", "-o", tmp_path), "--output")
    one_error_line(lib_cmd(lib, "backup", "-o", tmp_path / "no" / "b.sqlite"), "--output")
    one_error_line(lib_cmd(lib, "export", "base", "-o", ""), "-o")
    one_error_line(lib_cmd(lib, "export", "base", "-o", tmp_path / "no" / "b.shaper.json"), "-o")
