"""The design library: named designs with their key figures, in one SQLite file.

Each entry keeps a name (unique), notes, tags, created and modified times (UTC,
ISO 8601), the design document exactly as a design file holds it (loads
included), and the key figures of :mod:`core.space.figures` — the design's in the
``entries`` table, each speed's in ``speeds`` — so a list can be filtered and
sorted without recomputing anything. Documents read back are validated by the
same rules as a design file (:func:`core.files.io.parse_design`).

An entry and its document are in :mod:`core.library.entry`; opening and its
checks in :mod:`core.library.open`; schema and transactions in
:mod:`core.library.store`; rows read with their types checked in
:mod:`core.library.rows`; the rows an entry is written as in :mod:`core.library.writes`;
the filter syntax in :mod:`core.library.query`.
"""
from __future__ import annotations

import os
import sqlite3
from dataclasses import dataclass, fields
from pathlib import Path
from typing import Any, Callable, Iterable, Sequence

from core.base.errors import DesignError, FileFormatError
from core.space.figures import FIGURES_VERSION, Figures, SpeedFigures, figures
from core.files.atomic import atomic_write

from .backup import snapshot_to
from .entry import Entry, check_document, document_text, with_step
from .names import check_name, check_notes, check_tags, lookup_name, unique_name
from .open import connect
from .query import Condition, condition_sql, parse_filter, search_sql, sort_sql
from .rows import Damage, clean_row, damaged_entries, entry_label, listed_damage, read_lenient, unfit_sql
from .store import (LibraryError, backup_target, default_path, integrity_problems, resolve_path,
                            sqlite_error, transaction, utc_now)
from .writes import ENTRY_COLUMNS, SPEED_COLUMNS, insert_entry, rewrite_figures

# the columns of :meth:`Library.query_rows`; ``damaged`` is None, or why the row's values
# could not all be read (those are None; see :mod:`core.library.rows`)
LIST_COLUMNS = ENTRY_COLUMNS + SPEED_COLUMNS + ("damaged",)
_LIST_NULLABLE = frozenset(SPEED_COLUMNS)      # a design without the speed asked for
_LIST_KEYS = ("id",) + ENTRY_COLUMNS + SPEED_COLUMNS
_LIST_EXPRESSIONS = [f"e.{c}" for c in _LIST_KEYS[:-len(SPEED_COLUMNS)]] + [f"s.{c}" for c in SPEED_COLUMNS]
# a flag (SQLite checks every value's type in C), the id, the columns


def _list_select(notes_chars: int | None) -> str:
    """The list's columns; the notes cut to their first ``notes_chars`` characters by
    SQLite when given, so a list never carries a note's whole text (50 MB of notes
    took a pane 2 GB to show)."""
    expressions = [f"substr(e.notes, 1, {int(notes_chars)})" if e == "e.notes" and notes_chars is not None
                   else e for e in _LIST_EXPRESSIONS]
    return ", ".join([unfit_sql(zip(expressions, _LIST_KEYS), _LIST_NULLABLE)] + expressions)


def _cleaned(row: tuple) -> tuple:
    """A list row SQLite flagged (or one read with bytes for bad texts), cleaned in Python."""
    values, reason = clean_row(_LIST_KEYS, row[1:], _LIST_NULLABLE)
    return tuple(values[1:]) + (reason,)


_MAX_ROWS = 2 ** 62     # SQLite's LIMIT is a 64-bit integer; more rows than that is "all"
REFRESH_BATCH = 64      # entries written per transaction by ``refresh_figures``


@dataclass(frozen=True)
class RefreshReport:
    """What :meth:`Library.refresh_figures` did, by entry name."""

    updated: tuple[str, ...]
    failed: tuple[tuple[str, str], ...]     # (name, why its design cannot be computed)
    skipped: tuple[str, ...]                # removed or re-saved by another program meanwhile


class Library:
    """A checked, open library. Use as a context manager or call :meth:`close`."""

    def __init__(self, path: str | os.PathLike | None = None, create: bool = True) -> None:
        self.path = resolve_path(path)
        opened = connect(self.path, create=create, make_dirs=self.path == default_path())
        self._conn = opened.conn
        self.read_only: str | None = opened.read_only    # why it cannot be written, if so

    def close(self) -> None:
        self._conn.close()

    def __enter__(self) -> "Library":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def data_version(self) -> int:
        """Changes whenever another connection commits (cheap to poll)."""
        return self._read(lambda c: c.execute("PRAGMA data_version").fetchone()[0])

    def _transaction(self):
        """One write transaction; refused at once, in one line, if the library is read-only."""
        if self.read_only is not None:
            raise LibraryError("readonly", f"the library {self.path} can only be read: {self.read_only}; "
                               "nothing was changed", self.path)
        return transaction(self._conn, self.path)

    # ---- reading --------------------------------------------------------------
    def _read(self, work):
        try:
            return read_lenient(self._conn, work)
        except sqlite3.Error as exc:
            raise sqlite_error(exc, self.path) from None

    def names(self) -> list[str]:
        return self._read(lambda c: [r[0] for r in c.execute("SELECT name FROM entries ORDER BY name")
                                     if isinstance(r[0], str)])

    def unreadable_names(self) -> list[tuple[str, Damage]]:
        """(label, why) for each entry whose name cannot be read (not text, or not UTF-8):
        no name finds it, so :meth:`names` leaves it out, and an export of every entry must
        say it left it out (``rows.entry_label``: "entry #3 (its name is unreadable)")."""
        def work(c: sqlite3.Connection) -> list[tuple[str, Damage]]:
            out = []
            for entry_id, name in c.execute("SELECT id, name FROM entries ORDER BY id"):
                why = clean_row(("name",), (name,))[1]
                if why is not None:
                    out.append((entry_label(entry_id, name), why))
            return out
        return self._read(lambda c: read_lenient(c, work))

    def count(self) -> int:
        return self._read(lambda c: c.execute("SELECT count(*) FROM entries").fetchone()[0])

    def __contains__(self, name: str) -> bool:
        return self._read(lambda c: c.execute("SELECT 1 FROM entries WHERE name = ?", (lookup_name(name),))
                          .fetchone() is not None)

    def get(self, name: str) -> Entry:
        """The entry called ``name``; LibraryError('missing') if there is none, ('entry') if a
        stored value of it is unusable (see :mod:`core.library.rows`). ``name`` is looked up as
        it is stored (:func:`~core.library.names.lookup_name`)."""
        name = lookup_name(name)

        def work(c: sqlite3.Connection) -> Entry:
            row = c.execute(f"SELECT e.id, {', '.join(ENTRY_COLUMNS)}, d.text FROM entries e "
                            "LEFT JOIN documents d ON d.entry_id = e.id WHERE e.name = ?", (name,)).fetchone()
            if row is None:
                raise LibraryError("missing", f"there is no design named {name!r} in the library",
                                   self.path)
            values, reason = clean_row(("id",) + ENTRY_COLUMNS + ("text",), row)
            speeds = []
            for r in c.execute(f"SELECT {', '.join(SPEED_COLUMNS)} FROM speeds WHERE entry_id = ? "
                               "ORDER BY pos", (row[0],)):
                clean, why = clean_row(SPEED_COLUMNS, r)
                reason = reason or why
                speeds.append(SpeedFigures(**dict(zip(SPEED_COLUMNS, clean))))
            tags = []
            for r in c.execute("SELECT tag FROM tags WHERE entry_id = ? ORDER BY tag", (row[0],)):
                clean, why = clean_row(("tag",), r)
                reason = reason or why
                tags.append(clean[0])
            if reason is not None:
                raise LibraryError("entry", f"the design {name!r} in the library is damaged ({reason}); "
                                   "'shaper library check' lists every damaged design", self.path,
                                   damage=reason)
            v = dict(zip(("id",) + ENTRY_COLUMNS + ("text",), values))
            figs = Figures(**{f.name: v[f.name] for f in fields(Figures) if f.name != "speeds"},
                           speeds=tuple(speeds))
            return Entry(name=v["name"], notes=v["notes"], tags=tuple(tags), created=v["created"],
                         modified=v["modified"], text=v["text"], figures=figs,
                         figures_version=v["figures_version"])
        return self._read(work)

    def load(self, name: str) -> dict[str, Any]:
        """The validated design of ``name`` (as ``core.files.io.load_design`` returns it)."""
        return self.get(name).document()

    def query_rows(self, where: str | Sequence[Condition] = "", search: str = "", sort: str = "name",
                   descending: bool = False, rpm: float | None = None, limit: int | None = None,
                   offset: int = 0, notes_chars: int | None = None,
                   documents: bool = False) -> tuple[tuple[str, ...], list[tuple]]:
        """Entries matching the filter (see :mod:`core.library.query`): column keys and rows.

        Per-speed figures are those at ``rpm`` (None where the design lacks that speed),
        or at each design's first speed when ``rpm`` is None. ``tags`` is comma-joined.
        A row whose stored values cannot all be read has those as None and says why in
        ``damaged``. ``limit``/``offset`` give one page of the sorted list (SQLite then keeps only the
        top rows while sorting, which is what makes a page fast). ``notes_chars`` gives only
        the first that many characters of each note (a list to show; :meth:`get` has them all).
        ``documents`` also checks each listed row's name and opens its design document
        (about 1 ms a row), and marks the row ``damaged`` when ``check`` would.
        """
        conditions = parse_filter(where) if isinstance(where, str) else list(where)
        clauses, params = [], []
        if rpm is None:
            join = "LEFT JOIN speeds s ON s.entry_id = e.id AND s.pos = 0"
        else:
            join = "LEFT JOIN speeds s ON s.entry_id = e.id AND s.rpm BETWEEN ? AND ?"
            params += [float(rpm) - 1e-9, float(rpm) + 1e-9]
        for c in conditions:
            sql, values = condition_sql(c)
            clauses.append(sql)
            params += values
        if search.strip():
            sql, values = search_sql(search)
            clauses.append(sql)
            params += values
        where_sql = ("WHERE " + " AND ".join(clauses)) if clauses else ""
        limit_sql = (f"LIMIT {min(int(limit), _MAX_ROWS)} OFFSET {min(max(int(offset), 0), _MAX_ROWS)}"
                     if limit is not None else "")
        sql = f"SELECT {_list_select(notes_chars)} FROM entries e {join} {where_sql} {sort_sql(sort, descending)} {limit_sql}"

        def work(c: sqlite3.Connection) -> list[tuple]:
            rows = c.execute(sql, params).fetchall()
            every = c.text_factory is not str       # texts that are not UTF-8 came as bytes
            out = [row[2:] + (None,) if not (row[0] or every) else _cleaned(row) for row in rows]
            if documents:
                refused = listed_damage(c, [row[1] for row, done in zip(rows, out) if done[-1] is None],
                                           check_document)
                out = [done[:-1] + (refused[row[1]],) if row[1] in refused else done
                       for row, done in zip(rows, out)]
            return out
        return LIST_COLUMNS, self._read(work)

    def query(self, *args: Any, **kwargs: Any) -> list[dict[str, Any]]:
        """:meth:`query_rows` as JSON-ready dicts (``tags`` a list)."""
        keys, rows = self.query_rows(*args, **kwargs)
        out = []
        for row in rows:
            item = dict(zip(keys, row))
            item["tags"] = item["tags"].split(",") if item["tags"] else []
            out.append(item)
        return out

    # ---- writing ----------------------------------------------------------------
    def add(self, name: str, loaded: dict[str, Any], notes: str = "", tags: Iterable[str] = (),
            replace: bool = False) -> Entry:
        """Store a validated design (``load_design``'s dict) under ``name``.

        A name in use is refused (LibraryError('exists')) unless ``replace``, which keeps
        the entry's created time. The figures are computed before the write starts.
        """
        entry = self.make_entry(name, loaded, notes, tags)
        with self._transaction() as c:
            row = c.execute("SELECT id, created FROM entries WHERE name = ?", (entry.name,)).fetchone()
            if row is not None:
                if not replace:
                    raise self._exists(entry.name)
                c.execute("DELETE FROM entries WHERE id = ?", (row[0],))
                entry = Entry(**{**entry.__dict__, "created": row[1]})
            insert_entry(c, entry)
        return entry

    def make_entry(self, name: str, loaded: dict[str, Any], notes: str = "",
                   tags: Iterable[str] = ()) -> Entry:
        """An entry for ``loaded`` stamped now, not yet stored (figures computed here)."""
        now = utc_now()
        figs = figures(loaded["spec"], loaded["rpm"], loaded.get("masses"))
        return Entry(name=check_name(name), notes=check_notes(notes), tags=check_tags(tags), created=now,
                     modified=now, text=document_text(loaded), figures=figs,
                     figures_version=FIGURES_VERSION)

    def add_entries(self, entries: Sequence[Entry]) -> None:
        """Store ready entries in one transaction, all or none (names must be free)."""
        self.replace_entries((), entries)

    def replace_entries(self, remove: Iterable[str], add: Sequence[Entry]) -> None:
        """Delete the entries named ``remove`` and store ``add``, in one transaction.

        Every edit is such a swap of whole entries, so an edit and its undo are both
        one call (LibraryError 'missing'/'exists' if the library changed meanwhile).
        """
        with self._transaction() as c:
            for name in remove:
                if c.execute("DELETE FROM entries WHERE name = ?", (lookup_name(name),)).rowcount == 0:
                    raise LibraryError("missing", f"there is no design named {name!r} in the library",
                                       self.path)
            for entry in add:
                if c.execute("SELECT 1 FROM entries WHERE name = ?", (entry.name,)).fetchone():
                    raise self._exists(entry.name)
                insert_entry(c, entry)

    def restore(self, entry: Entry) -> None:
        """Put back a removed entry exactly as it was (undo of :meth:`remove`)."""
        self.add_entries([entry])

    def remove(self, name: str) -> Entry:
        """Delete ``name``; returns the entry so it can be restored."""
        entry = self.get(name)
        with self._transaction() as c:
            if c.execute("DELETE FROM entries WHERE name = ?", (entry.name,)).rowcount == 0:
                raise LibraryError("missing", f"there is no design named {name!r} in the library",
                                   self.path)
        return entry

    def rename(self, old: str, new: str) -> None:
        old, new = lookup_name(old), check_name(new)
        with self._transaction() as c:
            if new != old and c.execute("SELECT 1 FROM entries WHERE name = ?", (new,)).fetchone():
                raise self._exists(new)
            if c.execute("UPDATE entries SET name = ?, modified = ? WHERE name = ?",
                         (new, utc_now(), old)).rowcount == 0:
                raise LibraryError("missing", f"there is no design named {old!r} in the library",
                                   self.path)

    def duplicate(self, name: str, new: str | None = None) -> str:
        """Copy ``name`` to ``new`` (default: ``name (2)``…); returns the new name."""
        entry = self.get(name)
        new = check_name(new) if new is not None else unique_name(name, self.names())
        now = utc_now()
        self.add_entries([Entry(**{**entry.__dict__, "name": new, "created": now, "modified": now})])
        return new

    def update(self, name: str, notes: str | None = None, tags: Iterable[str] | None = None) -> None:
        """Change the notes and/or tags of ``name`` (its modified time too)."""
        entry = self.get(name)
        changed = Entry(**{**entry.__dict__, "modified": utc_now(),
                           "notes": entry.notes if notes is None else check_notes(notes),
                           "tags": entry.tags if tags is None else check_tags(tags)})
        with self._transaction() as c:
            if c.execute("DELETE FROM entries WHERE name = ?", (entry.name,)).rowcount == 0:
                raise LibraryError("missing", f"there is no design named {name!r} in the library",
                                   self.path)
            insert_entry(c, changed)

    def export(self, name: str, path: str | os.PathLike, step_deg: float | None = None) -> None:
        """Write ``name`` as a design file (atomically), at the crank-angle step ``step_deg``
        (°) when given (:func:`entry.with_step`: an entry stored before the file's sample
        limit); OSError if it cannot be written. The entry in the library stays as it is."""
        entry = self.get(name)
        text = entry.text if step_deg is None else with_step(entry.name, entry.text, step_deg)
        if step_deg is None:
            entry.document()              # never export what could not be opened again
        atomic_write(path, text + "\n")

    def backup(self, target: str | os.PathLike | None = None) -> Path:
        """A consistent copy of the whole library (SQLite's online backup), written by the
        project's safe writer (see :mod:`core.library.backup`); by default beside the library
        as ``NAME.backup-TIME``."""
        target = backup_target(self.path) if target is None else target
        return snapshot_to(self._conn, target, self.path)

    def damaged(self) -> list[tuple[str, str]]:
        """(entry, why) for each entry that cannot be shown or opened, and SQLite's own
        findings (``PRAGMA integrity_check``) as ('file', why): ``shaper library check``."""
        found = [("file", line) for line in self._read(integrity_problems)]
        return found + self._read(lambda c: list(damaged_entries(c, check_document)))

    # ---- figures an older program computed -------------------------------------------
    def stale_names(self) -> list[str]:
        """The entries whose figures an older computation made (below ``FIGURES_VERSION``)."""
        return self._read(lambda c: [r[0] for r in c.execute(
            "SELECT name FROM entries WHERE figures_version < ? ORDER BY name", (FIGURES_VERSION,))])

    def refresh_figures(self, names: Iterable[str] | None = None,
                        progress: Callable[[int, int], None] | None = None) -> RefreshReport:
        """Recompute the figures of ``names`` (default: :meth:`stale_names`) from their
        stored designs and store them as of this ``FIGURES_VERSION``; name, notes, tags,
        times and the document stay as they are.

        The figures are computed outside any transaction, then written in batches of
        ``REFRESH_BATCH`` entries, each one transaction, so a refresh killed midway keeps
        every batch it committed and leaves the rest stale, never half-written. An entry
        another program removed or re-saved meanwhile is skipped (a re-save stores fresh
        figures itself); one whose design can no longer be computed is left as it was
        and reported. ``progress(done, total)`` is called after each entry.
        """
        todo = self.stale_names() if names is None else list(dict.fromkeys(names))
        updated: list[str] = []
        failed: list[tuple[str, str]] = []
        skipped: list[str] = []
        for start in range(0, len(todo), REFRESH_BATCH):
            batch = []
            for i, name in enumerate(todo[start:start + REFRESH_BATCH], start + 1):
                try:
                    entry = self.get(name)
                    doc = entry.document(any_step=True)     # the figures never take the stored step
                    batch.append((entry, figures(doc["spec"], doc["rpm"], doc.get("masses"))))
                except LibraryError as exc:
                    if exc.kind == "entry":               # a damaged entry: reported, left alone
                        failed.append((name, str(exc)))
                    elif exc.kind == "missing":
                        skipped.append(name)
                    else:
                        raise
                except (DesignError, FileFormatError, ArithmeticError, ValueError, RuntimeError) as exc:
                    failed.append((name, str(exc)))
                if progress is not None:
                    progress(i, len(todo))
            with self._transaction() as c:
                for entry, figs in batch:
                    (updated if rewrite_figures(c, entry, figs, FIGURES_VERSION) else skipped).append(entry.name)
        return RefreshReport(tuple(updated), tuple(failed), tuple(skipped))

    # ---- internals ------------------------------------------------------------------
    def _exists(self, name: str) -> LibraryError:
        return LibraryError("exists", f"a design named {name!r} is already in the library", self.path)
