"""Design files in and out of the library: import files or folders, export entries.

Shared by ``shaper library import/export`` and the GUI's library pane, so both
name imported entries and exported files the same way.
"""
from __future__ import annotations

import errno
import os
import re
import shutil
import secrets
import stat
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable

from core.base.errors import FileFormatError
from core.files.atomic import remove_left
from core.library import Entry, Library

from .names import MAX_NAME, file_stem, safe_file_name, shown_file_name, unique_name
from .store import LibraryError

DESIGN_SUFFIX = ".shaper.json"


def expand_paths(paths: Iterable[str | os.PathLike]) -> list[Path]:
    """Files as given; a folder stands for its ``*.json`` files (not recursive), sorted."""
    out: list[Path] = []
    for p in paths:
        path = Path(p)
        try:
            folder = path.is_dir()
            files = sorted(f for f in path.iterdir() if f.is_file() and f.name.lower().endswith(".json")) \
                if folder else [path]
        except OSError:                 # a name too long, a folder that cannot be listed:
            files = [path]              # load_design says why, in one line
        out += files
    return out


def read_design_files(paths: Iterable[str | os.PathLike]) -> tuple[list[tuple[Path, dict[str, Any]]],
                                                                    list[tuple[Path, FileFormatError]]]:
    """Load and validate every file: ([(path, design)], [(path, why refused)]); ``why`` is
    the FileFormatError, whose text is core's sentence and whose reason a GUI translates."""
    from core.files.io import load_design
    good: list[tuple[Path, dict[str, Any]]] = []
    bad: list[tuple[Path, FileFormatError]] = []
    for path in expand_paths(paths):
        try:
            good.append((path, load_design(path)))
        except FileFormatError as exc:
            bad.append((path, exc))
    return good, bad


def import_entries(library: Library, designs: list[tuple[Path, dict[str, Any]]],
                   rename_duplicates: bool) -> list[Entry]:
    """Entries for loaded files, named after the files; stored in one transaction.

    A name already in the library (or twice among the files) is refused with
    LibraryError('exists') and nothing is stored, unless ``rename_duplicates``
    gives it the next free ``name (2)``, ``name (3)``….
    """
    taken = set(library.names())
    entries = []
    for path, loaded in designs:
        name = file_stem(path)[:MAX_NAME].strip() or "design"
        if rename_duplicates:
            name = unique_name(name, taken)
        taken.add(name)
        try:
            entries.append(library.make_entry(name, loaded, notes=f"imported from {shown_file_name(path)}"))
        except LibraryError as exc:         # say which file's name cannot be an entry's
            raise LibraryError(exc.kind, f"{shown_file_name(path)!r}: {exc}", exc.path) from None
    library.add_entries(entries)
    return entries


@dataclass(frozen=True)
class Exported:
    """What :func:`export_entries` wrote, and the entries it left out with why."""

    paths: tuple[Path, ...]
    skipped: tuple[tuple[str, LibraryError | FileFormatError], ...]
    """(entry name, why it cannot be exported): the error, whose text is core's sentence
    and whose fields a GUI says in its language."""


def export_entries(library: Library, folder: str | os.PathLike,
                   names: Iterable[str] | None = None) -> Exported:
    """Write entries (default: all) as design files into ``folder``, all or nothing.

    File names come from the entry names (characters no file system allows are
    replaced, cut to a length every file system takes); an existing file is never
    overwritten — the next free ``name (2)`` is used. The files are written into a
    temporary folder first and moved into place only when all are written (a missing
    ``folder`` is that temporary folder renamed), so a failure (a full disk) leaves no
    partial export. A damaged entry is left out and reported in ``skipped``.
    OSError if the folder cannot be written.
    """
    folder = Path(folder)
    texts: list[tuple[str, str]] = []        # (file name, text)
    skipped: list[tuple[str, LibraryError | FileFormatError]] = []
    used = {p.name for p in folder.iterdir()} if folder.is_dir() else set()
    for name in (library.names() if names is None else list(names)):
        try:
            entry = library.get(name)
            entry.document()                  # never export what could not be opened again
        except (LibraryError, FileFormatError) as exc:
            if isinstance(exc, LibraryError) and exc.kind not in ("entry", "missing"):
                raise
            skipped.append((name, exc))
            continue
        stem = unique_name(safe_file_name(name), {n[:-len(DESIGN_SUFFIX)] for n in used      # 'K1.4' and
                                                  if n.casefold().endswith(DESIGN_SUFFIX)},   # 'k1.4': one
                           fold_case=True)                                                    # file on Windows
        used.add(stem + DESIGN_SUFFIX)
        texts.append((stem + DESIGN_SUFFIX, entry.text + "\n"))
    if names is None:           # an entry no name finds was left out without a word
        skipped += [(label, LibraryError("entry", f"damaged ({why}); 'shaper library check' lists every damaged "
                                         "design", library.path, damage=why))
                    for label, why in library.unreadable_names()]
    exists = folder.is_dir()
    parent = folder if exists else (folder.parent if str(folder.parent) else Path("."))
    parent.mkdir(parents=True, exist_ok=True)
    remove_stale_staging(parent)
    staging = parent / f"{STAGING_PREFIX}{os.getpid()}-{secrets.token_hex(4)}"
    staging.mkdir()                             # the umask's mode, which a new folder keeps
    moved: list[Path] = []
    try:
        for i, (_, text) in enumerate(texts):
            with open(staging / f"{i}.tmp", "w", encoding="utf-8", newline="") as handle:
                handle.write(text)
                handle.flush()
                os.fsync(handle.fileno())
        if not exists:
            for i, (file_name, _) in enumerate(texts):
                os.rename(staging / f"{i}.tmp", staging / file_name)
            os.rename(staging, folder)
            return Exported(tuple(folder / n for n, _ in texts), tuple(skipped))
        for i, (file_name, _) in enumerate(texts):
            target = folder / file_name
            if os.path.lexists(target):          # made by another program meanwhile
                raise FileExistsError(errno.EEXIST, os.strerror(errno.EEXIST), str(target))
            os.rename(staging / f"{i}.tmp", target)
            moved.append(target)
    except BaseException:
        for path in moved:                      # take back what was already moved in
            path.unlink(missing_ok=True)
        shutil.rmtree(staging, ignore_errors=True)
        raise
    shutil.rmtree(staging, ignore_errors=True)
    return Exported(tuple(moved), tuple(skipped))


STAGING_PREFIX = ".shaper-export-"
_STAGING = re.compile(rf"{re.escape(STAGING_PREFIX)}(\d+)-[0-9a-f]{{8}}\Z")


def remove_stale_staging(parent: Path) -> list[str]:
    """Remove the staging folders in ``parent`` of exports killed mid-way (SIGKILL, power
    loss: their pid no longer runs), and return them. Each killed ``export --all`` left one,
    a hidden folder holding a whole export, that no later run removed. A staging folder of a
    live export, another user's, or a symbolic link is left alone, by the rule of a save's
    stale temporary files (``core.files.atomic.remove_left``)."""
    return remove_left(parent, _STAGING, stat.S_ISDIR, shutil.rmtree)
