"""``shaper library refresh``: recompute stored figures that an older program computed.

A library keeps each entry's key figures so that it can list and sort without
recomputing; each entry also keeps which computation made them
(``core.space.figures.FIGURES_VERSION``). After an update that computes a figure
differently, ``refresh`` recomputes the older entries from their stored designs
(``Library.refresh_figures``); ``--all`` or names recompute those entries anyway.
"""
from __future__ import annotations

import argparse
import sys

from ..library import Library
from .common import UsageError
from .output import print_json
from .streaming import Progress


def refresh_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("names", metavar="NAME", nargs="*",
                   help="entries to recompute (default: those whose figures an older version computed)")
    p.add_argument("--all", action="store_true", help="recompute every entry")
    p.add_argument("--json", action="store_true", help="print what was done as JSON")


def run_refresh(args: argparse.Namespace, lib: Library) -> int:
    """Exit status 0, or 1 when a stored design could no longer be computed (its figures
    are left as they were and named on stderr)."""
    if args.all and args.names:
        raise UsageError("--all: give NAMEs or --all, not both")
    for name in args.names:
        lib.get(name)                       # LibraryError('missing') names a wrong NAME
    names = lib.names() if args.all else (args.names or lib.stale_names())
    total = len(names)
    with Progress("recomputing figures", total) as progress:
        report = lib.refresh_figures(names, progress=lambda done, _total: progress.update(done))
    if args.json:
        print_json({"updated": list(report.updated), "skipped": list(report.skipped),
                    "failed": [{"name": n, "reason": r} for n, r in report.failed]})
    elif total == 0:
        print(f"every design's figures in {lib.path} are current")
    else:
        print(f"recomputed the figures of {len(report.updated)} of {total} designs in {lib.path}")
        for name in report.skipped:
            print(f"  {name!r}: removed or saved again by another program meanwhile; left to it")
    for name, reason in report.failed:
        print(f"shaper: {name!r}: cannot be computed any more ({reason}); its figures were left "
              "as they were", file=sys.stderr)
    return 1 if report.failed else 0
