"""The class table's refusals (``core.cli.tasks``) in the UI's language, so the Chinese
Class dialog marks a bad row with a Chinese sentence (issue 41, gap 2).

Core writes where ("tasks.csv line 7, column K") and what ("must be a number (got abc)")
in English. Here the place is rebuilt from its parts, and the what is matched against the
table's own phrases, then against core's shared ones (``shaperapp.widgets.messages``), as
the other refusals of core are given in Chinese. A phrase not known stays as core wrote it.
"""
from __future__ import annotations

import os
import re

from PySide6.QtCore import QCoreApplication

from core.cli.tasks import PART_COLUMNS

from shaperapp.widgets.messages import allowed_text

translate = QCoreApplication.translate

_WHERE = re.compile(r"^(.+?) line (\d+)(?:, column ([^:]+?))?: (.*)$", re.S)
_GOT = re.compile(r"^(.*) \(got (.*)\)$", re.S)

# (pattern on core.cli.tasks's English text, template with %1, %2 …)
_PATTERNS: tuple[tuple[str, str], ...] = (
    (r"empty; every student needs one$", "empty; every student needs one"),
    (r"must be one line of text without control characters$",
     "must be one line of text without control characters"),
    (r"at most (\d+) characters$", "at most %1 characters"),
    (r"must be yes or no$", "must be yes or no"),
    (r"(.+) is outside the table's folder; put the design file beside the table$",
     "%1 is outside the table's folder; put the design file beside the table"),
    (r"(\d+) cells, but the header names (\d+) columns$", "%1 cells, but the header names %2 columns"),
    (r"(--[\w-]+): required \(or use (--[\w-]+) or (--[\w-]+)\)$", "%1: required (or use %2 or %3)"),
    (r"(--[\w-]+): required$", "%1: required"),
    (r"(\S+) is also on line (\d+); each student needs a number of their own$",
     "%1 is also on line %2; each student needs a number of their own"),
    (r"the folder (.+) is also line (\d+)'s; give one of them a number that differs in more than letter case "
     r"and the characters a folder name cannot hold$",
     "the folder %1 is also line %2's; give one of them a number that differs in more than letter case and "
     "the characters a folder name cannot hold"),
    (r"(\S+) is a number a spreadsheet wrote short, its digits lost; format the column as text and save the "
     r"table again$",
     "%1 is a number a spreadsheet wrote short, its digits lost; format the column as text and save the table again"),
    (r"has no name$", "has no name"),
    (r"named twice$", "named twice"),
    (r"not a column; did you mean (\S+)\?$", "not a column; did you mean %1?"),
    (r"not a column; see 'shaper design --help' for the options$",
     "not a column; see 'shaper design --help' for the options"),
    (r"no column (\S+)$", "no column %1"),
    (r"not UTF-8 or GBK text; save it as \"CSV UTF-8\"$", "not UTF-8 or GBK text; save it as \"CSV UTF-8\""),
    (r"more than (\d+) students; split the class into several tables$",
     "more than %1 students; split the class into several tables"),
    (r"larger than (\d+) MB; a class is at most (\d+) rows$", "larger than %1 MB; a class is at most %2 rows"),
    (r"(\d+) of (\d+) students not written \((\d+) bad rows, (\d+) failed\)$",
     "%1 of %2 students not written (%3 bad rows, %4 failed)."),
    (r"empty; the first row names the columns \(student, student-number, …\)$",
     "empty; the first row names the columns (student, student-number, …)"),
    (r"no students; each row under the header is one student$",
     "no students; each row under the header is one student"),
    (r"a quote opens a cell that no quote closes before the table ends; close it, or write a quote that belongs "
     r"to the text twice$",
     "a quote opens a cell that no quote closes before the table ends; close it, or write a quote that belongs to "
     "the text twice"),
    # the run's own refusals of --output (shaperapp.course.class_command)
    (r"another 'shaper class' is writing into (.+); let it finish, then run this one$",
     "another 'shaper class' is writing into %1; let it finish, then run this one"),
    (r"cannot make the folder (.+): a file of that name is in the way; move it, then run the class again$",
     "cannot make the folder %1: a file of that name is in the way; move it, then run the class again"),
    (r"cannot make (.+?): (.+)$", "cannot make %1: %2"),
)


def _templates() -> dict[str, str]:
    # Listed literally so pyside6-lupdate finds every template.
    return {
        "empty; every student needs one": translate("ClassMessages", "empty; every student needs one"),
        "must be one line of text without control characters":
            translate("ClassMessages", "must be one line of text without control characters"),
        "at most %1 characters": translate("ClassMessages", "at most %1 characters"),
        "must be yes or no": translate("ClassMessages", "must be yes or no"),
        "%1 is outside the table's folder; put the design file beside the table":
            translate("ClassMessages", "%1 is outside the table's folder; put the design file beside the table"),
        "%1 cells, but the header names %2 columns":
            translate("ClassMessages", "%1 cells, but the header names %2 columns"),
        "%1: required (or use %2 or %3)": translate("ClassMessages", "%1: required (or use %2 or %3)"),
        "%1: required": translate("ClassMessages", "%1: required"),
        "%1 is also on line %2; each student needs a number of their own":
            translate("ClassMessages", "%1 is also on line %2; each student needs a number of their own"),
        "the folder %1 is also line %2's; give one of them a number that differs in more than letter case and the characters a folder name cannot hold":
            translate("ClassMessages", "the folder %1 is also line %2's; give one of them a number that differs in more than letter case and the characters a folder name cannot hold"),
        "%1 is a number a spreadsheet wrote short, its digits lost; format the column as text and save the table again":
            translate("ClassMessages", "%1 is a number a spreadsheet wrote short, its digits lost; format the column as text and save the table again"),
        "has no name": translate("ClassMessages", "has no name"),
        "named twice": translate("ClassMessages", "named twice"),
        "not a column; did you mean %1?": translate("ClassMessages", "not a column; did you mean %1?"),
        "not a column; see 'shaper design --help' for the options":
            translate("ClassMessages", "not a column; see 'shaper design --help' for the options"),
        "no column %1": translate("ClassMessages", "no column %1"),
        "not UTF-8 or GBK text; save it as \"CSV UTF-8\"":
            translate("ClassMessages", "not UTF-8 or GBK text; save it as \"CSV UTF-8\""),
        "more than %1 students; split the class into several tables":
            translate("ClassMessages", "more than %1 students; split the class into several tables"),
        "larger than %1 MB; a class is at most %2 rows":
            translate("ClassMessages", "larger than %1 MB; a class is at most %2 rows"),
        "empty; the first row names the columns (student, student-number, …)":
            translate("ClassMessages", "empty; the first row names the columns (student, student-number, …)"),
        "no students; each row under the header is one student":
            translate("ClassMessages", "no students; each row under the header is one student"),
        "a quote opens a cell that no quote closes before the table ends; close it, or write a quote that belongs to "
        "the text twice":
            translate("ClassMessages", "a quote opens a cell that no quote closes before the table ends; close it, "
                      "or write a quote that belongs to the text twice"),
        "another 'shaper class' is writing into %1; let it finish, then run this one":
            translate("ClassMessages", "another 'shaper class' is writing into %1; let it finish, then run this one"),
        "cannot make %1: %2": translate("ClassMessages", "cannot make %1: %2"),
        "cannot make the folder %1: a file of that name is in the way; move it, then run the class again":
            translate("ClassMessages", "cannot make the folder %1: a file of that name is in the way; move it, "
                      "then run the class again"),
        "%1 of %2 students not written (%3 bad rows, %4 failed).":
            translate("ClassMessages", "%1 of %2 students not written (%3 bad rows, %4 failed)."),
    }


_LACKS = re.compile(r"^lacks (.+), which the course design needs; give them as columns or in "
                    r"(--base|the design file)$", re.S)


def _part_names() -> dict[str, str]:
    # Listed literally so pyside6-lupdate finds them; keys as core.cli.tasks.PART_COLUMNS's.
    return {"rpm": translate("ClassMessages", "the speeds (column rpm)"),
            "forces": translate("ClassMessages", "the loads (columns lever-weight, lever-inertia, ram-weight, "
                                                 "cut-force …)"),
            "cam": translate("ClassMessages", "the feed cam (columns arm, swing, pressure, rise, dwell, return)"),
            "gear": translate("ClassMessages", "the gear pair (columns z1, z2, module)")}


def _lacking(text: str) -> str | None:
    """A row's "lacks the loads (…) and the gear pair (…), which the course design needs …"
    with each part named in the UI's language, or None for another text."""
    found = _LACKS.match(text)
    if found is None:
        return None
    listed, source = found.groups()
    names = _part_names()
    parts = [names[key] for key, english in PART_COLUMNS.items() if english in listed]
    if not parts:
        return None
    joined = parts[-1]
    if len(parts) > 1:
        joined = translate("ClassMessages", "%1 and %2").replace("%1", translate("ClassMessages", ", ").join(
            parts[:-1])).replace("%2", parts[-1])
    template = (translate("ClassMessages", "lacks %1, which the course design needs; give them as columns or in "
                                           "--base") if source == "--base" else
                translate("ClassMessages", "lacks %1, which the course design needs; give them as columns or in "
                                           "the design file"))
    return template.replace("%1", joined)


_OUTPUT = re.compile(r"^cannot (write into|write|make) (.+?): ([^:]+)$", re.S)


def _output(text: str) -> str | None:
    """An output the run cannot write ("cannot write into 机械2101: permission denied", the
    class's check of --output, and a student's "cannot write F: the disk is full"), its
    reason in the UI's language too; None for another text."""
    import errno

    from core.base.errors import os_reason as core_reason
    from shaperapp.widgets.file_messages import os_reason
    found = _OUTPUT.match(text)
    if found is None:
        return None
    how, path, reason = found.groups()
    numbers = {core_reason(OSError(n, "")): n for n in (errno.EACCES, errno.ENOSPC, errno.EDQUOT, errno.EROFS,
                                                         errno.ENOENT, errno.ENOTDIR, errno.EISDIR,
                                                         errno.ENAMETOOLONG, errno.ELOOP)}
    if reason in numbers:
        words = os_reason(numbers[reason], reason)
    elif reason == "it is not a folder":
        words = translate("ClassMessages", "it is not a folder")
    else:
        return None
    template = {"write into": translate("ClassMessages", "cannot write into %1: %2"),
                "write": translate("ClassMessages", "cannot write %1: %2"),
                "make": translate("ClassMessages", "cannot make %1: %2")}[how]
    return template.replace("%1", path).replace("%2", words)


def _what(text: str) -> str:
    """What is wrong, translated; a trailing "(got X)" kept as the value typed."""
    lacking = _lacking(text) or _output(text)
    if lacking is not None:
        return lacking
    from shaperapp.widgets.gear_messages import gear_text
    got = _GOT.match(text)
    said = got.group(1) if got else text
    body = gear_text(said) or allowed_text(said, _PATTERNS, _templates())
    if got:
        body = translate("ClassMessages", "%1 (got %2)").replace("%1", body).replace("%2", _value(got.group(2)))
    return body


_FROM = re.compile(r"^(.*) from (--base|the design file)$", re.S)


def _value(text: str) -> str:
    """A value typed, or one the row left to its design file ("300 from --base")."""
    found = _FROM.match(text)
    if found is None:
        return text
    template = (translate("ClassMessages", "%1 from --base") if found.group(2) == "--base"
                else translate("ClassMessages", "%1 from the design file"))
    return template.replace("%1", found.group(1))


def table_message(text: str) -> str:
    """A refusal of ``core.cli.tasks`` (a bad row's or the whole table's) in the UI's
    language: "tasks.csv line 7, column K: must be a number (got abc)"."""
    where = _WHERE.match(text)
    if where is None:
        name, _, rest = text.partition(": ")
        if not rest:
            return _what(text)
        return translate("ClassMessages", "%1: %2").replace("%1", name).replace("%2", _what(rest))
    name, line, column, rest = where.groups()
    if column is None:
        template = translate("ClassMessages", "%1 line %2: %3")
    else:
        template = translate("ClassMessages", "%1 line %2, column %3: %4").replace("%3", column).replace("%4", "%3")
    return template.replace("%1", name).replace("%2", line).replace("%3", _what(rest))


# the notes ``shaper class`` prints once it has run (shaperapp.course.class_command, core.cli.notes)
_DEFAULTED = re.compile(r"^--[\w-]+: (.+) gives no (\S+); (.+) taken$", re.S)
_NOTES: tuple[tuple[re.Pattern, str], ...] = (
    (re.compile(r"^(.+): removed (.+) of an earlier run, drawn from its data; this run writes no DXF \(--dxf\)$",
                re.S), "removed"),
    (re.compile(r"^(.+) holds an earlier run's files, not made from this table \(its row, line (\d+), is bad\) "
                r"and not in its answer key; left as it was$", re.S), "bad row"),
    (re.compile(r"^(.+) holds an earlier run's files, not made from this table \((.+) has no row for it\) "
                r"and not in its answer key; left as it was$", re.S), "no row"),
    (re.compile(r"^(.+) read as (\S+)$", re.S), "read as"),
)


def _note_templates() -> dict[str, str]:
    return {
        "removed": translate("ClassMessages", "%1: removed %2 of an earlier run, drawn from its data; this run "
                                              "writes no DXF"),
        "bad row": translate("ClassMessages", "%1 holds an earlier run's files, not made from this table (its row, "
                                              "line %2, is bad) and not in its answer key; left as it was"),
        "no row": translate("ClassMessages", "%1 holds an earlier run's files, not made from this table (%2 has no "
                                             "row for it) and not in its answer key; left as it was"),
        "read as": translate("ClassMessages", "%1 read as %2"),
    }


def notes_text(notes: list[str]) -> list[str]:
    """The notes of a ``shaper class`` run in the UI's language (the Chinese dialog showed
    them in core's English). The keys a design file lacked, with the values taken, are one
    line per file as File › Open says them (``defaulted_text``), not one per key; a note
    not known stays as the command wrote it."""
    from shaperapp.widgets.file_messages import defaulted_text
    lacking: dict[str, list[tuple[str, str]]] = {}
    said: list[str] = []
    templates = _note_templates()
    for note in notes:
        found = _DEFAULTED.match(note)
        if found is not None:
            lacking.setdefault(found.group(1), []).append((found.group(2), found.group(3)))
            continue
        for pattern, kind in _NOTES:
            known = pattern.match(note)
            if known is not None:
                note = re.sub(r"%(\d)", lambda m: known.group(int(m.group(1))), templates[kind])
                break
        said.append(note)
    return [defaulted_text(os.path.basename(path), tuple(keys)) for path, keys in lacking.items()] + said
