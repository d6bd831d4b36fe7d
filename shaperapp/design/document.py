"""File actions on the model: open, save, export, recent files.

Separated from the window so they can be tested without dialogs: every
action has a path-taking method; only the ``*_dialog`` wrappers ask the user.
Failures are reported through ``failed`` and change nothing.
"""
from __future__ import annotations

import os

from PySide6.QtCore import QObject, QSettings, Signal
from PySide6.QtWidgets import QMessageBox, QWidget

from core.files.design_file import file_parts
from core.base.errors import DesignError, FileFormatError
from core.files.io import atomic_write, curves_csv, load_design, masses_to_dict, save_design
from core.linkage.spec import Spec

from shaperapp.widgets import file_dialogs
from shaperapp.widgets.ask import use_last_valid
from shaperapp.widgets.cad_font import CAD_FONT_SETTING, dxf_filters, missing_font_text, remembered_filter
from shaperapp.widgets.file_messages import defaulted_text, describe_file_error, describe_os_error
from shaperapp.widgets.messages import describe

from .errors import as_typed
from .inputs import DEFAULT_RPMS, DEFAULT_STEP
from .model import DesignModel

MAX_RECENT = 8
MAX_PATH_CHARS = 4096      # longer is not a path any system opens (PATH_MAX)


class Document(QObject):
    """Connects the model to files. ``failed(str)`` carries a plain message; ``noted(str)`` what
    an opened file lacked and the values taken for it (``core.files.design_file.defaulted_keys``)."""

    failed = Signal(str)
    noted = Signal(str)
    recentChanged = Signal()
    saved = Signal(str)

    def __init__(self, model: DesignModel, settings: QSettings, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._settings = settings

    # ---- path-taking actions (tested directly) -------------------------
    def open_path(self, path: str) -> bool:
        """Open all or nothing: the file is read, validated and fully computed before
        the model changes; on any failure the design on screen stays as it was."""
        try:
            doc = load_design(path)
            self._model.load_state(doc["spec"], doc["rpm"], doc["step_deg"], path=os.path.abspath(path),
                                   masses=doc["masses"], parts=file_parts(doc))
        except FileFormatError as exc:
            self.failed.emit(self.tr("Could not open the design: %1").replace("%1", describe_file_error(exc)))
            return False
        except DesignError as exc:
            self.failed.emit(self.tr("Could not open %1: %2").replace("%1", path).replace("%2", describe(exc)))
            return False
        self._add_recent(path)
        if doc["defaulted"]:        # never a design changed without a word
            self.noted.emit(defaulted_text(os.path.basename(path), doc["defaulted"]))
        return True

    def save_to(self, path: str) -> bool:
        """Write the design on screen. While an input is invalid that is the last valid
        design, and the unsaved mark stays (what is typed is not what was saved)."""
        model = self._model
        try:
            save_design(path, model.valid_spec, model.rpms, model.step_deg, extra=saved_parts(model))
        except OSError as exc:
            self.failed.emit(self.tr("Could not save %1: %2").replace("%1", path)
                             .replace("%2", describe_os_error(exc)))
            return False
        if model.inputs_valid:
            model.set_clean(os.path.abspath(path))
        else:
            model.set_path(os.path.abspath(path))
        self._add_recent(path)
        self.saved.emit(path)
        return True

    def export_csv_to(self, path: str) -> bool:
        """Curves in the format of ``shaper curves``."""
        return self._write(path, curves_csv(self._model.motion))

    def export_forces_csv_to(self, path: str) -> bool:
        """Torque, power and joint forces in the format of ``shaper dynamics --csv``."""
        from core.files.dynamics_io import dynamics_csv     # not imported before the first paint
        return self._write(path, dynamics_csv(self._model.dynamics))

    def export_scheme_dxf_to(self, path: str, cad_font: str = "gb") -> bool:
        """The mechanism at the current crank angle for CAD, as ``shaper drawing --content
        scheme --cad-font`` writes it. A name without a suffix gets ``.dxf``; another suffix
        is refused (a DXF under a .png name would open nowhere); outlines without a font for
        them write nothing."""
        suffix = os.path.splitext(path)[1]
        if not suffix:
            path += ".dxf"
        elif suffix.lower() != ".dxf":
            self.failed.emit(self.tr("Could not write %1: a scheme for CAD is written as DXF (.dxf)")
                             .replace("%1", path))
            return False
        # ezdxf takes about a tenth of a second to import: only when a DXF is asked for
        from core.drawing.dxf import DxfAuditError
        from core.drawing.outline_text import OutlineFontMissing
        from core.drawing.scheme import write_scheme
        try:
            write_scheme(self._model.design, self._model.crank_deg, path, cad_font)
        except (OSError, DxfAuditError, OutlineFontMissing) as exc:
            reason = (describe_os_error(exc) if isinstance(exc, OSError) else missing_font_text()
                      if isinstance(exc, OutlineFontMissing) else str(exc))
            self.failed.emit(self.tr("Could not write %1: %2").replace("%1", path).replace("%2", reason))
            return False
        return True

    def _write(self, path: str, text: str) -> bool:
        try:
            atomic_write(path, text)
        except OSError as exc:
            self.failed.emit(self.tr("Could not write %1: %2").replace("%1", path)
                             .replace("%2", describe_os_error(exc)))
            return False
        return True

    def new(self) -> None:
        self._model.load_state(Spec(), DEFAULT_RPMS, DEFAULT_STEP, path="")

    # ---- recent files ----------------------------------------------------
    def recent_files(self) -> list[str]:
        """The remembered paths, newest first. The settings file is the user's to edit
        (or damage): anything but a list of plain paths is ignored, never iterated (a
        QSize there made the menu loop forever at start-up)."""
        value = self._settings.value("recentFiles", [])
        if isinstance(value, str):
            value = [value]
        if not isinstance(value, (list, tuple)):
            return []
        return [p for p in value[:MAX_RECENT]
                if isinstance(p, str) and p and len(p) <= MAX_PATH_CHARS and "\0" not in p]

    def _add_recent(self, path: str) -> None:
        path = os.path.abspath(path)
        files = [path] + [p for p in self.recent_files() if p != path]
        self._settings.setValue("recentFiles", files[:MAX_RECENT])
        self._settings.setValue("lastDir", os.path.dirname(path))
        self.recentChanged.emit()

    def last_dir(self) -> str:
        value = self._settings.value("lastDir", "")
        return value if isinstance(value, str) and os.path.isdir(value) else os.getcwd()

    # ---- interactive wrappers -------------------------------------------
    def _filter(self) -> str:
        return self.tr("Shaper designs (*.shaper.json *.json);;All files (*)")

    def confirm_discard(self, parent: QWidget) -> bool:
        """True when there is nothing unsaved, or the user saved or discarded it."""
        if not self._model.dirty:
            return True
        answer = QMessageBox.question(
            parent, self.tr("Unsaved changes"),
            self.tr("The design has unsaved changes. Save them first?"),
            QMessageBox.StandardButton.Save | QMessageBox.StandardButton.Discard
            | QMessageBox.StandardButton.Cancel, QMessageBox.StandardButton.Save)
        if answer == QMessageBox.StandardButton.Save:
            return self.save_dialog(parent)
        return answer == QMessageBox.StandardButton.Discard

    def new_dialog(self, parent: QWidget) -> None:
        if self.confirm_discard(parent):
            self.new()

    def open_dialog(self, parent: QWidget, path: str | None = None) -> bool:
        if not self.confirm_discard(parent):
            return False
        if path is None:
            path = file_dialogs.open_file_name(parent, self.tr("Open design"), self.last_dir(), self._filter())
        return bool(path) and self.open_path(path)

    def confirm_valid(self, parent: QWidget, saving: bool) -> bool:
        """True when every input is valid, or the user agreed to use the last valid
        design instead (for a save, the invalid inputs are then reverted — one undo
        step — so the screen shows what the file holds)."""
        model = self._model
        if model.inputs_valid:
            return True
        error = model.error or as_typed(model.forces_error)
        question = (self.tr("Save the last valid design instead? The invalid input is then reset to it.")
                    if saving else self.tr("Export the results of the last valid design instead?"))
        if not use_last_valid(parent, self.tr("Invalid input"), describe(error), question):
            return False
        if saving:
            model.revert_invalid()
        return True

    def save_dialog(self, parent: QWidget) -> bool:
        if not self.confirm_valid(parent, saving=True):
            return False
        if self._model.path:
            return self.save_to(self._model.path)
        return self._save_as(parent)

    def save_as_dialog(self, parent: QWidget) -> bool:
        return self.confirm_valid(parent, saving=True) and self._save_as(parent)

    def _save_as(self, parent: QWidget) -> bool:
        start = self._model.path or os.path.join(self.last_dir(), "design.shaper.json")
        path = file_dialogs.save_file_name(parent, self.tr("Save design as"), start, self._filter())
        return bool(path) and self.save_to(path)

    def export_csv_dialog(self, parent: QWidget) -> bool:
        if not self.confirm_valid(parent, saving=False):
            return False
        path = self._csv_path(parent, self.tr("Export curves to CSV"), "curves.csv")
        return bool(path) and self.export_csv_to(path)

    def export_forces_csv_dialog(self, parent: QWidget) -> bool:
        if not self.confirm_valid(parent, saving=False):
            return False
        path = self._csv_path(parent, self.tr("Export forces to CSV"), "forces.csv")
        return bool(path) and self.export_forces_csv_to(path)

    def export_scheme_dxf_dialog(self, parent: QWidget) -> bool:
        if not self.confirm_valid(parent, saving=False):
            return False
        start = os.path.join(self.last_dir(), "scheme.dxf")
        # the CAD texts (--cad-font) as two filters of one type, the last DXF's choice first
        kinds = dxf_filters()
        path, chosen = file_dialogs.save_file_and_filter(
            parent, self.tr("Export scheme as DXF"), start, ";;".join(kinds),
            remembered_filter(self._settings, kinds))
        cad_font = kinds.get(chosen, "gb")
        if not path or not self.export_scheme_dxf_to(path, cad_font):
            return False
        self._settings.setValue(CAD_FONT_SETTING, cad_font)
        return True

    def _csv_path(self, parent: QWidget, title: str, name: str) -> str:
        start = os.path.join(self.last_dir(), name)
        path = file_dialogs.save_file_name(parent, title, start, self.tr("CSV files (*.csv)"))
        return path


def saved_parts(model: DesignModel) -> dict:
    """What a design file holds beside the linkage, the speeds and the step: the loads and
    every registered part (the cam …), as Save writes them and Export course design… reads."""
    return {"forces": masses_to_dict(model.masses), **model.saved_parts()}
