"""An error the model shows, kept with the signal that tells of its change.

The model keeps two (the design's inputs, the loads), each emitting its signal only when
what the error says changes, so that a keystroke that keeps a field invalid in the same
way redraws nothing.
"""
from __future__ import annotations

from PySide6.QtCore import SignalInstance

from core.base.errors import DesignError


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
