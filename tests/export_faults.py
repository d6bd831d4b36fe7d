"""Jobs for the export's child process (``widgets.export_child``) that stand in for the
real ones or misbehave on purpose, for tests: the child imports a job by module name, so
:func:`in_child` puts this folder on the child's PYTHONPATH. A monkeypatch in the test's
process never reaches the child; these apply theirs inside it."""
import os
import time

from core.files.atomic import atomic_write


def in_child(monkeypatch, where: str, job) -> None:
    """Make the GUI's export start ``job`` (one of this module's) instead of the function
    at ``where`` ("module.name")."""
    monkeypatch.setattr(where, job)
    monkeypatch.setenv("PYTHONPATH", os.path.dirname(os.path.abspath(__file__)))


def last_run(window, timeout_ms: int = 600_000):
    """The window's latest export, waited for."""
    from shaperapp.widgets.export_process import ChildExport
    run = window.findChildren(ChildExport)[-1]
    assert run.wait(timeout_ms)
    return run


def finished(run):
    """What an export started by the GUI ended with (its ``result``), waited for."""
    assert run is not None and run.wait()
    return run.result


def stuck_report(progress, file_done, path, **_inputs):
    """Begin writing ``path`` (its temporary file is on disk), then hang without ever
    looking at ``progress`` again: deaf to Cancel, as a long step would be."""
    def pieces():
        yield b"%PDF-1.4 begun"
        progress.note(0.5)
        while True:
            time.sleep(1.0)
    atomic_write(path, pieces())


def broken_report(progress, file_done, path, **_inputs):
    """A report that cannot be built."""
    raise ValueError("the loads do not add up")


def _quick_report() -> None:
    """The course's report as a small stand-in file, written atomically as the real one:
    for tests about the run, not the report's pages."""
    from shaperapp.course import write
    write._report = lambda *args: None
    write.write_report = lambda report, path, *progress: atomic_write(path, b"%PDF-1.4\n%%EOF\n")


def quick_course(progress, file_done, **arguments):
    from shaperapp.course.write import write_course_of
    _quick_report()
    write_course_of(progress, file_done, **arguments)


def quick_course_dxfs(progress, file_done, **arguments):
    """The stand-in report, each sheet's PDF a stand-in too, its DXF the real one: for tests
    about the DXFs."""
    from shaperapp.course import write
    real = write.write_sheet

    def dxf_only(sheet, path, *args):
        if path.endswith(".pdf"):
            atomic_write(path, b"%PDF-1.4\n%%EOF\n")
        else:
            real(sheet, path, *args)
    write.write_sheet = dxf_only
    quick_course(progress, file_done, **arguments)


def quick_course_cancelled_after_the_report(progress, file_done, **arguments):
    """The stand-in report written, then waiting for Cancel before the first sheet (as a
    user who presses it then)."""
    from shaperapp.course.write import write_course_of
    _quick_report()
    waited = []

    def then_wait(path):
        file_done(path)
        while not progress.should_stop() and len(waited) < 600:
            waited.append(time.sleep(0.05))
    write_course_of(progress, then_wait, **arguments)


def quick_course_disk_full(progress, file_done, **arguments):
    """The stand-in report written, then the first sheet's write fails: the disk is full."""
    from shaperapp.course import write

    def full(sheet, path, *args):
        raise OSError(28, "No space left on device", path)
    write.write_sheet = full
    quick_course(progress, file_done, **arguments)
