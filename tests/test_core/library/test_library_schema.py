"""A library is opened only if its schema is exactly ours (issue 33, item 2).

Another program can add a trigger, a view, an index or a table to a library file; SQLite
would run a trigger on our next write (``AFTER INSERT … DELETE FROM entries`` deleted
every other design while ``add`` said it added one). Such a file is refused, its bytes
unchanged, by every action, and ``library check`` names each object. Every schema the
program itself writes (each version, with SQLite's own automatic indexes and statistics
tables) still opens.
"""
import hashlib
import shutil
import sqlite3

import pytest

from core.library import Library
from core.library import store as library_store
from core.library.store import LibraryError
from core.linkage.spec import Spec

from cli_runner import shaper_in_process
from locations import DATA

DESIGN = ("--crank", "100", "--K", "1.4", "--stroke", "300")

STRANGE = {
    "delete trigger": "CREATE TRIGGER t AFTER INSERT ON entries BEGIN "
                      "DELETE FROM entries WHERE id != NEW.id; END",
    "raising trigger": "CREATE TRIGGER t BEFORE INSERT ON entries BEGIN SELECT RAISE(ABORT, 'no'); END",
    "delete trigger on documents": "CREATE TRIGGER t AFTER INSERT ON documents BEGIN "
                                   "DELETE FROM documents WHERE entry_id != NEW.entry_id; END",
    "view": "CREATE VIEW v AS SELECT name FROM entries",
    "index": "CREATE INDEX extra ON entries(notes)",
    "table": "CREATE TABLE accounts (id INTEGER, owner TEXT)",
}


def make_library(path, names=("a", "b", "c")):
    with Library(path) as lib:
        for name in names:
            lib.add(name, {"spec": Spec(), "rpm": [40.0], "step_deg": 1.0, "masses": None})


def alter(path, *statements):
    conn = sqlite3.connect(path)
    for statement in statements:
        conn.execute(statement)
    conn.commit()
    conn.close()


def digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


def count(path):
    conn = sqlite3.connect(path)
    try:
        return conn.execute("SELECT count(*) FROM entries").fetchone()[0]
    finally:
        conn.close()


@pytest.mark.parametrize("kind", sorted(STRANGE))
def test_a_library_with_an_object_we_never_make_is_refused_unchanged(tmp_path, kind):
    path = tmp_path / "L.sqlite"
    make_library(path)
    alter(path, "PRAGMA journal_mode = DELETE", STRANGE[kind])
    before = digest(path)
    with pytest.raises(LibraryError) as caught:
        Library(path)
    assert caught.value.kind == "foreign" and caught.value.refused_file
    assert caught.value.objects and "unchanged" in str(caught.value)
    status, _, err = shaper_in_process("library", "add", *DESIGN, "--name", "d", "--library", path)
    assert status == 2 and err.count("\n") == 1 and "--library" in err
    status, _, err = shaper_in_process("library", "list", "--library", path)
    assert status == 2 and "--library" in err
    assert digest(path) == before and count(path) == 3
    assert sorted(p.name for p in tmp_path.iterdir()) == ["L.sqlite"]


def test_the_trigger_of_the_issue_deletes_nothing_through_add_or_import(tmp_path):
    path = tmp_path / "L.sqlite"
    make_library(path)
    alter(path, STRANGE["delete trigger"])
    status, _, err = shaper_in_process("library", "add", *DESIGN, "--name", "d", "--library", path)
    assert status == 2 and "trigger t on entries" in err
    design = tmp_path / "x.shaper.json"
    from core.files.io import save_design
    save_design(design, Spec(), [40.0], 1.0)
    status, _, err = shaper_in_process("library", "import", design, "--library", path)
    assert status == 2 and "trigger t" in err
    assert count(path) == 3


def test_check_names_each_strange_object(tmp_path):
    path = tmp_path / "L.sqlite"
    make_library(path)
    alter(path, STRANGE["delete trigger"], STRANGE["view"])
    status, out, _ = shaper_in_process("library", "check", "--library", path)
    assert status == 1
    assert "file: a trigger t on entries is not part" in out and "file: a view v is not part" in out
    assert "no damage found" not in out
    status, out, _ = shaper_in_process("library", "check", "--json", "--library", path)
    assert status == 1 and '"entry": "file"' in out and "trigger t" in out


def test_a_changed_index_of_ours_is_refused(tmp_path):
    path = tmp_path / "L.sqlite"
    make_library(path)
    alter(path, "DROP INDEX tags_by_tag", "CREATE INDEX tags_by_tag ON tags(entry_id)")
    with pytest.raises(LibraryError) as caught:
        Library(path)
    assert caught.value.objects == ("a changed index tags_by_tag on tags",)


def test_a_changed_column_default_is_refused(tmp_path):
    """Same columns by name, another default: the table is not ours (writable_schema
    is how another program would make it)."""
    path = tmp_path / "L.sqlite"
    make_library(path)
    conn = sqlite3.connect(path)
    sql = conn.execute("SELECT sql FROM sqlite_master WHERE name = 'entries'").fetchone()[0]
    conn.execute("PRAGMA writable_schema = ON")
    conn.execute("UPDATE sqlite_master SET sql = ? WHERE name = 'entries'",
                 (sql.replace("notes TEXT NOT NULL DEFAULT ''", "notes TEXT NOT NULL DEFAULT 'x'"),))
    conn.commit()
    conn.close()
    with pytest.raises(LibraryError) as caught:
        Library(path)
    assert caught.value.objects == ("a changed table entries",)


def test_every_schema_the_program_wrote_still_opens(tmp_path):
    """The version-1 fixture, a library made by each prefix of the migrations, and one
    with SQLite's statistics tables (ANALYZE) all open and keep their designs."""
    old = tmp_path / "v1.sqlite"
    shutil.copy(DATA / "library-v1.sqlite", old)
    with Library(old) as lib:
        assert lib.count() > 0
    for version in range(1, library_store.schema_version() + 1):
        path = tmp_path / f"made-v{version}.sqlite"
        conn = sqlite3.connect(path)
        conn.execute(f"PRAGMA application_id = {library_store.APPLICATION_ID}")
        for step in library_store.MIGRATIONS[:version]:
            step(conn)
        conn.execute(f"PRAGMA user_version = {version}")
        conn.commit()
        conn.close()
        with Library(path) as lib:
            assert lib.count() == 0
    stats = tmp_path / "stats.sqlite"
    make_library(stats)
    alter(stats, "ANALYZE")
    with Library(stats) as lib:
        assert lib.count() == 3


def test_connections_do_not_trust_the_schema(tmp_path):
    path = tmp_path / "L.sqlite"
    make_library(path)
    with Library(path) as lib:
        assert lib._conn.execute("PRAGMA trusted_schema").fetchone()[0] == 0


def _rewrite(path, table, old, new):
    """Change the statement SQLite keeps for ``table`` (as another program could, through
    writable_schema), checking the change took."""
    conn = sqlite3.connect(path)
    sql = conn.execute("SELECT sql FROM sqlite_master WHERE name = ?", (table,)).fetchone()[0]
    assert old in sql
    conn.execute("PRAGMA writable_schema = ON")
    conn.execute("UPDATE sqlite_master SET sql = ? WHERE name = ?", (sql.replace(old, new, 1), table))
    conn.commit()
    conn.close()


# Issue 42: constraints the pragmas do not show, which change what a write does
CONSTRAINTS = {
    "unique replace": ("entries", "name TEXT NOT NULL UNIQUE", "name TEXT NOT NULL UNIQUE ON CONFLICT REPLACE"),
    "not null ignore": ("tags", "tag TEXT NOT NULL", "tag TEXT NOT NULL ON CONFLICT IGNORE"),
    "check": ("entries", "K REAL NOT NULL", "K REAL NOT NULL CHECK (K < 1.5)"),
    "collation": ("entries", "name TEXT NOT NULL UNIQUE", "name TEXT NOT NULL UNIQUE COLLATE NOCASE"),
    "primary key replace": ("tags", "PRIMARY KEY (entry_id, tag)", "PRIMARY KEY (entry_id, tag) ON CONFLICT REPLACE"),
}


@pytest.mark.parametrize("case", sorted(CONSTRAINTS))
def test_a_changed_constraint_is_refused_and_named_by_check(tmp_path, case):
    """A library with 'entries.name UNIQUE ON CONFLICT REPLACE' or 'tags.tag NOT NULL ON
    CONFLICT IGNORE' passed the exact-schema check, and 'check' found nothing."""
    path = tmp_path / "L.sqlite"
    make_library(path)
    table, old, new = CONSTRAINTS[case]
    _rewrite(path, table, old, new)
    before = digest(path)
    with pytest.raises(LibraryError) as caught:
        Library(path)
    # a collation changes the constraint's automatic index too, which is named as well
    assert caught.value.objects[0] == f"a changed table {table}"
    assert set(caught.value.objects[1:]) <= {f"a changed index sqlite_autoindex_{table}_1 on {table}"}
    status, out, _ = shaper_in_process("library", "check", "--library", path)
    assert status == 1 and f"a changed table {table}" in out
    assert digest(path) == before


def test_layout_comments_and_quotes_of_a_statement_do_not_refuse_it(tmp_path):
    """What the statement says is compared, not how it is written."""
    path = tmp_path / "L.sqlite"
    make_library(path)
    _rewrite(path, "tags", "tag TEXT NOT NULL,", '"tag"   text /* the tag */ not NULL, -- one tag\n')
    with Library(path) as lib:
        assert lib.count() == 3
