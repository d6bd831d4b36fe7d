"""What every part's tab does, written once: the inputs' column (the form, the part's own
widgets, the export buttons) in a scroll area beside the part's drawing over its results,
and the export dialog that commits what is being typed, asks for a file and says a failure
in a message, never as a traceback.

A part's tab subclasses :class:`PartTab`, names its exports (``EXPORTS``; each ``kind`` is
done by its ``export_<kind>(path)``) with their file filters (``export_choice``), and builds
its widgets (after the part model, form and drawing: ``MODEL``, ``FORM``, ``VIEW``) before calling
:meth:`PartTab._assemble`.
"""
from __future__ import annotations

import os

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtWidgets import (QGridLayout, QHBoxLayout, QMessageBox, QPushButton, QScrollArea, QSplitter,
                               QVBoxLayout, QWidget)

from shaperapp.design.model import DesignModel
from shaperapp.widgets import file_dialogs
from shaperapp.widgets.ask import use_last_valid
from shaperapp.widgets.busy import busy_cursor
from shaperapp.widgets.file_messages import failure_reason

from .form import PartForm
from .model import PartModel
from .view import PartView


class PartTab(QWidget):
    """The layout and the exports of a part's tab; ``form`` is the part's :class:`PartForm`."""

    EXPORTS: tuple[str, ...] = ()
    MODEL: type[PartModel]
    FORM: type[PartForm]
    VIEW: type[PartView]

    def __init__(self, model: DesignModel, parent: QWidget | None, part_model: PartModel | None) -> None:
        """The part's model is the one given (the window keeps it from the start, for Save,
        and builds the tab only when it is first shown), else one of the tab's own."""
        super().__init__(parent)
        self.part_model = part_model if part_model is not None else self.MODEL(model, self)
        self.form = self.FORM(self.part_model)
        self.view = self.VIEW(self.part_model)

    def _assemble(self, above: tuple[QWidget, ...], below: tuple[QWidget, ...],
                  bottom: QWidget) -> QScrollArea:
        """Lay the tab out: on the left ``above``, the export buttons (two a row) and ``below``
        in a scroll area (returned, for the subclass to size), on the right the drawing over
        ``bottom``."""
        self.buttons = {kind: QPushButton(self) for kind in self.EXPORTS}
        for kind, button in self.buttons.items():
            button.clicked.connect(lambda _checked=False, k=kind: self._export_dialog(k))
        side = QWidget()
        column = QVBoxLayout(side)
        for widget in above:
            column.addWidget(widget)
        row = QGridLayout()
        for i, button in enumerate(self.buttons.values()):
            row.addWidget(button, i // 2, i % 2)
        column.addLayout(row)
        for widget in below:
            column.addWidget(widget)
        column.addStretch(1)
        scroll = QScrollArea()
        scroll.setWidget(side)
        scroll.setWidgetResizable(True)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        split = QSplitter(Qt.Orientation.Vertical)
        split.addWidget(self.view)
        split.addWidget(bottom)
        split.setStretchFactor(0, 1)
        split.setStretchFactor(1, 1)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(2, 2, 2, 2)
        layout.addWidget(scroll)
        layout.addWidget(split, 1)
        return scroll

    # ---- what a part fills in ----------------------------------------------
    def export_choice(self, kind: str) -> tuple[str, str]:
        """(the file dialog's filters, the file name it proposes) of an export ``kind``."""
        raise NotImplementedError

    def export_title(self) -> str:
        """The export dialog's title (and its failure message's), in the current language."""
        raise NotImplementedError

    def export_selected(self, kind: str) -> str:
        """The filter the dialog of ``kind`` selects first ('': Qt's first)."""
        return ""

    def export_chosen(self, kind: str, path: str, chosen: str) -> None:
        """Write ``kind`` to ``path``; ``chosen`` is the dialog's filter, for a part whose
        filters say how a type is written (the gear sheet's DXF texts). May raise."""
        getattr(self, "export_" + kind)(path)

    # ---- the shared path ---------------------------------------------------
    def _export_dialog(self, kind: str) -> None:
        self.form.commit()
        if not self._confirm_last_valid():
            return
        filters, name = self.export_choice(kind)
        title = self.export_title()
        path, chosen = file_dialogs.save_file_and_filter(
            self, title, os.path.join(os.path.expanduser("~"), name), filters, self.export_selected(kind))
        if not path:
            return
        try:
            with busy_cursor():         # the gear sheet as DXF with outlined texts: 0.5 s
                self.export_chosen(kind, path, chosen)
        except Exception as exc:        # never to sys.excepthook: the reason, in a message
            QMessageBox.warning(self, title, failure_reason(exc))

    def _confirm_last_valid(self) -> bool:
        """True when every typed field is valid, or the user agreed to export the last valid
        part: while a field is refused, an export writes the part on screen, which the fields
        no longer show (z1 typed as 4, a sheet of z1 = 13), so it asks first, as File › Export
        asks for the design's inputs (``Document.confirm_valid``)."""
        error = self.part_model.error
        if error is None:
            return True
        if not self.part_model.own_value:       # the part held is an earlier design's
            why = QCoreApplication.translate("PartTab", "Nothing was exported.")
            QMessageBox.warning(self, self.export_title(), self.form.describe(error) + "\n\n"
                                + self.part_model.unmade_text() + " " + why)
            return False
        # an explicit context: self.tr here would look the text up under the subclass's
        question = QCoreApplication.translate("PartTab", "%1 Export it instead?").replace("%1", self.form.kept())
        return use_last_valid(self, self.export_title(), self.form.describe(error), question)
