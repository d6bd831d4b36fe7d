"""A library entry stored before the design file's sample limit (``MAX_FILE_SAMPLES``).

Such an entry is whole: ``library add`` kept it when a step of 0.01° with two speeds was
allowed. It listed as "damaged" and ``show``/``export`` refused it with no way out. It now
lists as "too fine", ``check`` says its samples and the step that fits, and ``export``
refuses it with the command that exports it at that step, which the test runs. Nothing in
the library changes.
"""
from __future__ import annotations

import json
import shlex
import sqlite3

import pytest

from core.files.io import load_design
from core.linkage.limits import MAX_FILE_SAMPLES, angle_count

from cli_runner import shaper_in_process

FINE_STEP = 0.01            # 36 001 angles × 2 speeds = 72 002 samples


@pytest.fixture
def lib(tmp_path):
    """A library with 'ok' and 'old fine' (two speeds, stored at 0.5° and then given the
    step 0.01° in its document, as ``library add`` stored it before the limit)."""
    path = tmp_path / "lib.sqlite"
    for name, k in (("ok", "1.5"), ("old fine", "1.4")):
        status, _, err = shaper_in_process("library", "add", "--crank", "100", "--K", k, "--stroke", "300",
                                           "--rpm", "40", "60", "--step", "0.5", "--name", name,
                                           "--library", str(path))
        assert status == 0, err
    with sqlite3.connect(path) as c:
        entry_id, text = c.execute("SELECT d.entry_id, d.text FROM documents d JOIN entries e "
                                   "ON e.id = d.entry_id WHERE e.name = 'old fine'").fetchone()
        doc = json.loads(text)
        doc["step_deg"] = FINE_STEP
        c.execute("UPDATE documents SET text = ? WHERE entry_id = ?", (json.dumps(doc, indent=2), entry_id))
    return path


def stored(path) -> list[tuple]:
    with sqlite3.connect(path) as c:
        return c.execute("SELECT e.name, e.modified, d.text FROM entries e JOIN documents d "
                         "ON d.entry_id = e.id ORDER BY e.id").fetchall()


def test_an_old_fine_entry_lists_as_too_fine_not_damaged(lib):
    samples = angle_count(FINE_STEP) * 2
    assert samples > MAX_FILE_SAMPLES
    status, out, err = shaper_in_process("library", "list", "--library", str(lib))
    assert status == 0, err
    assert "old fine (too fine)" in out and "damaged" not in out + err, (out, err)
    assert f"too fine for a design file (stored before its limit of {MAX_FILE_SAMPLES}" in err
    status, out, err = shaper_in_process("library", "check", "--library", str(lib))
    assert status == 1 and "damaged" not in out, out
    assert f"'old fine': too fine: {samples} samples, limit {MAX_FILE_SAMPLES}; " \
           "'shaper library export' with --step 0.0121" in out, out
    status, _, err = shaper_in_process("library", "show", "old fine", "--library", str(lib))
    assert status == 2 and "too fine" in err and "--step 0.0121" in err, err


def test_the_refusals_advice_followed_exports_it(lib, tmp_path):
    """``export`` without a step names the command with the step that fits; that command,
    run as written, writes a design file every ``--design`` reader opens, the entry's
    design at that step; the library is unchanged."""
    before = stored(lib)
    target = tmp_path / "old fine.shaper.json"
    status, _, err = shaper_in_process("library", "export", "old fine", "--library", str(lib), "-o", str(target))
    lines = err.strip().splitlines()
    assert status == 2 and len(lines) == 1 and lines[0].startswith("shaper: error: NAME: 'old fine' is too fine"), err
    assert not target.exists()
    command = shlex.split(lines[0].split("export it at a coarser step: ", 1)[1])
    assert command[:3] == ["shaper", "library", "export"], command
    status, _, err = shaper_in_process(*command[1:])
    assert status == 0, err
    loaded = load_design(target)
    assert loaded["step_deg"] == 0.0121 and angle_count(0.0121) * 2 <= MAX_FILE_SAMPLES
    original = json.loads([t for n, _, t in before if n == "old fine"][0])
    written = json.loads(target.read_text())
    assert {**written, "step_deg": FINE_STEP} == original            # only the step changed
    status, out, err = shaper_in_process("analyze", "--design", str(target))
    assert status == 0 and "1.4000" in out, err
    assert stored(lib) == before                                    # nothing in the library changed


def test_a_step_still_too_fine_names_step_and_writes_nothing(lib, tmp_path):
    target = tmp_path / "x.shaper.json"
    status, _, err = shaper_in_process("library", "export", "old fine", "--library", str(lib),
                                       "--step", "0.012", "-o", str(target))
    assert status == 2 and err.startswith("shaper: error: --step: 'old fine' is too fine"), err
    assert "--step 0.0121" in err and not target.exists()
    status, _, err = shaper_in_process("library", "export", "--all", "--step", "1", "--library", str(lib),
                                       "-o", str(tmp_path / "all"))
    assert status == 2 and err.startswith("shaper: error: --step:"), err


@pytest.mark.parametrize("step", ["0", "-1", "1e9"])
def test_a_step_out_of_range_names_step(lib, tmp_path, step):
    """`export NAME --step 0` said `NAME: library entry …: invalid design (step = 0: …)`,
    naming the entry, not the option typed (hunt, 1 December)."""
    before = stored(lib)
    status, _, err = shaper_in_process("library", "export", "old fine", "--step", step,
                                       "-o", tmp_path / "x.json", "--library", lib)
    assert status == 2 and err == f"shaper: error: --step: must be ≥ 0.0002 and ≤ 90 ° (got {step})\n"
    assert not (tmp_path / "x.json").exists() and stored(lib) == before


def test_a_too_fine_entry_is_compared_its_step_left_aside(lib):
    """`library compare` refused an entry too fine for a design file with "use a step of at
    least 0.0121°", which its own --step could not give (hunt, 1 December): a comparison
    takes the linkage, the speeds and the loads, never the stored step, so it compares. Its
    figures are those of the same design stored at a coarse step."""
    before = stored(lib)
    status, out, err = shaper_in_process("library", "compare", "old fine", "ok", "--json", "--library", lib)
    assert status == 0, err
    fine = {f["figure"]: f["values"]["old fine"] for f in json.loads(out)["figures"]}
    status, _, err = shaper_in_process("library", "add", "--crank", "100", "--K", "1.4", "--stroke", "300",
                                       "--rpm", "40", "60", "--step", "0.5", "--name", "coarse", "--library", lib)
    assert status == 0, err
    status, out, err = shaper_in_process("library", "compare", "coarse", "ok", "--json", "--library", lib)
    coarse = {f["figure"]: f["values"]["coarse"] for f in json.loads(out)["figures"]}
    assert fine == coarse and fine["a_max_m_s2"] is not None
    assert stored(lib)[:len(before)] == before                     # nothing stored changed


def test_a_too_fine_entrys_figures_are_recomputed(lib):
    """`library refresh` said of an entry too fine for a design file that it 'cannot be
    computed any more' and kept its figures (hunt, 1 December): its figures never take the
    stored step, so they are recomputed; its document stays as stored."""
    before = {name: text for name, _, text in stored(lib)}
    status, out, err = shaper_in_process("library", "refresh", "old fine", "--library", lib)
    assert (status, err) == (0, "") and out == f"recomputed the figures of 1 of 1 designs in {lib}\n"
    assert {name: text for name, _, text in stored(lib)} == before
