"""File dialogs whose every label follows the UI language.

Qt 6's own file dialog labels "&Look in:" and "Files of &type:", but Qt's
shipped Chinese catalogue (qtbase_zh_CN) only knows the older "Look in:" and
"Files of type:", so those two labels stayed English in a Chinese UI. When the
catalogue translates the older texts, they are set explicitly. Native dialogs
(Windows, macOS, desktop portals) ignore this and use the system's language.
"""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QFileDialog, QWidget

# (label, text in Qt's catalogue) for labels whose Qt 6 text the catalogue lacks
_LABELS = ((QFileDialog.DialogLabel.LookIn, "Look in:"), (QFileDialog.DialogLabel.FileType, "Files of type:"))


def _dialog(parent: QWidget | None, title: str, start: str, filters: str) -> QFileDialog:
    dialog = QFileDialog(parent, title, start, filters)
    for label, text in _LABELS:
        translated = QCoreApplication.translate("QFileDialog", text)
        if translated != text:
            dialog.setLabelText(label, translated)
    return dialog


def _run(dialog: QFileDialog) -> str:
    if dialog.exec() != QFileDialog.DialogCode.Accepted or not dialog.selectedFiles():
        return ""
    return dialog.selectedFiles()[0]


def open_file_name(parent: QWidget | None, title: str, start: str, filters: str) -> str:
    """An existing file chosen by the user, or '' when cancelled."""
    dialog = _dialog(parent, title, start, filters)
    dialog.setAcceptMode(QFileDialog.AcceptMode.AcceptOpen)
    dialog.setFileMode(QFileDialog.FileMode.ExistingFile)
    return _run(dialog)


def save_file_name(parent: QWidget | None, title: str, start: str, filters: str) -> str:
    """A file name to write (overwriting is confirmed by the dialog), or '' when cancelled."""
    dialog = _dialog(parent, title, start, filters)
    dialog.setAcceptMode(QFileDialog.AcceptMode.AcceptSave)
    dialog.setFileMode(QFileDialog.FileMode.AnyFile)
    return _run(dialog)
