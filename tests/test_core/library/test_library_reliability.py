"""The library under stress: two writers, killed writers, damaged and newer files, migrations."""
import os
import random
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import pytest

from core.library import Library
from core.library import store as library_store
from core.library.backup import backup_copy
from core.library.store import APPLICATION_ID, LibraryError, schema_version
from core.linkage.spec import Spec
from cli_runner import shaper
from locations import DATA, ROOT, TESTS

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

WRITER = TESTS / "library_writer.py"
ROOT = ROOT
FIXTURE_V1 = DATA / "library-v1.sqlite"


def writer(path, prefix, count, fast=False):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.Popen([sys.executable, str(WRITER), str(path), prefix, str(count)]
                            + (["--fast"] if fast else []),
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)


def loaded(spec=Spec()):
    return {"spec": spec, "rpm": [40.0], "step_deg": 1.0, "masses": None}


def test_two_processes_write_at_once(tmp_path):
    path = tmp_path / "shared.sqlite"          # both start on a library that does not exist yet
    procs = [writer(path, prefix, 30) for prefix in ("a", "b")]
    outs = [p.communicate(timeout=300) for p in procs]
    for p, (out, err) in zip(procs, outs):
        assert p.returncode == 0, err
    printed = {name for out, _ in outs for name in out.split()}
    assert len(printed) == 60
    with Library(path) as lib:
        assert set(lib.names()) == printed
        for name in printed:
            assert lib.load(name)["rpm"] == [40.0, 60.0]
        assert lib._conn.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
        assert lib._conn.execute("PRAGMA journal_mode").fetchone()[0] == "wal"


def test_two_processes_adding_the_same_name(tmp_path):
    path = tmp_path / "race.sqlite"
    Library(path).close()
    procs = [writer(path, "same", 1) for _ in range(2)]
    results = [p.communicate(timeout=120) + (p.returncode,) for p in procs]
    codes = sorted(r[2] for r in results)
    assert codes[0] == 0 and codes[1] != 0            # exactly one of them stored it
    assert any("already in the library" in r[1] for r in results)
    with Library(path) as lib:
        assert lib.names() == ["same-0"]


def test_kill_during_writes_loses_nothing_committed(tmp_path):
    path = tmp_path / "killed.sqlite"
    rng = random.Random(20240501)
    committed: set[str] = set()
    for round_ in range(20):
        proc = writer(path, f"r{round_}", 100000, fast=True)
        # let it start and commit a few, then kill it at a random moment
        first = proc.stdout.readline().strip()
        assert first, proc.stderr.read()
        time.sleep(rng.uniform(0.0, 0.15))
        proc.send_signal(signal.SIGKILL)
        out = proc.stdout.read()        # the same buffered reader as readline (not communicate)
        proc.wait(timeout=60)
        proc.stderr.close()
        proc.stdout.close()
        names = {first} | set(out.split())
        committed |= names
        with Library(path) as lib:             # opens every time: the checks pass
            stored = set(lib.names())
            assert committed <= stored
            # at most the one entry whose commit returned but whose name was not printed yet
            assert len(stored - committed) <= 1
            committed = stored
            assert lib._conn.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
    with Library(path) as lib:
        for name in rng.sample(sorted(committed), 20):
            entry = lib.get(name)
            assert entry.document()["spec"] == Spec() and entry.notes == "x" * 2000
    assert len(committed) > 20


# ---- files that must be refused and left alone ------------------------------------------
def _snapshot(path):
    st = path.stat()
    return path.read_bytes(), st.st_mtime_ns, st.st_size


def _make_library(path, n=40):
    with Library(path) as lib:
        entry = lib.make_entry("t", loaded(), notes="n" * 3000)
        from dataclasses import replace
        lib.add_entries([replace(entry, name=f"e{i}") for i in range(n)])


def _damage_pages(path):
    data = bytearray(path.read_bytes())
    rng = random.Random(3)
    for i in range(4096, len(data)):
        data[i] = rng.randrange(256)
    path.write_bytes(bytes(data))


def _truncate(path):
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 3])


def _future(path):
    conn = sqlite3.connect(path)
    conn.execute(f"PRAGMA user_version = {schema_version() + 1}")
    conn.close()


def _foreign(path):
    path.unlink()
    conn = sqlite3.connect(path)
    conn.execute("CREATE TABLE accounts (id INTEGER, owner TEXT)")
    conn.commit()
    conn.close()


def _not_sqlite(path):
    path.write_bytes(b'{"format": "shaper-design"}' * 20)


@pytest.mark.parametrize("spoil, kind", [(_damage_pages, "damaged"), (_truncate, "damaged"),
                                         (_future, "newer"), (_foreign, "foreign"),
                                         (_not_sqlite, "foreign")])
def test_bad_libraries_are_refused_unchanged(tmp_path, spoil, kind):
    path = tmp_path / "lib.sqlite"
    _make_library(path)
    spoil(path)
    for side in (Path(f"{path}-wal"), Path(f"{path}-shm")):
        side.unlink(missing_ok=True)
    before = _snapshot(path)
    time.sleep(0.01)
    for attempt in range(2):
        with pytest.raises(LibraryError) as err:
            Library(path)
        assert err.value.kind == kind and err.value.refused_file
        assert "left unchanged" in str(err.value)
        assert _snapshot(path) == before
    copy = backup_copy(path)
    assert copy.read_bytes() == before[0] and _snapshot(path) == before


def test_newer_library_message_names_both_versions(tmp_path):
    path = tmp_path / "lib.sqlite"
    _make_library(path, 1)
    _future(path)
    with pytest.raises(LibraryError, match=f"schema {schema_version() + 1}; this version reads up to "
                                           f"{schema_version()}"):
        Library(path)


# ---- schema versions and migrations ---------------------------------------------------
def test_v0_empty_files_become_libraries(tmp_path):
    empty = tmp_path / "empty.sqlite"
    empty.write_bytes(b"")
    blank = tmp_path / "blank.sqlite"
    sqlite3.connect(blank).close()                  # an SQLite database without tables
    for path in (empty, blank):
        with Library(path) as lib:
            lib.add("x", loaded())
        conn = sqlite3.connect(path)
        assert conn.execute("PRAGMA user_version").fetchone()[0] == schema_version()
        assert conn.execute("PRAGMA application_id").fetchone()[0] == APPLICATION_ID
        conn.close()


def test_v1_fixture_opens_with_its_entries(tmp_path):
    path = tmp_path / "old.sqlite"
    path.write_bytes(FIXTURE_V1.read_bytes())
    with Library(path) as lib:
        assert lib.names() == ["block K1.4", "rod K1.6"]
        rod = lib.get("rod K1.6")
        assert rod.notes == "made with schema 1" and rod.tags == ("fixture",)
        assert rod.figures.K == pytest.approx(1.6) and rod.figures.variant == "rod"
        assert rod.document()["spec"].rod_ratio == pytest.approx(0.35)
        assert lib.query("a_max<4", rpm=40)[0]["name"] == "block K1.4"


def _add_rating(conn):
    conn.execute("ALTER TABLE entries ADD COLUMN rating INTEGER NOT NULL DEFAULT 3")


def _broken_step(conn):
    conn.execute("ALTER TABLE entries ADD COLUMN half_done INTEGER")
    conn.execute("THIS IS NOT SQL")


def test_migration_to_a_newer_schema_keeps_data_and_a_copy(tmp_path, monkeypatch):
    path = tmp_path / "old.sqlite"
    path.write_bytes(FIXTURE_V1.read_bytes())
    monkeypatch.setattr(library_store, "MIGRATIONS", library_store.MIGRATIONS + [_add_rating])
    with Library(path) as lib:
        assert lib.names() == ["block K1.4", "rod K1.6"]
        assert lib._conn.execute("SELECT rating FROM entries").fetchall() == [(3,), (3,)]
        assert lib._conn.execute("PRAGMA user_version").fetchone()[0] == schema_version() == 3
    copies = list(tmp_path.glob("old.sqlite.schema1-*"))
    assert len(copies) == 1
    copy = sqlite3.connect(copies[0])              # the copy is the library as it was
    assert copy.execute("PRAGMA user_version").fetchone()[0] == 1
    assert copy.execute("SELECT name FROM entries ORDER BY name").fetchall() == [("block K1.4",), ("rod K1.6",)]
    assert "rating" not in [r[1] for r in copy.execute("PRAGMA table_info(entries)")]
    copy.close()


def test_a_failed_migration_leaves_the_old_schema(tmp_path, monkeypatch):
    path = tmp_path / "old.sqlite"
    path.write_bytes(FIXTURE_V1.read_bytes())
    monkeypatch.setattr(library_store, "MIGRATIONS", library_store.MIGRATIONS + [_broken_step])
    with pytest.raises(LibraryError):
        Library(path)
    monkeypatch.undo()
    raw = sqlite3.connect(path)                    # still schema 1, nothing half-done
    assert raw.execute("PRAGMA user_version").fetchone()[0] == 1
    columns = [r[1] for r in raw.execute("PRAGMA table_info(entries)")]
    assert "half_done" not in columns and "figures_version" not in columns
    raw.close()
    with Library(path) as lib:                     # and usable: this program's migrations run
        assert lib._conn.execute("PRAGMA user_version").fetchone()[0] == schema_version()
        assert lib.count() == 2


def test_busy_library_gives_a_plain_error(tmp_path, monkeypatch):
    path = tmp_path / "lib.sqlite"
    Library(path).close()
    blocker = sqlite3.connect(path, isolation_level=None)
    blocker.execute("BEGIN IMMEDIATE")
    monkeypatch.setattr(library_store, "BUSY_TIMEOUT_S", 0.2)
    try:
        with Library(path) as lib:
            lib._conn.execute("PRAGMA busy_timeout = 200")
            with pytest.raises(LibraryError) as err:
                lib.add("x", loaded())
        assert err.value.kind == "busy" and "try again" in str(err.value)
    finally:
        blocker.execute("ROLLBACK")
        blocker.close()
    with Library(path) as lib:
        assert lib.count() == 0


def _special_files(tmp_path):
    """A pipe and a socket under tmp_path (a read from the pipe would block forever)."""
    import socket
    fifo = tmp_path / "pipe.sqlite"
    os.mkfifo(fifo)
    sock_path = tmp_path / "sock.sqlite"
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    sock.bind(str(sock_path))
    return sock, {"pipe": fifo, "socket": sock_path}


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_pipe_or_socket_is_refused_without_reading_it(tmp_path):
    """A FIFO as the library hung every command on its first read; now it is refused, as is
    a socket, by Library and by backup (which copies files it cannot open)."""
    sock, files = _special_files(tmp_path)
    try:
        for kind, path in files.items():
            with pytest.raises(LibraryError) as err:
                Library(path)
            assert err.value.kind == "location" and f"is a {kind}" in str(err.value)
            with pytest.raises(LibraryError, match=f"is a {kind}"):
                backup_copy(path, tmp_path / "copy.sqlite")
            assert not (tmp_path / "copy.sqlite").exists()
            result = shaper("library", "list", "--library", path)
            assert result.returncode == 2 and result.stderr.count("\n") == 1
            assert result.stderr.startswith("shaper: error: --library: ") and kind in result.stderr
    finally:
        sock.close()
