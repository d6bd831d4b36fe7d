"""Keystrokes in one field merge into one undo step without leaking.

PySide 6.11 keeps alive every command Qt deletes inside ``QUndoStack.push`` (a
merged or obsolete one), so each keystroke leaked its input states; the model now
merges through ``shaperapp.design.undo.push_edit``. The rule is Qt's: the same field and
typing session, nothing to redo, the top step not the saved state.
"""
import gc

from shaperapp.design.undo import InputEdit


def live_edits() -> int:
    gc.collect()
    return sum(1 for o in gc.get_objects() if isinstance(o, InputEdit))


def test_merged_keystrokes_leave_no_commands_behind(model):
    before = live_edits()
    for i in range(300):
        model.set_spec(time_ratio=1.4 + 0.001 * (i % 50 + 1))
    stack = model.undo_stack
    assert stack.count() == 1 and model.error is None
    assert live_edits() - before <= 2          # the one step (was 300: one per keystroke)


def test_merge_follows_qts_rule(model):
    stack = model.undo_stack
    model.set_spec(time_ratio=1.5)
    model.set_spec(time_ratio=1.6)                     # same field, same session: one step
    assert stack.count() == 1 and stack.index() == 1
    model.set_spec(stroke=320.0)                       # another field: a new step
    assert stack.count() == 2
    stack.undo()
    model.set_spec(stroke=330.0)                       # after an undo the redo step goes
    assert stack.count() == 2 and model.spec.stroke == 330.0
    stack.setClean()
    model.set_spec(stroke=340.0)                       # the saved step is never merged into
    assert stack.count() == 3 and model.dirty
    model.set_spec(stroke=330.0)                       # typed back: the step is dropped, clean
    assert stack.count() == 2 and not model.dirty and model.spec.stroke == 330.0
    stack.undo()
    stack.undo()
    assert model.spec.time_ratio == 1.4 and model.spec.stroke == 300.0
    stack.redo()
    assert model.spec.time_ratio == 1.6
