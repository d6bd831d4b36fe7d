"""What the library pane does, without dialogs: open a library, save, rename,
duplicate, delete (undoable), import, export, open a design into the model.

Every edit is one swap of whole entries in core (``Library.replace_entries``),
pushed on this object's own QUndoStack, so undo and redo are the same call with
the two sides exchanged. Failures are reported through ``failed`` with a plain
translated message and change nothing.
"""
from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path
from typing import Iterable, Sequence

from PySide6.QtCore import QCoreApplication, QObject, Signal
from PySide6.QtGui import QUndoCommand

from core.space.compare import Candidate
from core.base.errors import DesignError, FileFormatError
from core.files.design_file import file_parts
from core.space.figures import figures
from core.library import Entry, Library
from core.library.files import export_entries, import_entries, read_design_files
from core.library.names import check_name, unique_name
from core.library.backup import backup_copy
from core.library.entry import too_fine
from core.library.rows import Damage
from core.library.store import LibraryError, utc_now

from shaperapp.design.model import DesignModel
from shaperapp.design.undo import held_weakly, owned_undo_stack
from shaperapp.widgets.file_messages import defaulted_text, describe_damage, describe_file_error, describe_os_error
from shaperapp.widgets.messages import describe


class _Swap(QUndoCommand):
    """Replace entries ``before`` by ``after``; undo swaps them back."""

    def __init__(self, actions: "LibraryActions", text: str, before: Sequence[Entry],
                 after: Sequence[Entry]) -> None:
        super().__init__(text)
        self._swap = held_weakly(actions._swap)     # not keeping the stack's owner alive
        self._before, self._after = list(before), list(after)
        self._done = True        # pushed after the first swap succeeded

    def redo(self) -> None:
        if self._done:
            self._done = False
            return
        self._apply(self._before, self._after)

    def undo(self) -> None:
        self._apply(self._after, self._before)

    def _apply(self, old: Sequence[Entry], new: Sequence[Entry]) -> None:
        swap = self._swap()
        if swap is None:
            return
        try:
            swap(old, new)
        except _Reported:           # the library changed meanwhile: drop this step
            self.setObsolete(True)


class LibraryActions(QObject):
    """``changed`` after any edit; ``libraryChanged`` when another library is opened;
    ``failed(str)`` with a message; ``refused(object)`` with the LibraryError of a
    library file that was refused (the pane offers to copy it aside)."""

    changed = Signal()
    libraryChanged = Signal()
    failed = Signal(str)
    noted = Signal(str)
    """What an opened entry lacked and the values taken for it (``defaulted_text``)."""
    refused = Signal(object)

    def __init__(self, model: DesignModel, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self.library: Library | None = None
        self.undo_stack = owned_undo_stack(self)

    # ---- the library file --------------------------------------------------------
    def open_library(self, path: str | os.PathLike | None = None) -> bool:
        """Open (or create) a library; None: $SHAPER_LIBRARY or the per-user default."""
        try:
            library = Library(path)
        except LibraryError as exc:
            if exc.refused_file:
                self.refused.emit(exc)
            else:
                self.failed.emit(self.message(exc))
            return False
        self.close_library()
        self.library = library
        self.undo_stack.clear()
        self.libraryChanged.emit()
        return True

    def close_library(self) -> None:
        if self.library is not None:
            self.library.close()
            self.library = None
            self.undo_stack.clear()
            self.libraryChanged.emit()

    def copy_aside(self, error: LibraryError) -> str | None:
        """Copy a refused library file beside itself, byte for byte; the copy's path."""
        try:
            return str(backup_copy(error.path))
        except LibraryError as exc:
            self.failed.emit(self.message(exc))
            return None

    # ---- edits (undoable) -----------------------------------------------------------
    def exists(self, name: str) -> bool:
        return self.library is not None and name.strip() in self.library

    def save_current(self, name: str, notes: str = "", tags: Iterable[str] = (),
                     replace_existing: bool = False) -> bool:
        """Store the design on screen (with its speeds, step and loads) under ``name``."""
        m = self._model
        loaded = {"spec": m.valid_spec, "rpm": list(m.rpms), "step_deg": m.step_deg, "masses": m.masses,
                  **m.saved_parts()}          # the cam's inputs, as a design file keeps them

        def work(lib: Library) -> None:
            entry = lib.make_entry(name, loaded, notes, tags)
            before = [lib.get(entry.name)] if replace_existing and entry.name in lib else []
            if before:
                entry = replace(entry, created=before[0].created)
            self._push(self.tr("Save “%1”").replace("%1", entry.name), before, [entry])
        return self._run(work)

    def rename(self, name: str, new: str) -> bool:
        def work(lib: Library) -> None:
            entry = lib.get(name)
            renamed = replace(entry, name=check_name(new), modified=utc_now())
            self._push(self.tr("Rename “%1”").replace("%1", name), [entry], [renamed])
        return self._run(work)

    def duplicate(self, name: str) -> bool:
        def work(lib: Library) -> None:
            entry = lib.get(name)
            now = utc_now()
            copy = replace(entry, name=unique_name(name, lib.names()), created=now, modified=now)
            self._push(self.tr("Duplicate “%1”").replace("%1", name), [], [copy])
        return self._run(work)

    def delete(self, names: Sequence[str]) -> bool:
        def work(lib: Library) -> None:
            entries = [lib.get(n) for n in names]
            self._push(self.tr("Delete %1 design(s)").replace("%1", str(len(entries))), entries, [])
        return bool(names) and self._run(work)

    def import_paths(self, paths: Sequence[str | os.PathLike]) -> tuple[list[str], list[tuple[Path, FileFormatError]]]:
        """Import design files and folders (names taken get ``name (2)``…); returns the
        imported names and the refused files with why. Undo removes them all."""
        good, bad = read_design_files(paths)
        names: list[str] = []

        def work(lib: Library) -> None:
            entries = import_entries(lib, good, rename_duplicates=True)
            names.extend(e.name for e in entries)
            self.undo_stack.push(_Swap(self, self.tr("Import %1 design(s)").replace("%1", str(len(entries))), [], entries))
            self.changed.emit()
        if good:
            self._run(work)
        return names, bad

    def _push(self, text: str, before: Sequence[Entry], after: Sequence[Entry]) -> None:
        self._swap(before, after)
        self.undo_stack.push(_Swap(self, text, before, after))

    def _swap(self, before: Sequence[Entry], after: Sequence[Entry]) -> None:
        if self.library is None:
            return
        try:
            self.library.replace_entries([e.name for e in before], after)
        except LibraryError as exc:
            self.failed.emit(self.message(exc))
            raise _Reported() from None
        finally:
            self.changed.emit()

    def _run(self, work) -> bool:
        if self.library is None:
            self.failed.emit(self.tr("No library is open."))
            return False
        try:
            work(self.library)
        except _Reported:
            return False
        except LibraryError as exc:
            self.failed.emit(self.message(exc))
            return False
        except DesignError as exc:
            self.failed.emit(describe(exc))
            return False
        return True

    # ---- export and open --------------------------------------------------------------
    def export(self, name: str, path: str) -> bool:
        return self._export(lambda lib: lib.export(name, path), path)

    def export_all(self, folder: str) -> bool:
        """Every design into ``folder``, all or nothing; damaged entries are left out and named."""
        skipped: list[tuple[str, LibraryError | FileFormatError]] = []
        done = self._export(lambda lib: skipped.extend(export_entries(lib, folder).skipped), folder)
        if done and skipped:
            self.failed.emit(self.tr("These designs were not exported:") + "\n" + "\n".join(
                f"{name}: {refusal_text(why) if isinstance(why, FileFormatError) else self.message(why)}"
                for name, why in skipped[:20]))
        return done

    def _export(self, work, path: str) -> bool:
        try:
            return self._run(work)
        except (OSError, FileFormatError) as exc:
            detail = describe_os_error(exc) if isinstance(exc, OSError) else refusal_text(exc)
            self.failed.emit(self.tr("Could not write %1: %2").replace("%1", path).replace("%2", detail))
            return False

    def open_in_model(self, name: str) -> bool:
        """Load ``name`` into the model, all or nothing: the document is validated and its
        figures computed before the model is touched."""
        if self.library is None:
            return False
        try:
            doc = self.library.load(name)
            figures(doc["spec"], doc["rpm"], doc["masses"])
        except FileFormatError as exc:
            self.failed.emit(self.tr("Could not open the design: %1").replace("%1", refusal_text(exc)))
            return False
        except DesignError as exc:
            self.failed.emit(self.tr("Could not open the design: %1").replace("%1", describe(exc)))
            return False
        except LibraryError as exc:
            self.failed.emit(self.message(exc))
            return False
        try:
            self._load_into_model(doc, name)
        except DesignError as exc:          # an all-or-nothing load_state refuses and changes nothing
            self.failed.emit(self.tr("Could not open the design: %1").replace("%1", describe(exc)))
            return False
        if doc["defaulted"]:        # an entry stored from a file that lacked them (as File › Open says)
            entry = QCoreApplication.translate("messages", "library entry “%1”").replace("%1", name)
            self.noted.emit(defaulted_text(entry, doc["defaulted"]))
        return True

    def _load_into_model(self, doc: dict, name: str) -> None:
        """The one place the library replaces the model's design (see DesignModel.load_state)."""
        self._model.load_state(doc["spec"], doc["rpm"], doc["step_deg"], path="", masses=doc["masses"],
                               parts=file_parts(doc), library_name=name)

    def candidates(self, names: Sequence[str]) -> list[Candidate]:
        """Library entries as comparison candidates (invalid ones reported and left out)."""
        out = []
        for name in names:
            try:
                doc = self.library.get(name).document(any_step=True)  # type: ignore[union-attr]
            except (FileFormatError, LibraryError) as exc:      # a too fine entry compares (any_step)
                self.failed.emit(describe_file_error(exc) if isinstance(exc, FileFormatError) else self.message(exc))
                continue
            out.append(Candidate(name, doc["spec"], doc["masses"]))
        return out

    # ---- messages ------------------------------------------------------------------------
    def message(self, error: LibraryError) -> str:
        """A translated sentence for a library problem."""
        path = str(error.path) if error.path is not None else ""
        texts = {
            "exists": self.tr("That name is already in the library; choose another."),
            "name": self.tr("A name must not be empty, longer than 200 characters or contain line breaks."),
            "tag": self.tr("Tags are separated by commas; each at most 64 characters."),
            "missing": self.tr("That design is no longer in the library (another program may have changed it)."),
            "busy": self.tr("The library is busy: another program is writing to it. Try again."),
            "damaged": self.tr("The library %1 is damaged and cannot be opened. It was left unchanged."),
            "newer": self.tr("The library %1 was written by a newer version of Shaper Designer. It was "
                             "left unchanged; update Shaper Designer to use it."),
            "foreign": self.tr("%1 is not a Shaper Designer library. It was left unchanged."),
        }
        if error.objects:
            return self.tr("The library %1 holds what another program added (%2), which Shaper Designer "
                           "never makes and will not run. It was left unchanged.").replace("%1", path) \
                .replace("%2", ", ".join(error.objects))
        if error.kind == "entry":
            return self.tr("This design is damaged and cannot be opened; the rest of the library "
                           "can be used. (%1)").replace("%1", str(error) if error.damage is None
                                                        else describe_damage(error.damage))
        if error.kind == "readonly":
            return self.tr("The library %1 can only be read (the file or its folder cannot be "
                           "written); nothing was changed.").replace("%1", path)
        text = texts.get(error.kind)
        if text is None:
            return self.tr("Could not use the library: %1").replace("%1", str(error))
        return text.replace("%1", path)


def refusal_text(exc: FileFormatError) -> str:
    """Why an entry's design cannot be opened or exported, in the UI's language: an entry
    stored before the design file's sample limit says it is too fine and the step that
    exports it (``shaper library export --step``), not the design file's "use a step of at
    least …", which no field of the pane takes."""
    fine = too_fine(exc)
    return describe_file_error(exc) if fine is None else describe_damage(Damage("too_fine", cause=fine))


class _Reported(Exception):
    """A swap failed and its message was already emitted."""
