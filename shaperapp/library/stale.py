"""The Library pane's notice of figures an older version computed, with Recompute.

A library keeps each entry's figures and which computation made them
(``core.space.figures.FIGURES_VERSION``). After an update that computes a figure
differently, the list would sort and filter by the old numbers; this bar says how
many entries that concerns and recomputes them from their stored designs
(``Library.refresh_figures``, the same as ``shaper library refresh``), with a
progress dialog that can be cancelled: every batch written stays written.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, Qt, Signal
from PySide6.QtWidgets import QApplication, QHBoxLayout, QLabel, QProgressDialog, QPushButton, QWidget

from core.library import Library
from core.library.store import LibraryError


class _Cancelled(Exception):
    pass


class StaleFiguresBar(QWidget):
    """Hidden while every entry's figures are current."""

    refreshed = Signal()            # figures were written: the list should be read again
    failed = Signal(str)            # a translated sentence for the user

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._library: Library | None = None
        self._count = 0
        self.label = QLabel()
        self.label.setWordWrap(True)
        self.button = QPushButton()
        self.button.clicked.connect(self.recompute)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.label, 1)
        layout.addWidget(self.button)
        self.setStyleSheet("StaleFiguresBar { background: #fff4d6; }")
        self.setAttribute(Qt.WidgetAttribute.WA_StyledBackground)
        self.hide()

    def update_for(self, library: Library | None) -> None:
        """Count the stale entries of ``library`` (None: none open) and show or hide."""
        self._library = library
        try:
            self._count = len(library.stale_names()) if library is not None else 0
        except LibraryError:
            self._count = 0
        self._retranslate()
        self.setVisible(self._count > 0)

    def recompute(self) -> None:
        library = self._library
        if library is None or self._count == 0:
            return
        dialog = QProgressDialog(self.tr("Recomputing the figures…"), self.tr("Cancel"), 0, self._count, self)
        dialog.setWindowTitle(self.tr("Design library"))
        dialog.setWindowModality(Qt.WindowModality.WindowModal)
        dialog.setMinimumDuration(300)

        def progress(done: int, total: int) -> None:
            dialog.setMaximum(total)
            dialog.setValue(done)
            QApplication.processEvents()
            if dialog.wasCanceled():
                raise _Cancelled
        try:
            report = library.refresh_figures(progress=progress)
        except _Cancelled:
            report = None
        except LibraryError as exc:
            self.failed.emit(self.tr("Could not recompute the figures: %1").replace("%1", str(exc)))
            report = None
        finally:
            dialog.reset()
            dialog.deleteLater()
        self.refreshed.emit()
        self.update_for(library)
        if report is not None and report.failed:
            names = "\n".join(f"{name}: {why}" for name, why in report.failed[:20])
            self.failed.emit(self.tr("These designs can no longer be computed; their figures were "
                                     "left as they were:") + "\n" + names)

    def changeEvent(self, event) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self.label.setText(self.tr("The figures of %1 design(s) in this library were computed by an "
                                   "older version of Shaper Designer.").replace("%1", str(self._count)))
        self.button.setText(self.tr("Recompute"))
        self.button.setToolTip(self.tr("Recompute their figures from the stored designs"))
