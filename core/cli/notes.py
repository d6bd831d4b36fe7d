"""Notes a command prints on stderr once it has run: what a reader took for the user (a
design file's missing key, at its default). Held until the command returns, so that a
refusal stays the one line naming the option (``core.cli.main`` flushes them)."""
from __future__ import annotations

import sys
from typing import Any

NOTES: list[str] = []


def say_defaulted(option: str, path: object, doc: dict[str, Any]) -> None:
    """One note on stderr per key the design file lacks whose default the design is computed
    with (``core.files.design_file.defaulted_keys``): a design is never changed without a word.
    Said when the command has run (:func:`flush_notes`): a refusal stays one line."""
    NOTES.extend(f"{option}: {path} gives no {key}; {value} taken" for key, value in doc["defaulted"])


def flush_notes(ran: bool) -> None:
    """Print the notes of the command that ran (``ran``: it returned, whatever its status;
    not when a refusal or an error stopped it), then forget them."""
    if ran:
        for text in NOTES:
            print(f"shaper: note: {text}", file=sys.stderr)
    NOTES.clear()
