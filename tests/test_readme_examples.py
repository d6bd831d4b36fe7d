"""The README's command-line examples print what the README says they print.

Each ```console block of the README holds ``$ shaper …`` lines followed by
their output. The deterministic ones (no library file, no clock, no PDF) are
run here through a shell, so a figure in the README can never drift from what
the program computes.
"""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
CHECKED = ("synth", "analyze", "curves", "table", "dynamics", "sweep")


def examples() -> list[tuple[str, str]]:
    found = []
    for block in re.findall(r"```console\n(.*?)```", README.read_text(encoding="utf-8"), re.S):
        lines = block.splitlines()
        starts = [i for i, line in enumerate(lines) if line.startswith("$ ")]
        for j, i in enumerate(starts):
            end = starts[j + 1] if j + 1 < len(starts) else len(lines)
            command = lines[i][2:]
            if command.split()[1] in CHECKED:
                found.append((command, "\n".join(lines[i + 1:end]).rstrip()))
    return found


EXAMPLES = examples()


def test_the_readme_has_examples_of_every_checked_command():
    assert {command.split()[1] for command, _ in EXAMPLES} == set(CHECKED)


@pytest.mark.skipif(shutil.which("shaper") is None, reason="the shaper command is not installed")
@pytest.mark.parametrize("command, expected", EXAMPLES, ids=[c[:60] for c, _ in EXAMPLES])
def test_readme_example_output(command, expected, tmp_path):
    run = subprocess.run(["bash", "-c", command], capture_output=True, text=True, cwd=tmp_path,
                         timeout=120)
    assert (run.stdout + run.stderr).rstrip() == expected
