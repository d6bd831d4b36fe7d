"""An owner of an undo history (the design model, the library's actions, a part model's
edits on the design model's stack) discarded in a reference cycle is collected without a
crash and without a leak, whatever order the collector clears it in.

Before ``owned_undo_stack`` (shaperapp/design/undo.py), clearing a pushed command before
its stack's owner gave the command's C++ object back to Python, which deleted it while the
stack still listed it; the owner's destruction then deleted it again: "Segmentation fault"
in a later test's ``gc.collect()`` (the GUI fuzz with the library pane, 30 November), and
every time in the child below. The child puts the commands before the owner in the
collector's list on purpose (the owner frozen, the commands collected into the oldest
generation, the owner unfrozen after them), so the bad order is not left to chance.
"""
import os
import subprocess
import sys
import textwrap

CHILD = textwrap.dedent(r'''
    import gc, sys, weakref
    from PySide6.QtWidgets import QApplication
    app = QApplication([])
    from shaperapp.design.model import DesignModel
    from shaperapp.gear.model import GearModel
    from shaperapp.library.actions import LibraryActions

    def collect_history_first(name, make_owner, edit, stack_of):
        """``make_owner()`` is the object discarded; ``edit(owner)`` pushes the history on
        ``stack_of(owner)``."""
        gc.collect()
        owner = make_owner()
        gc.freeze()                   # the owner out of the collector's walks...
        edit(owner)
        count = stack_of(owner).count()
        assert count >= 2, (name, count)
        gc.collect()                  # ...its commands moved to the oldest generation...
        gc.unfreeze()                 # ...and the owner put after them
        owner.cycle = owner           # cyclic garbage once dropped, as in a closed window
        alive = weakref.ref(owner)
        del owner
        gc.collect()
        assert alive() is None, f"{name}: the owner outlived the collection (a leak)"
        print("collected", name, flush=True)

    def design_edits(model):
        for i, field in enumerate(("crank", "stroke", "crank", "stroke")):
            model.set_spec(**{field: (101.0 if field == "crank" else 301.0) + i})
        model.undo_stack.undo()       # one step left to redo

    def with_gear():
        model = DesignModel()
        model.gear = GearModel(model)     # a part model lives as long as its design model
        return model

    def gear_edits(model):
        model.gear.set_fields(z1=15.0)
        model.gear.set_fields(mode="shifts")
        model.gear.set_fields(z2=47.0)

    def library_edits(actions):
        assert actions.open_library(sys.argv[1])
        for name in ("a", "b", "c"):
            assert actions.save_current(name)
        assert actions.rename("a", "d")
        actions.undo_stack.undo()

    collect_history_first("design model", DesignModel, design_edits, lambda m: m.undo_stack)
    collect_history_first("gear model", with_gear, gear_edits, lambda m: m.undo_stack)
    model = DesignModel()
    collect_history_first("library actions", lambda: LibraryActions(model), library_edits,
                          lambda a: a.undo_stack)
    print("all collected", flush=True)
''')


def test_owners_of_undo_histories_are_collected_in_any_order(tmp_path):
    run = subprocess.run([sys.executable, "-c", CHILD, str(tmp_path / "library.sqlite")],
                         capture_output=True, text=True, timeout=120,
                         env={**os.environ, "QT_QPA_PLATFORM": "offscreen"})
    # before: status -11 (SIGSEGV) at the first collection, nothing printed
    assert run.returncode == 0, (run.returncode, run.stdout, run.stderr[-3000:])
    assert run.stdout.splitlines() == ["collected design model", "collected gear model",
                                       "collected library actions", "all collected"], run.stdout
