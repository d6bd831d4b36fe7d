"""File › Export drawing sheet…: paper, content, positions, polygon angles and title block,
with a preview of the sheet as it will be written; then PDF, SVG or DXF.

The sheet is built from the model's design on screen, the speed chosen of its speeds
(the first unless another is chosen; the title block shows it) and its
loads (the cam sheet from the Cam tab's last valid cam, the gear sheet from the design's
gear pair, ``shaperapp.design.gear_source``), in the UI's language, by the same code as ``shaper drawing``.
The file type is chosen before Save… so that the CAD texts (``--cad-font``) can be offered
for a DXF alone; a name typed with another type's suffix still writes that type.
"""
from __future__ import annotations

import datetime
import os
from typing import TYPE_CHECKING, Protocol

from PySide6.QtCore import QSettings, QSize, Qt, QTimer
from PySide6.QtGui import QImage, QPainter, QPixmap
from PySide6.QtWidgets import (QComboBox, QDialog, QDialogButtonBox, QDoubleSpinBox, QFileDialog,
                               QFormLayout, QHBoxLayout, QLabel, QLineEdit, QMessageBox, QSpinBox,
                               QWidget)

from core.drawing.motion import MAX_POSITIONS, motion_sheet
from core.drawing.sheet import PAPERS, Sheet
from core.forces.masses import masses_for_design
from core.base.errors import DesignError
from core.gear import GearPair, design_pair
from core.course_design.positions import DEFAULT_COUNT

from shaperapp.design.gear_source import design_gear
from shaperapp.design.model import DesignModel
from shaperapp.widgets.busy import busy_cursor
from shaperapp.widgets.cad_font import CadFontChoice, missing_font_text
from shaperapp.widgets.command_line import COVER_FIELDS, COVER_SETTINGS, MAX_TEXT, design_file_name, plain_text
from shaperapp.widgets.fonts import MissingFontError
from shaperapp.widgets.gear_messages import describe_gear_error
from shaperapp.widgets.file_messages import describe_os_error, failure_reason

from .content import DEFAULT_PAPER, SHEET_SUFFIXES, SheetChoice, build_sheet
from .render import paint_sheet, write_sheet

if TYPE_CHECKING:
    from core.cam import Cam


class SheetTypeError(ValueError):
    """A file name whose type is none of PDF, SVG and DXF (the message is the name)."""


class CamSource(Protocol):
    """Where the cam sheet's cam comes from: the Cam tab's model (its last valid cam, and
    the error of what is typed now, if any; ``own_value`` False, where it has it, when that
    cam is an earlier design's, this one's not made)."""

    @property
    def cam(self) -> "Cam": ...

    @property
    def error(self) -> "DesignError | None": ...


class PartErrorSource(Protocol):
    """The Gear tab's model, for the gear sheet: the error of what is typed now, if any (the
    sheet draws the design's last valid pair, ``shaperapp.design.gear_source``)."""

    @property
    def error(self) -> "DesignError | None": ...

PREVIEW_WIDTH = 560            # px of the preview's longer side


class DrawingSheetDialog(QDialog):
    """The choices on the left, the sheet's preview on the right; Save… writes the file."""

    def __init__(self, model: DesignModel, language: str = "en", parent: QWidget | None = None,
                 settings: QSettings | None = None, start_dir: str = "",
                 cam: CamSource | None = None, gear: PartErrorSource | None = None) -> None:
        super().__init__(parent)
        self._start = start_dir
        self._cam = cam                 # the Cam tab's model, for the cam sheet
        self._gear = gear               # the Gear tab's model, for the gear sheet's note
        self.setWindowTitle(self.tr("Export drawing sheet"))
        self.model, self.language, self._settings = model, language, settings
        self.written = ""
        self.paper = QComboBox()
        self.paper.addItems(list(PAPERS))
        self.paper.setCurrentText("A1")
        self.content = QComboBox()
        self.content.addItem(self.tr("Motion analysis"), "motion")
        self.content.addItem(self.tr("Kinetostatic analysis"), "forces")
        if cam is not None:
            self.content.addItem(self.tr("Feed cam"), "cam")
        self._add_gear_entry()
        self.speed = QComboBox()            # the design's speeds: the sheet is drawn at one
        for rpm in model.rpms:
            self.speed.addItem(self.tr("%1 r/min").replace("%1", f"{rpm:g}"))
        self.count = QSpinBox()
        self.count.setRange(1, MAX_POSITIONS)
        self.count.setValue(DEFAULT_COUNT)
        self.angles = []
        for _ in range(2):
            box = QDoubleSpinBox()
            box.setRange(-360.0, 720.0)
            box.setDecimals(2)
            box.setSuffix(" °")
            self.angles.append(box)
        # the report's cover fields, remembered where the report's dialog keeps them
        self.fields = {"design": QLineEdit(design_file_name(model.path) if model.path else ""),
                       **{key: QLineEdit() for key in COVER_FIELDS},
                       "date": QLineEdit(datetime.date.today().isoformat())}
        for key, edit in self.fields.items():
            edit.setMaxLength(MAX_TEXT)
            if settings is not None and key in COVER_FIELDS:
                edit.setText(str(settings.value(COVER_SETTINGS + key, "") or ""))
        self.file_type = QComboBox()
        for label, suffix in ((self.tr("PDF document"), ".pdf"), (self.tr("SVG image"), ".svg"),
                              (self.tr("DXF drawing"), ".dxf")):
            self.file_type.addItem(label, suffix)
        self.cad_font = CadFontChoice(settings)
        self.cad_font.setEnabled(False)         # a PDF until DXF is chosen
        form = QFormLayout()
        form.addRow(self.tr("Paper:"), self.paper)
        form.addRow(self.tr("Content:"), self.content)
        form.addRow(self.tr("Crank speed:"), self.speed)
        form.addRow(self.tr("Positions:"), self.count)
        form.addRow(self.tr("Polygons at φ (working stroke):"), self.angles[0])
        form.addRow(self.tr("Polygons at φ (return stroke):"), self.angles[1])
        form.addRow(self.tr("File type:"), self.file_type)
        form.addRow(self.tr("CAD texts:"), self.cad_font)
        form.addRow(self.tr("Design name:"), self.fields["design"])
        for key, label in zip(COVER_FIELDS + ("date",), (
                self.tr("Student:"), self.tr("Student number:"), self.tr("Class:"), self.tr("School:"),
                self.tr("Supervisor:"), self.tr("Date:"))):
            form.addRow(label, self.fields[key])
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Save
                                   | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(self._save_dialog)
        buttons.rejected.connect(self.reject)
        form.addRow(buttons)
        self.preview = QLabel()
        self.preview.setMinimumSize(QSize(PREVIEW_WIDTH, round(PREVIEW_WIDTH * 594 / 841)))
        self.preview.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.message = QLabel()
        self.message.setWordWrap(True)
        form.addRow(self.message)
        layout = QHBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.preview, 1)
        self._drawn_note = ""           # what the preview says (why it is empty, the cam's note)
        self._default_angles()
        self._content = self.content.currentData()
        self.file_type.currentIndexChanged.connect(self._type_changed)
        self.cad_font.currentIndexChanged.connect(self._show_notes)
        self.content.currentIndexChanged.connect(self._content_changed)
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(150)
        self._timer.timeout.connect(self.update_preview)
        for signal in (self.paper.currentIndexChanged, self.content.currentIndexChanged,
                       self.speed.currentIndexChanged, self.count.valueChanged, self.angles[0].valueChanged,
                       self.angles[1].valueChanged, *(e.textChanged for e in self.fields.values())):
            # not connect(self._timer.start): the signal's value (the paper's index 0 for A0,
            # the 24 positions) became the interval, and typing re-drew the sheet per key
            signal.connect(lambda *_: self._timer.start())
        self.update_preview()

    def _default_angles(self) -> None:
        """The polygon positions the sheet would choose (mid working, mid return stroke)."""
        drawn = motion_sheet(self.model.design, self.model.rpms[0], PAPERS["A3"],
                             count=self.count.value())
        for box, value in zip(self.angles, drawn.diagram_deg):
            box.setValue(value)

    def _add_gear_entry(self) -> None:
        """The meshing sheet, disabled (saying why) when the design has no gear pair."""
        self.content.addItem(self.tr("Gear meshing"), "gear")
        try:
            has_gear = design_gear(self.model) is not None
        except DesignError as exc:          # a "gear" object that is not valid
            has_gear, why = False, self.tr("The design's gear pair is not valid: %1").replace(
                "%1", describe_gear_error(exc))
        else:
            why = self.tr("The design has no gear pair: open a design file with one (its "
                          "\"gear\" object) to draw the meshing sheet.")
        index = self.content.count() - 1
        item = self.content.model().item(index)
        item.setEnabled(has_gear)
        if not has_gear:
            self.content.setItemData(index, why, Qt.ItemDataRole.ToolTipRole)

    def _type_changed(self) -> None:
        """The CAD texts are a DXF's alone."""
        self.cad_font.setEnabled(self.file_type.currentData() == ".dxf")
        self._show_notes()

    def _show_notes(self) -> None:
        """Under the choices: the preview's note, then why the chosen outlines cannot be drawn."""
        self.message.setText(" ".join(t for t in (self._drawn_note, self.cad_font.problem()) if t))

    def _content_changed(self) -> None:
        """The polygon angles are the linkage sheets' choice, not the cam's or the gear's; the
        number of positions only the motion sheet's, which draws the mechanism at each. The
        paper follows the content's usual one (A2 for the gear, as ``shaper drawing``) unless
        the user chose another."""
        content = self.content.currentData()
        self.count.setEnabled(content == "motion")
        self.speed.setEnabled(content != "gear")      # the meshing sheet has no speed
        for box in self.angles:
            box.setEnabled(content not in ("cam", "gear"))
        if self.paper.currentText() == DEFAULT_PAPER.get(self._content, "A1"):
            self.paper.setCurrentText(DEFAULT_PAPER.get(content, "A1"))
        self._content = content

    def choice(self) -> SheetChoice:
        text = {key: plain_text(edit.text()) for key, edit in self.fields.items()}   # a pasted tab …
        content = self.content.currentData()
        return SheetChoice(content, self.paper.currentText(), self.count.value(),
                           (self.angles[0].value(), self.angles[1].value()), text["design"],
                           text["student"], text["date"] or datetime.date.today().isoformat(),
                           text["school"], self._cam_of_design() if content == "cam" and self._cam else None,
                           text["number"], text["group"], text["supervisor"],
                           self._gear_pair() if content == "gear" else None,
                           self.speed.currentIndex() if content != "gear" else 0)

    def _cam_of_design(self) -> "Cam":
        """The Cam tab's cam; its error when this design's cam cannot be made: the tab then
        still holds the cam of the design opened before, which is no sheet of this one."""
        if not getattr(self._cam, "own_value", True):
            raise self._cam.error
        return self._cam.cam

    def _gear_pair(self) -> "GearPair | None":
        """The design's gear pair (DesignError when it cannot be made: the preview says why)."""
        inputs = design_gear(self.model)
        return None if inputs is None else design_pair(inputs)

    def sheet(self) -> Sheet:
        masses = masses_for_design(self.model.design, self.model.masses)
        return build_sheet(self.model.valid_spec, self.model.rpms, masses, self.choice())

    def update_preview(self) -> None:
        """The sheet painted as it will print, scaled to the preview; a sheet that cannot be
        built leaves the preview empty and says why under the choices."""
        try:
            sheet = self.sheet()
        except Exception as exc:        # never to sys.excepthook: the reason, in the dialog
            self.preview.setPixmap(QPixmap())
            self._drawn_note = self.tr("The sheet cannot be drawn: %1").replace("%1", failure_reason(exc))
            self._show_notes()
            return
        px = PREVIEW_WIDTH / sheet.paper.width * 2.0         # 2× for a sharp preview on HiDPI
        image = QImage(round(sheet.paper.width * px), round(sheet.paper.height * px),
                       QImage.Format.Format_RGB32)
        image.fill(Qt.GlobalColor.white)
        painter = QPainter(image)
        painter.scale(px, px)
        try:
            paint_sheet(sheet, painter, self.language)
            self._drawn_note = self._part_note()
        except MissingFontError:
            self._drawn_note = self.tr("No font with Chinese characters is installed: install one "
                                       "(on Debian/Ubuntu: fonts-noto-cjk) or switch the language "
                                       "to English.")
        finally:
            painter.end()
        self._show_notes()
        pixmap = QPixmap.fromImage(image)
        pixmap.setDevicePixelRatio(2.0)
        self.preview.setPixmap(pixmap)

    def _part_note(self) -> str:
        """On the cam or gear sheet while that tab shows an error: which part is drawn (the
        gear sheet said nothing, a pair whose numbers the Gear tab's fields no longer showed)."""
        content = self.content.currentData()
        if content == "cam" and self._cam is not None and self._cam.error is not None:
            return self.tr("The Cam tab has an error; the sheet shows its last valid cam.")
        if content == "gear" and self._gear is not None and self._gear.error is not None:
            return self.tr("The Gear tab has an error; the sheet shows its last valid gear pair.")
        return ""

    def export(self, path: str) -> None:
        """Write the sheet to ``path`` (PDF, SVG or DXF by its suffix; a DXF's texts as the CAD
        texts choice says). SheetTypeError (a ValueError) for another suffix, before anything
        is built; MissingFontError, OutlineFontMissing (no CJK font for the outlines: nothing
        written), OSError as the writer raises, and whatever building the sheet raises."""
        suffix = os.path.splitext(path)[1].lower()
        if suffix not in SHEET_SUFFIXES:
            raise SheetTypeError(os.path.basename(path))
        write_sheet(self.sheet(), path, self.language, self.choice().design_name, self.cad_font.value())
        self.written = path
        if suffix == ".dxf":
            self.cad_font.remember()
        if self._settings is not None:
            for key in COVER_FIELDS:
                self._settings.setValue(COVER_SETTINGS + key, self.fields[key].text().strip())

    def _save_dialog(self) -> None:
        from core.drawing.outline_text import OutlineFontMissing   # ezdxf: on demand
        suffix = self.file_type.currentData()
        start = os.path.join(self._start_dir(), f"{self.content.currentData()}{suffix}")
        filters = {self.tr("PDF document (*.pdf)"): ".pdf", self.tr("SVG image (*.svg)"): ".svg",
                   self.tr("DXF drawing (*.dxf)"): ".dxf"}
        chosen = next(name for name, kind in filters.items() if kind == suffix)
        path, chosen = QFileDialog.getSaveFileName(self, self.windowTitle(), start, ";;".join(filters),
                                                   chosen)
        if not path:
            return
        if not os.path.splitext(os.path.basename(path))[1]:     # typed without a type
            path += filters.get(chosen, suffix)
        typed = self.file_type.findData(os.path.splitext(path)[1].lower())
        if typed >= 0:                  # the type written is the one shown (and its CAD texts)
            self.file_type.setCurrentIndex(typed)
        try:
            with busy_cursor():
                self.export(path)
        except OutlineFontMissing:
            failure = missing_font_text() + " " + self.tr("Nothing was written.")
        except SheetTypeError:
            failure = self.tr("A drawing sheet is written as PDF (.pdf), SVG (.svg) or DXF (.dxf); "
                              "%1 is none of them. Nothing was written.")
            failure = failure.replace("%1", os.path.basename(path))
        except MissingFontError:
            failure = self.tr("No font with Chinese characters is installed: install one (on "
                              "Debian/Ubuntu: fonts-noto-cjk) or switch the language to English.")
        except OSError as exc:
            failure = self.tr("Could not write %1: %2").replace("%1", path).replace(
                "%2", describe_os_error(exc))
        except Exception as exc:        # the sheet could not be built: say why, write nothing
            failure = self.tr("The sheet cannot be drawn: %1. Nothing was written.").replace(
                "%1", failure_reason(exc))
        else:
            failure = ""
        if failure:
            QMessageBox.warning(self, self.windowTitle(), failure)
            return
        self.accept()

    def _start_dir(self) -> str:
        if self._start:
            return self._start
        return os.path.dirname(self.model.path) if self.model.path else os.path.expanduser("~")


def export_sheet_dialog(model: DesignModel, parent: QWidget, language: str, start_dir: str,
                        settings: QSettings | None = None,
                        cam: CamSource | None = None, gear: PartErrorSource | None = None) -> str:
    """Show the dialog (``cam``: the Cam tab's model, for the cam sheet); returns the path
    written or ''."""
    dialog = DrawingSheetDialog(model, language, parent, settings, start_dir, cam, gear)
    dialog.exec()
    return dialog.written
