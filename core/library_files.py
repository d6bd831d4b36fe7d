"""Design files in and out of the library: import files or folders, export entries.

Shared by ``shaper library import/export`` and the GUI's library pane, so both
name imported entries and exported files the same way.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Iterable

from .errors import FileFormatError
from .io import load_design
from .library import Entry, Library
from .library_names import file_stem, safe_file_name, unique_name

DESIGN_SUFFIX = ".shaper.json"


def expand_paths(paths: Iterable[str | os.PathLike]) -> list[Path]:
    """Files as given; a folder stands for its ``*.json`` files (not recursive), sorted."""
    out: list[Path] = []
    for p in paths:
        path = Path(p)
        if path.is_dir():
            out += sorted(f for f in path.iterdir() if f.is_file() and f.name.lower().endswith(".json"))
        else:
            out.append(path)
    return out


def read_design_files(paths: Iterable[str | os.PathLike]) -> tuple[list[tuple[Path, dict[str, Any]]],
                                                                    list[tuple[Path, str]]]:
    """Load and validate every file: ([(path, design)], [(path, why refused)])."""
    good: list[tuple[Path, dict[str, Any]]] = []
    bad: list[tuple[Path, str]] = []
    for path in expand_paths(paths):
        try:
            good.append((path, load_design(path)))
        except FileFormatError as exc:
            bad.append((path, str(exc)))
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
        name = file_stem(path)
        if rename_duplicates:
            name = unique_name(name, taken)
        taken.add(name)
        entries.append(library.make_entry(name, loaded, notes=f"imported from {path.name}"))
    library.add_entries(entries)
    return entries


def export_entries(library: Library, folder: str | os.PathLike,
                   names: Iterable[str] | None = None) -> list[Path]:
    """Write entries (default: all) as design files into ``folder``; returns the paths.

    File names come from the entry names (characters no file system allows are
    replaced); an existing file is never overwritten — the next free ``name (2)``
    is used. OSError if the folder cannot be written.
    """
    folder = Path(folder)
    written: list[Path] = []
    used = {p.name for p in folder.iterdir()} if folder.is_dir() else set()
    for name in (library.names() if names is None else list(names)):
        stem = safe_file_name(name)
        candidate = unique_name(stem, {n[:-len(DESIGN_SUFFIX)] for n in used if n.endswith(DESIGN_SUFFIX)})
        path = folder / (candidate + DESIGN_SUFFIX)
        library.export(name, path)
        used.add(path.name)
        written.append(path)
    return written
