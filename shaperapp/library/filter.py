"""The library filter as the pane shows it: field names (and variant, rod side values)
in the UI's language, turned into core's syntax before it is parsed.

The pane's columns read "方案", "最大压力角 (°)" …, but ``core.library.query`` knows
only its own names, so "方案=滑块" was refused. A condition may name a field by its
column title (with or without the unit in brackets) and give a variant or rod side
as shown in the table; everything else (operators, numbers, quoting) is core's, and
core's own names still work.
"""
from __future__ import annotations

import re

from core.library.query import OPERATORS

from shaperapp.widgets.figure_labels import _LABELS, _WORDS, figure_label, variant_label

_UNIT = re.compile(r"\s*[(（][^()（）]*[)）]\s*$")


def _names() -> dict[str, str]:
    """Shown field name (lower case) → core key, the longest first."""
    names: dict[str, str] = {}
    for key in _LABELS:
        label = figure_label(key).strip()
        for name in (label, _UNIT.sub("", label)):
            if name and name.lower() != key.lower():
                names.setdefault(name.lower(), key)
    return dict(sorted(names.items(), key=lambda item: -len(item[0])))


def _segments(text: str) -> list[str]:
    """``text`` split at the commas outside double quotes (``\\"`` escapes a quote)."""
    parts, start, quoted, i = [], 0, False, 0
    while i < len(text):
        ch = text[i]
        if ch == "\\" and quoted:
            i += 2
            continue
        if ch == '"':
            quoted = not quoted
        elif ch == "," and not quoted:
            parts.append(text[start:i])
            start = i + 1
        i += 1
    parts.append(text[start:])
    return parts


def core_filter(text: str) -> str:
    """``text`` with shown field names and values replaced by core's ('方案=滑块' →
    'variant=block'); conditions already in core's names are left as they are."""
    names = _names()
    values = {variant_label(word).lower(): word for word in _WORDS}
    operator = "|".join(re.escape(op) for op in OPERATORS)
    out = []
    for segment in _segments(text):
        stripped = segment.lstrip()
        lead = segment[:len(segment) - len(stripped)]
        for name, key in names.items():
            match = re.match(rf"({re.escape(name)})\s*({operator})(\s*)(.*)$", stripped, re.IGNORECASE | re.DOTALL)
            if match is None:
                continue
            value = match.group(4)
            if key in ("variant", "rod_side") and value.strip().lower() in values:
                value = values[value.strip().lower()]
            stripped = f"{key}{match.group(2)}{match.group(3)}{value}"
            break
        out.append(lead + stripped)
    return ",".join(out)
