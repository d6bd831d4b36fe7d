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
