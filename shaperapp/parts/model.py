"""What every part model does, written once: the typed fields as one value of the undo
history, the edit pushed on the design model's undo stack, the computation through core
with the refused value named and the last valid part kept, and the part's place in the
design file.

A part (the cam, the gear pair, a future belt drive) subclasses :class:`PartModel` and
fills in only what differs: its file key (``PART``), how typed fields become core inputs
and a part (``compute``), what an opened file's part types (``typed_of``), what Save
writes (``document``) and the history's text of an edit (``edit_text``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Hashable

from PySide6.QtCore import QObject, Signal

from core.base.errors import DesignError
from shaperapp.design.model import DesignModel
from shaperapp.design.results import COMPUTE_ERRORS, compute_error
from shaperapp.design.undo import InputEdit, push_edit


@dataclass(frozen=True)
class Typed:
    """A part's fields as typed: floats, or text that is not a number; one state of the
    undo history (a value, so two states compare and an edit back to the start is none)."""

    values: tuple[tuple[str, Any], ...] = ()

    @property
    def dict(self) -> dict[str, Any]:
        return dict(self.values)

    def with_(self, **changes: Any) -> Any:
        """The same kind of typed fields with ``changes`` applied."""
        return type(self)(tuple(sorted({**self.dict, **changes}.items())))


def number(name: str, value: Any, not_finite: str = "must be a finite number") -> float:
    """The float of a typed field; DesignError naming the field for text or a non-finite value."""
    if isinstance(value, str):
        raise DesignError(name, value, "must be a number")
    if not math.isfinite(value):
        raise DesignError(name, value, not_finite)
    return float(value)


class PartModel(QObject):
    """Signals: ``valueChanged`` (a new valid part), ``errorChanged`` (the refusal, or
    whether the part on screen is this design's: ``own_value``), ``typedChanged``.

    Holds the typed fields, the last valid part and why the typed fields are refused; the
    fields typed since the last valid part (``_edited``, the latest last) let a subclass
    blame an error on several fields to the one the user typed (:meth:`blame`)."""

    typedChanged = Signal()
    errorChanged = Signal()
    valueChanged = Signal()
    PART = ""
    """The part's key in the design file, and in the undo steps' merge key."""

    def __init__(self, model: DesignModel, typed: Typed, value: Any,
                 check: Any = None, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.design_model = model
        self._typed = typed
        self._valid_typed = typed
        self._value = value
        self._error: DesignError | None = None
        self._own = True        # the value was made from this design's typed fields
        self._edited: list[str] = []
        model.parts.register(self.PART, self.document, check)
        model.loaded.connect(self._load)

    @property
    def typed(self) -> Any:
        return self._typed

    @property
    def error(self) -> DesignError | None:
        """Why the typed fields are refused, as of the last computation (None: valid)."""
        return self._error

    @property
    def own_value(self) -> bool:
        """Whether the part on screen was made from this design's fields: False after a file
        (or library entry) whose part could not be made, until one is: the drawing then
        still shows the part of the design opened before, no "last valid" one of this."""
        return self._own

    def set_fields(self, **changes: Any) -> None:
        """Change some typed fields (one undoable step; keystrokes in one field merge)."""
        after = self._typed.with_(**changes)
        if after == self._typed:
            return
        names = tuple(sorted(changes))
        push_edit(self.design_model.undo_stack,
                  InputEdit(self._apply, self._typed, after, self.merge_key(names), self.edit_text))

    # ---- what a part fills in ----------------------------------------------
    def merge_key(self, names: tuple[str, ...]) -> Hashable | None:
        """The undo merge key of an edit of ``names`` (None: never merges)."""
        return (self.PART, names)

    def edit_text(self) -> str:
        """The history's name of an edit, in the current language."""
        raise NotImplementedError

    def unmade_text(self) -> str:
        """What the tab says instead of the part while this design's cannot be made
        (``own_value`` False), in the current language: the form, the drawing."""
        raise NotImplementedError

    def compute(self, typed: Any) -> Any:
        """The part of ``typed``; DesignError (or one of COMPUTE_ERRORS) when it has none."""
        raise NotImplementedError

    def typed_of(self, data: Any) -> Typed:
        """The typed fields of an opened file's part (None: the file has none, the defaults)."""
        raise NotImplementedError

    def document(self) -> Any:
        """The part on screen as the design file keeps it."""
        raise NotImplementedError

    def blame(self, error: DesignError) -> DesignError:
        """The error as the form shows it (by default core's field)."""
        return error

    def refused(self) -> None:
        """Called after the typed fields were refused (the last valid part stays)."""

    # ---- the shared path ---------------------------------------------------
    def _load(self) -> None:
        """A file was opened (or New): its part, or the default one."""
        self._edited = []
        typed = self.typed_of(self.design_model.parts.loaded(self.PART))
        was_own, self._own = self._own, False
        self._apply(typed, edited=False)
        if was_own and not self._own:       # same refusal's text, but no longer this design's part
            self.errorChanged.emit()
        # What was opened is what Save writes back, made or not: a cam the file's linkage
        # refuses (it feeds during the cut) is the user's to mend, and Save wrote the last
        # cam made instead, the default or the previous file's (hunt s13-hunt2).
        self._valid_typed = typed

    def _apply(self, typed: Typed, edited: bool = True) -> None:
        if edited:          # an edit, an undo or a redo: what changed is what was typed
            changed = sorted(k for k, v in typed.dict.items() if self._typed.dict.get(k) != v)
            self._edited = [n for n in self._edited if n not in changed] + changed
        self._typed = typed
        self.typedChanged.emit()
        self._recompute()

    def _recompute(self) -> None:
        try:
            value = self.compute(self._typed)
        except DesignError as exc:
            self._set_error(self.blame(exc))
            self.refused()
            return
        except COMPUTE_ERRORS as exc:       # a corner of the closed forms: said, never a traceback
            self._set_error(compute_error(exc))
            self.refused()
            return
        self._own = True            # before the signal: its readers ask whether the part is this design's
        self._set_error(None)
        self._edited = []
        self._valid_typed = self._typed
        if value != self._value:
            self._value = value
            self.valueChanged.emit()

    def _set_error(self, error: DesignError | None) -> None:
        changed = str(error) != str(self._error)
        self._error = error
        if changed:
            self.errorChanged.emit()
