"""What the report must print, found independently of the report: the CLI's own values,
and a positions-table number as its column prints it (one number of decimals per column,
five significant digits of the column's largest value)."""
from __future__ import annotations

import math
import re
from typing import Sequence

from cli_runner import shaper_run_in_process


def cli_values(*command: str) -> list[str]:
    """Every number-bearing value the CLI prints as 'label  value', split at ' / ' (repeats
    kept; the rod side's "(trailing)" left out)."""
    result = shaper_run_in_process(*command)
    assert result.returncode == 0, result.stderr
    values = []
    for line in result.stdout.splitlines():
        parts = re.split(r"\s{2,}", line.strip(), maxsplit=1)
        if len(parts) == 2 and re.search(r"\d", parts[1]) and "% of the stroke" not in parts[1]:
            values += [v.replace(" (trailing)", "") for v in parts[1].split(" / ")]
    return values


def column_text(values: Sequence[float], value: float) -> str:
    """``value`` as a column of ``values`` (NaN left out) prints it."""
    finite = [abs(v) for v in values if v is not None and math.isfinite(v)]
    largest = max(finite, default=0.0)
    decimals = min(max(4 - math.floor(math.log10(largest)), 0), 6) if largest > 0 else 3
    text = f"{value:.{decimals}f}"
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text
