"""Copies of a library file: a consistent copy of a library in use, or byte for byte a
file that cannot be opened (``shaper library backup``, the pane's "keep a copy").

A copy is written by the project's safe writer (:func:`core.files.atomic.atomic_write`), so it
keeps the rules every other output keeps: a symbolic link is written through (the link
stays), a pipe or a device is written to and never replaced, a file that is replaced
keeps its mode, and a failure leaves nothing behind — no half copy, no temporary file,
no copy of the main file without its ``-wal`` file. A file that is mostly holes (a
sparse file whose length is not its data) is refused instead of being copied as that
many bytes of zeros.
"""
from __future__ import annotations

import os
import shutil
import sqlite3
import stat
import tempfile
from pathlib import Path
from typing import Iterator

from core.files.atomic import atomic_write
from core.base.errors import os_reason

from .store import LibraryError, backup_target, check_regular, sqlite_uri

CHUNK = 1 << 20                 # bytes read and written at a time
SPARSE_MIN_BYTES = 1 << 20      # smaller files are copied whatever their holes


def file_pieces(path: str | os.PathLike) -> Iterator[bytes]:
    """The bytes of ``path`` in chunks (what :func:`atomic_write` writes)."""
    with open(path, "rb") as handle:
        while chunk := handle.read(CHUNK):
            yield chunk


def data_bytes(path: str | os.PathLike, size: int) -> int:
    """How many of the ``size`` bytes of ``path`` are data, not holes (``size`` where the
    file system cannot tell)."""
    if not hasattr(os, "SEEK_DATA"):
        return size
    total, offset = 0, 0
    with open(path, "rb") as handle:
        fd = handle.fileno()
        try:
            while offset < size:
                start = os.lseek(fd, offset, os.SEEK_DATA)
                end = os.lseek(fd, start, os.SEEK_HOLE)
                total += end - start
                offset = end
        except OSError:             # ENXIO: no data after offset; EINVAL: not supported
            return total if offset else size
    return total


def _check_source(path: Path) -> None:
    """A copy is made only of a regular file that is not mostly holes."""
    check_regular(path)
    size = path.stat().st_size
    if size >= SPARSE_MIN_BYTES:
        data = data_bytes(path, size)
        if 2 * data < size:
            raise LibraryError("location", f"{path} is {size:,} bytes long but only {data:,} of them are "
                               "data (a sparse file, mostly holes, which no library is); "
                               "it was not copied and left unchanged", path)


def _writes_in_place(target: Path) -> bool:
    """Whether ``target`` exists and is not a regular file (a pipe, a device): written to."""
    try:
        return not stat.S_ISREG(os.stat(target).st_mode)
    except OSError:
        return False


def backup_copy(path: str | os.PathLike, target: str | os.PathLike | None = None,
                label: str = "backup") -> Path:
    """Copy the library file (and its ``-wal`` file, if any) byte for byte, never touching it.

    The copy goes to ``target`` or beside the file as ``NAME.LABEL-YYYYMMDDTHHMMSSZ``; the
    copy of the ``-wal`` file gets SQLite's own suffix, so the copy opens as it was. Both
    sources are checked before anything is written, and a copy of the main file whose
    ``-wal`` file then cannot be written is removed again. OSError (a WriteError naming
    ``target``) if the copy cannot be written; LibraryError for a source that cannot be copied.
    """
    source = Path(path)
    wal = Path(f"{source}-wal")
    _check_source(source)
    has_wal = os.path.lexists(wal)
    if has_wal:
        _check_source(wal)          # a folder or a pipe named like SQLite's log: nothing copied
    target = backup_target(source, label) if target is None else Path(target)
    if has_wal and _writes_in_place(target):
        raise LibraryError("location", f"{source} has a -wal file, so its copy needs a regular file "
                           f"beside which the -wal copy can go, not {target}; nothing was copied", source)
    new = not os.path.lexists(target)
    try:
        atomic_write(target, file_pieces(source))
        if has_wal:
            try:
                atomic_write(Path(f"{target}-wal"), file_pieces(wal))
            except BaseException:
                if new:
                    Path(os.path.realpath(target)).unlink(missing_ok=True)
                raise
    except OSError as exc:
        raise LibraryError("io", f"cannot copy {source} to {target}: {os_reason(exc)}", source) from None
    return target


def snapshot_to(conn: sqlite3.Connection, target: str | os.PathLike, path: str | os.PathLike) -> Path:
    """A consistent copy of the open library (SQLite's online backup) written to ``target``
    by :func:`atomic_write`. The backup is made in a temporary folder beside the file that
    ``target`` names (or in the system's temporary folder for a pipe or a device), then
    written in chunks; the folder is removed whatever happens. LibraryError('io') naming
    ``target`` and a plain reason (a full disk) if it cannot be written."""
    target = Path(target)
    try:
        near = None if _writes_in_place(target) else str(Path(os.path.realpath(target)).parent)
        folder = tempfile.mkdtemp(prefix=".shaper-backup-", dir=near)
    except OSError as exc:
        raise LibraryError("io", f"cannot write the copy {target}: {os_reason(exc)}", path) from None
    try:
        copy = Path(folder) / "copy.sqlite"
        dest = sqlite3.connect(sqlite_uri(copy), uri=True)
        try:
            conn.backup(dest)
        finally:
            dest.close()
        atomic_write(target, file_pieces(copy))
    except (OSError, sqlite3.Error) as exc:
        reason = os_reason(exc) if isinstance(exc, OSError) else str(exc)
        raise LibraryError("io", f"cannot write the copy {target}: {reason}", path) from None
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return target
