"""A class rerun after a kill leaves no temporary file in a student's folder, also where
the student was complete and is not written again (the kill came after its last file)."""
import os
import subprocess
import sys
from pathlib import Path

from shaperapp.course.class_run import STAMP_FILE, Job, expected_files, run_student, stamp_of

DESIGN = Path(__file__).parents[2] / "data" / "my.shaper.json"


def test_a_complete_student_is_not_rewritten_and_its_stale_temps_go(tmp_path):
    folder = tmp_path / "S01-x"
    folder.mkdir()
    job = Job(0, str(folder), "S01-x", DESIGN.read_text(encoding="utf-8"), "en", "A3", False, "t", "d",
              {"student": "x", "number": "S01"})
    for name in expected_files(job):
        (folder / name).write_text(job.design_text if name.endswith(".json") else "made before")
    (folder / STAMP_FILE).write_text(stamp_of(job) + "\n")
    gone = subprocess.Popen([sys.executable, "-c", "pass"])
    gone.wait()
    stale = [f".{name}.{gone.pid}-0123abcd.tmp" for name in ("01-motion.pdf", "design.shaper.json", STAMP_FILE)]
    for name in stale:
        (folder / name).write_text("partial")
    result = run_student(job)
    assert result.skipped and result.error == "" and result.entry is not None
    assert sorted(os.listdir(folder)) == sorted([*expected_files(job), STAMP_FILE])
    assert (folder / "01-motion.pdf").read_text() == "made before"            # not written again


def test_a_student_made_by_other_code_is_made_again(tmp_path, monkeypatch):
    """The stamp names the code that made the files, not only the version, which stays
    the same from one fix to the next: files a changed program would make otherwise
    are not "up to date"."""
    import shaperapp.course.class_run as class_run
    from core.version import source_fingerprint
    folder = tmp_path / "S01-x"
    folder.mkdir()
    job = Job(0, str(folder), "S01-x", DESIGN.read_text(encoding="utf-8"), "en", "A3", False, "t", "d",
              {"student": "x", "number": "S01"})
    for name in expected_files(job):
        (folder / name).write_text("made before")
    (folder / STAMP_FILE).write_text(stamp_of(job) + "\n")
    assert class_run.is_current(job)
    made = class_run.made_by()
    monkeypatch.setattr(class_run, "made_by", lambda: made + " fixed")
    assert not class_run.is_current(job)
    # the fingerprint follows a package's every file and nothing but its bytecode
    package = tmp_path / "made" / "tool"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("X = 1\n")
    monkeypatch.syspath_prepend(str(tmp_path / "made"))
    first = source_fingerprint("tool")
    (package / "__pycache__").mkdir()
    (package / "__pycache__" / "x.pyc").write_bytes(b"compiled")
    assert source_fingerprint("tool") == first
    (package / "words.qm").write_bytes(b"translation")
    second = source_fingerprint("tool")
    (package / "__init__.py").write_text("X = 2\n")
    assert len({first, second, source_fingerprint("tool")}) == 3


def test_a_run_without_dxf_removes_an_earlier_runs_dxfs_and_says_so(tmp_path, monkeypatch):
    """A run with --dxf, then one without it and a changed row: the folder kept the first
    run's DXFs, drawn for the earlier crank, beside the new PDFs, and was stamped current.
    The DXFs of the course's names go, and the result names them (the command's note); a
    file of another name stays. (The course's writing is left out here: only the folder.)"""
    import shaperapp.course.class_run as class_run
    import shaperapp.course.write as write
    import shaperapp.report.kept_views as kept_views
    monkeypatch.setattr(write, "write_course", lambda *a, **k: iter(()))
    # nor Qt: a report's plot views kept in English here served a later test's Chinese report
    monkeypatch.setattr(class_run, "_language", lambda lang: lang)
    monkeypatch.setattr(kept_views, "keep_plot_views", lambda: None)
    folder = tmp_path / "S01-x"
    folder.mkdir()
    job = Job(0, str(folder), "S01-x", DESIGN.read_text(encoding="utf-8"), "en", "A3", False, "t", "d",
              {"student": "x", "number": "S01"})
    earlier = ["01-motion.dxf", "03-cam.dxf", "01-motion.pdf"]
    for name in [*earlier, "my-notes.dxf"]:
        (folder / name).write_text("an earlier run's")
    result = run_student(job)
    assert result.error == "" and not result.skipped
    assert sorted(os.listdir(folder)) == sorted(["01-motion.pdf", "my-notes.dxf", "design.shaper.json", STAMP_FILE])
    assert result.removed == ("01-motion.dxf", "03-cam.dxf")
