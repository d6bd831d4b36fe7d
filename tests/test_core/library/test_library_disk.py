"""A full disk is a full disk, not a damaged library (issue 33, item 4).

On a full file system SQLite cannot make its shared-memory file, and reports a disk
I/O error when the library is first read; ``library list`` called the intact file
damaged and advised a backup. SQLite's result code tells the cases apart: SQLITE_FULL,
or a disk I/O error on a file system without room, is a full disk (exit 1, nothing
changed, no backup advice); SQLITE_CORRUPT and SQLITE_NOTADB are damage. The real
full disk is simulated: SQLite's ``max_page_count`` gives a genuine SQLITE_FULL on a
write, and the open-time disk I/O error is injected with its real extended code.
"""
import os
import sqlite3

import pytest

from core.library import Library
from core.library import open as library_open
from core.library import store as library_store
from core.library.store import LibraryError, sqlite_error
from core.linkage.spec import Spec

from cli_runner import shaper_in_process

FULL = "the disk is full (no space left on the device)"
SQLITE_IOERR_SHMSIZE = 10 | (19 << 8)
SQLITE_IOERR_WRITE = 10 | (3 << 8)
SQLITE_CORRUPT = 11


def make_library(path):
    with Library(path) as lib:
        lib.add("a", {"spec": Spec(), "rpm": [40.0], "step_deg": 1.0, "masses": None})


def sqlite_exception(text, code):
    exc = sqlite3.OperationalError(text)
    exc.sqlite_errorcode = code
    return exc


class FailingConnection:
    """A real connection whose first read of the schema fails with ``exc``."""

    def __init__(self, conn, exc):
        self._conn, self._exc = conn, exc

    def execute(self, sql, *args):
        if sql.startswith("PRAGMA application_id"):
            raise self._exc
        return self._conn.execute(sql, *args)

    def close(self):
        self._conn.close()


def fail_on_open(monkeypatch, exc):
    real = library_open._open
    monkeypatch.setattr(library_open, "_open", lambda path, read_only: FailingConnection(real(path, read_only), exc))


def no_room(monkeypatch, free_blocks):
    real = os.statvfs

    def statvfs(path):
        fs = real(path)
        return os.statvfs_result((fs.f_bsize, fs.f_frsize, fs.f_blocks, free_blocks, free_blocks,
                                  fs.f_files, fs.f_ffree, fs.f_favail, fs.f_flag, fs.f_namemax))
    monkeypatch.setattr(library_store.os, "statvfs", statvfs)


def test_a_write_that_fills_the_disk_says_the_disk_is_full(tmp_path):
    path = tmp_path / "L.sqlite"
    make_library(path)
    with Library(path) as lib:
        pages = lib._conn.execute("PRAGMA page_count").fetchone()[0]
        lib._conn.execute(f"PRAGMA max_page_count = {pages}")      # SQLite's own SQLITE_FULL
        with pytest.raises(LibraryError) as caught:
            lib.add("b", {"spec": Spec(), "rpm": [40.0], "step_deg": 1.0, "masses": None}, notes="x" * 200_000)
        assert caught.value.kind == "io" and FULL in str(caught.value)
        assert not caught.value.refused_file
        assert lib.names() == ["a"]


def test_a_disk_io_error_on_a_full_disk_at_opening_is_not_damage(tmp_path, monkeypatch):
    path = tmp_path / "L.sqlite"
    make_library(path)
    before = path.read_bytes()
    fail_on_open(monkeypatch, sqlite_exception("disk I/O error", SQLITE_IOERR_SHMSIZE))
    no_room(monkeypatch, 0)
    with pytest.raises(LibraryError) as caught:
        Library(path)
    assert caught.value.kind == "io" and FULL in str(caught.value) and not caught.value.refused_file
    status, _, err = shaper_in_process("library", "list", "--library", path)
    assert status == 1 and FULL in err and "damaged" not in err and "backup" not in err
    assert err.count("\n") == 1 and err.startswith("shaper: error: --library")
    assert path.read_bytes() == before


def test_a_disk_io_error_with_room_left_is_an_io_error_not_damage(tmp_path, monkeypatch):
    path = tmp_path / "L.sqlite"
    make_library(path)
    fail_on_open(monkeypatch, sqlite_exception("disk I/O error", SQLITE_IOERR_WRITE))
    no_room(monkeypatch, 1 << 20)
    with pytest.raises(LibraryError) as caught:
        Library(path)
    assert caught.value.kind == "io" and "disk I/O error" in str(caught.value)
    assert not caught.value.refused_file


def test_corruption_is_still_damage(tmp_path, monkeypatch):
    path = tmp_path / "L.sqlite"
    make_library(path)
    fail_on_open(monkeypatch, sqlite_exception("database disk image is malformed", SQLITE_CORRUPT))
    with pytest.raises(LibraryError) as caught:
        Library(path)
    assert caught.value.kind == "damaged"


@pytest.mark.parametrize("code, kind", [(13, "io"), (10 | (12 << 8), "io"), (5, "busy"), (6, "busy"),
                                        (11, "damaged"), (26, "damaged"), (8, "readonly")])
def test_result_codes_map_to_kinds(tmp_path, monkeypatch, code, kind):
    no_room(monkeypatch, 0)
    error = sqlite_error(sqlite_exception("message", code), tmp_path / "L.sqlite")
    assert error.kind == kind
    if code in (13, 10 | (12 << 8)):
        assert FULL in str(error)
