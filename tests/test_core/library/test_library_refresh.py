"""Figures an older program stored are found and recomputed (``Library.refresh_figures``,
``shaper library refresh``), and nothing else about an entry changes."""
import json
import sqlite3
from pathlib import Path

import pytest

import core.library as library_module
import core.library.entry as library_entry
# What the commands write, run in this process (each process costs its start-up);
# test_cli_library.py runs the real command.
from cli_runner import shaper_run_in_process as shaper
from core.forces.masses import MassProperties
from core.space.figures import FIGURES_VERSION, figures
from core.library import Library
from core.library.store import schema_version
from core.linkage.spec import Spec
from locations import DATA

LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)
FIXTURE_V1 = DATA / "library-v1.sqlite"
SPECS = {f"K{k}": Spec(time_ratio=k) for k in (1.3, 1.4, 1.5)}
SPECS["rod"] = Spec(time_ratio=1.6, variant="rod", rod_ratio=0.35)


def loaded(spec):
    return {"spec": spec, "rpm": [40.0, 60.0], "step_deg": 1.0, "masses": LOADS}


@pytest.fixture
def path(tmp_path):
    path = tmp_path / "lib.sqlite"
    with Library(path) as lib:
        for name, spec in SPECS.items():
            lib.add(name, loaded(spec), notes=f"about {name}", tags=["t"])
    return path


def age(path, name, version=0):
    """What an older program left: an older figures version and figures that differ."""
    conn = sqlite3.connect(path)
    with conn:
        entry_id = conn.execute("SELECT id FROM entries WHERE name = ?", (name,)).fetchone()[0]
        conn.execute("UPDATE entries SET figures_version = ?, K = K + 0.5 WHERE id = ?", (version, entry_id))
        conn.execute("UPDATE speeds SET a_max_m_s2 = a_max_m_s2 * 0.74, max_torque_N_m = 1 WHERE entry_id = ?",
                     (entry_id,))
    conn.close()


def fresh(spec):
    return figures(spec, [40.0, 60.0], LOADS)


def test_stale_entries_are_found_and_recomputed_and_nothing_else_changes(path):
    age(path, "rod")
    age(path, "K1.3")
    with Library(path) as lib:
        before = {name: lib.get(name) for name in lib.names()}
        assert lib.stale_names() == ["K1.3", "rod"]
        assert not before["rod"].figures_current and before["K1.4"].figures_current
        assert before["rod"].figures != fresh(SPECS["rod"])
        done = []
        report = lib.refresh_figures(progress=lambda i, n: done.append((i, n)))
        assert report.updated == ("K1.3", "rod") and report.failed == () and report.skipped == ()
        assert done == [(1, 2), (2, 2)]
        assert lib.stale_names() == []
        for name, old in before.items():
            new = lib.get(name)
            assert new.figures == fresh(SPECS[name])          # computed anew by core.space.figures
            assert new.figures_current
            assert (new.name, new.notes, new.tags, new.created, new.modified, new.text) == \
                   (old.name, old.notes, old.tags, old.created, old.modified, old.text)
        assert lib.query("name=rod", rpm=60)[0]["a_max_m_s2"] == fresh(SPECS["rod"]).speeds[1].a_max_m_s2


def test_a_newer_computation_makes_every_entry_stale(path, monkeypatch):
    monkeypatch.setattr(library_module, "FIGURES_VERSION", FIGURES_VERSION + 1)
    monkeypatch.setattr(library_entry, "FIGURES_VERSION", FIGURES_VERSION + 1)   # Entry.figures_current
    with Library(path) as lib:
        assert lib.stale_names() == sorted(SPECS)
        assert not lib.get("K1.4").figures_current
        assert lib.refresh_figures().updated == tuple(sorted(SPECS))
        assert lib.stale_names() == []
        assert lib.get("K1.4").figures_version == FIGURES_VERSION + 1
        lib.add("new", loaded(Spec(time_ratio=1.45)))          # a new entry is stamped current
        assert lib.get("new").figures_version == FIGURES_VERSION + 1


def test_schema_1_library_is_migrated_with_its_figures_as_version_1(tmp_path):
    path = tmp_path / "old.sqlite"
    path.write_bytes(FIXTURE_V1.read_bytes())
    with Library(path) as lib:
        assert lib._conn.execute("PRAGMA user_version").fetchone()[0] == schema_version() == 2
        assert {lib.get(n).figures_version for n in lib.names()} == {1}
        assert lib.stale_names() == ([] if FIGURES_VERSION == 1 else lib.names())
    assert len(list(tmp_path.glob("old.sqlite.schema1-*"))) == 1


def test_a_design_that_no_longer_computes_is_left_and_reported(path):
    age(path, "K1.5")
    age(path, "rod")
    conn = sqlite3.connect(path)
    with conn:      # a rule the stored design breaks (as a stricter later version might)
        doc = json.loads(conn.execute("SELECT d.text FROM documents d JOIN entries e ON e.id = d.entry_id "
                                      "WHERE e.name = 'rod'").fetchone()[0])
        doc["spec"]["rod_ratio"] = 0.01
        conn.execute("UPDATE documents SET text = ? WHERE entry_id = (SELECT id FROM entries WHERE name = 'rod')",
                     (json.dumps(doc),))
    conn.close()
    with Library(path) as lib:
        stored = lib.get("rod")
        report = lib.refresh_figures()
        assert report.updated == ("K1.5",)
        assert [name for name, _ in report.failed] == ["rod"] and "rod" in report.failed[0][1]
        assert lib.get("rod") == stored and lib.stale_names() == ["rod"]


def test_an_entry_saved_again_meanwhile_is_skipped(path, monkeypatch):
    """Another program re-saves the entry while this one computes: its write wins."""
    age(path, "K1.3")
    real = library_module.figures

    def racing(spec, rpm, masses):
        monkeypatch.setattr(library_module, "figures", real)       # race once
        with Library(path) as other:
            other.add("K1.3", loaded(Spec(time_ratio=1.35)), replace=True)
        return real(spec, rpm, masses)
    monkeypatch.setattr(library_module, "figures", racing)
    with Library(path) as lib:
        report = lib.refresh_figures(["K1.3"])
        assert report.updated == () and report.skipped == ("K1.3",)
        assert lib.get("K1.3").figures == fresh(Spec(time_ratio=1.35))


def test_an_interrupted_refresh_keeps_the_batches_it_committed(path, monkeypatch):
    monkeypatch.setattr(library_module, "REFRESH_BATCH", 2)
    for name in SPECS:
        age(path, name)

    def stop(done, total):
        if done == 3:
            raise KeyboardInterrupt
    with Library(path) as lib:
        with pytest.raises(KeyboardInterrupt):
            lib.refresh_figures(progress=stop)
        assert lib.stale_names() == sorted(SPECS)[2:]          # the first batch landed whole
        assert lib._conn.execute("PRAGMA quick_check").fetchone()[0] == "ok"
        assert lib.refresh_figures().updated == tuple(sorted(SPECS)[2:])


def test_cli_notes_stale_figures_and_refreshes_them(path):
    age(path, "rod")
    listed = shaper("library", "list", "--library", path)
    assert listed.returncode == 0 and "1 of the 4 designs listed has figures" in listed.stderr
    shown = json.loads(shaper("library", "show", "rod", "--json", "--library", path).stdout)
    assert shown["figures_current"] is False and shown["figures_version"] == 0
    refreshed = shaper("library", "refresh", "--library", path)
    assert refreshed.returncode == 0 and "recomputed the figures of 1 of 1 designs" in refreshed.stdout
    shown = json.loads(shaper("library", "show", "rod", "--json", "--library", path).stdout)
    assert shown["figures_current"] is True and shown["K"] == pytest.approx(1.6, abs=1e-9)
    again = shaper("library", "list", "--library", path)
    assert again.returncode == 0 and again.stderr == ""
    every = json.loads(shaper("library", "refresh", "--all", "--json", "--library", path).stdout)
    assert every == {"updated": sorted(SPECS), "skipped": [], "failed": []}


@pytest.mark.parametrize("words, option", [(["--all", "rod"], "--all"), (["nobody"], "NAME")])
def test_cli_refresh_bad_input_is_one_line(path, words, option):
    result = shaper("library", "refresh", *words, "--library", path)
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"shaper: error: {option}")
