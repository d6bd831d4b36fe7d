"""How the report prints a positions-table number, computed independently of the program:
one number of decimals per column, five significant digits of the column's largest value."""
from __future__ import annotations

import math
from typing import Sequence


def column_text(values: Sequence[float], value: float) -> str:
    """``value`` as a column of ``values`` (NaN left out) prints it."""
    finite = [abs(v) for v in values if v is not None and math.isfinite(v)]
    largest = max(finite, default=0.0)
    decimals = min(max(4 - math.floor(math.log10(largest)), 0), 6) if largest > 0 else 3
    text = f"{value:.{decimals}f}"
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text
