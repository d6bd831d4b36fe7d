"""A design library's location, schema, migrations, transactions and copies.

A library is one SQLite file in WAL mode. Whether an existing file may be
opened (and written) is decided before anything touches it, in
:mod:`core.library.open`; a refused file is left exactly as it was, and
:func:`core.library.backup.backup_copy` copies it aside byte for byte.

Every write is one ``BEGIN IMMEDIATE`` transaction, and a second process
waits up to ``BUSY_TIMEOUT_S`` for the lock, so two programs can share one
library. ``synchronous=FULL`` makes each commit durable before it returns.
"""
from __future__ import annotations

import errno
import os
import sqlite3
import stat
from contextlib import contextmanager
from datetime import datetime, timezone
from pathlib import Path
from typing import Callable, Iterator
from urllib.parse import quote

from core.files.atomic import fit_name
from core.base.errors import os_reason

APP_NAME = "shaper-designer"
FILE_NAME = "library.sqlite"
ENV_VAR = "SHAPER_LIBRARY"
APPLICATION_ID = 0x53485052          # "SHPR" in the SQLite header
BUSY_TIMEOUT_S = 10.0
SQLITE_HEADER = b"SQLite format 3\x00"


class LibraryError(Exception):
    """A library problem with a plain message. ``kind`` is one of ``damaged``,
    ``newer``, ``foreign``, ``io``, ``busy``, ``name``, ``tag``, ``exists``, ``missing``,
    ``location`` (the path is a folder, or its folder does not exist: the path is wrong,
    not the disk), ``readonly`` (a write to a library opened read-only) or ``entry``
    (one entry's stored values are unusable; the rest of the library is fine, and
    ``damage`` says why, as :class:`core.library.rows.Damage`)."""

    def __init__(self, kind: str, message: str, path: str | os.PathLike | None = None,
                 objects: tuple[str, ...] = (), damage: str | None = None) -> None:
        super().__init__(message)
        self.kind = kind
        self.damage = damage
        self.path = None if path is None else Path(path)
        self.objects = objects      # a refused file's schema objects that are not ours, described

    @property
    def refused_file(self) -> bool:
        """True when the library file itself was refused (and left unchanged)."""
        return self.kind in ("damaged", "newer", "foreign")


# ---- location ---------------------------------------------------------------
def default_path() -> Path:
    """The per-user library file (platformdirs decides the folder)."""
    import platformdirs
    return platformdirs.user_data_path(APP_NAME, appauthor=False) / FILE_NAME


def resolve_path(explicit: str | os.PathLike | None = None) -> Path:
    """``explicit`` if given, else ``$SHAPER_LIBRARY`` if set and not empty, else the default."""
    if explicit:
        return Path(explicit)
    env = os.environ.get(ENV_VAR, "")
    return Path(env) if env else default_path()


# ---- schema -----------------------------------------------------------------
_SCHEMA_V1 = """
CREATE TABLE entries (
    id INTEGER PRIMARY KEY,
    name TEXT NOT NULL UNIQUE,
    notes TEXT NOT NULL DEFAULT '',
    tags TEXT NOT NULL DEFAULT '',          -- the tags table's tags joined by ',' (for listing)
    created TEXT NOT NULL,
    modified TEXT NOT NULL,
    variant TEXT NOT NULL,
    rod_side TEXT,
    K REAL NOT NULL,
    stroke_mm REAL NOT NULL,
    theta_deg REAL NOT NULL,
    crank_mm REAL NOT NULL,
    frame_mm REAL NOT NULL,
    lever_mm REAL NOT NULL,
    rod_mm REAL,
    guide_mm REAL NOT NULL,
    pressure_angle_max_deg REAL
);
CREATE TABLE documents (
    entry_id INTEGER PRIMARY KEY REFERENCES entries(id) ON DELETE CASCADE,
    text TEXT NOT NULL
);
CREATE TABLE speeds (                   -- one row per distinct speed of the document
    entry_id INTEGER NOT NULL REFERENCES entries(id) ON DELETE CASCADE,
    pos INTEGER NOT NULL,
    rpm REAL NOT NULL,
    v_work_max_m_s REAL NOT NULL,
    v_work_mean_m_s REAL NOT NULL,
    v_return_max_m_s REAL NOT NULL,
    a_max_m_s2 REAL NOT NULL,
    mean_torque_N_m REAL,
    max_torque_N_m REAL,
    flywheel_inertia_kg_m2 REAL,
    PRIMARY KEY (entry_id, pos)
) WITHOUT ROWID;
CREATE TABLE tags (
    entry_id INTEGER NOT NULL REFERENCES entries(id) ON DELETE CASCADE,
    tag TEXT NOT NULL,
    PRIMARY KEY (entry_id, tag)
);
CREATE INDEX tags_by_tag ON tags(tag);
CREATE UNIQUE INDEX speeds_by_rpm ON speeds(entry_id, rpm);
CREATE INDEX entries_by_modified ON entries(modified);
"""


def _create_v1(conn: sqlite3.Connection) -> None:
    # executescript() would commit the caller's transaction, so run one statement at a time.
    for statement in _SCHEMA_V1.split(";"):
        if statement.strip():
            conn.execute(statement)


def _add_figures_version(conn: sqlite3.Connection) -> None:
    """Schema 2: which computation of the figures (``core.space.figures.FIGURES_VERSION``) each
    entry's stored figures come from, so that figures an older program computed can be
    found and recomputed. Schema 1 was written by figures version 1."""
    conn.execute("ALTER TABLE entries ADD COLUMN figures_version INTEGER NOT NULL DEFAULT 1")


# MIGRATIONS[i] turns a library at schema i into schema i + 1, inside the caller's
# transaction (SQLite's DDL is transactional, so a failed step leaves schema i).
# Schema 0 is an empty database. Append a function here to change the schema.
MIGRATIONS: list[Callable[[sqlite3.Connection], None]] = [_create_v1, _add_figures_version]


def schema_version() -> int:
    """The schema this program writes: the number of migrations."""
    return len(MIGRATIONS)


# ---- opening (the decision is in core.library.open) ---------------------------
def check_regular(path: Path) -> None:
    """A library is a regular file (a link to one is fine). A pipe would block the first
    read forever and a device is no database: both are refused before anything opens them."""
    try:
        mode = path.stat().st_mode
    except OSError as exc:
        raise LibraryError("io", f"cannot read the library {path}: {exc.strerror or exc}", path) from None
    if not stat.S_ISREG(mode):
        kind = ("a folder" if stat.S_ISDIR(mode) else "a pipe" if stat.S_ISFIFO(mode) else "a socket" if stat.S_ISSOCK(mode)
                else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else "not a regular file")
        raise LibraryError("location", f"{path} is {kind}, not a library file; it was left unchanged", path)


def integrity_problems(conn: sqlite3.Connection, limit: int = 20) -> list[str]:
    """SQLite's full check of the file (every page, index and constraint): [] when sound."""
    rows = [row[0] for row in conn.execute(f"PRAGMA integrity_check({int(limit)})")]
    return [] if rows == ["ok"] else [" ".join(r.replace("*** in database main ***", "").split())
                                      for r in rows]


def migrate(conn: sqlite3.Connection, path: Path, version: int) -> None:
    """Bring the schema up to date in one transaction; keep a copy of a non-empty library
    first (removed again if the migration fails, so failed attempts leave no copies)."""
    copy = snapshot(conn, backup_target(path, f"schema{version}"), path) if version > 0 else None
    try:
        _migrate_steps(conn, path)
    except BaseException:
        if copy is not None:
            copy.unlink(missing_ok=True)
        raise


def _migrate_steps(conn: sqlite3.Connection, path: Path) -> None:
    with transaction(conn, path):
        current = conn.execute("PRAGMA user_version").fetchone()[0]   # another process may have won
        if current > schema_version():
            raise LibraryError("newer", f"{path} was just upgraded by a newer Shaper Designer", path)
        if current == 0:
            conn.execute(f"PRAGMA application_id = {APPLICATION_ID}")
        for step in range(current, schema_version()):
            MIGRATIONS[step](conn)
            conn.execute(f"PRAGMA user_version = {step + 1}")


@contextmanager
def transaction(conn: sqlite3.Connection, path: str | os.PathLike) -> Iterator[sqlite3.Connection]:
    """One write transaction, taken at once (BEGIN IMMEDIATE), committed or rolled back whole."""
    try:
        conn.execute("BEGIN IMMEDIATE")
    except sqlite3.Error as exc:
        raise sqlite_error(exc, Path(path)) from None
    try:
        yield conn
    except BaseException as exc:
        try:
            conn.execute("ROLLBACK")
        except sqlite3.Error:
            pass
        if isinstance(exc, sqlite3.Error):
            raise sqlite_error(exc, Path(path)) from None
        raise
    try:
        conn.execute("COMMIT")
    except sqlite3.Error as exc:
        try:
            conn.execute("ROLLBACK")
        except sqlite3.Error:
            pass
        raise sqlite_error(exc, Path(path)) from None


# SQLite's primary result codes (an extended code's low byte is its primary code)
_BUSY, _LOCKED, _READONLY, _IOERR, _CORRUPT, _FULL, _NOTADB = 5, 6, 8, 10, 11, 13, 26
_ROOM_BYTES = 1 << 20       # a file system with less free than this counts as full


def sqlite_code(exc: sqlite3.Error) -> int | None:
    """SQLite's primary result code of ``exc`` (None when it carries none)."""
    code = getattr(exc, "sqlite_errorcode", None)
    return code & 0xFF if isinstance(code, int) else None


def is_damage(exc: sqlite3.Error) -> bool:
    """Whether ``exc`` says the file itself is damaged (SQLITE_CORRUPT, SQLITE_NOTADB), not
    that the disk, the lock or the memory failed, which leave the file as it was."""
    code = sqlite_code(exc)
    if code is not None:
        return code in (_CORRUPT, _NOTADB)
    text = str(exc)
    return "malformed" in text or "not a database" in text


def disk_full(path: str | os.PathLike) -> bool:
    """Whether the file system holding ``path`` has (next to) no room left: what a disk
    I/O error of SQLite (it cannot make its shared-memory file, or grow one) then means."""
    folder = Path(path).parent if not Path(path).is_dir() else Path(path)
    try:
        fs = os.statvfs(folder if str(folder) else ".")
    except (OSError, AttributeError):
        return False
    return fs.f_bavail * fs.f_frsize < _ROOM_BYTES or (fs.f_files > 0 and fs.f_favail == 0)


def sqlite_error(exc: sqlite3.Error, path: Path) -> LibraryError:
    """``exc`` as one plain LibraryError, told apart by SQLite's result code: a busy
    library, a full disk, a damaged file, a read-only one or another failure (io)."""
    text = str(exc)
    code = sqlite_code(exc)
    if code in (_BUSY, _LOCKED) or (code is None and ("locked" in text or "busy" in text)):
        return LibraryError("busy", f"the library {path} is busy (another program is writing "
                            f"to it for more than {BUSY_TIMEOUT_S:g} s); try again", path)
    if code == _FULL or (code == _IOERR and disk_full(path)):
        return LibraryError("io", f"cannot use the library {path}: {os_reason(OSError(errno.ENOSPC, ''))}; "
                            "nothing was changed", path)
    if isinstance(exc, sqlite3.DatabaseError) and is_damage(exc):
        return LibraryError("damaged", f"{path} is damaged ({text}); it was left unchanged", path)
    if code == _READONLY or "readonly" in text or "read-only" in text:
        return LibraryError("readonly", f"the library {path} can only be read ({text}); "
                            "nothing was changed", path)
    return LibraryError("io", f"cannot use the library {path}: {text}", path)


def sqlite_uri(path: str | os.PathLike, query: str = "") -> str:
    """``path`` as an SQLite URI (``uri=True``): any bytes a file name may hold (also those
    that are not UTF-8) survive, and ``query`` (``mode=ro``…) can be added."""
    uri = "file:" + quote(os.fsencode(os.path.abspath(path)))
    return uri + ("?" + query if query else "")


def utc_now() -> str:
    """Now as UTC ISO 8601 with milliseconds, e.g. 2024-05-01T12:00:00.000Z (sorts as text)."""
    now = datetime.now(timezone.utc)
    return now.strftime("%Y-%m-%dT%H:%M:%S.") + f"{now.microsecond // 1000:03d}Z"


def snapshot(conn: sqlite3.Connection, target: str | os.PathLike, path: str | os.PathLike) -> Path:
    """A consistent copy of the open library (SQLite's online backup), written atomically."""
    target = Path(target)
    tmp = target.with_name(f".{fit_name(target.name, 16)}.tmp")     # room for SQLite's -journal
    try:
        if os.path.islink(target):
            os.stat(target)             # a link loop or a link to nothing: not replaced by a file
        tmp.unlink(missing_ok=True)
        dest = sqlite3.connect(sqlite_uri(tmp), uri=True)
        try:
            conn.backup(dest)
        finally:
            dest.close()
        os.replace(tmp, target)
    except (OSError, sqlite3.Error) as exc:
        tmp.unlink(missing_ok=True)
        raise LibraryError("io", f"cannot write the copy {target}: "
                           f"{getattr(exc, 'strerror', None) or exc}", path) from None
    return target


def backup_target(path: str | os.PathLike, label: str = "backup") -> Path:
    """A free file name beside ``path``: ``NAME.LABEL-YYYYMMDDTHHMMSSZ`` (``-2``… if taken)."""
    source = Path(path)
    stamp = datetime.now(timezone.utc).strftime("%Y%m%dT%H%M%SZ")
    base = fit_name(source.name, len(f".{label}-{stamp}-999"))      # within NAME_MAX bytes
    target = source.with_name(f"{base}.{label}-{stamp}")
    n = 2
    while target.exists():
        target = source.with_name(f"{base}.{label}-{stamp}-{n}")
        n += 1
    return target
