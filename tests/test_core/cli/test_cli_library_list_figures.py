"""``shaper library list`` writes each figure in the one precision of its kind, as the
report, ``shaper synth``/``dynamics`` and the class's answer key write it (methods.md,
"Figures in tables"): H 300.000 mm and J_F 816.8 kg·m² for the task book's loads; it
wrote 300.00 and 816.75, so a teacher comparing a student's library with the answer key
read two numbers for one."""
from __future__ import annotations

import re

from cli_runner import shaper_in_process

DESIGN = ("--crank", 100, "--K", 1.4, "--stroke", 300, "--rpm", 60, "--lever-mass", 20, "--lever-inertia", 1.1,
          "--ram-mass", 70, "--cut-force", 7000, "--cut-height", 80)


def test_the_list_writes_each_figure_as_the_other_commands_do(tmp_path):
    path = tmp_path / "lib.sqlite"
    status, _, err = shaper_in_process("library", "add", *DESIGN, "--name", "seed 003", "--library", path)
    assert status == 0, err
    status, listing, err = shaper_in_process("library", "list", "--library", path)
    assert status == 0, err
    head, row = (line.split("  ") for line in listing.splitlines())
    cells = dict(zip([h.strip() for h in head if h.strip()], [c.strip() for c in row if c.strip()]))
    status, synth, _ = shaper_in_process("synth", *DESIGN[:6])
    status, dynamics, _ = shaper_in_process("dynamics", *DESIGN)

    def printed(text, label):
        return re.search(rf"^{re.escape(label)}\s+([^\s°]+)", text, re.M).group(1)
    assert cells["H mm"] == "300.000" == printed(synth, "stroke H")
    assert cells["θ °"] == printed(synth, "extreme-position angle θ") == "30.000"
    assert cells["K"] == printed(synth, "time ratio K") == "1.4000"
    assert cells["J_F kg·m²"] == printed(dynamics, "flywheel J_F") == "816.8"
