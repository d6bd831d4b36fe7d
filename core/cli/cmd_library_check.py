"""``shaper library check``: the entries whose stored values cannot be shown or opened.

A library another program wrote to, or a damaged disk, can hold values of the wrong
type in single rows (see :mod:`core.library.rows`); the rest of the library stays
usable and this lists what is not, with SQLite's own ``integrity_check`` findings.
"""
from __future__ import annotations

import argparse

from ..library import Library
from .output import print_json


def check_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--json", action="store_true", help="print a JSON array of {entry, problem}")


def run_check(args: argparse.Namespace, lib: Library) -> int:
    """Every damaged entry (and SQLite's findings, as entry 'file') on its own line; exit
    status 1 if there is any, else 0."""
    with lib:
        found = lib.damaged()
        total = lib.count()
    if args.json:
        print_json([{"entry": entry, "problem": why} for entry, why in found])
    else:
        for entry, why in found:
            print(f"{entry}: {why}")
        entries = sum(1 for entry, _ in found if entry != "file")
        print(f"{entries} of {total} designs in {lib.path} are damaged" if found
              else f"no damage found in {lib.path} ({total} designs)")
    return 1 if found else 0
