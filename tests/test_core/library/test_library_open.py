"""Opening a library is decided up front: usable, damaged, read-only, newer or foreign.

A refused library keeps its bytes (checked by hash, with the -wal file) and gets no copy
beside it, however often it is tried; a read-only one can be read and every write is
refused in one line with the reason. Tests run as root, whom permissions do not stop,
so read-only is simulated where root is concerned by making ``unwritable`` report a
reason (SQLite then really opens the file with ``mode=ro``); the real permission case
runs only for an ordinary user.
"""
import hashlib
import os
import shutil
import sqlite3
from pathlib import Path

import pytest

from core.files.io import save_design
from core.library import Library
from core.library import open as library_open
from core.library import store as library_store
from core.library.store import LibraryError
from core.linkage.spec import Spec

from cli_runner import shaper_in_process
from locations import DATA

FIXTURE_V1 = DATA / "library-v1.sqlite"
DESIGN = ("--crank", "100", "--K", "1.4", "--stroke", "300")
ACTIONS = [("list",), ("list", "--json"), ("show", "a"), ("add", *DESIGN, "--name", "n"),
           ("remove", "a"), ("rename", "a", "z"), ("compare", "a", "b"), ("refresh",), ("check",),
           ("import", "IMPORT"), ("export", "a", "-o", "OUT")]


def make_library(path, names=("a", "b")):
    with Library(path) as lib:
        for name in names:
            lib.add(name, {"spec": Spec(), "rpm": [40.0], "step_deg": 1.0, "masses": None},
                    notes="M" * 300)


def folder_state(folder):
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in sorted(Path(folder).iterdir())
            if p.is_file()}


def run_all(path, tmp_path):
    """Every action on ``path``: (status, stderr) each."""
    design = tmp_path / "in" / "d.shaper.json"
    if not design.exists():
        design.parent.mkdir(exist_ok=True)
        save_design(design, Spec(), [40.0], 1.0)
    out = []
    for action in ACTIONS:
        args = [str(design) if a == "IMPORT" else str(tmp_path / "in" / "o.json") if a == "OUT" else a
                for a in action]
        status, _, err = shaper_in_process("library", *args, "--library", path)
        out.append((action, status, err))
    return out


def crafted(path, *sql):
    make_library(path)
    with sqlite3.connect(path) as conn:
        for statement in sql:
            conn.execute(statement)
    conn.close()


DAMAGED = {
    "schema 1 but schema 2 tables": ("PRAGMA user_version = 1",),
    "schema -1": ("PRAGMA user_version = -1",),
    "no tables": ("DROP TABLE tags", "DROP TABLE speeds", "DROP TABLE documents", "DROP TABLE entries"),
    "no documents table": ("DROP TABLE documents",),
    "a column missing": ("ALTER TABLE entries DROP COLUMN notes",),
}


@pytest.mark.parametrize("sql", DAMAGED.values(), ids=list(DAMAGED))
def test_damaged_library_is_refused_unchanged_and_uncopied(tmp_path, sql):
    folder = tmp_path / "lib"
    folder.mkdir()
    path = folder / "lib.sqlite"
    crafted(path, *sql)
    before = folder_state(folder)
    for action, status, err in run_all(path, tmp_path) + run_all(path, tmp_path):
        assert status == 2, (action, err)
        assert err.count("\n") == 1 and err.startswith("shaper: error: --library: ")
        assert "damaged" in err and "left unchanged" in err
    assert folder_state(folder) == before          # same bytes, no copy, no -wal or -shm
    with pytest.raises(LibraryError) as refused:
        Library(path)
    assert refused.value.kind == "damaged" and folder_state(folder) == before


def test_refused_library_can_still_be_copied_once(tmp_path):
    path = tmp_path / "lib.sqlite"
    crafted(path, *DAMAGED["no tables"])
    status, out, err = shaper_in_process("library", "backup", "--library", path)
    assert status == 0 and len(list(tmp_path.glob("lib.sqlite.backup-*"))) == 1


def test_failed_migration_leaves_no_copy(tmp_path, monkeypatch):
    path = tmp_path / "old.sqlite"
    shutil.copy(FIXTURE_V1, path)

    def broken(conn):
        conn.execute("NOT SQL")
    monkeypatch.setattr(library_store, "MIGRATIONS", library_store.MIGRATIONS[:1] + [broken])
    for _ in range(3):
        with pytest.raises(LibraryError):
            Library(path)
    assert list(tmp_path.glob("old.sqlite.schema1-*")) == []


def test_symlink_loop_is_refused(tmp_path):
    os.symlink(tmp_path / "loop2", tmp_path / "loop1")
    os.symlink(tmp_path / "loop1", tmp_path / "loop2")
    for action, status, err in run_all(tmp_path / "loop1", tmp_path):
        assert status == 2 and "loop of symbolic links" in err and err.count("\n") == 1, (action, err)
    assert not (tmp_path / "loop1").exists() and os.path.islink(tmp_path / "loop1")


def test_random_bytes_in_a_data_page_spoil_one_entry_not_the_library(tmp_path):
    """64 bytes inside a stored text (a page SQLite's quick_check passes) make that entry
    damaged; the others stay usable and nothing gives an internal error."""
    path = tmp_path / "lib.sqlite"
    make_library(path, names=("a", "b", "c"))
    data = bytearray(path.read_bytes())
    at = data.index(b"M" * 200)                     # the notes of one entry
    data[at:at + 64] = bytes(range(128, 192))       # not UTF-8
    path.write_bytes(bytes(data))
    for action, status, err in run_all(path, tmp_path):
        assert "internal error" not in err and status in (0, 1, 2), (action, err)
        if status == 2:
            assert err.count("\n") == 1
    status, out, err = shaper_in_process("library", "check", "--library", path)
    assert status == 1 and "notes is not text" in out and "1 of " in out


def test_read_only_library_is_read_and_writes_refused_in_one_line(tmp_path, monkeypatch):
    folder = tmp_path / "lib"
    folder.mkdir()
    path = folder / "lib.sqlite"
    make_library(path)
    read_only = "its folder cannot be written (simulated)"
    # As root, permissions stop nothing: make the check report what it would for a user.
    monkeypatch.setattr(library_open, "unwritable", lambda path: read_only)
    before = hashlib.sha256(path.read_bytes()).hexdigest()
    results = {action[0]: (status, err) for action, status, err in run_all(path, tmp_path)}
    for name in ("list", "show", "compare", "check", "export"):
        status, err = results[name]
        assert status in (0, 1) and "opened read-only" in err and read_only in err, (name, err)
    for name in ("add", "remove", "rename", "import"):
        status, err = results[name]
        assert status == 2 and err.count("\n") == 1 and "can only be read" in err and read_only in err, (name, err)
    assert hashlib.sha256(path.read_bytes()).hexdigest() == before
    with Library(path) as lib:
        assert lib.read_only == read_only and lib.names() == ["a", "b"]


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="permissions do not stop root")
def test_read_only_folder_for_a_user(tmp_path):
    folder = tmp_path / "lib"
    folder.mkdir()
    make_library(folder / "lib.sqlite")
    folder.chmod(0o555)
    try:
        with Library(folder / "lib.sqlite") as lib:
            assert lib.read_only and lib.names() == ["a", "b"]
            with pytest.raises(LibraryError) as refused:
                lib.remove("a")
        assert refused.value.kind == "readonly"
    finally:
        folder.chmod(0o755)


def test_older_library_that_cannot_be_written_is_refused_unmigrated(tmp_path, monkeypatch):
    path = tmp_path / "old.sqlite"
    shutil.copy(FIXTURE_V1, path)
    before = folder_state(tmp_path)
    monkeypatch.setattr(library_open, "unwritable", lambda p: "its folder cannot be written (simulated)")
    for _ in range(2):
        with pytest.raises(LibraryError) as refused:
            Library(path)
        assert refused.value.kind == "readonly" and "must be upgraded" in str(refused.value)
    after = folder_state(tmp_path)            # (here SQLite may add its -wal/-shm: the folder is writable)
    assert after["old.sqlite"] == before["old.sqlite"]                  # no migration
    assert not [name for name in after if ".schema1-" in name]          # no copy
