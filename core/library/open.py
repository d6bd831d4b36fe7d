"""Opening a design library: decided once, up front, before anything is written.

A file is one of:

- **usable**: ours, its schema version and its tables agree, SQLite's
  ``quick_check`` passes; an older schema is migrated (after a copy);
- **read-only**: usable, but the file or its folder cannot be written: opened
  with SQLite's ``mode=ro`` (or ``immutable=1`` where even SQLite's shared-memory
  file cannot be made), ``Library.read_only`` says why and every write is refused
  in one line naming that reason;
- **damaged** (not an SQLite file, SQLite's check fails, a schema version that
  does not match its tables, a negative version, missing tables or columns),
  **newer** (a later schema) or **foreign** (another program's database): refused
  with :class:`~core.library.store.LibraryError`, the file's bytes untouched
  (no migration, no journal mode change, no copy).

Checking a schema against its version costs one ``PRAGMA table_info`` per table;
the expected columns of each version come from running the migrations on an
in-memory database, so the check can never disagree with the migrations.
"""
from __future__ import annotations

import errno
import os
import sqlite3
import stat
from dataclasses import dataclass
from pathlib import Path

from . import store as library_store
from .schema import describe, expected_objects, schema_objects, strange_objects
from .store import (APPLICATION_ID, BUSY_TIMEOUT_S, SQLITE_HEADER, LibraryError, check_regular, is_damage,
                    migrate, schema_version, sqlite_code, sqlite_error, sqlite_uri)

_UNCHANGED = "it was left unchanged"


@dataclass(frozen=True)
class Opened:
    """An open, checked library connection; ``read_only`` is None or why it cannot be written."""

    conn: sqlite3.Connection
    read_only: str | None


def connect(path: str | os.PathLike, create: bool = True, make_dirs: bool = False) -> Opened:
    """Open, check and (for a new or older library) migrate the library at ``path``.

    A missing file is created when ``create``; its folder too when ``make_dirs``
    (the default location), otherwise a missing folder is an error.
    """
    path = Path(path)
    exists = library_exists(path)
    if not exists and not create:
        raise LibraryError("missing", f"there is no design library at {path}", path)
    if exists:
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
    read_only = unwritable(path) if exists else None
    if not exists and unwritable(path.parent) is not None:
        raise LibraryError("readonly", f"cannot create the library {path}: the folder "
                           f"{path.parent} cannot be written", path)
    conn = _open(path, read_only)
    try:
        version = _check_contents(conn, path)
        conn.execute(f"PRAGMA busy_timeout = {int(BUSY_TIMEOUT_S * 1000)}")
        if read_only is None:
            conn.execute("PRAGMA foreign_keys = ON")
            conn.execute("PRAGMA synchronous = FULL")
        if version < schema_version():
            if read_only is not None:
                raise LibraryError("readonly", f"{path} was written by an older Shaper Designer and "
                                   f"must be upgraded before use, but {read_only}; {_UNCHANGED}", path)
            migrate(conn, path, version)
        if read_only is None and conn.execute("PRAGMA journal_mode").fetchone()[0].lower() != "wal":
            conn.execute("PRAGMA journal_mode = WAL")
    except LibraryError:
        conn.close()
        raise
    except sqlite3.Error as exc:
        conn.close()
        raise sqlite_error(exc, path) from None
    return Opened(conn, read_only)


def library_exists(path: Path) -> bool:
    """Whether ``path`` names something; a link loop, a too long name or a folder is refused
    here (``Path.exists`` would take a loop for a missing file and create a library)."""
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        return False
    except OSError as exc:
        why = {errno.ELOOP: "a loop of symbolic links", errno.ENAMETOOLONG: "a name that is too long",
               errno.ENOTDIR: "a path through something that is not a folder"}.get(exc.errno)
        if why is None:
            raise LibraryError("io", f"cannot read the library {path}: {exc.strerror or exc}",
                               path) from None
        raise LibraryError("location", f"{path} is {why}, not a library file", path) from None
    if stat.S_ISDIR(mode):
        raise LibraryError("location", f"{path} is a folder, not a library file", path)
    return True


def unwritable(path: Path) -> str | None:
    """Why the library file ``path`` (or a folder) cannot be written by us, or None if it can.

    SQLite writes beside the file (its -wal and -shm files), so the folder counts too.
    """
    folder = path if path.is_dir() else (path.parent if str(path.parent) else Path("."))
    if not path.is_dir() and not os.access(path, os.W_OK):
        return "the file cannot be written (its permissions or a read-only disk)"
    if not os.access(folder, os.W_OK):
        return f"its folder {folder} cannot be written (its permissions or a read-only disk)"
    return None


def _open(path: Path, read_only: str | None) -> sqlite3.Connection:
    """A connection that runs nothing the file's schema asks for beyond plain SQL
    (``trusted_schema = OFF``, as SQLite advises for files from elsewhere)."""
    conn = _connection(path, read_only)
    try:
        conn.execute("PRAGMA trusted_schema = OFF")
    except sqlite3.Error as exc:
        conn.close()
        raise LibraryError("io", f"cannot open the library {path}: {exc}", path) from None
    return conn


def _connection(path: Path, read_only: str | None) -> sqlite3.Connection:
    """A connection; read-only ones by URI (``mode=ro``, else ``immutable=1`` where SQLite
    cannot make its shared-memory file in a read-only folder)."""
    try:
        if read_only is None:
            return sqlite3.connect(sqlite_uri(path), uri=True, timeout=BUSY_TIMEOUT_S, isolation_level=None)
        conn = sqlite3.connect(sqlite_uri(path, "mode=ro"), uri=True, timeout=BUSY_TIMEOUT_S,
                               isolation_level=None)
        try:
            conn.execute("SELECT count(*) FROM sqlite_master").fetchone()
            return conn
        except sqlite3.OperationalError:
            conn.close()
        return sqlite3.connect(sqlite_uri(path, "immutable=1"), uri=True, isolation_level=None)
    except sqlite3.Error as exc:
        raise LibraryError("io", f"cannot open the library {path}: {exc}", path) from None


def _check_header(path: Path) -> None:
    try:
        with open(path, "rb") as handle:
            head = handle.read(len(SQLITE_HEADER))
    except OSError as exc:
        raise LibraryError("io", f"cannot read the library {path}: {exc.strerror or exc}", path) from None
    if head and head != SQLITE_HEADER:
        raise LibraryError("foreign" if len(head) == len(SQLITE_HEADER) else "damaged",
                           f"{path} is not a Shaper Designer library (not an SQLite database); "
                           f"{_UNCHANGED}", path)


def _check_contents(conn: sqlite3.Connection, path: Path) -> int:
    """The schema version of a library we may use; refuses anything else, unchanged."""
    try:
        app_id = conn.execute("PRAGMA application_id").fetchone()[0]
        version = conn.execute("PRAGMA user_version").fetchone()[0]
        tables = conn.execute("SELECT count(*) FROM sqlite_master").fetchone()[0]
        check = [row[0] for row in conn.execute("PRAGMA quick_check(3)")]
        ours = app_id == APPLICATION_ID and 0 < version <= schema_version()
        columns = _columns(conn) if ours else {}
        objects = schema_objects(conn) if ours else {}
    except sqlite3.DatabaseError as exc:
        if not _about_the_file(exc):        # a full disk, a lock, memory: the file is as it was
            raise sqlite_error(exc, path) from None
        raise LibraryError("damaged", f"{path} is damaged ({exc}); {_UNCHANGED}", path) from None
    if check != ["ok"]:
        detail = " ".join("; ".join(check).replace("*** in database main ***", "").split())
        raise LibraryError("damaged", f"{path} is damaged (SQLite's check: {detail[:200]}); "
                           f"{_UNCHANGED}", path)
    if app_id == 0 and version == 0 and tables == 0:
        return 0                                  # a new, empty database
    if app_id != APPLICATION_ID:
        raise LibraryError("foreign", f"{path} is an SQLite database but not a Shaper Designer "
                           f"library; {_UNCHANGED}", path)
    if version > schema_version():
        raise LibraryError("newer", f"{path} was written by a newer Shaper Designer (library schema "
                           f"{version}; this version reads up to {schema_version()}); {_UNCHANGED} — "
                           "update Shaper Designer to use it", path)
    if version <= 0:
        raise LibraryError("damaged", f"{path} is damaged (its schema version {version} is not one "
                           f"Shaper Designer ever wrote); {_UNCHANGED}", path)
    problem = _schema_problem(columns, expected_columns(tuple(library_store.MIGRATIONS[:version])))
    if problem:
        raise LibraryError("damaged", f"{path} is damaged (it says schema version {version}, but "
                           f"{problem}); {_UNCHANGED}", path)
    strange = strange_objects(objects, expected_objects(tuple(library_store.MIGRATIONS[:version])))
    if strange:
        raise LibraryError("foreign", f"{path} holds {describe(strange)} that Shaper Designer never makes "
                           f"(another program changed it, and SQLite would run what it does); "
                           f"{_UNCHANGED}", path, objects=tuple(strange))
    return version


def _about_the_file(exc: sqlite3.Error) -> bool:
    """Whether a failure to read the schema says something about the file (damaged, or
    not a schema SQLite can read) rather than about the disk, a lock or the memory."""
    if is_damage(exc):
        return True
    code = sqlite_code(exc)
    if code is None:
        return not any(word in str(exc) for word in ("locked", "busy", "disk", "memory", "unable to open"))
    return code not in _NOT_THE_FILE


# SQLite's result codes for what is not the file's fault: BUSY, LOCKED, NOMEM, READONLY,
# IOERR, FULL, CANTOPEN, PERM (the file is left as it was and may be fine)
_NOT_THE_FILE = frozenset({5, 6, 7, 8, 10, 13, 14, 3})


def _columns(conn: sqlite3.Connection) -> dict[str, tuple[str, ...]]:
    names = [r[0] for r in conn.execute("SELECT name FROM sqlite_master WHERE type = 'table'")]
    return {name: tuple(sorted(str(r[1]) for r in conn.execute("SELECT * FROM pragma_table_info(?)",
                                                                (name,))))
            for name in names if isinstance(name, str)}


def expected_columns(steps: tuple) -> dict[str, tuple[str, ...]]:
    """The tables and columns the migration ``steps`` make (those up to a schema version),
    read from the objects they make (:func:`~core.library.schema.expected_objects`)."""
    return {name: tuple(sorted(str(column[0]) for column in meaning[1]))
            for (kind, name), meaning in expected_objects(steps).items() if kind == "table"}


def _schema_problem(actual: dict[str, tuple[str, ...]], expected: dict[str, tuple[str, ...]]) -> str:
    for table, columns in expected.items():
        if table not in actual:
            return f"there is no table {table}"
        extra = sorted(set(actual[table]) - set(columns))
        missing = sorted(set(columns) - set(actual[table]))
        if missing:
            return f"the table {table} lacks the column {missing[0]}"
        if extra:
            return f"the table {table} has an extra column {extra[0]}"
    return ""
