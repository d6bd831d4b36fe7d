"""Undo and redo of input edits: one QUndoCommand type holding two input states.

Every design and load edit goes through the model's setters, which push an
:class:`InputEdit` from the inputs before to the inputs after. Keystrokes in one
field arrive as several edits with the same ``key`` (the fields touched and the
typing session); they merge into one step through ``id``/``mergeWith``, done by
:func:`push_edit` rather than by ``QUndoStack.push`` (see there why).
"""
from __future__ import annotations

import inspect
import weakref
from typing import Callable, Hashable, TypeVar

import shiboken6
from PySide6.QtCore import QCoreApplication, QObject
from PySide6.QtGui import QUndoCommand, QUndoStack

from shaperapp.widgets.messages import field_name

from .inputs import Inputs

MERGE_ID = 1
F = TypeVar("F", bound=Callable)


def held_weakly(function: F) -> Callable[[], F | None]:
    """``function`` for a command to keep: a bound method through a weak reference (None
    once its object is gone), any other callable as it is.

    Why: a command must not keep its stack's owner alive (a model's method does), or the
    owner could never be collected while the stack holds the command (see
    :func:`owned_undo_stack`)."""
    if inspect.ismethod(function):
        return weakref.WeakMethod(function)
    return lambda: function


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
    ``describe`` gives the history text in the current language. Both callables are
    held weakly (:func:`held_weakly`): once their object is gone the edit does nothing."""

    def __init__(self, apply: Callable[[Inputs], None], before: Inputs, after: Inputs,
                 key: Hashable | None, describe: Callable[[], str]) -> None:
        super().__init__(describe())
        self._describe = held_weakly(describe)  # the text in the current language, again after a switch
        self._apply = held_weakly(apply)
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
        describe = self._describe()
        if describe is not None:
            self.setText(describe())

    def redo(self) -> None:
        self._go_to(self.after)

    def undo(self) -> None:
        self._go_to(self.before)

    def _go_to(self, inputs: Inputs) -> None:
        apply = self._apply()
        if apply is not None:
            apply(inputs)


def owned_undo_stack(owner: QObject) -> QUndoStack:
    """A QUndoStack that ``owner`` owns, whose commands Qt deletes before the owner goes.

    Why: a Python command pushed on a stack is the stack's child in PySide's bookkeeping,
    and a command usually refers back to the owner (an :class:`InputEdit` holds the model's
    bound method), so a discarded owner is cyclic garbage. Python's collector clears the
    objects of a cycle in no set order; clearing a command first gives its C++ object back
    to Python (shiboken's ``tp_clear``), which deletes it while the stack still lists it,
    and the owner's destruction then deletes it again: a segmentation fault (PySide 6.11;
    seen in the tests' collections, and ``tests/test_shaperapp/design/test_undo_collected.py``
    makes it happen on purpose). A finalizer holds the stack, so neither it nor its commands
    are garbage, and has Qt delete the commands when the owner dies, before the collector
    clears anything (weakref callbacks run first) or while the owner is freed."""
    stack = QUndoStack(owner)
    weakref.finalize(owner, _delete_commands, stack)
    return stack


def _delete_commands(stack: QUndoStack) -> None:
    if shiboken6.isValid(stack):          # not when Qt deleted the owner (and the stack) first
        stack.blockSignals(True)          # the owner's slots are being torn down
        stack.clear()


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
