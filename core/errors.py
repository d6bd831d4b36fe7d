"""One domain exception for every bad input, so front ends can name the field.

The CLI maps ``parameter`` to an option name, the GUI to a form field and a
translated message; neither has to parse the text.
"""
from __future__ import annotations

import math


class DesignError(ValueError):
    """A parameter is outside the range the mechanism can be built with.

    ``parameter`` is the core name (``crank``, ``time_ratio``, ``stroke`` …),
    ``value`` the offending value and ``allowed`` a human-readable range.
    """

    def __init__(self, parameter: str, value: object, allowed: str) -> None:
        self.parameter = parameter
        self.value = value
        self.allowed = allowed
        super().__init__(f"{parameter} = {_fmt(value)}: {allowed}")


class FileFormatError(ValueError):
    """A design file that cannot be read; the current design stays untouched."""


def _fmt(value: object) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    return repr(value) if isinstance(value, str) else str(value)


def require_finite(parameter: str, value: object) -> float:
    try:
        number = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise DesignError(parameter, value, "must be a number") from None
    if not math.isfinite(number):
        raise DesignError(parameter, value, "must be a finite number")
    return number


def require_range(parameter: str, value: object, low: float, high: float,
                  unit: str = "", low_open: bool = True, high_open: bool = False) -> float:
    """Check ``low < value <= high`` (openness selectable) and return it as float."""
    number = require_finite(parameter, value)
    too_low = number <= low if low_open else number < low
    too_high = number >= high if high_open else number > high
    if too_low or too_high:
        raise DesignError(parameter, number, range_text(low, high, unit, low_open, high_open))
    return number


def range_text(low: float, high: float, unit: str = "", low_open: bool = True,
               high_open: bool = False) -> str:
    """The ``allowed`` text of a range check, e.g. "must be > 1 and ≤ 5"."""
    left = ">" if low_open else "≥"
    right = "<" if high_open else "≤"
    unit_text = f" {unit}" if unit else ""
    return f"must be {left} {low:g} and {right} {high:g}{unit_text}"
