"""The exact schema of a library: every object SQLite keeps in ``sqlite_master``.

A library is a file students pass around, and SQLite runs what its schema holds:
a trigger added by another program (``AFTER INSERT ON entries BEGIN DELETE …``)
would silently delete designs on our next write, a view or an index on an
expression runs code on reads. So a file is used only if its objects are exactly
those the migrations up to its schema version make — each table with the same
columns (types, NOT NULL, defaults, keys), foreign keys and constraints (conflict
clauses, CHECKs, collations: its statement, compared token by token), each index on the
same columns — and nothing else. SQLite's own bookkeeping tables (``sqlite_sequence``,
``sqlite_stat1``…) are allowed; its automatic indexes (``sqlite_autoindex_*``) must
be exactly the ones the constraints make.

Objects are compared by what they mean (SQLite's ``pragma`` functions), not by their
SQL text, so whitespace or comments can never refuse a file the program wrote.
"""
from __future__ import annotations

import re
import sqlite3
from functools import lru_cache
from typing import Callable, Sequence

# tables SQLite itself creates and uses (AUTOINCREMENT counters, ANALYZE statistics)
_SQLITE_TABLES = frozenset({"sqlite_sequence", "sqlite_stat1", "sqlite_stat2", "sqlite_stat3",
                            "sqlite_stat4"})

Objects = dict[tuple[str, str], tuple]


def schema_objects(conn: sqlite3.Connection) -> Objects:
    """Every object of the main database as ``{(type, name): what it means}``."""
    rows = conn.execute("SELECT type, name, tbl_name, sql FROM main.sqlite_master").fetchall()
    out: Objects = {}
    for kind, name, table, sql in rows:
        if kind == "table" and name in _SQLITE_TABLES:
            continue
        meaning = _meaning(conn, str(kind), str(name), str(table))
        if kind in ("table", "index"):          # a partial index's WHERE is in its statement only
            meaning += (sql_tokens(sql if isinstance(sql, str) else None),)
        out[(str(kind), str(name))] = meaning
    return out


# One token of SQL: a comment (dropped), a string or blob literal (kept as written), a quoted
# identifier ("x", [x], `x`: compared unquoted, in lower case), a word or number (lower case),
# or one other character.
_TOKEN = re.compile(r"""--[^\n]*|/\*.*?(?:\*/|\Z)|[xX]?'(?:[^']|'')*'|"(?:[^"]|"")*"|\[[^\]]*\]|`(?:[^`]|``)*`"""
                    r"""|[A-Za-z0-9_$.]+|\S""", re.DOTALL)


def sql_tokens(sql: str | None) -> tuple[str, ...]:
    """The statement ``sql`` as tokens, without its comments, white space, identifier quotes
    and letter case: what it says, not how it is laid out. The pragmas SQLite offers do
    not show a table's conflict clauses (``UNIQUE ON CONFLICT REPLACE``, ``NOT NULL ON
    CONFLICT IGNORE``), CHECK constraints or collations, which change what a write does
    (issue 42: a library with them passed this check); its statement does."""
    out = []
    for token in _TOKEN.findall(sql or ""):
        if token.startswith(("--", "/*")):
            continue
        if token[0] in "\"[`":
            token = token[1:-1].replace(token[0] * 2, token[0]) if token[0] != "[" else token[1:-1]
        out.append(token if token[0] in "'xX" and "'" in token else token.lower())
    return tuple(out)


def _meaning(conn: sqlite3.Connection, kind: str, name: str, table: str) -> tuple:
    if kind == "table":
        return (table,
                tuple(sorted(tuple(r) for r in conn.execute("SELECT name, type, \"notnull\", dflt_value, pk, "
                                                           "hidden FROM pragma_table_xinfo(?)", (name,)))),
                tuple(sorted(tuple(r[2:]) for r in conn.execute("SELECT * FROM pragma_foreign_key_list(?)",
                                                                (name,)))))
    if kind == "index":
        listed = [tuple(r[2:]) for r in conn.execute("SELECT * FROM pragma_index_list(?)", (table,))
                  if r[1] == name]
        return (table, tuple(listed),
                tuple(tuple(r) for r in conn.execute("SELECT * FROM pragma_index_xinfo(?)", (name,))))
    return (table,)            # a view or trigger: none is ours, whatever it does


@lru_cache(maxsize=8)
def expected_objects(steps: tuple[Callable[[sqlite3.Connection], None], ...]) -> Objects:
    """The objects the migration ``steps`` make (those up to a schema version)."""
    conn = sqlite3.connect(":memory:")
    try:
        for step in steps:
            step(conn)
        return schema_objects(conn)
    finally:
        conn.close()


def strange_objects(actual: Objects, expected: Objects) -> list[str]:
    """Each object of ``actual`` that ``expected`` lacks or defines otherwise, described
    in a few words (``a trigger t on entries``); [] when the schema is exactly ours."""
    out = []
    for (kind, name), meaning in actual.items():
        if expected.get((kind, name)) == meaning:
            continue
        where = f" on {meaning[0]}" if kind in ("trigger", "index") else ""
        what = f"changed {kind}" if (kind, name) in expected else kind
        out.append(f"{'an' if what[0] in 'aeiou' else 'a'} {what} {name}{where}")
    return out


def describe(objects: Sequence[str], limit: int = 3) -> str:
    """Up to ``limit`` object descriptions joined, with how many more there are."""
    shown = ", ".join(objects[:limit])
    return shown + (f" and {len(objects) - limit} more" if len(objects) > limit else "")
