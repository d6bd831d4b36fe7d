"""load_design refuses every hostile file with one plain sentence, fast and without blocking."""
import json
import os
import time

import pytest

from core.base.errors import FileFormatError
from core.files.io import load_design, save_design
from core.linkage.spec import Spec

from hostile_files import CASES, DUPLICATES, VALID, build_case


def test_corpus_is_large_enough():
    assert len(CASES) >= 40


@pytest.mark.parametrize("name", sorted(CASES))
def test_hostile_file_is_refused(tmp_path, name):
    path = build_case(name, tmp_path)
    start = time.perf_counter()
    with pytest.raises(FileFormatError) as info:
        load_design(path)
    elapsed = time.perf_counter() - start
    message = str(info.value)
    assert elapsed < 2.0, f"{name} took {elapsed:.1f} s"
    assert str(path) in message
    assert "\n" not in message and len(message) < len(str(path)) + 200
    assert "Traceback" not in message and "Error" not in message   # no exception class names


def test_the_corpus_base_document_is_valid(tmp_path):
    """So each case is refused for its own defect, not for the base."""
    path = tmp_path / "ok.json"
    path.write_text(json.dumps(VALID))
    doc = load_design(path)
    assert doc["spec"] == Spec() and doc["rpm"] == [40.0, 60.0] and doc["step_deg"] == 1.0


def test_fifo_does_not_block(tmp_path):
    """The FIFO has no writer: opening it for reading must not wait for one."""
    path = build_case("fifo", tmp_path)
    start = time.perf_counter()
    with pytest.raises(FileFormatError, match="not a regular file"):
        load_design(path)
    assert time.perf_counter() - start < 1.0


def test_plain_messages_for_common_mistakes(tmp_path):
    cases = {"spec_missing": "'spec' entry is missing", "version_true": "unsupported version (true)",
             "rpm_strings": 'crank speed "40" is not a number', "rpm_true": "crank speed true is not a number",
             "rpm_denormal": "must be ≥ 0.01 and ≤ 1000 r/min", "int_400_digits": "too large",
             "deep_arrays": "nested more than", "bad_utf8": "not UTF-8", "folder": "is a folder",
             "sparse_5_GB": "larger than 1 MB", "nan": "NaN is not a number",
             "inactive_frame_text": "frame = 'ጼ': must be a number"}
    for name, expected in cases.items():
        with pytest.raises(FileFormatError) as info:
            load_design(build_case(name, tmp_path))
        assert expected in str(info.value), (name, str(info.value))


def test_a_file_of_exactly_the_cap_is_read(tmp_path):
    body = json.dumps(VALID).encode()
    path = tmp_path / "full.json"
    path.write_bytes(body + b" " * (1_000_000 - len(body)))
    assert load_design(path)["rpm"] == [40.0, 60.0]


def test_symlink_to_a_valid_file_is_followed(tmp_path):
    save_design(tmp_path / "real.json", Spec(time_ratio=1.6), [30.0], 2.0)
    os.symlink(tmp_path / "real.json", tmp_path / "link.json")
    assert load_design(tmp_path / "link.json")["spec"].time_ratio == 1.6


def test_inactive_fields_are_checked_as_if_active(tmp_path):
    """Issue 12: what a file holds must open in either mode (K is inactive in dimensions mode)."""
    spec = Spec(mode="dimensions", time_ratio=0.9)
    path = tmp_path / "d.json"
    save_design(path, spec, [40.0], 1.0)
    with pytest.raises(FileFormatError, match="time_ratio"):
        load_design(path)
    Spec(mode="dimensions").check_fields()


def test_utf8_bom_is_accepted(tmp_path):
    path = tmp_path / "bom.json"
    path.write_bytes(b"\xef\xbb\xbf" + json.dumps(VALID).encode())
    assert load_design(path)["spec"] == Spec()


@pytest.mark.parametrize("name", ["fifo", "version_true", "rpm_strings", "link_to_dev_zero"])
def test_cli_design_option_refuses_with_one_line(tmp_path, name):
    """Every subcommand's --design goes through load_design: exit 2, one line, no traceback."""
    from cli_runner import shaper
    path = build_case(name, tmp_path)
    result = shaper("analyze", "--design", path)
    assert result.returncode == 2
    assert len(result.stderr.strip().splitlines()) == 1 and "Traceback" not in result.stderr
    assert str(path) in result.stderr


@pytest.mark.parametrize("key", sorted(DUPLICATES))
def test_a_key_written_twice_is_refused_naming_it(tmp_path, key):
    """Issue 42: json kept the last of two "spec" objects (K 1.6 used, K 1.4 ignored), two
    "gear" objects, "z1": 3, "z1": 13 silently. Each document is valid once read by plain
    json (so the repeat is its only defect) and is now refused in one line naming the key."""
    from core.files.design_file import parse_design
    text = DUPLICATES[key]
    parse_design(json.dumps(json.loads(text)).encode(), "plain")      # valid but for the repeat
    path = tmp_path / "twice.json"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(FileFormatError) as info:
        load_design(path)
    assert info.value.reason == "duplicate_key"
    assert f'"{key}" appears twice' in str(info.value) and str(path) in str(info.value)


@pytest.mark.parametrize("command", [("gear",), ("analyze",), ("course", "-o", "out"),
                                     ("report", "-o", "r.pdf"), ("drawing", "-o", "d.svg")])
def test_every_command_refuses_a_key_written_twice(tmp_path, monkeypatch, command):
    """gear, course, report and drawing accepted a design file with two "spec" objects.
    The command runs in this process, in ``tmp_path`` (its output names are relative): the
    test is about what it refuses and writes, not how it starts (a Qt command's process
    costs ~2.5 s of CPU; test_cli.py runs the console script)."""
    from cli_runner import shaper_run_in_process
    path = tmp_path / "twice.json"
    path.write_text(DUPLICATES["gear" if command == ("gear",) else "spec"], encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    result = shaper_run_in_process(*command, "--design", path)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "appears twice" in lines[0] and "Traceback" not in result.stderr
    assert not any(p.name != "twice.json" for p in tmp_path.iterdir())      # nothing written
