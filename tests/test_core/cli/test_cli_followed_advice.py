"""Each refusal of `shaper class` and `shaper library` that tells the user what to do is
followed literally here, and then the command (or the table) is accepted (hunt of
1 December). The gear's and the course's advice are followed in their own tests
(test_gear_amounts, test_gear_edges, test_gear_apart; test_cli_tasks' "lacks" row)."""
from __future__ import annotations

import re
import shlex

import pytest

from cli_runner import shaper_in_process
from core.cli.tasks import TableError, read_tasks
from locations import DATA

from test_cli_tasks import base  # noqa: F401  (the module-scoped base design file, a fixture)


def refused(path, base) -> str:
    with pytest.raises(TableError) as info:
        read_tasks(str(path), base)
    return str(info.value)


def accepted(path, base) -> list:
    students, _ = read_tasks(str(path), base)
    assert students and all(s.error == "" for s in students), [s.error for s in students]
    return students


def test_save_it_as_csv_utf8(tmp_path, base):
    table = tmp_path / "t.csv"
    text = "student,student-number\nJosé Müller,2021001\n"
    table.write_bytes(text.encode("latin-1"))
    assert refused(table, base).endswith('not UTF-8 or GBK text; save it as "CSV UTF-8"')
    table.write_bytes(text.encode("utf-8"))                 # what Excel's "CSV UTF-8" writes, less its BOM
    assert accepted(table, base)[0].name == "José Müller"


def test_did_you_mean_the_column(tmp_path, base):
    table = tmp_path / "t.csv"
    table.write_text("student,student-numbr,crank\nA,1,100\n", encoding="utf-8")
    meant = re.search(r"did you mean (\S+)\?$", refused(table, base)).group(1)
    table.write_text(f"student,{meant},crank\nA,1,100\n", encoding="utf-8")
    assert accepted(table, base)[0].number == "1"


def test_format_the_column_as_text(tmp_path, base):
    table = tmp_path / "t.csv"
    table.write_text("student,student-number\nA,2.02301E+11\n", encoding="utf-8")
    students, _ = read_tasks(str(table), base)
    assert students[0].error.endswith("format the column as text and save the table again")
    table.write_text("student,student-number\nA,202301000123\n", encoding="utf-8")   # the column as text: its digits
    assert accepted(table, base)[0].number == "202301000123"


def test_put_the_design_file_beside_the_table(tmp_path, base):
    folder = tmp_path / "class"
    folder.mkdir()
    table = folder / "t.csv"
    table.write_text(f"student,student-number,design\nA,1,{base}\n", encoding="utf-8")
    students, _ = read_tasks(str(table), None)
    assert students[0].error.endswith("is outside the table's folder; put the design file beside the table")
    (folder / "mine.shaper.json").write_bytes(open(base, "rb").read())
    table.write_text("student,student-number,design\nA,1,mine.shaper.json\n", encoding="utf-8")
    assert accepted(table, None)[0].document["gear"]["z1"] == 13


def test_give_one_of_them_a_number_that_differs(tmp_path, base):
    table = tmp_path / "t.csv"
    table.write_text("student,student-number\nA,s1\nA,S1\n", encoding="utf-8")
    assert "give one of them a number that differs in more than letter case" in refused(table, base)
    table.write_text("student,student-number\nA,s1\nA,S2\n", encoding="utf-8")
    assert len(accepted(table, base)) == 2


def test_or_use_rename_duplicates(tmp_path):
    library = tmp_path / "lib.sqlite"
    design = tmp_path / "K1.shaper.json"
    design.write_bytes((DATA / "my.shaper.json").read_bytes())
    assert shaper_in_process("library", "import", design, "--library", library)[0] == 0
    status, _, err = shaper_in_process("library", "import", design, "--library", library)
    assert status == 2 and err.rstrip().endswith("(or use --rename-duplicates)"), err
    status, text, err = shaper_in_process("library", "import", design, "--library", library, "--rename-duplicates")
    assert status == 0 and "K1 (2)" in text, err


def test_keep_a_copy_with_the_printed_command_even_for_a_path_with_a_quote(tmp_path, monkeypatch):
    """The backup command printed for a damaged library is typed as printed: for a path
    holding ', it was put in quotes unescaped (`--library 'Zhang's lib.sqlite'`), which a
    shell reads as an unclosed quote."""
    monkeypatch.chdir(tmp_path)
    damaged = tmp_path / "Zhang's lib.sqlite"
    damaged.write_bytes(b"SQLite format 3\x00" + b"\x07" * 2000)
    status, _, err = shaper_in_process("library", "list", "--library", damaged.name)
    assert status == 2, err
    words = shlex.split(err.split("keep a copy with: ", 1)[1])           # as a shell splits it
    assert words[:3] == ["shaper", "library", "backup"]
    status, text, err = shaper_in_process(*words[1:])
    assert status == 0, err
    copy = tmp_path / text.split(" to ", 1)[1].strip()
    assert copy.read_bytes() == damaged.read_bytes()


def test_close_the_quote(tmp_path, base):
    """A quote that opens a cell and is never closed took the rest of the table as that cell:
    the row was refused as 'column student-number: empty', the rows after it were lost
    (hunt, 1 December). The table is refused naming the line the quote opens on; closed,
    or doubled as the text's own quote, it is read whole."""
    table = tmp_path / "t.csv"
    table.write_text('student,student-number\nA,1\n"B,2\nC,3\n', encoding="utf-8")
    assert refused(table, base) == ("t.csv line 3: a quote opens a cell that no quote closes before the table "
                                    "ends; close it, or write a quote that belongs to the text twice")
    table.write_text('student,student-number\nA,1\n"B",2\nC,3\n', encoding="utf-8")
    assert [s.name for s in accepted(table, base)] == ["A", "B", "C"]
    table.write_text('student,student-number\nA,1\n"""B",2\nC,3\n', encoding="utf-8")
    assert [s.name for s in accepted(table, base)] == ["A", '"B', "C"]
