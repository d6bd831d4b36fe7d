"""Issue 42, items 1, 5 and 6: text nobody can print (Unicode's noncharacters, control
characters and escape sequences) is refused where a user types it and escaped or replaced
where a file brings it; an entry whose document cannot be opened looks damaged everywhere."""
import sqlite3
import xml.dom.minidom

import pytest

# What the commands write or refuse, in this process (a drawing's or report's process
# costs ~2.5 s of CPU to start); test_cli.py runs the real command.
from cli_runner import shaper_in_process, shaper_run_in_process as shaper

DESIGN = ("--crank", 100, "--K", 1.4, "--stroke", 300, "--rpm", 40)
# every noncharacter, from Unicode's own definition (chapter 23.7): U+FDD0..U+FDEF and the last
# two code points of each of the 17 planes, built independently of core.base.text's table
EVERY_NONCHARACTER = [chr(c) for c in range(0xFDD0, 0xFDF0)] + \
    [chr(c) for c in range(0x110000) if c & 0xFFFE == 0xFFFE]


def test_the_noncharacters_are_the_66_unicode_defines():
    from core.base.text import CONTROL, NONCHARACTERS, UNPRINTABLE
    assert len(EVERY_NONCHARACTER) == 66
    assert all(CONTROL.search(c) and UNPRINTABLE.search(c) for c in EVERY_NONCHARACTER)
    near = ["\ufdcf", "\ufdf0", "\ufffd", "\U0001fffd", "\U00010000", "中", "é"]
    assert not any(CONTROL.search(c) for c in near)
    assert len(set(NONCHARACTERS) - set("-")) == 66 - 32 + 2          # ranges written as a-b


def test_terminal_text_escapes_what_would_drive_a_terminal():
    from core.base.text import terminal_text
    text = "a\x1b]0;pwned\x07\x1b[2J\nb\r\uffff\x9b"
    shown = terminal_text(text)
    assert not any(ord(c) < 32 or 0x7f <= ord(c) <= 0x9f for c in shown)
    assert shown == r"a\x1b]0;pwned\x07\x1b[2J\nb\r\uffff\x9b"
    assert terminal_text("one\ntwo\tthree\r\n", multi_line=True) == "one\ntwo\tthree\r\n"


@pytest.mark.parametrize("char", ["\uffff", "\ufffe", "\ufdd0", "\U0010ffff"])
def test_a_drawing_title_with_a_noncharacter_is_refused(tmp_path, char):
    """Issue 42: --title $'x\\uffffy' exited 0 with an SVG no XML parser reads."""
    run = shaper("drawing", *DESIGN, "--sheet", "A3", "-o", tmp_path / "a.svg", "--title", f"x{char}y")
    assert run.returncode == 2 and run.stderr.strip().count("\n") == 0
    assert run.stderr.startswith("shaper: error: --title:") and "noncharacter" in run.stderr
    assert not (tmp_path / "a.svg").exists()


def test_a_design_file_named_with_a_noncharacter_draws_a_readable_svg(tmp_path):
    """Issue 42: a design file named n\\uffff.shaper.json gave an unreadable gear sheet."""
    import json
    from hostile_files import VALID
    path = tmp_path / "n\uffff.shaper.json"
    path.write_text(json.dumps(dict(VALID, gear={"z1": 13, "z2": 52, "module_mm": 4})), encoding="utf-8")
    run = shaper("drawing", "--design", path, "--content", "gear", "--sheet", "A3", "-o", tmp_path / "g.svg")
    assert run.returncode == 0, run.stderr
    text = (tmp_path / "g.svg").read_text(encoding="utf-8")
    xml.dom.minidom.parseString(text.encode("utf-8"))                 # well-formed
    assert "\uffff" not in text and "n\ufffd" in text                 # the name, replaced


def _library(tmp_path, *names):
    lib = tmp_path / "lib.sqlite"
    for name in names:
        assert shaper_in_process("library", "add", *DESIGN, "--name", name, "--library", lib)[0] == 0
    return lib


def _set(lib, sql, *params):
    with sqlite3.connect(lib) as c:
        c.execute(sql, params)
    c.close()


@pytest.mark.parametrize("option", ["--name", "--tags"])
def test_library_refuses_a_noncharacter_in_a_name_or_tag(tmp_path, option):
    lib = tmp_path / "lib.sqlite"
    extra = ("--name", "ok") if option == "--tags" else ()
    status, _, err = shaper_in_process("library", "add", *DESIGN, *extra, option, "x\uffff", "--library", lib)
    assert status == 2 and err.startswith(f"shaper: error: {option}") and err.count("\n") == 1


def test_report_compares_with_an_entry_whose_stored_name_holds_a_noncharacter(tmp_path):
    """Issue 42: an entry named x\\uffff made 'report --compare' fail with an internal error
    (ZeroDivisionError in the figure fitting: the comparison's SVG could not be read)."""
    lib = _library(tmp_path, "x")
    _set(lib, "UPDATE entries SET name = ?", "x\uffff")            # as an older version stored it
    run = shaper("report", "--crank", 100, "--K", 1.5, "--stroke", 300, "--rpm", 40,
                 "--compare", "x\uffff", "--library", lib, "-o", tmp_path / "r.pdf")
    assert run.returncode == 0, run.stderr
    assert (tmp_path / "r.pdf").stat().st_size > 0


@pytest.mark.parametrize("notes", ["\x1b]0;pwned\x07\x1b[2J", "a\x00b", "bell\x07", "lone\rCR", "x\uffff",
                                   "next\x85line", "sep\u2028"])
def test_notes_refuse_control_characters(tmp_path, notes):
    lib = tmp_path / "lib.sqlite"
    status, _, err = shaper_in_process("library", "add", *DESIGN, "--name", "a", "--notes", notes, "--library", lib)
    assert status == 2 and err.startswith("shaper: error: --notes:") and err.count("\n") == 1
    assert not lib.exists() or shaper_in_process("library", "list", "--json", "--library", lib)[1].strip() == "[]"


def test_notes_keep_line_breaks_and_tabs(tmp_path):
    lib = tmp_path / "lib.sqlite"
    notes = "first line\nsecond\tcolumn\r\nthird"
    assert shaper_in_process("library", "add", *DESIGN, "--name", "a", "--notes", notes, "--library", lib)[0] == 0
    status, out, _ = shaper_in_process("library", "show", "a", "--library", lib)
    assert status == 0 and "first line\nsecond\tcolumn\r\nthird" in out


def test_printers_escape_what_a_library_file_brings(tmp_path):
    """Issue 42: a note holding ESC sequences was printed raw by 'show' (the terminal's title
    changed, the screen cleared); names with LF, CR or ESC broke 'list''s table and 'check'
    said "no damage found"."""
    lib = _library(tmp_path, "plain", "noted", "evil")
    _set(lib, "UPDATE entries SET notes = ? WHERE name = 'noted'", "\x1b]0;pwned\x07\x1b[2J")
    _set(lib, "UPDATE entries SET name = ? WHERE name = 'evil'", "e\x1b[2Jv\ni\rl")
    status, out, _ = shaper_in_process("library", "show", "noted", "--library", lib)
    assert status == 0 and "\x1b" not in out and "\x07" not in out and r"\x1b]0;pwned\x07" in out
    status, out, err = shaper_in_process("library", "list", "--library", lib)
    lines = out.splitlines()
    assert status == 0 and "\x1b" not in out and "\r" not in out and len(lines) == 4      # header + 3 rows
    assert any(line.startswith(r"e\x1b[2Jv\ni\rl (damaged)") for line in lines)
    assert "1 of the 3 designs listed is damaged" in err
    status, out, _ = shaper_in_process("library", "check", "--library", lib)
    assert status == 1 and "\x1b" not in out and "1 of 3 designs" in out and "not one line" in out


def test_an_entry_whose_document_cannot_be_opened_looks_damaged(tmp_path):
    """Issue 42: 'check' reported such an entry and 'compare'/'export' refused it, but 'list'
    showed it without "(damaged)" and 'show' printed it with exit 0 (against docs/cli.md)."""
    lib = _library(tmp_path, "good", "bad")
    _set(lib, "UPDATE documents SET text = ? WHERE entry_id = (SELECT id FROM entries WHERE name = 'bad')",
         '{"format": "shaper-design", "version": 1, "spec": {"mode": "synthesis", "crank": 100, '
         '"time_ratio": 0.5, "stroke": 300}}')
    status, out, _ = shaper_in_process("library", "list", "--library", lib)
    assert status == 0 and any(line.startswith("bad (damaged)") for line in out.splitlines())
    assert not any(line.startswith("good (damaged)") for line in out.splitlines())
    import json
    rows = {r["name"]: r["damaged"] for r in json.loads(shaper_in_process("library", "list", "--json",
                                                                          "--library", lib)[1])}
    assert rows["good"] is None and "design document cannot be opened" in rows["bad"]
    status, out, err = shaper_in_process("library", "show", "bad", "--library", lib)
    assert status == 2 and out == "" and err.startswith("shaper: error: NAME:") and err.count("\n") == 1
    assert shaper_in_process("library", "show", "good", "--library", lib)[0] == 0


def _pieces(cell: str) -> list[str]:
    """A cell as a spreadsheet that splits on ; , | or tab reads it (spaces trimmed)."""
    import re
    return [p.strip(" ") for p in re.split(r"[;,|\t]", cell)]


def test_every_csv_cell_of_user_text_is_guarded_as_a_whole_and_per_name(tmp_path):
    """Issue 42: two tied designs made the "best" cell 'a;=cmd|' /C calc'!A0' with only the
    first name guarded; a name holding ';=' was unguarded in the header and the curves."""
    import csv
    lib = _library(tmp_path, "a", "=cmd|' /C calc'!A0")       # one design twice: they tie
    assert shaper_in_process("library", "add", "--crank", 100, "--K", 1.6, "--stroke", 300, "--rpm", 40,
                             "--name", "b;=cmd|' /C calc'!A0", "--library", lib)[0] == 0
    names = ("a", "=cmd|' /C calc'!A0", "b;=cmd|' /C calc'!A0")
    status, _, err = shaper_in_process("library", "compare", *names, "--rpm", 40, "--csv", tmp_path / "t.csv",
                                       "--curves-csv", tmp_path / "c.csv", "--library", lib)
    assert status == 0, err
    table = list(csv.reader((tmp_path / "t.csv").open(encoding="utf-8")))
    curves = list(csv.reader((tmp_path / "c.csv").open(encoding="utf-8")))
    best = [row[-1] for row in table[2:] if row[-1]]
    assert best and all(cell.startswith("a;") for cell in best)     # a and its twin are best
    text_cells = table[0] + best + [row[0] for row in curves[1:]]
    assert any("=cmd" in cell for cell in best) and any("=cmd" in row[0] for row in curves[1:])
    for cell in text_cells:
        for piece in _pieces(cell):
            assert not piece.startswith(("=", "+", "-", "@")), (cell, piece)


# Unicode's explicit bidirectional embeddings, overrides and isolates (UAX #9, table 2), listed
# independently of core.base.text: LRE RLE PDF LRO RLO, LRI RLI FSI PDI.
BIDI_CONTROLS = ["\u202a", "\u202b", "\u202c", "\u202d", "\u202e", "\u2066", "\u2067", "\u2068", "\u2069"]


@pytest.mark.parametrize("char", BIDI_CONTROLS, ids=[f"U+{ord(c):04X}" for c in BIDI_CONTROLS])
def test_a_bidi_override_is_refused_where_a_control_character_is(tmp_path, char):
    """A student 'a<RLO>fdp.exe' got the folder 1-a<RLO>fdp.exe, which a file manager shows as
    '1-aexe.pdf', and the same reversed text on the task sheet and in the terminal (hunt,
    1 December): every text option, a class row's name and a library name refuse the nine
    bidi controls as they refuse a control character; the implicit marks LRM/RLM and
    Arabic or Hebrew letters stay accepted."""
    from core.base.text import CONTROL, NOTE_FORBIDDEN, UNPRINTABLE
    from core.cli.tasks import read_tasks
    assert CONTROL.search(char) and UNPRINTABLE.search(char) and NOTE_FORBIDDEN.search(char)
    assert not any(CONTROL.search(c) or UNPRINTABLE.search(c) for c in "\u200e\u200fعبرית\u200b\u2065\u206a")
    table = tmp_path / "t.csv"
    table.write_text(f"student,student-number\na{char}fdp.exe,1\nمحمد\u200f,2\n", encoding="utf-8")
    students = read_tasks(str(table), None)[0]
    assert students[0].error == "t.csv line 2, column student: must be one line of text without control characters"
    assert "control" not in students[1].error
    status, _, err = shaper_in_process("library", "add", *DESIGN, "--name", f"x{char}y",
                                       "--library", tmp_path / "lib.sqlite")
    assert status == 2 and err.startswith("shaper: error: --name:") and err.count("\n") == 1
