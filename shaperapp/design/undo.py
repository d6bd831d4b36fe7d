"""Undo and redo of input edits: one QUndoCommand type holding two input states.

Every design and load edit goes through the model's setters, which push an
:class:`InputEdit` from the inputs before to the inputs after. Keystrokes in one
field arrive as several edits with the same ``key`` (the fields touched and the
typing session); they merge into one step through ``id``/``mergeWith``, done by
:func:`push_edit` rather than by ``QUndoStack.push`` (see there why).
"""
from __future__ import annotations

from typing import Callable, Hashable

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QUndoCommand, QUndoStack

from shaperapp.widgets.messages import field_name

from .inputs import Inputs

MERGE_ID = 1


def edit_text(names: list[str]) -> str:
    """The history's name of an edit of the fields ``names``, in the current language."""
    if names == ["mode"]:
        return QCoreApplication.translate("model", "switch input mode")
    if len(names) == 1:
        return field_name(names[0])
    return QCoreApplication.translate("model", "edit %1 fields").replace("%1", str(len(names)))


class InputEdit(QUndoCommand):
    """Go from ``before`` to ``after`` (redo) and back (undo) through ``apply``.

    ``key`` is None for an edit that never merges (a choice, a speed added), else
    a hashable naming the fields and the typing session; consecutive edits with
    equal keys merge. An edit merged back to where it started becomes obsolete.
    ``describe`` gives the history text in the current language."""

    def __init__(self, apply: Callable[[Inputs], None], before: Inputs, after: Inputs,
                 key: Hashable | None, describe: Callable[[], str]) -> None:
        super().__init__(describe())
        self._describe = describe     # the text in the current language, again after a switch
        self._apply = apply
        self.before = before
        self.after = after
        self.key = key

    def id(self) -> int:  # noqa: A003 - Qt's name
        return MERGE_ID if self.key is not None else -1

    def mergeWith(self, other: QUndoCommand) -> bool:  # noqa: N802 - Qt's name
        if not isinstance(other, InputEdit) or other.key is None or other.key != self.key:
            return False
        self.after = other.after
        self.setObsolete(self.after == self.before)
        return True

    def retranslate(self) -> None:
        self.setText(self._describe())

    def redo(self) -> None:
        self._apply(self.after)

    def undo(self) -> None:
        self._apply(self.before)


def push_edit(stack: QUndoStack, edit: InputEdit) -> None:
    """``stack.push(edit)``, except that an edit Qt would merge into the command on top
    is merged here, by the same rule (same key, nothing to redo, the top not the saved
    state): PySide 6.11 keeps every command that Qt deletes inside ``push()`` alive, so
    each merged keystroke leaked its two input states and closures (about 2 KB; 4000
    keystrokes made an edit 15 % slower). A merge back to where the step started makes
    it obsolete; Qt drops an obsolete command on undo, a no-op here (before == after)."""
    index = stack.index()
    top = stack.command(index - 1) if index > 0 else None
    if not (isinstance(top, InputEdit) and edit.key is not None and top.key == edit.key
            and index == stack.count() and index != stack.cleanIndex()):
        stack.push(edit)
        return
    edit.redo()
    top.mergeWith(edit)
    if top.isObsolete():
        stack.undo()


def retranslate_history(stack: QUndoStack) -> None:
    """Every undo/redo entry of ``stack`` in the current language (after a language switch)."""
    for i in range(stack.count()):
        command = stack.command(i)
        if isinstance(command, InputEdit):
            command.retranslate()
