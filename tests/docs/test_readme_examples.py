"""The command-line examples of the README and of docs/ print what they say they print.

Each ```console block of README.md and of every docs/*.md page holds ``$ shaper …``
lines followed by their output. The deterministic ones (no library file, no clock,
no PDF) are run here, so a figure in the docs can never drift from what the program
computes: a line with a pipe through a shell, the others through ``core.cli.main`` in the
test's process with the words a shell would pass (what is checked is the output; the
console script as a process is ``test_cli.py``'s, and a new Python with scipy cost 0.3 s
a cam example). The README's table of subcommands gives one command line for each; those
are run as a user types them, through a shell, and must succeed.
"""
import os
import re
import shlex
import shutil
import subprocess
from pathlib import Path

import pytest
from cli_runner import shaper_in_process
from locations import ROOT

ROOT = ROOT
README = ROOT / "README.md"
PAGES = [README, *sorted((ROOT / "docs").glob("*.md"))]
CHECKED = ("synth", "analyze", "curves", "table", "dynamics", "sweep", "cam", "gear")
# Every subcommand of ``shaper`` (core/cli's CORE_COMMANDS plus the Qt ones, report and drawing).
SUBCOMMANDS = ("synth", "curves", "analyze", "dynamics", "table", "sweep", "optimize", "cam", "gear", "library",
               "report", "drawing", "course", "design", "class")
DESIGN_FILE = ROOT / "tests" / "data" / "my.shaper.json"
TASKS_FILE = ROOT / "tests" / "data" / "tasks.csv"   # the GUI's default design, saved: what course reads


def console_examples(text: str) -> list[tuple[str, str]]:
    """(command, expected output) of every ``$ shaper …`` line of ``text``'s console blocks."""
    found = []
    for block in re.findall(r"```console\n(.*?)```", text, re.S):
        lines = block.splitlines()
        starts = [i for i, line in enumerate(lines) if line.startswith("$ ")]
        for j, i in enumerate(starts):
            end = starts[j + 1] if j + 1 < len(starts) else len(lines)
            found.append((lines[i][2:], "\n".join(lines[i + 1:end]).rstrip()))
    return found


def examples() -> list[tuple[str, str, str]]:
    return [(page.name, command, expected) for page in PAGES
            for command, expected in console_examples(page.read_text(encoding="utf-8"))
            if command.split()[1] in CHECKED]


def table_commands() -> list[str]:
    """The example column of the README's table of subcommands."""
    return re.findall(r"^\| \[`[a-z]+`\]\([^)]*\) \|[^|]*\| `(shaper [^`]*)` \|$",
                      README.read_text(encoding="utf-8"), re.M)


EXAMPLES = examples()
SHELL_SYNTAX = set("|&;<>()$`*?~\\")       # a line with any of these needs a shell
TABLE = table_commands()


def test_the_docs_have_examples_of_every_checked_command():
    assert {command.split()[1] for _, command, _ in EXAMPLES} == set(CHECKED)


def test_console_blocks_are_found_in_docs_pages():
    """The collector reads docs/ too: the checked examples now live in docs/cli.md."""
    assert any(page != README.name for page, _, _ in EXAMPLES)


def test_the_readme_table_has_one_example_of_every_subcommand():
    assert sorted(command.split()[1] for command in TABLE) == sorted(SUBCOMMANDS)


@pytest.mark.skipif(shutil.which("shaper") is None, reason="the shaper command is not installed")
@pytest.mark.parametrize("page, command, expected", EXAMPLES,
                         ids=[f"{p}:{c[:60]}" for p, c, _ in EXAMPLES])
def test_docs_example_output(page, command, expected, tmp_path, monkeypatch):
    words = shlex.split(command)
    if SHELL_SYNTAX & set(command) or words[0] != "shaper":
        run = subprocess.run(["bash", "-c", command], capture_output=True, text=True, cwd=tmp_path,
                             timeout=120)
        printed = run.stdout + run.stderr
    else:
        monkeypatch.chdir(tmp_path)          # where the line's own files go, as in the shell
        _, out, err = shaper_in_process(*words[1:])
        printed = out + err
    assert printed.rstrip() == expected


@pytest.mark.skipif(shutil.which("shaper") is None, reason="the shaper command is not installed")
@pytest.mark.parametrize("command", TABLE, ids=[c.split()[1] for c in TABLE])
def test_readme_table_example_runs(command, tmp_path):
    env = {**os.environ, "SHAPER_LIBRARY": str(tmp_path / "library.sqlite")}
    shutil.copy(DESIGN_FILE, tmp_path / DESIGN_FILE.name)     # a design file as a user has one
    shutil.copy(TASKS_FILE, tmp_path / TASKS_FILE.name)       # and a class's table of one student
    run = subprocess.run(["bash", "-c", command], capture_output=True, text=True, cwd=tmp_path,
                         timeout=600, env=env)
    # my.shaper.json was saved before the cam had a hub, a pivot boss and a least clearance
    # (issue 34): a command reading it says the defaults it takes, one note each, nothing else
    notes = [line for line in run.stderr.splitlines()
             if re.fullmatch(r"shaper: note: --(design|base): my\.shaper\.json gives no "
                             r"cam\.(hub_mm|boss_mm|clearance_mm); (12\.5|3) mm taken", line)]
    assert run.returncode == 0 and run.stderr == "".join(n + "\n" for n in notes), run.stderr
    assert len(notes) == (3 if "my.shaper.json" in command else 0)
    assert run.stdout or any(tmp_path.iterdir())
