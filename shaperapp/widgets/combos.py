"""Refilling a choice list in the current language without losing the user's choice."""
from __future__ import annotations

from PySide6.QtWidgets import QComboBox


def fill_combo(combo: QComboBox, items: dict[str, str], select: str | None = None) -> None:
    """``items`` (key → shown text) into ``combo`` without emitting signals, keeping the
    current key (or choosing ``select``); the first item when that key is not among them."""
    current = combo.currentData() if select is None else select
    combo.blockSignals(True)
    combo.clear()
    for key, text in items.items():
        combo.addItem(text, key)
    combo.setCurrentIndex(max(combo.findData(current), 0))
    combo.blockSignals(False)
