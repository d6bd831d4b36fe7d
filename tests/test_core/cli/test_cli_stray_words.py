"""Issue 42, item 9: every message names the option at fault and keeps its reason.

A stray word got argparse's "unrecognized arguments: 60" (35 times in the fuzz), which
names no option; a gear's z1 of 1e300 in a file printed a 301-digit integer that the
160-character cut ended before the reason."""
import json

import pytest

from cli_runner import shaper_in_process

DESIGN = ("--crank", "100", "--K", "1.4", "--stroke", "300")


def _one_line(args):
    status, out, err = shaper_in_process(*args)
    assert status == 2 and out == "" and err.count("\n") == 1, (status, err)
    assert err.startswith("shaper: error: ")
    return err[len("shaper: error: "):].strip()


@pytest.mark.parametrize("args, option, word", [
    (("analyze", *DESIGN, "--rpm", "40", "--json", "3"), "--json", "3"),
    (("analyze", *DESIGN, "foo"), "--stroke", "foo"),
    (("analyze", "--crank", "100", "--K=1.4", "7", "--stroke", "300"), "--K", "7"),
    (("gear", "--z1", "13", "--z2", "52", "--module", "4", "5"), "--module", "5"),
    (("analyze", *DESIGN, ""), "--stroke", ""),        # an empty word is named too
])
def test_a_stray_word_names_the_option_it_follows(args, option, word):
    message = _one_line(args)
    assert message.startswith(f"{option}: takes ") and f"'{word}' is left over" in message
    assert "unrecognized arguments" not in message


def test_a_second_speed_where_one_is_taken_names_rpm(tmp_path):
    lib = tmp_path / "lib.sqlite"
    for name in ("a", "b"):
        assert shaper_in_process("library", "add", *DESIGN, "--name", name, "--library", lib)[0] == 0
    message = _one_line(("library", "compare", "a", "b", "--rpm", "40", "60", "--library", lib))
    assert message.startswith("--rpm: takes one value, so '60' is left over")
    assert "shaper library compare --help" in message


def test_a_stray_word_before_any_option_is_named_itself():
    message = _one_line(("analyze", "foo", *DESIGN))
    assert message.startswith("'foo': not an argument of 'shaper analyze'")


@pytest.mark.parametrize("z1, shown", [(1e300, "1e+300"), (1e20, "1e+20")])
def test_a_huge_whole_number_in_a_file_keeps_the_reason(tmp_path, z1, shown):
    doc = {"format": "shaper-design", "version": 1,
           "spec": {"mode": "synthesis", "crank": 100.0, "time_ratio": 1.4, "stroke": 300.0},
           "rpm": [40], "step_deg": 1, "gear": {"z1": z1, "z2": 52, "module_mm": 4}}
    path = tmp_path / "z.json"
    path.write_text(json.dumps(doc), encoding="utf-8")
    for command in ("gear", "analyze"):
        message = _one_line((command, "--design", path))
        assert f"z1 = {shown}: must be" in message and "teeth" in message and len(message) < 200
    assert _one_line(("gear", "--z1", repr(z1), "--z2", "52", "--module", "4")).endswith(f"(got {shown})")


@pytest.mark.parametrize("args, word", [
    # the fuzz's case (CI, 29 November): an empty word left over printed
    # "unrecognized arguments: " and named nothing
    (("library", "remove", "--", "--library", ""), ""),
    # after "--" every word is positional: '--library' there is the entry's name, not the
    # option, so 'x' was not "left over by --library"
    (("library", "remove", "--", "--library", "x"), "x"),
])
def test_a_word_after_the_positionals_is_named_itself(args, word):
    message = _one_line(args)
    assert message.startswith(f"{word!r}: not an argument of 'shaper {args[0]}"), message
    assert "unrecognized arguments" not in message and "takes" not in message
