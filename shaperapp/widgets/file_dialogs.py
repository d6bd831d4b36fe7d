"""File dialogs whose every label follows the UI language.

Qt 6's own file dialog labels "&Look in:" and "Files of &type:", but Qt's
shipped Chinese catalogue (qtbase_zh_CN) only knows the older "Look in:" and
"Files of type:", so those two labels stayed English in a Chinese UI. When the
catalogue translates the older texts, they are set explicitly. Native dialogs
(Windows, macOS, desktop portals) ignore this and use the system's language.

Every Qt file dialog, also those of ``QFileDialog.getSaveFileName`` and the like, is
fixed up when it is shown (``localize``, called by ``dialog_titles``' filter): the
labels as above, the detail view's dates in the UI language's short format (Qt's file
model writes them in the system locale's, "25 11 2026 12:15" in a Chinese UI), and
its size and date columns as wide as their texts (they elided, "852…KiB").
"""
from __future__ import annotations

from PySide6.QtCore import QAbstractProxyModel, QCoreApplication, QLocale
from PySide6.QtWidgets import (QFileDialog, QFileSystemModel, QHeaderView, QStyledItemDelegate,
                               QTreeView, QWidget)

# (label, text in Qt's catalogue) for labels whose Qt 6 text the catalogue lacks
_LABELS = ((QFileDialog.DialogLabel.LookIn, "Look in:"), (QFileDialog.DialogLabel.FileType, "Files of type:"))


SIZE_COLUMN, DATE_COLUMN = 1, 3      # of QFileSystemModel


class _DateDelegate(QStyledItemDelegate):
    """A file's date in the default locale's short format (the UI language's)."""

    def initStyleOption(self, option, index) -> None:
        super().initStyleOption(option, index)
        model = index.model()
        while isinstance(model, QAbstractProxyModel):
            index = model.mapToSource(index)
            model = model.sourceModel()
        if isinstance(model, QFileSystemModel) and index.isValid():
            option.text = QLocale().toString(model.lastModified(index), QLocale.FormatType.ShortFormat)


def localize(dialog: QFileDialog) -> None:
    """Labels, dates and column widths of a Qt file dialog in the UI language (see above)."""
    for label, text in _LABELS:
        translated = QCoreApplication.translate("QFileDialog", text)
        if translated != text:
            dialog.setLabelText(label, translated)
    for view in dialog.findChildren(QTreeView):
        if not isinstance(view.itemDelegateForColumn(DATE_COLUMN), _DateDelegate):
            view.setItemDelegateForColumn(DATE_COLUMN, _DateDelegate(view))
        header = view.header()
        for column in (SIZE_COLUMN, DATE_COLUMN):
            if column < header.count():
                header.setSectionResizeMode(column, QHeaderView.ResizeMode.ResizeToContents)


def _dialog(parent: QWidget | None, title: str, start: str, filters: str) -> QFileDialog:
    dialog = QFileDialog(parent, title, start, filters)
    localize(dialog)
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
    return save_file_and_filter(parent, title, start, filters)[0]


def save_file_and_filter(parent: QWidget | None, title: str, start: str, filters: str,
                         selected: str = "") -> tuple[str, str]:
    """:func:`save_file_name` and the filter chosen with it, ``selected`` first: where two
    filters of one type say how it is written (the scheme's DXF texts). ('', '') when cancelled."""
    dialog = _dialog(parent, title, start, filters)
    dialog.setAcceptMode(QFileDialog.AcceptMode.AcceptSave)
    dialog.setFileMode(QFileDialog.FileMode.AnyFile)
    if selected:
        dialog.selectNameFilter(selected)
    path = _run(dialog)
    return path, dialog.selectedNameFilter() if path else ""
