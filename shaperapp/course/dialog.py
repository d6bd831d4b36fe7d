"""File › Export course design…: the sheets' paper, DXF and speed (``shaper course``'s
--sheet, --dxf, --rpm-index), a folder, then the report and every sheet written into it
in a child process under a progress dialog that leaves the window usable
(``widgets.export_process``), by the same code as ``shaper course``.

The design is the one on screen as Save would write it (``document.saved_parts``), read
back by the design file's own reader, so the GUI and the command make the same files
and refuse the same things, before anything is written. The cover fields are the report
dialog's (``COVER_SETTINGS``). The bar moves with every section and page of the report
and every sheet. Cancel stops at the next of those steps: the files written so far stay,
each complete, and the message says how many; the file being made is not written (each
file is written atomically, in one go, once it is whole).
"""
from __future__ import annotations

import datetime
import json
import os
from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication, QSettings
from PySide6.QtWidgets import (QCheckBox, QComboBox, QDialog, QDialogButtonBox, QFileDialog,
                               QFormLayout, QLabel, QMessageBox, QWidget)

from core.course_design.plan import CourseError, plan_course
from core.files.design_file import parse_design
from core.drawing.sheet import PAPERS
from core.files.io import design_document

from shaperapp.design.document import saved_parts
from shaperapp.design.model import DesignModel
from shaperapp.widgets.cad_font import CadFontChoice, outline_font_problem
from shaperapp.widgets.command_line import COVER_FIELDS, COVER_SETTINGS, design_file_name, plain_text
from shaperapp.widgets.fonts import MissingFontError
from shaperapp.widgets.i18n import join_sentences
from shaperapp.widgets.file_messages import describe_os_error, failure_reason
from shaperapp.widgets.export_child import job_bytes
from shaperapp.widgets.export_process import ChildExport

from .write import Covering, write_course_of


translate = QCoreApplication.translate


def key_names() -> dict[str, str]:
    """The design file's parts as the refusal names them, in the UI's language."""
    return {"rpm": translate("CourseExport", "the speeds"),
            "forces": translate("CourseExport", "the loads"),
            "cam": translate("CourseExport", "the feed cam"),
            "gear": translate("CourseExport", "the gear pair")}


@dataclass(frozen=True)
class CourseOptions:
    """What ``shaper course`` takes besides the design: --sheet, --dxf, --rpm-index and
    --cad-font."""

    paper: str = "A1"
    dxf: bool = False
    speed: int = 0          # the sheets' speed, an index into the design's speeds
    cad_font: str = "gb"    # the DXFs' texts (core.drawing.CAD_FONTS)


class CourseOptionsDialog(QDialog):
    """The sheets' paper (A0–A3), DXF beside each PDF (and its CAD texts), and the speed
    they are drawn at. OK with outlines chosen and no font for them says so and stays."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None,
                 settings: QSettings | None = None) -> None:
        super().__init__(parent)
        self.setWindowTitle(self.tr("Export course design"))
        self.paper = QComboBox()
        self.paper.addItems(list(PAPERS))
        self.paper.setCurrentText(CourseOptions.paper)
        self.dxf = QCheckBox(self.tr("Each sheet as DXF too, beside its PDF"))
        self.speed = QComboBox()
        for rpm in model.rpms:
            self.speed.addItem(self.tr("%1 r/min").replace("%1", f"{rpm:g}"))
        form = QFormLayout(self)
        form.addRow(self.tr("Paper of the sheets:"), self.paper)
        form.addRow(self.tr("Sheets at crank speed:"), self.speed)
        form.addRow(self.dxf)
        self.cad_font = CadFontChoice(settings)
        self.cad_font.setEnabled(False)
        form.addRow(self.tr("CAD texts of the DXFs:"), self.cad_font)
        self.message = QLabel()
        self.message.setWordWrap(True)
        form.addRow(self.message)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        form.addRow(buttons)
        self.dxf.toggled.connect(self.cad_font.setEnabled)
        self.dxf.toggled.connect(self._show_problem)
        self.cad_font.currentIndexChanged.connect(self._show_problem)

    def _show_problem(self) -> None:
        self.message.setText(self.cad_font.problem())

    def accept(self) -> None:
        """Remember the CAD texts; not with outlines that cannot be drawn (the message says why)."""
        self._show_problem()
        if self.message.text():
            return
        if self.dxf.isChecked():
            self.cad_font.remember()
        super().accept()

    def options(self) -> CourseOptions:
        return CourseOptions(self.paper.currentText(), self.dxf.isChecked(), self.speed.currentIndex(),
                             self.cad_font.value() if self.dxf.isChecked() else "gb")


def ask_course_options(model: DesignModel, parent: QWidget | None,
                       settings: QSettings | None = None) -> CourseOptions | None:
    """The options as the user chooses them, or None when the dialog is cancelled."""
    dialog = CourseOptionsDialog(model, parent, settings)
    accepted = dialog.exec() == QDialog.DialogCode.Accepted
    dialog.deleteLater()
    return dialog.options() if accepted else None


def covering(model: DesignModel, settings: QSettings | None, paper: str = "A1", speed: int = 0,
             cad_font: str = "gb") -> Covering:
    """The design's name (its file's), today's date, the report dialog's cover fields, the
    sheets' paper and speed, the DXFs' texts."""
    cover = {key: plain_text(str(settings.value(COVER_SETTINGS + key, "") or "")) if settings else ""
             for key in COVER_FIELDS}
    name = design_file_name(model.path) if model.path else ""
    return Covering(paper, name, datetime.date.today().isoformat(), cover, cad_font=cad_font, speed=speed)


def plan(model: DesignModel, folder: str, dxf: bool = False):
    """The checked course design of the model (CourseError as ``shaper course`` refuses)."""
    doc = design_document(model.valid_spec, model.rpms, model.step_deg, saved_parts(model))
    name = os.path.basename(model.path) if model.path else translate("CourseExport", "the design")
    read = parse_design(json.dumps(doc).encode("utf-8"), name)
    return plan_course(read, frozenset(doc), name, folder, dxf=dxf)


def refusal(exc: CourseError) -> str:
    """Why nothing was written, in the UI's language."""
    if exc.missing:
        names = ", ".join(key_names().get(key, key) for key, _ in exc.missing)
        text = translate("CourseExport", "The design lacks what the course design needs: %1. "
                         "Nothing was written.")
        return text.replace("%1", names)
    if exc.option == "--cad-font":      # outline_font_problem's words, already translated
        return join_sentences(exc.reason, translate("CourseExport", "Nothing was written."))
    if exc.option == "--output":
        return translate("CourseExport", "Nothing can be written into this folder; choose another. "
                         "Nothing was written.")
    reason = failure_reason(exc.cause) if exc.cause is not None else exc.reason
    return translate("CourseExport", "The course design cannot be made: %1. Nothing was written."
                     ).replace("%1", reason)


def export_course(model: DesignModel, folder: str, language: str, parent: QWidget | None = None,
                  settings: QSettings | None = None,
                  options: CourseOptions = CourseOptions()) -> ChildExport:
    """Start writing the course design into ``folder`` in a child process, under a progress
    dialog that leaves the window usable; returns the running export, whose ``result`` at
    its end is the paths written and '' or why it stopped (in the UI's language).
    CourseError (nothing started) when the design cannot make one (:func:`refusal`), or
    when the DXFs' outlines find no font (``--cad-font``)."""
    course = plan(model, folder, options.dxf)
    problem = outline_font_problem(options.cad_font) if options.dxf else ""
    if problem:
        raise CourseError("--cad-font", problem)
    total = len(course.files)
    job = job_bytes(write_course_of, language, course=course, language=language,
                    covering=covering(model, settings, options.paper, options.speed, options.cad_font))

    def conclude(run: ChildExport) -> tuple[list[str], str]:
        written = list(run.files)
        if run.state == "done":
            return written, ""
        if run.state == "cancelled":
            text = translate("CourseExport", "Cancelled: %1 of %2 files written, each complete.")
            return written, text.replace("%1", str(len(written))).replace("%2", str(total))
        failure = course_failure(run.error, folder)
        if written:
            failure = join_sentences(failure, translate("CourseExport", "The %1 files written before it are "
                                                        "complete.").replace("%1", str(len(written))))
        return written, failure
    return ChildExport(job, [file.path for file in course.files], folder,
                       translate("CourseExport", "Export course design"),
                       translate("CourseExport", "Writing the course design…"), parent, conclude)


def course_failure(exc: BaseException | None, folder: str) -> str:
    """Why the course design stopped, in the UI's language: one line, never a traceback."""
    if isinstance(exc, MissingFontError):
        return translate("CourseExport", "No font with Chinese characters is installed: install one "
                         "(on Debian/Ubuntu: fonts-noto-cjk) or switch the language to English.")
    if isinstance(exc, OSError):
        return translate("CourseExport", "Could not write %1: %2").replace(
            "%1", exc.filename or folder).replace("%2", describe_os_error(exc))
    return translate("CourseExport", "The course design cannot be made: %1.").replace(
        "%1", failure_reason(exc) if exc is not None else "?")


def export_course_dialog(model: DesignModel, parent: QWidget, language: str, start_dir: str,
                         settings: QSettings | None = None) -> ChildExport | None:
    """Ask for the options and a folder and start writing the course design into it;
    returns the running export (its ``result``: :func:`export_course`'s) or None when
    nothing was started. A refusal or a failure is shown in a message."""
    options = ask_course_options(model, parent, settings)
    if options is None:
        return None
    folder = QFileDialog.getExistingDirectory(
        parent, translate("CourseExport", "Export course design: choose a folder"), start_dir)
    if not folder:
        return None
    title = translate("CourseExport", "Export course design")
    try:
        run = export_course(model, folder, language, parent, settings, options)
    except CourseError as exc:
        QMessageBox.warning(parent, title, refusal(exc))
        return None

    def tell() -> None:
        if run.result[1]:
            QMessageBox.warning(parent, title, run.result[1])
    run.ended.connect(tell)
    return run
