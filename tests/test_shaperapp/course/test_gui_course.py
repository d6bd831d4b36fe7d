"""File › Export course design…: the folder dialog (patched), the files of ``shaper course``
from the design on screen, the refusal, Cancel and a failed write, in messages."""
import os
import re

import pytest

from language_checks import has_pdftotext, pdf_text

NAMES = ["00-report.pdf", "01-motion.pdf", "02-kinetostatic.pdf", "03-cam.pdf", "04-gear.pdf"]


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
    assert window.act_course in window.menu_file.actions()
    window.set_language("en")
    assert window.act_course.text() == "Export course desi&gn…"
    window.set_language("zh_CN")
    qtbot.waitUntil(lambda: window.act_course.text() != "Export course desi&gn…")
    assert re.search(r"[\u4e00-\u9fff]", window.act_course.text())


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


@pytest.fixture
def quick_report(monkeypatch):
    """The report written as a small stand-in file (atomically, as the real one): the
    tests of Cancel and of a failed write are about the run, not the report's pages."""
    from core.files.atomic import atomic_write
    monkeypatch.setattr("shaperapp.course.write._report", lambda *args: None)
    monkeypatch.setattr("shaperapp.course.write.write_report",
                        lambda report, path, *progress: atomic_write(path, b"%PDF-1.4\n%%EOF\n"))


def test_cancel_after_the_first_file_keeps_it_complete_and_says_so(window, answers, monkeypatch,
                                                                    quick_report):
    out, shown = answers
    asked = []
    monkeypatch.setattr("shaperapp.widgets.progress_dialog.QProgressDialog.wasCanceled",
                        lambda self: asked.append(1) or len(asked) > 1)
    window.act_course.trigger()
    assert os.listdir(out) == ["00-report.pdf"]
    assert (out / "00-report.pdf").read_bytes().rstrip().endswith(b"%%EOF")
    assert shown == ["Cancelled: 1 of 5 files written, each complete."]


def test_a_failed_write_names_the_file_and_the_files_before_it(window, answers, monkeypatch, quick_report):
    out, shown = answers

    def full(sheet, path, *args):
        raise OSError(28, "No space left on device", path)
    monkeypatch.setattr("shaperapp.course.write.write_sheet", full)
    window.act_course.trigger()
    assert os.listdir(out) == ["00-report.pdf"]
    assert len(shown) == 1 and "01-motion.pdf" in shown[0] and "disk is full" in shown[0]
    assert shown[0].endswith("The 1 files written before it are complete.")


@pytest.mark.slow          # the whole course at A1 from the window
@pytest.mark.skipif(not has_pdftotext(), reason="poppler-utils not installed")
def test_export_writes_the_files_of_shaper_course_with_the_report_cover(window, answers):
    out, shown = answers
    window.settings.setValue("report/student", "Wang Wu")      # as the report dialog keeps it
    window.act_course.trigger()
    # the design on screen always has a gear pair (the Gear tab's, the default one here)
    assert shown == []
    assert sorted(os.listdir(out)) == NAMES
    assert "Wang Wu" in pdf_text(out / "01-motion.pdf")
    assert "Wang Wu" in pdf_text(out / "00-report.pdf")
    assert "Feed cam" in " ".join(pdf_text(out / "03-cam.pdf").split())
    assert "Gear meshing" in " ".join(pdf_text(out / "04-gear.pdf").split())
