"""Options every subcommand shares: --design, --version, help, negative numbers, encodings."""
import json
import os
import subprocess

import pytest

from core.files.io import save_design
from core.linkage.spec import Spec

# The real console script where the process is the point (its bare run, --version, an ASCII
# console); what a command writes or refuses, in this process (no start-up per run).
from cli_runner import shaper, shaper_run_in_process as in_process

SEED003 = ["--crank", "100", "--K", "1.4", "--stroke", "300"]


def test_bare_shaper_prints_usage_and_version_is_known():
    out = shaper()
    assert out.returncode == 0 and "COMMAND" in out.stdout and "synth" in out.stdout
    version = shaper("--version")
    assert version.returncode == 0 and version.stdout.startswith("shaper ")


@pytest.mark.parametrize("command", ["synth", "curves", "analyze", "dynamics"])
def test_every_subcommand_help_has_a_description_and_an_example(command):
    out = in_process(command, "--help")
    assert out.returncode == 0
    assert "example:" in out.stdout and f"shaper {command}" in out.stdout.split("example:")[1]
    assert "--design" in out.stdout


def test_design_file_stands_for_the_design_options(tmp_path):
    path = tmp_path / "d.shaper.json"
    spec = Spec(crank=110.0, time_ratio=1.5, stroke=320.0, variant="rod", rod_ratio=0.3)
    save_design(path, spec, [35.0], 2.0)
    from_file = json.loads(in_process("analyze", "--design", path, "--json").stdout)
    direct = json.loads(in_process("analyze", "--crank", "110", "--K", "1.5", "--stroke", "320",
                                   "--rod-ratio", "0.3", "--rpm", "35", "--json").stdout)
    assert from_file == direct
    # The file's step is the curves' default step.
    rows = in_process("curves", "--design", path).stdout.splitlines()
    assert len(rows) == 1 + 181


def test_design_file_and_design_options_exclude_each_other(tmp_path):
    path = tmp_path / "d.shaper.json"
    save_design(path, Spec(), [40.0], 1.0)
    out = in_process("analyze", "--design", path, "--crank", "100")
    assert out.returncode == 2 and "--design" in out.stderr and len(out.stderr.splitlines()) == 1


def test_bad_design_file_exits_2_with_one_line(tmp_path):
    path = tmp_path / "bad.json"
    path.write_text("{not json")
    out = in_process("analyze", "--design", path)
    assert out.returncode == 2 and out.stderr.startswith("shaper: error: --design:")
    assert len(out.stderr.splitlines()) == 1


def test_negative_speed_gets_a_range_message():
    out = in_process("curves", *SEED003, "--rpm", "-1e5")
    assert out.returncode == 2 and "--rpm" in out.stderr and "1000" in out.stderr


def test_step_and_angles_exclude_each_other():
    out = in_process("curves", *SEED003, "--step", "1", "--angles", "0,1")
    assert out.returncode == 2 and "--angles" in out.stderr and "--step" in out.stderr


def test_k_near_one_names_k_in_synth():
    out = in_process("synth", "--crank", "100", "--K", "1.000000000001", "--stroke", "300")
    assert out.returncode == 2 and "--K" in out.stderr and "--dims" not in out.stderr


@pytest.mark.parametrize("command", [["synth"], ["analyze"]])
def test_ascii_console_gets_spelled_out_symbols(command):
    env = dict(os.environ, PYTHONIOENCODING="ascii")
    exe = [a for a in [__import__("shutil").which("shaper")] if a]
    out = subprocess.run(exe + command + SEED003, capture_output=True, text=True, env=env,
                         encoding="ascii")
    assert out.returncode == 0, out.stderr
    assert "theta" in out.stdout or "m/s^2" in out.stdout


# ---- habits of a command line (issue 20 item 9) -----------------------------------------
@pytest.mark.parametrize("args,expected", [
    (["synth", *SEED003[:2], "--k", "1.4", "--stroke", "300"], "--k: unknown option; did you mean --K?"),
    (["library", "list", "--srot", "name"], "--srot: unknown option; did you mean --sort?"),
    (["synht", "--crank", "100"], "did you mean synth?"),
    (["optimize", *SEED003, "--objective", "acel", "--vary", "crank=80:120"], "did you mean accel?"),
    (["synth", *SEED003, "--zzz", "3"], "--zzz: unknown option; see 'shaper synth --help'"),
])
def test_a_mistyped_option_gets_the_close_match(args, expected):
    """`--k 1.4` said only "unrecognized arguments"."""
    from cli_runner import shaper_in_process
    status, out, err = shaper_in_process(*args)
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and expected in err, err


def _verbs():
    from core.cli import _command_modules
    verbs = [(name, []) for name in _command_modules() if name != "library"]
    from core.cli.cmd_library import ACTIONS
    return verbs + [("library", [action]) for action, _, _ in ACTIONS]


@pytest.mark.parametrize("command,action", _verbs())
def test_every_verb_has_an_example_that_parses(command, action, capsys):
    """The library's ten actions had no example; every example must be a valid command."""
    from core.cli import build_parser
    parser = build_parser()
    with pytest.raises(SystemExit):
        parser.parse_args([command, *action, "--help"])
    text = capsys.readouterr().out
    assert "example:" in text, (command, action)
    examples = [line.strip() for line in text.split("example:")[1].splitlines()
                if line.strip().startswith(f"shaper {' '.join([command, *action])}")]
    assert examples, text
    import shlex
    for example in examples:
        parser.parse_args(shlex.split(example)[1:])       # raises UsageError if it is wrong
    assert "seed" not in text.lower() and "README" not in text          # the user's words


def test_library_list_help_gives_the_filter_syntax_and_sort_fields(capsys):
    from core.cli import build_parser
    from core.library.query import FIELDS, OPERATORS
    with pytest.raises(SystemExit):
        build_parser().parse_args(["library", "list", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    for key in FIELDS:
        if key != "tag":
            assert key in text, key
    assert all(op in text for op in OPERATORS) and "tag=TAG" in text


@pytest.mark.parametrize("lang", ["en", "zh", "zh_CN"])
def test_every_lang_option_takes_both_spellings_of_chinese(lang, capsys):
    """`report --lang` took en|zh, `shaperapp --lang` en|zh_CN."""
    from core.cli import build_parser
    from shaperapp.widgets import i18n
    args = build_parser().parse_args(["report", *SEED003, "-o", "r.pdf", "--lang", lang])
    assert args.lang == lang
    assert i18n.language_of(lang) == ("en" if lang == "en" else "zh_CN")
    from shaperapp.app import main
    with pytest.raises(SystemExit) as done:
        main(["--lang", lang, "--help"])          # parsed before any window: a choice error exits 2
    assert done.value.code == 0 and "zh_CN" in capsys.readouterr().out


def test_version_imports_nothing_of_the_engine():
    """``shaper --version`` prints one line without loading numpy, ezdxf, Qt or the
    subcommands (issue 43 item 5): before, it built every subcommand's parser and loaded
    all three, about 1.5 s on a quiet machine for one line."""
    import sys
    probe = ("import sys, runpy; sys.argv = ['shaper', '--version']\n"
             "try:\n    runpy.run_module('core', run_name='__main__')\n"
             "except SystemExit as exc:\n    status = exc.code\n"
             "heavy = sorted(m for m in sys.modules if m.split('.')[0] in "
             "('numpy', 'ezdxf', 'PySide6', 'scipy', 'shaperapp') or m.startswith('core.cli'))\n"
             "print('STATUS', status, 'HEAVY', heavy)\n")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120)
    assert done.stdout.startswith("shaper ")
    assert "STATUS 0 HEAVY []" in done.stdout, done.stdout
