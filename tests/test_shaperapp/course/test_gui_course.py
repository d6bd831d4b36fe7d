"""File › Export course design…: the folder dialog (patched), the refusal, Cancel and a
failed write, in messages. The files it writes, those of ``shaper course`` with the report's
cover, are test_course_progress's (one whole course from the window for both)."""
import os

import pytest

import export_faults
from export_faults import in_child, last_run
from language_checks import check_file_menu_entry
from PySide6.QtWidgets import QPushButton
from shaperapp.widgets.export_process import ChildExport


@pytest.fixture
def answers(monkeypatch, tmp_path):
    """The options dialog answers ``shaper course``'s defaults (A1, no DXF, the first
    speed), the folder dialog ``tmp_path / "out"``; the warnings are recorded."""
    from shaperapp.course.dialog import CourseOptions
    out = tmp_path / "out"
    out.mkdir()
    shown = []
    monkeypatch.setattr("shaperapp.course.dialog.ask_course_options", lambda *a: CourseOptions())
    monkeypatch.setattr("shaperapp.course.dialog.QFileDialog.getExistingDirectory",
                        lambda *a, **k: str(out))
    monkeypatch.setattr("shaperapp.course.dialog.QMessageBox.warning",
                        lambda parent, title, text: shown.append(text))
    return out, shown


def test_file_menu_has_export_course_design_in_both_languages(window, qtbot):
    check_file_menu_entry(window, qtbot, window.act_course, "Export course desi&gn…")


def test_the_design_on_screen_always_holds_a_gear_pair(window):
    """The window keeps the Gear tab's model from the start, so the course design never
    lacks the gear sheet (issue 35: the gear is required like the other parts)."""
    from shaperapp.course.dialog import plan
    course = plan(window.model, str(window.settings.fileName()) + ".out")
    assert [f.part.stem for f in course.files][-1] == "gear"
    assert course.drawn["gear"] == window.gear_model.pair


def test_a_design_without_a_part_is_refused_and_nothing_written(window, answers, monkeypatch):
    """A design whose file would hold no cam (no Cam part registered) names the feed cam."""
    out, shown = answers
    monkeypatch.setattr(window.model, "saved_parts", lambda: {})
    window.act_course.trigger()
    assert len(shown) == 1 and "feed cam" in shown[0] and "Nothing was written" in shown[0]
    assert os.listdir(out) == []


def test_cancel_after_the_first_file_keeps_it_complete_and_says_so(window, answers, monkeypatch):
    out, shown = answers
    in_child(monkeypatch, "shaperapp.course.dialog.write_course_of",
             export_faults.quick_course_cancelled_after_the_report)
    window.act_course.trigger()
    run = window.findChildren(ChildExport)[-1]
    run.progressed.connect(lambda fraction: fraction > 0.5 and run.dialog.findChild(QPushButton).click())
    assert last_run(window).state == "cancelled"
    assert os.listdir(out) == ["00-report.pdf"]
    assert (out / "00-report.pdf").read_bytes().rstrip().endswith(b"%%EOF")
    assert shown == ["Cancelled: 1 of 5 files written, each complete."]


def test_a_failed_write_names_the_file_and_the_files_before_it(window, answers, monkeypatch):
    out, shown = answers
    in_child(monkeypatch, "shaperapp.course.dialog.write_course_of", export_faults.quick_course_disk_full)
    window.act_course.trigger()
    assert last_run(window).state == "failed"
    assert os.listdir(out) == ["00-report.pdf"]
    assert len(shown) == 1 and "01-motion.pdf" in shown[0] and "disk is full" in shown[0]
    assert shown[0].endswith("The 1 files written before it are complete.")
