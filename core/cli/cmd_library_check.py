"""``shaper library check``: the entries whose stored values cannot be shown or opened.

A library another program wrote to, or a damaged disk, can hold values of the wrong
type in single rows (see :mod:`core.library.rows`); the rest of the library stays
usable and this lists what is not, with SQLite's own ``integrity_check`` findings.
"""
from __future__ import annotations

import argparse
from typing import Callable

from ..library import Library
from ..library.store import LibraryError
from core.base.text import terminal_text
from .output import print_json


def check_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--json", action="store_true", help="print a JSON array of {entry, problem}")


def run_check(args: argparse.Namespace, open_library: Callable[[], Library]) -> int:
    """Every damaged entry (and SQLite's findings, as entry 'file') on its own line; exit
    status 1 if there is any, else 0. A file refused for schema objects that are not ours
    (a trigger another program added) has each of them listed as a finding of 'file'."""
    try:
        lib = open_library()
    except LibraryError as exc:
        if not exc.objects:
            raise
        return _report([("file", f"{what} is not part of a Shaper Designer library")
                        for what in exc.objects], args.json,
                       str(exc))
    with lib:
        found = lib.damaged()
        total = lib.count()
    fine = sum(1 for _, why in found if getattr(why, "kind", None) == "too_fine")
    entries = sum(1 for entry, _ in found if entry != "file") - fine
    summary = [f"{entries} of {total} designs in {lib.path} are damaged"] if entries or len(found) > fine else []
    if fine:        # whole, but stored before the design file's sample limit
        summary.append(f"{fine} of {total} designs in {lib.path} {'is' if fine == 1 else 'are'} too fine "
                       "for a design file")
    return _report(found, args.json, "; ".join(summary) if found
                   else f"no damage found in {lib.path} ({total} designs)")


def _report(found: list[tuple[str, str]], as_json: bool, summary: str) -> int:
    if as_json:
        print_json([{"entry": entry, "problem": why} for entry, why in found])
    else:
        for entry, why in found:
            print(terminal_text(f"{entry}: {why}"))
        print(summary)
    return 1 if found else 0
