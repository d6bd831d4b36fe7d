"""A class's task table (``shaper class --tasks TASKS.csv``, issue 41): one row per student,
read as a spreadsheet saves it and turned into each student's design file.

A column is a design option named as the command line names it without its dashes
(``crank``, ``K``, ``rod-ratio``, ``lever-mass``, ``z1`` …; an option's dest, such as
``time_ratio``, is taken too), found in ``shaper design``'s own parser: each row is parsed
by that parser and checked by :func:`core.cli.cmd_design.document_from_args`, the code of
every subcommand, so an option added there is a column here without a change. Besides
them: ``student`` and ``student-number`` (required), ``class`` and ``design`` (a design file
beside the table that the row's options change, instead of ``--base``).

Everything about the table as a whole (its encoding, header, size, two students with one
number or one folder) is a :class:`TableError` found before anything is written; a bad row
is a :class:`Student` with its ``error``: one line naming its line and column.
"""
from __future__ import annotations

import argparse
import csv
import io
import os
import re
import stat
import unicodedata
from dataclasses import dataclass
from typing import Any

from core.base.errors import DesignError, FileFormatError
from core.base.text import UNPRINTABLE
from .common import Parser, UsageError, design_error_text, one_line

MAX_TABLE_BYTES = 5_000_000
MAX_STUDENTS = 1000
"""A class of more is refused whole, before any row is read (500 take about 9 minutes on 2
cores: 40 students of 方案 I's data, A3, in 41 s with 2 workers at a load of 3, 1 December)."""
MAX_TEXT = 200
NAME_COLUMNS = {"student": "student", "student-number": "number", "student_number": "number",
                "class": "group", "design": "design"}
# A Chinese teacher's headings of the name columns, answered with the column's name (the
# table's columns are the command line's words; 学号 was "not a column", with no hint).
CHINESE_NAMES = {"学生": "student", "姓名": "student", "学号": "student-number", "班级": "class"}
TRUE_WORDS, FALSE_WORDS = {"1", "true", "yes", "y", "x", "是"}, {"0", "false", "no", "n", "否"}
# what a file name may not hold on Windows, macOS or Linux (each becomes "_")
_UNSAFE = re.compile(r'[<>:"/\\|?*\x00-\x1f\x7f]|\.\.+')
_RESERVED = {"CON", "PRN", "AUX", "NUL", *(f"COM{i}" for i in range(1, 10)), *(f"LPT{i}" for i in range(1, 10))}
MAX_FOLDER_BYTES = 120
# A student number as Excel writes a long number it holds as a number ("2.02301E+11"): the
# digits are gone, and every printout, the folder and the answer key would carry it so.
_SHORTENED = re.compile(r"[0-9](?:\.[0-9]+)?E\+[0-9]+", re.I)


class TableError(ValueError):
    """The table cannot be used at all; nothing is written. The message names the file and,
    where there is one, the line and column."""


@dataclass(frozen=True)
class Student:
    line: int                 # the row's first line in the file (the header is line 1)
    name: str
    number: str
    group: str
    folder: str               # the folder's name under DIR
    document: dict[str, Any] | None   # the design file's document; None with an error
    error: str = ""           # "tasks.csv line 7, column K: must be > 1 (got 0.9)"


def design_parser() -> argparse.ArgumentParser:
    """The parser a row is read with: ``shaper design``'s, without its -o."""
    from .cmd_design import configure
    parser = Parser(prog="shaper class", add_help=False)
    configure(parser, output=False)
    return parser


def column_actions(parser: argparse.ArgumentParser) -> dict[str, argparse.Action]:
    """Column name → the option: each long option without its dashes, and its dest."""
    names: dict[str, argparse.Action] = {}
    for action in parser._actions:
        for flag in action.option_strings:
            if flag.startswith("--"):
                names[flag[2:]] = action
        if action.option_strings:
            names.setdefault(action.dest, action)
    return names


def decode(raw: bytes, name: str) -> tuple[str, str]:
    """The table's text and its encoding: UTF-8 (with or without a BOM), else GBK, which a
    Chinese Excel saves "CSV" in; anything else is refused by name."""
    try:
        return raw.decode("utf-8-sig"), "UTF-8"
    except UnicodeDecodeError:
        pass
    try:
        return raw.decode("gbk"), "GBK"
    except UnicodeDecodeError:
        raise TableError(f"{name}: not UTF-8 or GBK text; save it as \"CSV UTF-8\"") from None


def read_rows(path: str) -> tuple[list[tuple[int, list[str]]], str]:
    """(line, cells) of every non-empty row, the header first, and the encoding."""
    name = os.path.basename(path)
    try:
        info = os.stat(path)
        if not stat.S_ISREG(info.st_mode):
            raise TableError(f"--tasks: {path} is not a file")
        if info.st_size > MAX_TABLE_BYTES:
            raise TableError(f"{name}: larger than {MAX_TABLE_BYTES // 1_000_000} MB; a class "
                             f"is at most {MAX_STUDENTS} rows")
        raw = _read(path)
    except OSError as exc:
        raise TableError(f"--tasks: cannot read {path}: {exc.strerror or exc}") from None
    text, encoding = decode(raw, name)
    first = text.split("\n", 1)[0]
    delimiter = max((",", ";", "\t"), key=first.count)
    opened = _unclosed_quote(text, delimiter)
    if opened is not None:      # it read the rest of the table as one cell: "column student-number: empty"
        raise TableError(f"{name} line {opened}: a quote opens a cell that no quote closes before the table "
                         "ends; close it, or write a quote that belongs to the text twice")
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter)
    rows, line = [], 1
    try:
        for cells in reader:
            if any(c.strip() for c in cells):
                rows.append((line, [c.strip() for c in cells]))
                if len(rows) > MAX_STUDENTS + 1:
                    raise TableError(f"{name}: more than {MAX_STUDENTS} students; split the class "
                                     "into several tables")
            line = reader.line_num + 1
    except csv.Error as exc:
        raise TableError(f"{name} line {reader.line_num}: {exc}") from None
    if not rows:
        raise TableError(f"{name}: empty; the first row names the columns (student, student-number, …)")
    return rows, encoding


def _unclosed_quote(text: str, delimiter: str) -> int | None:
    """The line of the row where a quoted cell opens that no quote closes (the reader then
    takes the rest of the table as that cell), or None."""
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter, strict=True)
    start = 1
    try:
        for _ in reader:
            start = reader.line_num + 1
    except csv.Error as exc:
        return start if "unexpected end of data" in str(exc) else None
    return None


def _read(path: str) -> bytes:
    with open(path, "rb") as handle:
        return handle.read(MAX_TABLE_BYTES + 1)


def read_tasks(path: str, base: str | None, group: str = "") -> tuple[list[Student], str]:
    """Every row as a Student (a bad one with its error), and the table's encoding.
    TableError for a table that cannot be used at all."""
    name = os.path.basename(path)
    rows, encoding = read_rows(path)
    (_, header), body = rows[0], rows[1:]
    parser = design_parser()
    actions = column_actions(parser)
    _check_header(name, header, actions)
    if not body:                # a header alone ran with no word, exit 0, and made DIR empty
        raise TableError(f"{name}: no students; each row under the header is one student")
    here = os.path.dirname(os.path.abspath(path))
    students = [_student(name, line, header, cells, parser, actions, base, here, group)
                for line, cells in body]
    _check_unique(name, students)
    return students, encoding


def _check_header(name: str, header: list[str], actions: dict[str, argparse.Action]) -> None:
    from . import close_match
    seen: set[str] = set()
    for index, column in enumerate(header, start=1):
        if not column:
            raise TableError(f"{name} line 1, column {index}: has no name")
        if column in seen:
            raise TableError(f"{name} line 1, column {column}: named twice")
        seen.add(column)
        if column not in NAME_COLUMNS and column not in actions:
            match = CHINESE_NAMES.get(column) or close_match(column, list(NAME_COLUMNS)
                                                               + [k for k in actions if "_" not in k])
            hint = f"; did you mean {match}?" if match else "; see 'shaper design --help' for the options"
            raise TableError(f"{name} line 1, column {column}: not a column{hint}")
    for required in ("student", "student-number"):
        if required not in seen and not (required == "student-number" and "student_number" in seen):
            raise TableError(f"{name} line 1: no column {required}")


def _student(name: str, line: int, header: list[str], cells: list[str], parser: argparse.ArgumentParser,
             actions: dict[str, argparse.Action], base: str | None, here: str, group: str) -> Student:
    where = f"{name} line {line}"
    values = {NAME_COLUMNS.get(c, c): "" for c in NAME_COLUMNS}
    if len(cells) > len(header):
        return Student(line, "", "", "", "", None, f"{where}: {len(cells)} cells, but the header names "
                       f"{len(header)} columns")
    row = dict(zip(header, cells))
    for column, field in NAME_COLUMNS.items():
        if row.get(column):
            values[field] = row[column]
    person = [_text(where, column, row.get(column, "")) for column in ("student", "student-number", "class")]
    student, number = values["student"], values["number"]
    folder = folder_name(number, student)
    blank = Student(line, student, number, values["group"] or group, folder, None)
    for error in person:
        if error:
            return _with_error(blank, error)
    for column, field in (("student", "student"), ("student-number", "number")):
        if not values[field]:
            return _with_error(blank, f"{where}, column {column}: empty; every student needs one")
    if _SHORTENED.fullmatch(number):
        return _with_error(blank, f"{where}, column student-number: {number} is a number a spreadsheet wrote "
                           "short, its digits lost; format the column as text and save the table again")
    try:
        argv, given, off = _argv(where, row, actions, base, here)
        args = parser.parse_args(argv)
        args.defaults_said = not row.get("design")      # the base's: said once, not per student
        from .cmd_design import document_from_args
        document = document_from_args(args)
        if "--no-gravity" in off and document.get("forces") is not None:
            document["forces"]["gravity"] = True        # "no" kept a base's gravity off: its forces without it
    except _CellError as exc:
        return _with_error(blank, str(exc))
    except UsageError as exc:
        return _with_error(blank, _located(where, str(exc), given))
    except DesignError as exc:
        return _with_error(blank, _located(where, design_error_text(exc), given))
    except FileFormatError as exc:
        return _with_error(blank, f"{where}, column design: {exc}" if row.get("design")
                           else f"{where}: --base: {exc}")
    lacking = _lacking(document, "the design file" if row.get("design") else "--base")
    if lacking:
        return _with_error(blank, f"{where}: {lacking}")
    return Student(line, student, number, blank.group, folder, document)


# What a course design needs of the design file (core.course_design.plan.PARTS's keys), as
# the table's columns that give it (the Class dialog translates a row's "lacks …" by them).
PART_COLUMNS = {"rpm": "the speeds (column rpm)",
                 "forces": "the loads (columns lever-weight, lever-inertia, ram-weight, cut-force …)",
                 "cam": "the feed cam (columns arm, swing, pressure, rise, dwell, return)",
                 "gear": "the gear pair (columns z1, z2, module)"}


def _lacking(document: dict[str, Any], source: str) -> str:
    """'' or why the row's design cannot make the course design: the parts its files need
    that neither the row nor its design file gives. Without this the row passed, its
    student failed when the report was written ('CourseError: --design: design.shaper.json
    has no "forces" …', a file the teacher never named) and left a folder holding only
    its design file, and the task sheets were printed for students who got nothing."""
    from core.course_design.plan import missing_parts
    missing = [key for key, _ in missing_parts(document.keys())]
    if not missing:
        return ""
    parts = [PART_COLUMNS.get(key, key) for key in missing]
    listed = parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]
    return f"lacks {listed}, which the course design needs; give them as columns or in {source}"


class _CellError(ValueError):
    pass


def _with_error(student: Student, error: str) -> Student:
    from dataclasses import replace
    return replace(student, error=one_line(error))


def _text(where: str, column: str, value: str) -> str:
    """'' or why a name cell cannot be printed on a cover."""
    if UNPRINTABLE.search(value):
        return f"{where}, column {column}: must be one line of text without control characters"
    if len(value) > MAX_TEXT:
        return f"{where}, column {column}: at most {MAX_TEXT} characters (got {len(value)})"
    return ""


def _argv(where: str, row: dict[str, str], actions: dict[str, argparse.Action], base: str | None,
          here: str) -> tuple[list[str], dict[str, str], list[str]]:
    """The row as ``shaper design``'s words, each option given → its column, and the switches
    the row turns off ("no" in a switch's column), which no word of ``shaper design`` says."""
    argv: list[str] = []
    given: dict[str, str] = {}
    off: list[str] = []
    for column, cell in row.items():
        if column in NAME_COLUMNS or not cell:
            continue
        action = actions[column]
        flag = max(action.option_strings, key=len)
        given[flag] = column
        if action.nargs in ("+", "*"):
            argv += [flag, *cell.replace(",", " ").split()]
        elif isinstance(action, argparse._AppendAction):    # --rotor, given once a part
            argv += [f"{flag}={part}" for part in cell.split()]
        elif action.nargs == 0:              # a switch (--no-gravity): yes or no
            word = cell.lower()
            if word not in TRUE_WORDS | FALSE_WORDS:
                raise _CellError(f"{where}, column {column}: must be yes or no (got {cell!r})")
            argv += [flag] if word in TRUE_WORDS else []
            off += [] if word in TRUE_WORDS else [flag]
        else:
            argv.append(f"{flag}={cell}")
    design = row.get("design", "")
    if design:
        argv += ["--design", beside(where, design, here)]
        given["--design"] = "design"
    elif base is not None:
        argv += ["--design", base]
        given["--design"] = ""              # the base's: named as the teacher gave it, --base
    return argv, given, off


def beside(where: str, design: str, here: str) -> str:
    """The path of a ``design`` cell: a file in the table's folder or below it, never
    outside (../x, an absolute path elsewhere, a link that leads out)."""
    path = os.path.join(here, design)
    inside = os.path.realpath(here)
    real = os.path.realpath(path)
    if os.path.commonpath([inside, real]) != inside:
        raise _CellError(f"{where}, column design: {design!r} is outside the table's folder; put the "
                         "design file beside the table")
    return path


_OPTION = re.compile(r"^(?:argument )?(--[\w-]+)(?:/\S+)?(?: \(([^)]*)\))?: (.*)$", re.S)


def _located(where: str, message: str, given: dict[str, str]) -> str:
    """A command-line message ("--K: must be > 1 (got 0.9)") as the table's: the column that
    gave the option (a value of the row's design file, "--design (cam.rise_deg)", as its
    column design; of the base file, as --base), else the message as it is after the line."""
    found = _OPTION.match(message)
    if found and found.group(1) in given:
        part = f" ({found.group(2)})" if found.group(2) else ""
        column = given[found.group(1)]
        return (f"{where}, column {column}{part}: {found.group(3)}" if column
                else f"{where}: --base{part}: {found.group(3)}")
    if found and "--design" in given and not found.group(2):
        # a value the row left to its design file ("--stroke: must be > 300.007 mm …" for
        # the base's stroke under the row's crank and K): named as the column that sets it,
        # the value as the file's (the Class dialog translates "(got …)" and keeps its value)
        source = "the design file" if given["--design"] else "--base"
        what = re.sub(r"\(got ([^()]*)\)$", rf"(got \1 from {source})", found.group(3))
        return f"{where}, column {found.group(1)[2:]}: {what}"
    return f"{where}: {message}"


def folder_name(number: str, student: str) -> str:
    """``<number>-<student>`` as a folder name on any system: no separator, no "..", no
    control or reserved character (each "_"), no reserved device name, no leading dot or
    trailing dot or space, at most MAX_FOLDER_BYTES bytes; letters of any script kept."""
    text = unicodedata.normalize("NFC", f"{number}-{student}")
    text = _UNSAFE.sub("_", text).strip().rstrip(". ")
    encoded = text.encode("utf-8")[:MAX_FOLDER_BYTES]
    text = encoded.decode("utf-8", "ignore").rstrip(". ")
    if not text or text.startswith(".") or text.split(".")[0].upper() in _RESERVED:
        text = "_" + text
    return text


def _check_unique(name: str, students: list[Student]) -> None:
    """TableError for two students with one number or one folder (Windows and macOS do not
    tell upper from lower case), naming both lines."""
    numbers: dict[str, int] = {}
    folders: dict[str, int] = {}
    for s in students:
        if _SHORTENED.fullmatch(s.number):     # its own row's error says why (two are alike)
            continue
        if s.number and s.number in numbers:
            raise TableError(f"{name} line {s.line}, column student-number: {s.number} is also on line "
                             f"{numbers[s.number]}; each student needs a number of their own")
        numbers.setdefault(s.number, s.line)
        if s.folder and s.folder.casefold() in folders:
            raise TableError(f"{name} line {s.line}: the folder {s.folder} is also line "
                             f"{folders[s.folder.casefold()]}'s; give one of them a number that differs in more than "
                             "letter case and the characters a folder name cannot hold")
        folders.setdefault(s.folder.casefold(), s.line)
