"""Safe file writes: the target is always the complete old or the complete new file.

Below ``io`` (which formats) and beside ``errors``: it knows nothing about
designs or curves, only about getting text onto a disk without losing the
previous version, replacing what must not be replaced or leaving litter.
"""
from __future__ import annotations

import errno
import itertools
import os
import re
import stat
import sys
import time
from typing import Callable, Iterable

from core.base.errors import WriteError

_TEMP_SUFFIX = ".tmp"
FIFO_WAIT_S = 10.0           # how long a FIFO given as output waits for a reader
NAME_MAX = 255               # bytes in one file name on nearly every file system
# what a temporary name adds to the target's name: "." before, ".<pid>-<8 hex>.tmp" after
_TEMP_ROOM = 1 + len(f".{2 ** 32}-{'0' * 8}{_TEMP_SUFFIX}")


def fit_name(name: str, room: int) -> str:
    """``name`` if it leaves ``room`` bytes of a file name free, else its first bytes (cut at
    a character) and ``~`` with 8 hex digits of its hash, so that names built from a long
    name (temporary files, copies) stay within ``NAME_MAX`` bytes and stay distinct."""
    raw = os.fsencode(name)
    limit = NAME_MAX - room
    if len(raw) <= limit:
        return name
    cut = raw[:limit - 9]
    for _ in range(3):                      # not in the middle of a UTF-8 character
        try:
            cut.decode("utf-8")
            break
        except UnicodeDecodeError:
            cut = cut[:-1]
    import hashlib      # only for a name too long for the folder (OpenSSL: milliseconds at start-up)
    return os.fsdecode(cut) + "~" + hashlib.sha256(raw).hexdigest()[:8]


def atomic_write(path: str | os.PathLike, text: str | bytes | Iterable[str] | Iterable[bytes]) -> None:
    """Write ``text`` (a string, bytes such as an encoded image, or an iterable of
    string pieces) so that ``path`` ends up either the old file or the whole new
    one, never a mixture.

    - A regular file (or a new one) is written to a temporary sibling
      ``.NAME.<pid>-<8 hex>.tmp`` (a NAME too long for that is cut, see
      :func:`fit_name`, so any name the file system takes can be written),
      flushed and fsynced, renamed over the target, and the folder is fsynced. The new file keeps the permission
      bits (and, where allowed, the owner) of the file it replaces; a new file
      gets the mode the umask gives (0644 under umask 022).
    - A symbolic link is followed: its target is replaced, the link stays.
    - A target that is not a regular file (FIFO, device, ``/dev/stdout`` and
      anything else under ``/proc``) is written to directly, never replaced. A FIFO
      that no program opens for reading within ``FIFO_WAIT_S`` seconds is given up
      (WriteError) instead of waiting for ever.
    - On every failure the temporary file is removed. Before writing, temporary
      siblings left by a process that no longer runs (killed mid-save) are
      removed too, so they never accumulate.

    Raises :class:`~core.base.errors.WriteError` (an OSError) naming ``path``, with a
    plain reason such as a full disk.
    """
    pieces = [text] if isinstance(text, (str, bytes)) else text
    name = os.fspath(path)
    if not name:
        raise WriteError(path, OSError(None, "no file name was given"))
    if name.endswith(("/", os.sep)):
        raise WriteError(path, OSError(None, "the name ends with a slash, so it names a folder"))
    try:
        try:
            status: os.stat_result | None = os.stat(path)
        except FileNotFoundError:
            status = None
        if status is not None and stat.S_ISDIR(status.st_mode):
            raise IsADirectoryError(errno.EISDIR, os.strerror(errno.EISDIR))
        if status is not None and (not stat.S_ISREG(status.st_mode) or _descriptor_alias(path)):
            _write_in_place(path, pieces)
        else:
            _write_and_replace(os.path.realpath(path), pieces, status)
    except OSError as exc:
        raise WriteError(path, exc) from None


def _open_pieces(fd_or_path, pieces: Iterable[str] | Iterable[bytes], mode: str):
    """Open for writing in text (UTF-8) or binary mode, whichever the first piece needs;
    returns the file and the pieces (the first one put back)."""
    iterator = iter(pieces)
    first = next(iterator, "")
    binary = isinstance(first, bytes)
    opener = os.fdopen if isinstance(fd_or_path, int) else open
    handle = (opener(fd_or_path, mode + "b") if binary
              else opener(fd_or_path, mode, encoding="utf-8", newline=""))
    return handle, itertools.chain([first], iterator)


def _write_in_place(path: str | os.PathLike, pieces: Iterable[str] | Iterable[bytes]) -> None:
    handle, pieces = _open_pieces(_open_fifo(path) if _is_fifo(path) else path, pieces, "w")
    with handle:
        for piece in pieces:
            handle.write(piece)


def _is_fifo(path: str | os.PathLike) -> bool:
    try:
        return stat.S_ISFIFO(os.stat(path).st_mode)
    except OSError:
        return False


def _open_fifo(path: str | os.PathLike) -> int:
    """A FIFO opened for writing once a reader opens it, waiting at most ``FIFO_WAIT_S``.

    A plain open would wait for a reader for ever; a non-blocking one fails at once
    (ENXIO) while there is none, so it is retried until the deadline. The descriptor is
    then made blocking again: a reader that reads slowly is waited for as usual.
    """
    deadline = time.monotonic() + FIFO_WAIT_S
    while True:
        try:
            fd = os.open(path, os.O_WRONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
            break
        except OSError as exc:
            if exc.errno != errno.ENXIO:
                raise
            if time.monotonic() >= deadline:
                raise OSError(errno.ENXIO, f"it is a pipe that no program opened for reading within "
                              f"{FIFO_WAIT_S:g} s") from None
            time.sleep(0.02)
    os.set_blocking(fd, True)
    return fd


def _write_and_replace(target: str, pieces: Iterable[str] | Iterable[bytes], old: os.stat_result | None) -> None:
    directory, name = os.path.split(target)
    directory = directory or "."
    remove_stale_temps(target)
    tmp = os.path.join(directory, f".{fit_name(name, _TEMP_ROOM)}.{os.getpid()}-{os.urandom(4).hex()}"
                                  f"{_TEMP_SUFFIX}")
    # A new file gets 0666 less the umask; a replacement starts private, then takes the old mode.
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0),
                 0o666 if old is None else 0o600)
    try:
        if old is not None:
            _copy_owner_and_mode(fd, old)
        handle, pieces = _open_pieces(fd, pieces, "w")
        with handle:
            for piece in pieces:
                handle.write(piece)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, target)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
    _fsync_directory(directory)


def _copy_owner_and_mode(fd: int, old: os.stat_result) -> None:
    if hasattr(os, "fchown") and (old.st_uid, old.st_gid) != (os.geteuid(), os.getegid()):
        for uid, gid in ((old.st_uid, old.st_gid), (-1, old.st_gid)):
            try:
                os.fchown(fd, uid, gid)   # root keeps both; a group member keeps the group
                break
            except OSError:
                continue
    os.fchmod(fd, stat.S_IMODE(old.st_mode))


def _fsync_directory(directory: str) -> None:
    """Make the rename durable; a file system that cannot fsync a folder is left as it is."""
    try:
        fd = os.open(directory, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _descriptor_alias(path: str | os.PathLike) -> bool:
    """Whether ``path`` leads into /proc (``/dev/stdout``, ``/dev/fd/N``): a descriptor
    of this process, to be written to and never replaced."""
    current = os.path.abspath(path)
    for _ in range(40):
        if os.path.realpath(os.path.dirname(current)).startswith("/proc/"):
            return True
        if not os.path.islink(current):
            return False
        current = os.path.join(os.path.dirname(current), os.readlink(current))
    return False


# Linux's inode flags (ioctl FS_IOC_GETFLAGS, <linux/fs.h>): a file that is immutable
# (chattr +i) or append-only (chattr +a) cannot be replaced by a rename, even by root.
_FS_IOC_GETFLAGS = 0x80086601
_UNREPLACEABLE = {0x00000010: "it is immutable (chattr +i)", 0x00000020: "it is append-only (chattr +a)"}


def replace_refusal(path: str | os.PathLike) -> str | None:
    """Why :func:`atomic_write` could not replace the existing file ``path`` (its inode
    flags say immutable or append-only), or None: found before the first of several
    files is written, so a run that would fail on the second writes nothing (issue 42:
    ``course`` wrote 00-report.pdf, then failed on an immutable 01-motion.pdf). None too
    where the system cannot tell (not Linux, a file system without the flags)."""
    if not sys.platform.startswith("linux"):
        return None
    try:
        import fcntl
        import struct
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_NOCTTY", 0))
    except (OSError, ImportError):
        return None
    try:
        flags = struct.unpack("i", fcntl.ioctl(fd, _FS_IOC_GETFLAGS, b"\0" * 4))[0]
    except OSError:
        return None
    finally:
        os.close(fd)
    return next((why for bit, why in _UNREPLACEABLE.items() if flags & bit), None)


def temp_pattern(target: str | os.PathLike) -> re.Pattern[str]:
    """The names :func:`atomic_write` gives its temporary siblings of ``target``."""
    name = fit_name(os.path.basename(os.fspath(target)), _TEMP_ROOM)
    return re.compile(rf"\.{re.escape(name)}\.(\d+)-[0-9a-f]{{8}}{re.escape(_TEMP_SUFFIX)}\Z")


def remove_stale_temps(target: str | os.PathLike) -> list[str]:
    """Remove temporary siblings of ``target`` left by processes that no longer run
    (a save killed mid-way); return their paths. A temp file of a live process
    (a save in progress) and files of other users are never touched."""
    if os.name != "posix":
        return []
    return remove_left(os.path.dirname(os.fspath(target)) or ".", temp_pattern(target), stat.S_ISREG, os.unlink)


def remove_left(directory: str | os.PathLike, pattern: re.Pattern[str], kind: Callable[[int], bool],
                remove: Callable[[str], None]) -> list[str]:
    """Remove (``remove``) each entry of ``directory`` whose name ``pattern`` matches, its
    group 1 the pid of the process that made it, when that process no longer runs
    (:func:`left_by_ended`), the entry is this user's and of ``kind`` (``stat.S_ISREG``,
    ``stat.S_ISDIR``: never a symbolic link); return their paths. The one rule for what a
    killed writer left: a save's temporary file, an export's staging folder."""
    removed = []
    try:
        entries = [e for e in os.scandir(directory) if pattern.match(e.name)]
    except OSError:
        return []
    for entry in entries:
        if not left_by_ended(int(pattern.match(entry.name).group(1))):
            continue
        try:
            info = entry.stat(follow_symlinks=False)
            if kind(info.st_mode) and info.st_uid == os.geteuid():
                remove(entry.path)
                removed.append(entry.path)
        except OSError:
            continue
    return removed


def left_by_ended(pid: int) -> bool:
    """Whether a temporary file or folder named with ``pid`` was left by a process that no
    longer runs: not this one, not one that may still finish its write."""
    return pid != os.getpid() and not _running(pid)


def _running(pid: int) -> bool:
    """Whether process ``pid`` may still finish its save. A zombie may not: it was killed
    and waits only to be reaped, which can take seconds after a ``kill -9`` (seen here: a
    class's killed worker stayed a zombie of PID 1 for 1-3 s, the rerun took its temp file
    for a save in progress and left it beside the student's files)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, ValueError):
        return True    # another user's process, or not a pid we can ask about: leave it
    return not _zombie(pid)


def _zombie(pid: int) -> bool:
    """True when Linux's /proc says ``pid`` has ended and is not yet reaped (state Z or X);
    False where there is no /proc to ask."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as handle:
            fields = handle.read().rsplit(b")", 1)[1].split()   # after the name, which may hold ") "
    except (OSError, IndexError):
        return False
    return bool(fields) and fields[0] in (b"Z", b"X")
