"""An error the model shows, kept with the signal that tells of its change.

The model keeps two (the design's inputs, the loads), each emitting its signal only when
what the error says changes, so that a keystroke that keeps a field invalid in the same
way redraws nothing.
"""
from __future__ import annotations

import re

from PySide6.QtCore import SignalInstance

from core.base.errors import DesignError

_RANGE = re.compile(r"must be (≥|>) (\S+) and (<|≤) (\S+)")


def same_error(a: DesignError | None, b: DesignError | None) -> bool:
    """Both none, or both saying the same: a keystroke that keeps a field invalid in the
    same way changes no error, so the model emits nothing."""
    return (a is None) == (b is None) and str(a) == str(b)


class ShownError:
    """The error now shown (``value``, None when there is none) and its ``changed`` signal."""

    def __init__(self, changed: SignalInstance) -> None:
        self.value: DesignError | None = None
        self._changed = changed

    def set(self, error: DesignError | None, force: bool = False) -> None:
        """Show ``error``; the signal when it says something else, or always when ``force``."""
        same = same_error(error, self.value)
        self.value = error
        if not same or force:
            self._changed.emit()


def as_typed(error: DesignError | None) -> DesignError | None:
    """``error`` in the units of the field it came from. The Loads form takes the idle margin
    in % and core checks the fraction: "less than 0.5" beside a field in % sent a user who
    typed 60 to type 0.49, an idle margin of 0.49 %. Restated: "less than 50 %"."""
    match = None if error is None or error.parameter != "idle_fraction" else _RANGE.fullmatch(error.allowed)
    if match is None:
        return error
    low, high = (100.0 * float(match.group(i)) for i in (2, 4))
    value = 100.0 * error.value if isinstance(error.value, float) else error.value
    return DesignError(error.parameter, value, f"must be {match.group(1)} {low:g} and {match.group(3)} {high:g} %")
