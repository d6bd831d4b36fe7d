"""Opening a design library safely: location, checks, schema and migrations.

A library is one SQLite file in WAL mode. Before anything is written to an
existing file it is checked: the SQLite header, that the file is ours
(``PRAGMA application_id``), that its schema is not newer than this program
(``PRAGMA user_version``) and that SQLite's ``quick_check`` passes. A file
that fails any check is refused with :class:`LibraryError` and left exactly
as it was; :func:`backup_copy` copies it aside byte for byte.

Every write is one ``BEGIN IMMEDIATE`` transaction, and a second process
waits up to ``BUSY_TIMEOUT_S`` for the lock, so two programs can share one
library. ``synchronous=FULL`` makes each commit durable before it returns.
"""
from __future__ import annotations

import os
import shutil
import sqlite3
import stat
from contextlib import contextmanager
from datetime import datetime, timezone
from pathlib import Path
from typing import Callable, Iterator

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
    (one entry's stored values are unusable; the rest of the library is fine)."""

    def __init__(self, kind: str, message: str, path: str | os.PathLike | None = None) -> None:
        super().__init__(message)
        self.kind = kind
        self.path = None if path is None else Path(path)

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
    """Schema 2: which computation of the figures (``core.figures.FIGURES_VERSION``) each
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


# ---- opening ------------------------------------------------------------------
def connect(path: str | os.PathLike, create: bool = True, make_dirs: bool = False) -> sqlite3.Connection:
    """Open, check and (for a new or older library) migrate the library at ``path``.

    A missing file is created when ``create``; its folder too when ``make_dirs``
    (the default location), otherwise a missing folder is an error.
    """
    path = Path(path)
    exists = path.exists()
    if not exists and not create:
        raise LibraryError("missing", f"there is no design library at {path}", path)
    if exists:
        if path.is_dir():
            raise LibraryError("location", f"{path} is a folder, not a library file", path)
        check_regular(path)
        _check_header(path)
    elif not path.parent.exists():
        if not make_dirs:
            raise LibraryError("location", f"cannot create the library {path}: the folder "
                               f"{path.parent} does not exist", path)
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise LibraryError("io", f"cannot create the folder {path.parent}: "
                               f"{exc.strerror or exc}", path) from None
    try:
        conn = sqlite3.connect(str(path), timeout=BUSY_TIMEOUT_S, isolation_level=None)
    except sqlite3.Error as exc:
        raise LibraryError("io", f"cannot open the library {path}: {exc}", path) from None
    try:
        version = _check_contents(conn, path)
        conn.execute(f"PRAGMA busy_timeout = {int(BUSY_TIMEOUT_S * 1000)}")
        conn.execute("PRAGMA foreign_keys = ON")
        conn.execute("PRAGMA synchronous = FULL")
        if version < schema_version():
            _migrate(conn, path, version)
        if conn.execute("PRAGMA journal_mode").fetchone()[0].lower() != "wal":
            conn.execute("PRAGMA journal_mode = WAL")
    except LibraryError:
        conn.close()
        raise
    except sqlite3.Error as exc:
        conn.close()
        raise sqlite_error(exc, path) from None
    return conn


def check_regular(path: Path) -> None:
    """A library is a regular file (a link to one is fine). A pipe would block the first
    read forever and a device is no database: both are refused before anything opens them."""
    try:
        mode = path.stat().st_mode
    except OSError as exc:
        raise LibraryError("io", f"cannot read the library {path}: {exc.strerror or exc}", path) from None
    if not stat.S_ISREG(mode):
        kind = ("a pipe" if stat.S_ISFIFO(mode) else "a socket" if stat.S_ISSOCK(mode)
                else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else "not a regular file")
        raise LibraryError("location", f"{path} is {kind}, not a library file; it was left unchanged", path)


def _check_header(path: Path) -> None:
    try:
        with open(path, "rb") as handle:
            head = handle.read(len(SQLITE_HEADER))
    except OSError as exc:
        raise LibraryError("io", f"cannot read the library {path}: {exc.strerror or exc}", path) from None
    if head and head != SQLITE_HEADER:
        raise LibraryError("foreign" if len(head) == len(SQLITE_HEADER) else "damaged",
                           f"{path} is not a Shaper Designer library (not an SQLite database); "
                           "it was left unchanged", path)


def _check_contents(conn: sqlite3.Connection, path: Path) -> int:
    """The schema version of a library we may use; refuses anything else, unchanged."""
    try:
        app_id = conn.execute("PRAGMA application_id").fetchone()[0]
        version = conn.execute("PRAGMA user_version").fetchone()[0]
        tables = conn.execute("SELECT count(*) FROM sqlite_master").fetchone()[0]
        check = [row[0] for row in conn.execute("PRAGMA quick_check(3)")]
    except sqlite3.DatabaseError as exc:
        text = str(exc)
        if "locked" in text or "busy" in text:
            raise sqlite_error(exc, path) from None
        raise LibraryError("damaged", f"{path} is damaged ({text}); it was left unchanged", path) from None
    if check != ["ok"]:
        detail = " ".join("; ".join(check).replace("*** in database main ***", "").split())
        raise LibraryError("damaged", f"{path} is damaged (SQLite's check: {detail[:200]}); "
                           "it was left unchanged", path)
    if app_id == 0 and version == 0 and tables == 0:
        return 0                                  # a new, empty database
    if app_id != APPLICATION_ID:
        raise LibraryError("foreign", f"{path} is an SQLite database but not a Shaper Designer "
                           "library; it was left unchanged", path)
    if version > schema_version():
        raise LibraryError("newer", f"{path} was written by a newer Shaper Designer (library schema "
                           f"{version}; this version reads up to {schema_version()}); it was left "
                           "unchanged — update Shaper Designer to use it", path)
    return version


def integrity_problems(conn: sqlite3.Connection, limit: int = 20) -> list[str]:
    """SQLite's full check of the file (every page, index and constraint): [] when sound."""
    rows = [row[0] for row in conn.execute(f"PRAGMA integrity_check({int(limit)})")]
    return [] if rows == ["ok"] else [" ".join(r.replace("*** in database main ***", "").split())
                                      for r in rows]


def _migrate(conn: sqlite3.Connection, path: Path, version: int) -> None:
    """Bring the schema up to date in one transaction; keep a copy of a non-empty library first."""
    if version > 0:
        snapshot(conn, backup_target(path, f"schema{version}"), path)
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


def sqlite_error(exc: sqlite3.Error, path: Path) -> LibraryError:
    text = str(exc)
    if "locked" in text or "busy" in text:
        return LibraryError("busy", f"the library {path} is busy (another program is writing "
                            f"to it for more than {BUSY_TIMEOUT_S:g} s); try again", path)
    if isinstance(exc, sqlite3.DatabaseError) and ("malformed" in text or "not a database" in text):
        return LibraryError("damaged", f"{path} is damaged ({text}); it was left unchanged", path)
    return LibraryError("io", f"cannot use the library {path}: {text}", path)


def utc_now() -> str:
    """Now as UTC ISO 8601 with milliseconds, e.g. 2024-05-01T12:00:00.000Z (sorts as text)."""
    now = datetime.now(timezone.utc)
    return now.strftime("%Y-%m-%dT%H:%M:%S.") + f"{now.microsecond // 1000:03d}Z"


def backup_copy(path: str | os.PathLike, target: str | os.PathLike | None = None,
                label: str = "backup") -> Path:
    """Copy the library file (and its ``-wal`` file, if any) byte for byte, never touching it.

    The copy goes to ``target`` or beside the file as ``NAME.LABEL-YYYYMMDDTHHMMSSZ``; the
    copy of the ``-wal`` file gets SQLite's own suffix, so the copy opens as it was.
    """
    source = Path(path)
    if source.exists() and not source.is_dir():
        check_regular(source)          # never read a pipe (it would block) or a device
    target = backup_target(source, label) if target is None else Path(target)
    try:
        for src, dst in ((source, target), (Path(f"{source}-wal"), Path(f"{target}-wal"))):
            if src.exists():
                _copy_atomic(src, dst)
    except OSError as exc:
        raise LibraryError("io", f"cannot copy {source} to {target}: {exc.strerror or exc}",
                           source) from None
    return target


def snapshot(conn: sqlite3.Connection, target: str | os.PathLike, path: str | os.PathLike) -> Path:
    """A consistent copy of the open library (SQLite's online backup), written atomically."""
    target = Path(target)
    tmp = target.with_name(f".{target.name}.tmp")
    try:
        tmp.unlink(missing_ok=True)
        dest = sqlite3.connect(str(tmp))
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
    target = source.with_name(f"{source.name}.{label}-{stamp}")
    n = 2
    while target.exists():
        target = source.with_name(f"{source.name}.{label}-{stamp}-{n}")
        n += 1
    return target


def _copy_atomic(source: Path, target: Path) -> None:
    """Copy through a temporary file beside ``target``, synced, then renamed into place."""
    tmp = target.with_name(f".{target.name}.tmp")
    try:
        shutil.copyfile(source, tmp)
        with open(tmp, "rb+") as handle:
            os.fsync(handle.fileno())
        os.replace(tmp, target)
    finally:
        tmp.unlink(missing_ok=True)
