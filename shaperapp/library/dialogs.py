"""Small dialogs of the library pane: save under a name, and a refused library file."""
from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication
from PySide6.QtWidgets import (QDialog, QDialogButtonBox, QFormLayout, QLineEdit, QMessageBox,
                               QPlainTextEdit, QWidget)


class SaveDialog(QDialog):
    """Name, notes and tags for the design being saved to the library."""

    def __init__(self, parent: QWidget | None = None, name: str = "") -> None:
        super().__init__(parent)
        self.setWindowTitle(self.tr("Save design to library"))
        self.name_edit = QLineEdit(name)
        self.name_edit.setMaxLength(200)
        self.notes_edit = QPlainTextEdit()
        self.notes_edit.setTabChangesFocus(True)
        self.notes_edit.setMinimumHeight(80)
        self.tags_edit = QLineEdit()
        self.tags_edit.setPlaceholderText(self.tr("comma-separated, e.g. final, rod"))
        form = QFormLayout(self)
        form.addRow(self.tr("Name:"), self.name_edit)
        form.addRow(self.tr("Notes:"), self.notes_edit)
        form.addRow(self.tr("Tags:"), self.tags_edit)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Save
                                   | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        form.addRow(buttons)
        self._save = buttons.button(QDialogButtonBox.StandardButton.Save)
        self.name_edit.textChanged.connect(lambda text: self._save.setEnabled(bool(text.strip())))
        self._save.setEnabled(bool(name.strip()))

    def values(self) -> tuple[str, str, list[str]]:
        tags = [t.strip() for t in self.tags_edit.text().split(",") if t.strip()]
        return self.name_edit.text().strip(), self.notes_edit.toPlainText(), tags


def _tr(text: str) -> str:
    return QCoreApplication.translate("LibraryDialogs", text)


def ask_refused_library(parent: QWidget, message: str) -> str:
    """Tell the user a library file was refused; returns "copy", "other" or "cancel"."""
    box = QMessageBox(QMessageBox.Icon.Warning, _tr(TITLE), message,
                      QMessageBox.StandardButton.NoButton, parent)
    box.setInformativeText(_tr(ADVICE))
    copy = box.addButton(_tr(COPY), QMessageBox.ButtonRole.ActionRole)
    other = box.addButton(_tr(OTHER), QMessageBox.ButtonRole.AcceptRole)
    box.addButton(QMessageBox.StandardButton.Cancel)
    box.exec()
    clicked = box.clickedButton()
    return "copy" if clicked is copy else "other" if clicked is other else "cancel"


TITLE = QT_TRANSLATE_NOOP("LibraryDialogs", "Design library")
ADVICE = QT_TRANSLATE_NOOP("LibraryDialogs", "You can keep a copy of the file aside (it is copied byte "
                           "for byte), then choose or create another library.")
COPY = QT_TRANSLATE_NOOP("LibraryDialogs", "Copy it aside")
OTHER = QT_TRANSLATE_NOOP("LibraryDialogs", "Choose another library…")
