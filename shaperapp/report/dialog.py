"""File › Export report…: choose the positions, the two diagram angles and whether to
include the comparison, then the file.

The report is built from the model's design on screen, its speeds and loads,
in the UI's language, by the same code as ``shaper report``. The comparison's
other designs are the Compare tab's, which it keeps on the model
(``DesignModel.comparison_candidates``), so this dialog reads only the model.
"""
from __future__ import annotations

import datetime
import html
import os
from dataclasses import replace
from typing import Callable

from PySide6.QtCore import QCoreApplication, QSettings
from PySide6.QtWidgets import (QCheckBox, QDialog, QDialogButtonBox, QDoubleSpinBox, QFileDialog,
                               QFormLayout, QLineEdit, QMessageBox, QSpinBox, QWidget)

from core.cli.allocator import return_freed_memory
from core.cam.file import cam_from_dict
from core.space.compare import MAX_DESIGNS, Candidate
from core.forces.masses import masses_for_design
from core.course_design.positions import DEFAULT_COUNT, MAX_COUNT, position_table, positions
from core.base.progress import Progress
from shaperapp.design.gear_source import design_gear
from shaperapp.design.model import DesignModel

from .blocks import Cover
from .command import MAX_TEXT
from .command import report_kind, write_report
from .content import BUILD_SHARE, Options, build, default_diagram_angles, inputs_name
from shaperapp.widgets.fonts import MissingFontError
from shaperapp.widgets.command_line import plain_text, printable_labels
from shaperapp.widgets.file_messages import describe_os_error, failure_reason
from shaperapp.widgets.export_child import job_bytes
from shaperapp.widgets.export_process import ChildExport

translate = QCoreApplication.translate


class ReportOptionsDialog(QDialog):
    """Positions count and the crank angles of the two vector-diagram positions."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None,
                 settings: QSettings | None = None) -> None:
        super().__init__(parent)
        self.setWindowTitle(self.tr("Export design report"))
        self._settings = settings
        self.design_name = QLineEdit(design_name(model))
        self.design_name.setPlaceholderText(inputs_name(model.valid_spec))
        self.cover = {}
        for field in Cover.FIELDS + ("date",):
            edit = QLineEdit()
            edit.setMaxLength(MAX_TEXT)
            if settings is not None and field != "date":     # the student's, for every report
                edit.setText(str(settings.value(f"report/{field}", "") or ""))
            self.cover[field] = edit
        self.cover["date"].setText(datetime.date.today().isoformat())
        wide = self.fontMetrics().horizontalAdvance(self.design_name.placeholderText() + "MMMM")
        for edit in [self.design_name, *self.cover.values()]:
            edit.setMinimumWidth(max(wide, 24 * self.fontMetrics().averageCharWidth()))
        self.count = QSpinBox()
        self.count.setRange(1, MAX_COUNT)
        self.count.setValue(DEFAULT_COUNT)
        design = model.design
        table = position_table(design, positions(design, DEFAULT_COUNT), model.rpms[:1])
        work, back = default_diagram_angles(table, model.metrics)
        self.angles = []
        for value in (work, back):
            box = QDoubleSpinBox()
            box.setRange(-360.0, 720.0)
            box.setDecimals(2)
            box.setSuffix(" °")
            box.setValue(value)
            self.angles.append(box)
        form = QFormLayout(self)
        form.addRow(self.tr("Design name:"), self.design_name)
        for field, label in zip(Cover.FIELDS + ("date",), (
                self.tr("Student:"), self.tr("Student number:"), self.tr("Class:"), self.tr("School:"),
                self.tr("Supervisor:"), self.tr("Date:"))):
            form.addRow(label, self.cover[field])
        form.addRow(self.tr("Positions in the table:"), self.count)
        form.addRow(self.tr("Vector diagrams at φ (working stroke):"), self.angles[0])
        form.addRow(self.tr("Vector diagrams at φ (return stroke):"), self.angles[1])
        self.others = other_designs(model)
        self.include_comparison = QCheckBox(self.tr("Include the comparison"))
        self.include_comparison.setEnabled(1 <= len(self.others) < MAX_DESIGNS)
        self.include_comparison.setChecked(self.include_comparison.isEnabled())
        if not self.others:
            tip = self.tr("Add designs on the Compare tab to compare this design with them.")
        elif len(self.others) >= MAX_DESIGNS:
            tip = self.tr("The Compare tab has %1 designs besides this one; a report compares "
                          "at most %2.").replace("%1", str(len(self.others))) \
                .replace("%2", str(MAX_DESIGNS - 1))
        else:
            # a tooltip is rich text when it looks like it: the names go in escaped, in <p>
            tip = "<p>" + html.escape(self.tr("This design beside the Compare tab's designs (%1) at "
                                              "%2 r/min.")).replace("%1", html.escape(", ".join(
                                                  c.label for c in self.others))) \
                .replace("%2", f"{model.rpms[0]:g}") + "</p>"
        self.include_comparison.setToolTip(tip)
        form.addRow(self.include_comparison)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        form.addRow(buttons)

    def options(self) -> Options:
        others = tuple(self.others) if self.include_comparison.isChecked() else ()
        cover = Cover(**{field: plain_text(self.cover[field].text()) for field in Cover.FIELDS})
        return Options(self.count.value(), (self.angles[0].value(), self.angles[1].value()), others,
                       cover)

    def name(self) -> str:
        return plain_text(self.design_name.text())

    def date(self) -> str:
        return plain_text(self.cover["date"].text()) or datetime.date.today().isoformat()

    def remember(self) -> None:
        """Keep the cover fields (not the date) for the next report, in this or a later run."""
        if self._settings is not None:
            for field in Cover.FIELDS:
                self._settings.setValue(f"report/{field}", self.cover[field].text().strip())


def design_name(model: DesignModel) -> str:
    """The design's file name without its type, or '' for a design not saved to a file."""
    if not model.path:
        return ""
    name = os.path.splitext(os.path.basename(model.path))[0]
    return plain_text(name[: -len(".shaper")] if name.endswith(".shaper") else name)


def other_designs(model: DesignModel) -> list[Candidate]:
    """The Compare tab's designs other than the one on screen (same inputs and loads)."""
    return printable_labels([c for c in model.comparison_candidates
                             if (c.spec, c.masses) != (model.valid_spec, model.masses)])


def export_report(model: DesignModel, path: str, language: str, options: Options = Options(),
                  name: str = "", date: str = "", progress: Progress = Progress()) -> int:
    """Build the report of the design on screen and write it (PDF, or HTML for .html/.htm);
    ValueError for a name of another type, before anything is built. The design is
    called ``name``, else by its file name, else by its inputs. ``progress`` hears of every
    section and page; Cancelled when it says stop, and nothing is written."""
    report_kind(path)
    return write_report_of(progress, lambda _path: None, path, language,
                           **report_inputs(model, options, name, date))


def report_inputs(model: DesignModel, options: Options = Options(), name: str = "",
                  date: str = "") -> dict:
    """What the report is built from, taken from the model now: the snapshot an export in
    a child process works on while the design on screen may change."""
    masses = masses_for_design(model.design, model.masses)
    cam = model.saved_parts().get("cam")
    if cam is not None and options.cam is None:
        options = replace(options, cam=cam_from_dict(cam))
    gear = design_gear(model)
    if gear is not None and options.gear is None:
        options = replace(options, gear=gear)
    return {"spec": model.valid_spec, "rpms": list(model.rpms), "masses": masses,
            "title": name or design_name(model), "date": date or datetime.date.today().isoformat(),
            "options": options}


def write_report_of(progress: Progress, file_done: Callable[[str], None], path: str, language: str,
                    spec, rpms: list[float], masses, title: str, date: str, options: Options) -> int:
    """Build the report of :func:`report_inputs` and write it to ``path``; the page count.
    The job of the export's child process (``widgets.export_child``)."""
    report = build(spec, rpms, masses, title, date, language, options, progress.part(0.0, BUILD_SHARE))
    try:
        pages = write_report(report, path, progress.part(BUILD_SHARE, 1.0))
    finally:
        del report
        return_freed_memory()           # the report's figures and pages, freed now (issue 42)
    file_done(path)
    return pages


def export_report_dialog(model: DesignModel, parent: QWidget, language: str, start_dir: str,
                         settings: QSettings | None = None) -> ChildExport | None:
    """Ask for the options and a file, then start writing the report in a child process
    (the window stays usable); returns the running export, whose ``result`` at its end is
    the path written or '', or None when nothing was started. A failure is shown in a
    message. The cover fields are kept in ``settings`` once accepted."""
    dialog = ReportOptionsDialog(model, parent, settings)
    if dialog.exec() != QDialog.DialogCode.Accepted:
        return None
    dialog.remember()
    start = os.path.join(start_dir, "report.pdf")
    pdf_filter = translate("ReportOptionsDialog", "PDF document (*.pdf)")
    path, chosen = QFileDialog.getSaveFileName(
        parent, translate("ReportOptionsDialog", "Export design report"), start,
        pdf_filter + ";;" + translate("ReportOptionsDialog", "HTML page (*.html)"))
    if not path:
        return None
    if not os.path.splitext(os.path.basename(path))[1]:      # typed without a type
        path += ".pdf" if chosen == pdf_filter else ".html"
    try:
        report_kind(path)
    except ValueError:
        QMessageBox.warning(parent, translate("ReportOptionsDialog", "Export design report"),
                            translate("ReportOptionsDialog", "A report is written as PDF (.pdf) or HTML "
                                      "(.html, .htm); %1 is neither. Nothing was written.")
                            .replace("%1", os.path.basename(path)))
        return None
    title = translate("ReportOptionsDialog", "Export design report")
    job = job_bytes(write_report_of, language, path=path, language=language,
                    **report_inputs(model, dialog.options(), dialog.name(), dialog.date()))

    def conclude(run: ChildExport) -> str:
        if run.state == "done":
            return path
        if run.state == "failed":
            QMessageBox.warning(parent, title, report_failure(run.error, path))
        return ""
    return ChildExport(job, [path], path, title, translate("ReportOptionsDialog", "Writing the report…"),
                       parent, conclude)


def report_failure(exc: BaseException | None, path: str) -> str:
    """Why the report was not written, in the UI's language: one line, never a traceback."""
    if isinstance(exc, MissingFontError):
        return translate("ReportOptionsDialog", "No font with Chinese characters is installed. Install one "
                         "(on Debian/Ubuntu: fonts-noto-cjk) or switch the language to English.")
    if isinstance(exc, OSError):
        return translate("ReportOptionsDialog", "Could not write %1: %2").replace("%1", path) \
            .replace("%2", describe_os_error(exc))
    return translate("ReportOptionsDialog", "The report cannot be made: %1. Nothing was "
                     "written.").replace("%1", failure_reason(exc) if exc is not None else "?")
