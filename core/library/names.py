"""Names in a design library: what an entry may be called, its tags, and the names
it gets on import (from a file name), on a copy (``base (2)``) or on export (a file
name every system accepts). Pure string rules, shared by the library, its files
and the GUI.
"""
from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Iterable

from core.base.text import CONTROL, NOTE_FORBIDDEN

from .store import LibraryError

MAX_NAME = 200
MAX_TAG = 64


def storable(text: str) -> bool:
    """Whether ``text`` can be stored as UTF-8: bytes that are not UTF-8 on a command line
    reach Python as lone surrogates, which no UTF-8 text (and no SQLite text) can hold."""
    try:
        text.encode("utf-8")
        return True
    except UnicodeEncodeError:
        return False


def check_name(name: object) -> str:
    """A usable entry name (stripped, as :func:`lookup_name` strips), or LibraryError('name')."""
    if not isinstance(name, str) or not name.strip():
        raise LibraryError("name", "a design name must not be empty")
    name = lookup_name(name)
    if len(name) > MAX_NAME or CONTROL.search(name):
        raise LibraryError("name", f"a design name must be one line of at most {MAX_NAME} characters, "
                           "without control characters, noncharacters or line breaks")
    return name


def lookup_name(name: str) -> str:
    """The stored form of a name given to find an entry: stripped of white space (Unicode's,
    U+00A0 and U+3000 too) as :func:`check_name` strips it when storing, so a name is found
    as it was typed when saved."""
    return name.strip() if isinstance(name, str) else name


def check_tags(tags: Iterable[str]) -> tuple[str, ...]:
    """Stripped, de-duplicated, sorted tags; LibraryError('tag') for a bad one."""
    out = set()
    for tag in tags:
        tag = str(tag).strip()
        if not tag:
            continue
        if len(tag) > MAX_TAG or "," in tag or CONTROL.search(tag):
            raise LibraryError("tag", f"a tag must be at most {MAX_TAG} characters, without "
                               f"commas, control characters, noncharacters or line breaks (got {tag[:80]!r})")
        out.add(tag)
    return tuple(sorted(out))


def check_notes(notes: object) -> str:
    """Notes as stored: any text of lines (LF or CR LF) and tabs, but no other control
    character (an ESC sequence retitles or clears the terminal that shows it), no
    noncharacter, no lone CR; LibraryError('notes') otherwise (issue 42)."""
    notes = "" if notes is None else str(notes)
    bad = NOTE_FORBIDDEN.search(notes)
    if bad:
        raise LibraryError("notes", "notes may hold line breaks and tabs but no other control "
                           f"character or noncharacter (got {bad.group()!r} at character {bad.start() + 1})")
    return notes


def unique_name(base: str, taken: Iterable[str], fold_case: bool = False) -> str:
    """``base``, or ``base (2)``, ``base (3)``… whichever is not in ``taken``; with
    ``fold_case`` letter case does not tell two apart (a file name on Windows and macOS)."""
    key = str.casefold if fold_case else str
    taken = {key(t) for t in taken}
    if key(base) not in taken:
        return base
    n = 2
    while key(f"{base} ({n})") in taken:
        n += 1
    return f"{base} ({n})"


def shown_file_name(path: str | os.PathLike) -> str:
    """A file's name as text that can be stored: bytes that are not UTF-8 become �."""
    return os.fsencode(Path(path).name).decode("utf-8", "replace")


def file_stem(path: str | os.PathLike) -> str:
    """The entry name a design file gets on import: its name without ``.shaper.json``/``.json``."""
    name = shown_file_name(path)
    for suffix in (".shaper.json", ".json"):
        if name.lower().endswith(suffix) and len(name) > len(suffix):
            return name[:-len(suffix)]
    return name


MAX_STEM_BYTES = 200     # an exported file's name without ``.shaper.json`` and `` (N)``


def safe_file_name(name: str) -> str:
    """An entry name usable as a file name on every system (for exporting a whole library).

    Cut to ``MAX_STEM_BYTES`` bytes of UTF-8, not characters: file systems count bytes
    (255 at most), and 120 Chinese characters are already 360 bytes.
    """
    cleaned = re.sub(r'[<>:"/\\|?*\x00-\x1f\x7f]', "_", name).strip(" .")
    cut = cleaned.encode("utf-8", "replace")[:MAX_STEM_BYTES].decode("utf-8", "ignore").rstrip(" .")
    return cut or "design"
