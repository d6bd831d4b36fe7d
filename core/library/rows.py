"""Library rows read with their types checked, so no stored value can break a reader.

SQLite keeps whatever a column is given: a blob or a word in a REAL column, a
``1e999`` (infinity), text that is not UTF-8. Such a value, written by another
program or left by a damaged disk, once reached the CLI's number formatting
("internal error") and the GUI's table (a crash). Every row read from a library
goes through :func:`clean_row`: a value of the wrong type becomes ``None`` and
the row is marked damaged with the reason; a non-finite number becomes ``None``
(undefined) too. The other rows stay usable. ``shaper library check`` lists the
damaged ones (:func:`damaged_entries`).
"""
from __future__ import annotations

import math
import sqlite3
from functools import lru_cache
from typing import Any, Callable, Iterable, Iterator, Sequence, TypeVar

from core.space.figures import DESIGN_KEYS, SPEED_KEYS
from core.base.text import CONTROL

from .entry import too_fine

T = TypeVar("T")

# what each column must hold: "text", "number" or "integer"; "?" after it: may be NULL
KINDS: dict[str, str] = {
    "id": "integer", "name": "text", "notes": "text", "tags": "text", "created": "text",
    "modified": "text", "variant": "text", "rod_side": "text?", "figures_version": "integer",
    "text": "text", "rpm": "number", "pos": "integer", "tag": "text",
    **{key: "number" for key in DESIGN_KEYS}, **{key: "number" for key in SPEED_KEYS},
}
KINDS.update(rod_mm="number?", pressure_angle_max_deg="number?", mean_torque_N_m="number?",
             max_torque_N_m="number?", flywheel_inertia_kg_m2="number?")


# Why a stored row cannot be read: core's English sentence per kind ({key} the column,
# {table} the child table, {cause} the refusal). A front end keys its own sentences on
# the kind (shaperapp/widgets/messages.py), so it never parses this text.
DAMAGE_TEXTS = {
    "empty": "{key} is empty",
    "not_text": "{key} is not text",
    "not_integer": "{key} is not a whole number",
    "not_number": "{key} is not a number",
    "not_finite": "{key} is not a finite number",
    "no_document": "there is no design document",
    "document_not_utf8": "the design document is not UTF-8 text",
    "document_refused": "its design document cannot be opened ({cause})",
    "too_fine": "too fine: {cause.samples} samples, limit {cause.limit}; 'shaper library export' "
                "with --step {cause.coarsest:g} writes it at a step a design file holds",
    "not_one_line": "{key} is not one line of text (it holds a control character or a noncharacter)",
}


class Damage(str):
    """Why an entry's row cannot be read: its English sentence (so every caller that
    prints or formats it keeps working), with the ``kind`` (a key of ``DAMAGE_TEXTS``),
    the column ``key``, the child ``table`` (speeds, tags; "" for the entry itself) and
    the refusal ``cause`` kept, for a front end that says it in another language."""
    kind: str
    key: str
    table: str
    cause: Exception | None

    def __new__(cls, kind: str, key: str = "", table: str = "", cause: Exception | None = None) -> "Damage":
        text = DAMAGE_TEXTS[kind].format(key=key, cause=cause)
        self = super().__new__(cls, f"{table}: {text}" if table else text)
        self.kind, self.key, self.table, self.cause = kind, key, table, cause
        return self

    def __reduce__(self):                       # pickles (the forked workers) as itself
        return Damage, (self.kind, self.key, self.table, self.cause)

    def in_table(self, table: str) -> "Damage":
        """The same damage, found in the child table ``table``."""
        return Damage(self.kind, self.key, table, self.cause)


def _problem(key: str, value: Any, nullable: bool) -> Damage | None:
    """Why ``value`` cannot be column ``key``'s value, or None if it can."""
    kind = KINDS.get(key, "text?").rstrip("?")
    if value is None:
        return None if nullable or KINDS.get(key, "?").endswith("?") else (
            Damage("no_document") if key == "text" else Damage("empty", key))
    if kind == "text":
        return None if isinstance(value, str) else (
            Damage("document_not_utf8") if key == "text" else Damage("not_text", key))
    if kind == "integer":
        return None if type(value) is int else Damage("not_integer", key)
    if type(value) not in (float, int):
        return Damage("not_number", key)
    return None if math.isfinite(value) else Damage("not_finite", key)


@lru_cache(maxsize=32)
def _fast_types(keys: tuple[str, ...]) -> tuple[tuple[type, ...], ...]:
    """Per column, the Python types that are certainly fine (a float still if finite)."""
    kinds = [KINDS.get(key, "text?").rstrip("?") for key in keys]
    return tuple((str,) if k == "text" else (int,) if k == "integer" else (float, int) for k in kinds)


def clean_row(keys: Sequence[str], row: Sequence[Any],
              nullable: frozenset[str] = frozenset()) -> tuple[list[Any], Damage | None]:
    """``row`` with every unusable value replaced by None, and the first reason (None: sound).

    Columns in ``nullable`` may be empty here whatever their kind (a speed's
    figures in a list where the design lacks that speed).
    """
    values = list(row)
    reason = None
    for i, (key, value, fast) in enumerate(zip(keys, values, _fast_types(tuple(keys)))):
        if type(value) in fast and (type(value) is not float or value - value == 0.0):
            continue                              # the common case, checked fast
        why = _problem(key, value, key in nullable)
        if why is None:
            continue
        values[i] = None
        if reason is None:
            reason = why
    return values, reason


_LARGEST = "1.7976931348623157e308"     # the largest finite double; inf lies beyond it


def unfit_sql(columns: Iterable[tuple[str, str]], nullable: frozenset[str] = frozenset()) -> str:
    """An SQL expression that is 1 where a value of ``columns`` ((SQL expression, key)
    pairs) has the wrong type for its key or is not finite, else 0. Checked by SQLite in
    C, so sound rows cost nothing in Python; a flagged row then goes through
    :func:`clean_row` for the reason. (Text that is not UTF-8 passes this flag: SQLite
    does not decode it; :func:`read_lenient` finds it.)"""
    tests = []
    for expr, key in columns:
        kind = KINDS.get(key, "text?")
        empty = "1" if kind.endswith("?") or key in nullable else "0"     # what NULL counts as
        kind = kind.rstrip("?")
        # SQLite orders NULL < numbers < text < blob, so a range test says the type too,
        # and costs less than typeof(); NULL gives NULL, which coalesce turns into ``empty``.
        if kind == "text":
            fits = f"{expr} >= '' AND {expr} < X''"
        elif kind == "integer":
            fits = f"typeof({expr}) = 'integer'"
        else:
            fits = f"{expr} BETWEEN -{_LARGEST} AND {_LARGEST}"
        tests.append(f"NOT coalesce({fits}, {empty})")
    return "(" + " OR ".join(tests) + ")"


def _lenient_text(raw: bytes) -> str | bytes:
    """SQLite text as str, or the raw bytes where it is not UTF-8 (then the column's check
    reports it as not text) instead of an exception for the whole query."""
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw


def read_lenient(conn: sqlite3.Connection, work: Callable[[sqlite3.Connection], T]) -> T:
    """``work(conn)``; if a stored text is not UTF-8, again with such texts read as bytes."""
    try:
        return work(conn)
    except sqlite3.OperationalError as exc:
        if "decode" not in str(exc).lower():
            raise
    previous = conn.text_factory
    conn.text_factory = _lenient_text
    try:
        return work(conn)
    finally:
        conn.text_factory = previous


def entry_label(entry_id: Any, name: Any) -> str:
    """How a (possibly damaged) entry is named in a message."""
    return repr(name) if isinstance(name, str) else f"entry #{entry_id} (its name is unreadable)"


_ENTRY_SQL = ("SELECT e.*, d.text FROM entries e LEFT JOIN documents d ON d.entry_id = e.id "
              "ORDER BY e.id")


def damaged_entries(conn: sqlite3.Connection, check_document: Callable[[str, str], None]) -> Iterator[tuple[str, str]]:
    """(entry, why) for every entry that cannot be shown or opened: a value of the wrong
    type in it, its speeds or tags, no document, or a document ``check_document(name,
    text)`` refuses (it raises with the reason)."""
    def work(c: sqlite3.Connection) -> list[tuple[str, str]]:
        out = []
        bad_speeds = _bad_children(c, "speeds", ("rpm",) + SPEED_KEYS)
        bad_tags = _bad_children(c, "tags", ("tag",))
        cursor = c.execute(_ENTRY_SQL)
        keys = [d[0] for d in cursor.description]
        for row in cursor:
            values, reason = clean_row(keys, row)
            entry_id = row[0]
            label = entry_label(entry_id, row[keys.index("name")])
            reason = reason or bad_speeds.get(entry_id) or bad_tags.get(entry_id)
            reason = (reason or name_damage(values[keys.index("name")])
                      or document_damage(values[keys.index("name")], values[-1], check_document))
            if reason is not None:
                out.append((label, reason))
        return out
    return iter(read_lenient(conn, work))


def name_damage(name: str) -> Damage | None:
    """Why ``name`` (a sound text) is no name an entry may have: a line break, ESC or
    another control character (printed, it broke ``list``'s table and drove the terminal;
    ``check_name`` refuses them, another program may have written one), or None."""
    return Damage("not_one_line", "name") if CONTROL.search(name) else None


def document_damage(name: str, text: str, check_document: Callable[[str, str], None]) -> Damage | None:
    """Why the stored design document ``text`` of ``name`` cannot be opened
    (``check_document`` refuses it), or None."""
    try:
        check_document(name, text)
    except Exception as exc:          # noqa: BLE001 — any refusal is the reason
        fine = too_fine(exc)          # whole, but stored before the sample limit
        return Damage("document_refused", cause=exc) if fine is None else Damage("too_fine", cause=fine)
    return None


def listed_damage(conn: sqlite3.Connection, ids: Sequence[Any],
                     check_document: Callable[[str, str], None], chunk: int = 500) -> dict[Any, Damage]:
    """Entry id → why the entry cannot be shown or opened, for the entries ``ids`` whose
    stored values have the right types: a name that is not one line, or a design
    document that cannot be opened. What ``library list`` marks "(damaged)" beside the type
    checks SQLite makes (issue 42: a list showed such an entry as healthy)."""
    out: dict[Any, Damage] = {}
    for start in range(0, len(ids), chunk):
        part = list(ids[start:start + chunk])
        for entry_id, name, text in conn.execute(
                "SELECT e.id, e.name, d.text FROM entries e LEFT JOIN documents d ON d.entry_id = e.id "
                f"WHERE e.id IN ({', '.join('?' * len(part))})", part):
            why = (name_damage(name) or _problem("text", text, False)
                   or document_damage(name, text, check_document))
            if why is not None:
                out[entry_id] = why
    return out


def _bad_children(c: sqlite3.Connection, table: str, keys: Sequence[str]) -> dict[Any, str]:
    """Entry id → the first problem among its rows in ``table``."""
    out: dict[Any, str] = {}
    for row in c.execute(f"SELECT entry_id, {', '.join(keys)} FROM {table}"):
        _, reason = clean_row(keys, row[1:])
        if reason is not None and row[0] not in out:
            out[row[0]] = reason.in_table(table)
    return out
