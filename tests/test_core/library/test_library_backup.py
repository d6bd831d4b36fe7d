"""``library backup`` keeps the rules every other writer keeps (issue 33, item 5).

It replaced a symbolic link and a pipe with a file, turned a 0444 copy into 0644, left a
copy behind when the ``-wal`` file could not be copied, wrote a sparse file of holes as
that many bytes of zeros, and a name too long for the file system ended in exit 1
("internal error"). Each case below is checked on what is on disk afterwards.
"""
import os
import sqlite3
import stat
import threading

import pytest

from core.library import Library
from core.library.backup import backup_copy, data_bytes
from core.library.store import LibraryError
from core.linkage.spec import Spec

from cli_runner import shaper_in_process

SQLITE_HEADER = b"SQLite format 3\x00"


def make_library(path, names=("a", "b")):
    with Library(path) as lib:
        for name in names:
            lib.add(name, {"spec": Spec(), "rpm": [40.0], "step_deg": 1.0, "masses": None})


def names_in(path):
    conn = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    try:
        return sorted(r[0] for r in conn.execute("SELECT name FROM entries"))
    finally:
        conn.close()


def backup(library, *extra):
    return shaper_in_process("library", "backup", "--library", library, *extra)


def test_a_link_as_output_is_written_through(tmp_path):
    library = tmp_path / "L.sqlite"
    make_library(library)
    real = tmp_path / "real.sqlite"
    real.write_bytes(b"")
    link = tmp_path / "link.sqlite"
    link.symlink_to(real.name)
    status, _, err = backup(library, "-o", link)
    assert status == 0, err
    assert link.is_symlink() and os.readlink(link) == real.name
    assert names_in(real) == ["a", "b"]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_pipe_as_output_is_written_to_not_replaced(tmp_path):
    library = tmp_path / "L.sqlite"
    make_library(library)
    pipe = tmp_path / "pipe"
    os.mkfifo(pipe)
    received = []
    reader = threading.Thread(target=lambda: received.append(open(pipe, "rb").read()))
    reader.start()
    status, _, err = backup(library, "-o", pipe)
    reader.join(timeout=30)
    assert status == 0, err
    assert stat.S_ISFIFO(os.stat(pipe).st_mode)
    copy = tmp_path / "received.sqlite"
    copy.write_bytes(received[0])
    assert received[0].startswith(SQLITE_HEADER) and names_in(copy) == ["a", "b"]


def test_a_read_only_copy_keeps_its_mode(tmp_path):
    library = tmp_path / "L.sqlite"
    make_library(library)
    out = tmp_path / "copy.sqlite"
    out.write_bytes(b"old")
    out.chmod(0o444)
    status, _, err = backup(library, "-o", out)
    assert status == 0, err
    assert stat.S_IMODE(out.stat().st_mode) == 0o444 and names_in(out) == ["a", "b"]


def test_a_wal_that_is_a_folder_leaves_nothing_behind(tmp_path):
    library = tmp_path / "L.sqlite"
    make_library(library)
    for extra in ("-wal", "-shm"):
        if os.path.lexists(f"{library}{extra}"):
            os.remove(f"{library}{extra}")
    os.mkdir(f"{library}-wal")
    before = sorted(os.listdir(tmp_path))
    for args in (("-o", tmp_path / "copy.sqlite"), ()):
        status, _, err = backup(library, *args)
        assert status == 2 and err.count("\n") == 1 and "--library" in err and "L.sqlite-wal" in err
        assert sorted(os.listdir(tmp_path)) == before


def _wal_library(path):
    """A refused file (another program's id) in WAL mode with a -wal file beside it."""
    conn = sqlite3.connect(path)
    conn.execute("PRAGMA journal_mode = WAL")
    conn.execute("PRAGMA wal_autocheckpoint = 0")
    conn.execute("CREATE TABLE t (x)")
    conn.execute("INSERT INTO t VALUES (1)")
    conn.commit()
    return conn                     # kept open, so the -wal file stays


def test_a_copy_whose_wal_cannot_be_written_is_removed_again(tmp_path):
    library = tmp_path / "other.sqlite"
    conn = _wal_library(library)
    try:
        assert os.path.getsize(f"{library}-wal") > 0
        out = tmp_path / "copy.sqlite"
        os.mkdir(f"{out}-wal")                      # the -wal copy cannot be written
        before = sorted(os.listdir(tmp_path))
        with pytest.raises(LibraryError):
            backup_copy(library, out)
        assert sorted(os.listdir(tmp_path)) == before
        good = backup_copy(library, tmp_path / "good.sqlite")
        assert good.read_bytes() == library.read_bytes()
        assert open(f"{good}-wal", "rb").read() == open(f"{library}-wal", "rb").read()
    finally:
        conn.close()


def test_a_sparse_file_of_holes_is_refused_not_copied_dense(tmp_path):
    library = tmp_path / "S.sqlite"
    with open(library, "wb") as handle:
        handle.write(SQLITE_HEADER + b"\x10\x00" + bytes(82))
        handle.truncate(64 << 20)
    if data_bytes(library, 64 << 20) == 64 << 20:
        pytest.skip("this file system does not report holes")
    status, _, err = backup(library, "-o", tmp_path / "copy.sqlite")
    assert status == 2 and err.count("\n") == 1 and "--library" in err and "holes" in err
    assert sorted(os.listdir(tmp_path)) == ["S.sqlite"]


def test_a_sparse_but_sound_library_is_copied_compactly(tmp_path):
    """A library whose file was lengthened with holes still opens; its copy holds its pages."""
    library = tmp_path / "L.sqlite"
    make_library(library)
    os.truncate(library, 256 << 20)
    out = tmp_path / "copy.sqlite"
    status, _, err = backup(library, "-o", out)
    assert status == 0, err
    assert out.stat().st_size < 1 << 20 and names_in(out) == ["a", "b"]


def test_a_name_too_long_is_a_usage_error_naming_the_option(tmp_path):
    library = tmp_path / "L.sqlite"
    make_library(library)
    status, _, err = backup(library, "-o", tmp_path / ("x" * 256))
    assert status == 2 and err.count("\n") == 1 and err.startswith("shaper: error: --output: ")
    assert "too long" in err


def test_a_failed_snapshot_leaves_no_temporary_folder(tmp_path):
    library = tmp_path / "L.sqlite"
    make_library(library)
    out = tmp_path / "sub"
    out.mkdir()
    target = out / "copy.sqlite"
    os.mkdir(target)                 # atomic_write refuses a folder
    with Library(library) as lib, pytest.raises(LibraryError) as caught:
        lib.backup(target)
    assert caught.value.kind == "io"
    assert os.listdir(out) == ["copy.sqlite"] and os.listdir(target) == []


def test_a_copy_to_standard_output_is_only_the_copy(tmp_path):
    """``-o /dev/stdout`` writes the library's bytes and nothing else there (the line
    saying what was copied goes to stderr), so ``> copy.sqlite`` is a whole library."""
    import subprocess
    import sys
    library = tmp_path / "L.sqlite"
    make_library(library)
    copy = tmp_path / "copy.sqlite"
    with open(copy, "wb") as out:
        done = subprocess.run([sys.executable, "-m", "core", "library", "backup", "--library", str(library),
                               "-o", "/dev/stdout"], stdout=out, stderr=subprocess.PIPE, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "copied" in done.stderr
    data = copy.read_bytes()
    page = int.from_bytes(data[16:18], "big")
    assert data.startswith(SQLITE_HEADER) and len(data) % page == 0
    assert names_in(copy) == ["a", "b"]
