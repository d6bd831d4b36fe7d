"""The one question an action asks while an input is refused: go on with the last valid
design or part (the file, the export), or stop. Cancel is the default, so Enter never
writes what the fields no longer show."""
from __future__ import annotations

from PySide6.QtWidgets import QMessageBox, QWidget


def use_last_valid(parent: QWidget, title: str, reason: str, question: str) -> bool:
    """True when the user, told ``reason`` (the refused input's message), answers Yes to
    ``question`` (whether to use the last valid one instead)."""
    answer = QMessageBox.question(parent, title, reason + "\n\n" + question,
                                  QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.Cancel,
                                  QMessageBox.StandardButton.Cancel)
    return answer == QMessageBox.StandardButton.Yes
