"""The task sheet prints a weight as the task book gives it (issue 41 item 2): a design file
whose loads were typed as weights (G4 = 200 N, G6 = 700 N) holds no masses, and the sheet's
data set must read those weights back, not fail on the missing mass (KeyError before)."""
from __future__ import annotations

import json

from cli_runner import shaper_in_process
from core.drawing.class_sheets import TASK_WORDS, data_rows
from core.forces.masses import GRAVITY
from core.linkage.spec import Spec

SCHEME_I = ("--dims", "110,380,540", "--rod-ratio", "0.25", "--rpm", "60", "--lever-inertia", "1.1",
            "--cut-force", "7000", "--cut-height", "80")


def _rows(tmp_path, *loads):
    path = tmp_path / "d.shaper.json"
    status, _, err = shaper_in_process("design", *SCHEME_I, *loads, "-o", path)
    assert status == 0, err
    doc = json.loads(path.read_text(encoding="utf-8"))
    design = Spec.from_dict(doc["spec"]).design()
    labels = {word: word for word in TASK_WORDS}
    return {row[1]: row[2] for row in data_rows(doc, design, labels)}


def test_weights_typed_are_printed_as_typed(tmp_path):
    rows = _rows(tmp_path, "--lever-weight", "200", "--ram-weight", "700")
    assert rows["G_4"] == "200" and rows["G_6"] == "700"


def test_masses_are_printed_as_their_weights(tmp_path):
    rows = _rows(tmp_path, "--lever-mass", "20", "--ram-mass", "70")
    assert float(rows["G_4"]) == float(f"{20 * GRAVITY:.4g}")
    assert float(rows["G_6"]) == float(f"{70 * GRAVITY:.4g}")
