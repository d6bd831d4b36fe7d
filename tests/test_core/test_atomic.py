"""core.files.atomic.atomic_write: special targets, permissions, symlinks, durability, failures.

Every file lives under tmp_path; device-like targets are FIFOs, pipes and
/proc/self/fd links made here, never a real device.
"""
import errno
import os
import stat
import subprocess
import sys

import pytest

from core.files.atomic import atomic_write, remove_stale_temps, temp_pattern
from core.base.errors import WriteError

from output_checks import read_fifo_in_background


def temps(folder):
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(".tmp"))


@pytest.fixture
def umask_022():
    old = os.umask(0o022)
    yield
    os.umask(old)


# ---- regular files -----------------------------------------------------------------

def test_new_file_gets_the_mode_the_umask_gives(tmp_path, umask_022):
    path = tmp_path / "new.csv"
    atomic_write(path, "a,b\n")
    assert stat.S_IMODE(path.stat().st_mode) == 0o644
    assert path.read_text() == "a,b\n"
    os.umask(0o077)
    atomic_write(tmp_path / "private.csv", "x")
    assert stat.S_IMODE((tmp_path / "private.csv").stat().st_mode) == 0o600


@pytest.mark.parametrize("mode", [0o644, 0o640, 0o600, 0o664, 0o444])
def test_replacing_keeps_the_old_permissions(tmp_path, umask_022, mode):
    path = tmp_path / "design.json"
    path.write_text("old")
    path.chmod(mode)
    atomic_write(path, "new")
    assert path.read_text() == "new"
    assert stat.S_IMODE(path.stat().st_mode) == mode


def test_pieces_are_written_in_order(tmp_path):
    path = tmp_path / "t.csv"
    atomic_write(path, (f"{i}\n" for i in range(1000)))
    assert path.read_text() == "".join(f"{i}\n" for i in range(1000))


def test_the_file_and_its_folder_are_fsynced(tmp_path, monkeypatch):
    synced = []
    real_fsync = os.fsync

    def recording_fsync(fd):
        synced.append(stat.S_ISDIR(os.fstat(fd).st_mode))
        real_fsync(fd)

    monkeypatch.setattr(os, "fsync", recording_fsync)
    atomic_write(tmp_path / "f.txt", "x")
    assert synced == [False, True]     # the data first, then the rename in its folder


# ---- symlinks and special files ---------------------------------------------------

def test_a_symlink_is_followed_and_stays_a_link(tmp_path):
    real = tmp_path / "real" / "design.json"
    real.parent.mkdir()
    real.write_text("old")
    real.chmod(0o640)
    link = tmp_path / "link.json"
    link.symlink_to(os.path.join("real", "design.json"))     # relative, as users make them
    atomic_write(link, "new")
    assert link.is_symlink() and os.readlink(link) == os.path.join("real", "design.json")
    assert real.read_text() == "new"
    assert stat.S_IMODE(real.stat().st_mode) == 0o640
    assert temps(tmp_path) == [] and temps(real.parent) == []


def test_a_dangling_symlink_creates_its_target(tmp_path, umask_022):
    link = tmp_path / "link.csv"
    link.symlink_to(tmp_path / "target.csv")
    atomic_write(link, "x")
    assert link.is_symlink() and (tmp_path / "target.csv").read_text() == "x"
    assert stat.S_IMODE((tmp_path / "target.csv").stat().st_mode) == 0o644


def test_a_fifo_is_written_to_and_never_replaced(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    reader, received = read_fifo_in_background(fifo)
    atomic_write(fifo, ["first,", "second\n"])
    reader.join(timeout=10)
    assert received == ["first,second\n"]
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert temps(tmp_path) == []


def test_a_link_to_a_pipe_descriptor_is_written_through(tmp_path):
    # Like /dev/stdout when stdout is a pipe: a /proc/self/fd link to a FIFO.
    read_fd, write_fd = os.pipe()
    link = tmp_path / "stdout"
    link.symlink_to(f"/proc/self/fd/{write_fd}")
    try:
        atomic_write(link, "through the pipe\n")
        os.close(write_fd)
        with os.fdopen(read_fd) as reader:
            assert reader.read() == "through the pipe\n"
    finally:
        for fd in (read_fd, write_fd):
            try:
                os.close(fd)
            except OSError:
                pass
    assert link.is_symlink() and temps(tmp_path) == []


@pytest.mark.skipif(not os.path.isdir("/proc/self/fd"), reason="needs /proc")
def test_a_descriptor_alias_of_a_regular_file_is_not_replaced(tmp_path):
    # ``shaper curves --csv /dev/stdout > out.csv``: /dev/stdout leads through /proc to
    # out.csv, which the shell holds open; replacing it would send the shell's output
    # to an orphaned file. It must be written in place (same inode).
    out = tmp_path / "out.csv"
    with open(out, "w") as held:
        inode = os.fstat(held.fileno()).st_ino
        alias = tmp_path / "stdout"
        alias.symlink_to(f"/proc/self/fd/{held.fileno()}")
        atomic_write(alias, "in place\n")
        assert os.stat(out).st_ino == inode
    assert out.read_text() == "in place\n"
    assert temps(tmp_path) == []


def test_a_folder_is_refused_naming_it(tmp_path):
    with pytest.raises(WriteError) as info:
        atomic_write(tmp_path, "x")
    assert str(tmp_path) in str(info.value) and "folder" in str(info.value)


def test_a_missing_folder_names_the_users_path(tmp_path):
    path = tmp_path / "no" / "such" / "file.csv"
    with pytest.raises(WriteError) as info:
        atomic_write(path, "x")
    assert str(info.value) == f"cannot write {path}: the folder does not exist"
    assert info.value.filename == str(path)


# ---- failures: the old file stays, no temp file, the user's path in the message ------------

def failing_pieces(error):
    yield "partial text\n" * 1000
    raise error


@pytest.mark.parametrize("where", ["open", "write", "fsync", "replace"])
def test_a_full_disk_anywhere_keeps_the_old_file_and_leaves_no_temp(tmp_path, monkeypatch, where):
    path = tmp_path / "design.json"
    path.write_text("old")
    full = OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    text = "new"
    if where == "write":
        text = failing_pieces(full)
    else:
        real = getattr(os, where)

        def fail_on_temp(*args, **kwargs):
            first = args[0]
            if where == "fsync" and not stat.S_ISREG(os.fstat(first).st_mode):
                return real(*args, **kwargs)
            raise full

        monkeypatch.setattr(os, where, fail_on_temp)
    with pytest.raises(WriteError) as info:
        atomic_write(path, text)
    monkeypatch.undo()
    assert path.read_text() == "old"
    assert temps(tmp_path) == []
    message = str(info.value)
    assert message.startswith(f"cannot write {path}: ") and "disk is full" in message
    assert ".tmp" not in message and info.value.errno == errno.ENOSPC


def test_an_interrupt_or_a_computing_error_removes_the_temp(tmp_path):
    path = tmp_path / "curves.csv"
    path.write_text("old")
    for error in (KeyboardInterrupt(), MemoryError(), ValueError("bad row")):
        with pytest.raises(type(error)):
            atomic_write(path, failing_pieces(error))
        assert path.read_text() == "old" and temps(tmp_path) == []


# ---- stale temp files ----------------------------------------------------------------

def dead_pid():
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    return child.pid


def test_the_next_save_removes_temps_of_dead_processes_only(tmp_path):
    path = tmp_path / "d.json"
    path.write_text("old")
    dead = f".d.json.{dead_pid()}-0123abcd.tmp"
    live_process = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(30)"])
    try:
        live = f".d.json.{live_process.pid}-89abcdef.tmp"
        own = f".d.json.{os.getpid()}-00000000.tmp"
        other = [".d.json.tmp", ".d.json.12-xyz.tmp", ".e.json.1-0123abcd.tmp", "d.json.1-0123abcd.tmp"]
        for name in [dead, live, own, *other]:
            (tmp_path / name).write_text("partial")
        atomic_write(path, "new")
        left = {p.name for p in tmp_path.iterdir()}
        assert dead not in left
        assert {live, own, *other, "d.json"} == left
    finally:
        live_process.kill()
        live_process.wait()


def test_temp_names_match_the_documented_pattern(tmp_path, monkeypatch):
    seen = []
    real_replace = os.replace

    def spy(src, dst):
        seen.append(os.path.basename(src))
        real_replace(src, dst)

    monkeypatch.setattr(os, "replace", spy)
    atomic_write(tmp_path / "a b.json", "x")
    assert len(seen) == 1 and temp_pattern(tmp_path / "a b.json").match(seen[0])
    assert seen[0].startswith(f".a b.json.{os.getpid()}-")


def test_remove_stale_temps_never_follows_or_removes_a_symlink(tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("keep")
    link = tmp_path / f".x.json.{dead_pid()}-0123abcd.tmp"
    link.symlink_to(victim)
    assert remove_stale_temps(tmp_path / "x.json") == []
    assert link.is_symlink() and victim.read_text() == "keep"


@pytest.mark.parametrize("name, reason", [("", "no file name was given"),
                                          ("missing/", "the name ends with a slash, so it names a folder"),
                                          ("x.csv/", "the name ends with a slash, so it names a folder")])
def test_a_name_that_is_no_file_is_refused_without_writing(tmp_path, monkeypatch, name, reason):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(WriteError) as info:
        atomic_write(name, "x")
    assert str(info.value).endswith(f": {reason}")
    assert list(tmp_path.iterdir()) == []


def test_bytes_are_written_atomically_too(tmp_path):
    """Encoded images go through the same replace-by-rename as text."""
    target = tmp_path / "plot.png"
    target.write_bytes(b"old")
    atomic_write(target, b"\x89PNG\r\n\x1a\n" + bytes(range(256)))
    assert target.read_bytes() == b"\x89PNG\r\n\x1a\n" + bytes(range(256))
    assert [p.name for p in tmp_path.iterdir()] == ["plot.png"]


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="no /proc to tell a zombie")
def test_a_killed_process_not_yet_reaped_holds_no_save(tmp_path):
    """A process killed mid-save stays a zombie until its parent reaps it (PID 1, seconds
    later, for a killed class's workers): its temp file is litter, not a save in progress.
    A rerun of the class treated it as live and left it beside the student's files."""
    path = tmp_path / "d.json"
    killed = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(30)"])
    try:
        killed.kill()
        os.waitid(os.P_PID, killed.pid, os.WEXITED | os.WNOWAIT)     # dead, and left unreaped
        stale = tmp_path / f".d.json.{killed.pid}-0123abcd.tmp"
        stale.write_text("partial")
        atomic_write(path, "new")
        assert sorted(p.name for p in tmp_path.iterdir()) == ["d.json"]
    finally:
        killed.wait()
