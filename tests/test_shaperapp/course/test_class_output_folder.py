"""``shaper class``'s output folder: a rerun into a folder of an earlier run names the
folders it does not make (a student whose row is now bad or gone keeps the earlier run's
folder, whole and stamped, beside the new ones) and leaves them; a second run into a
folder being written is refused; an output that cannot be a folder is said in the plain
words of every other output."""
from __future__ import annotations

import os
import shutil
import subprocess

import pytest

from cli_runner import shaper_in_process
from shaperapp.course.class_run import STAMP_FILE, earlier_folders


def _earlier(folder, name):
    (folder / name).mkdir(parents=True)
    (folder / name / STAMP_FILE).write_text("an earlier run's\n")
    (folder / name / "00-report.pdf").write_text("an earlier run's report")


def test_an_earlier_runs_folder_of_a_bad_or_gone_row_is_named_and_left(tmp_path):
    out = tmp_path / "class"
    _earlier(out, "2-bad")
    _earlier(out, "3-gone")
    (out / "notes").mkdir()                          # the teacher's: no stamp
    tasks = tmp_path / "tasks.csv"
    tasks.write_text("student,student-number,crank,K,stroke\nbad,2,100,0.9,300\n", encoding="utf-8")
    status, out_text, err = shaper_in_process("class", "--tasks", tasks, "-o", out)
    assert status == 2 and out_text == ""
    lines = err.splitlines()
    assert lines[0] == "shaper: error: tasks.csv line 2, column K: must be > 1 and ≤ 5 (got 0.9)"
    assert lines[1] == (f"shaper: note: {out / '2-bad'} holds an earlier run's files, not made from this table "
                        "(its row, line 2, is bad) and not in its answer key; left as it was")
    assert lines[2] == (f"shaper: note: {out / '3-gone'} holds an earlier run's files, not made from this table "
                        "(tasks.csv has no row for it) and not in its answer key; left as it was")
    assert lines[3].startswith("shaper: error: 1 of 1 students not written") and len(lines) == 4
    assert (out / "2-bad" / "00-report.pdf").read_text() == "an earlier run's report"
    assert sorted(p.name for p in out.iterdir()) == ["2-bad", "3-gone", "notes"]


def test_only_stamped_folders_other_than_this_runs_are_earlier(tmp_path):
    _earlier(tmp_path, "1-made")
    _earlier(tmp_path, "2-old")
    (tmp_path / "3-mine").mkdir()
    (tmp_path / "4-file").write_text("")
    (tmp_path / "5-link").symlink_to(tmp_path / "2-old")
    assert earlier_folders(str(tmp_path), {"1-made"}) == ["2-old"]
    assert earlier_folders(str(tmp_path / "missing"), set()) == []


def test_a_second_run_into_a_folder_being_written_is_refused_before_it_writes(tmp_path):
    """Two runs into one folder at once (a rerun with a changed table started while the
    first still ran) wrote each other's students: the first run's answer key gave the
    second run's crank for a student its own table gave another. The folder is held by
    the run writing it (a lock the system drops when that process ends, a kill too); a
    second run is one line, exit 2, and writes nothing."""
    import fcntl
    out = tmp_path / "class"
    out.mkdir()
    tasks = tmp_path / "tasks.csv"
    tasks.write_text("student,student-number,crank,K,stroke,lever-weight,lever-inertia,ram-weight,cut-force,arm,"
                     "swing,pressure,rise,dwell,return,z1,z2,module\n"
                     "a,1,100,1.4,300,200,1.1,700,7000,125,15,40,75,10,75,13,40,6\n", encoding="utf-8")
    first = os.open(out, os.O_RDONLY)                  # the run writing the folder holds it
    try:
        fcntl.flock(first, fcntl.LOCK_EX | fcntl.LOCK_NB)
        status, text, err = shaper_in_process("class", "--tasks", tasks, "-o", out)
    finally:
        os.close(first)
    assert status == 2 and text == ""
    assert err == f"shaper: error: --output: another 'shaper class' is writing into {out}; let it finish, then run this one\n"
    assert list(out.iterdir()) == []


def test_an_output_that_cannot_be_a_folder_is_said_in_plain_words(tmp_path):
    """-o naming a file read 'cannot make F: File exists', and a name too long 'File name
    too long': the system's words, not those of every other output ('it is not a folder',
    'the name is too long', as shaper course says them)."""
    tasks = tmp_path / "tasks.csv"
    tasks.write_text("student,student-number,crank,K,stroke,lever-weight,lever-inertia,ram-weight,cut-force,arm,"
                     "swing,pressure,rise,dwell,return,z1,z2,module\n"
                     "a,1,100,1.4,300,200,1.1,700,7000,125,15,40,75,10,75,13,40,6\n", encoding="utf-8")
    a_file = tmp_path / "afile"
    a_file.write_text("mine")
    status, _, err = shaper_in_process("class", "--tasks", tasks, "-o", a_file)
    assert status == 2 and err == f"shaper: error: --output: cannot write into {a_file}: it is not a folder\n"
    long = tmp_path / ("d" * 300)
    status, _, err = shaper_in_process("class", "--tasks", tasks, "-o", long)
    assert status == 2 and err == f"shaper: error: --output: cannot make {long}: the name is too long\n"
    assert a_file.read_text() == "mine"


def test_a_table_of_no_students_or_bad_rows_only_makes_no_folder(tmp_path, qapp):
    """A header alone is refused by name, exit 2 (it ran with no word, exit 0, and made DIR
    empty); a table of bad rows only names them and makes no DIR either (hunt, 1 December).
    Each in the dialog's language too: the refusal has its Chinese words."""
    from shaperapp.course.class_messages import table_message
    from shaperapp.widgets import i18n
    header = tmp_path / "header.csv"
    header.write_text("student,student-number,crank,K\n\n", encoding="utf-8")
    status, out_text, err = shaper_in_process("class", "--tasks", header, "-o", tmp_path / "none")
    assert (status, out_text) == (2, "")
    assert err == "shaper: error: header.csv: no students; each row under the header is one student\n"
    bad = tmp_path / "bad.csv"
    bad.write_text("student,student-number,crank,K\nx,1,100,0.9\n", encoding="utf-8")
    status, _, err = shaper_in_process("class", "--tasks", bad, "-o", tmp_path / "none")
    assert status == 2 and "1 of 1 students not written" in err
    assert not (tmp_path / "none").exists()
    i18n.set_language("zh_CN")
    try:
        assert table_message("header.csv: no students; each row under the header is one student") == \
            "header.csv：没有学生；列名行之下每一行为一名学生"
    finally:
        i18n.set_language("en")


ROW = ("student,student-number,crank,K,stroke,lever-weight,lever-inertia,ram-weight,cut-force,arm,"
       "swing,pressure,rise,dwell,return,z1,z2,module\n"
       "a,1,100,1.4,300,200,1.1,700,7000,125,15,40,75,10,75,13,40,6\n")


@pytest.mark.skipif(shutil.which("chattr") is None or os.geteuid() != 0, reason="chattr +i needs root and e2fsprogs")
def test_a_folder_the_run_cannot_write_into_is_one_line_before_any_student(tmp_path):
    """An immutable DIR, or DIR/tasks.pdf a folder: one line naming --output before any
    student (hunt, 1 December: each student failed as '[Errno 1] Operation not permitted:
    …', then tasks.pdf failed too; with tasks.pdf a folder every student was written and
    then the run failed). A student's folder that cannot be written is said in plain words."""
    tasks = tmp_path / "tasks.csv"
    tasks.write_text(ROW, encoding="utf-8")
    locked = tmp_path / "locked"
    locked.mkdir()
    (locked / "1-a").mkdir()
    (locked / "1-a" / ".class-stamp").write_text("an earlier run's\n")
    subprocess.run(["chattr", "+i", str(locked)], check=True)
    try:
        status, text, err = shaper_in_process("class", "--tasks", tasks, "-o", locked)
    finally:
        subprocess.run(["chattr", "-i", str(locked)], check=True)
    assert (status, text) == (2, "") and err == f"shaper: error: --output: cannot write into {locked}: permission denied\n"
    busy = tmp_path / "busy"
    (busy / "tasks.pdf").mkdir(parents=True)
    status, text, err = shaper_in_process("class", "--tasks", tasks, "-o", busy)
    assert (status, text) == (2, "") and err == f"shaper: error: --output: cannot write {busy / 'tasks.pdf'}: it is a folder\n"
    assert [p.name for p in busy.iterdir()] == ["tasks.pdf"]
    subprocess.run(["chattr", "+i", str(locked / "1-a")], check=True)
    try:
        status, _, err = shaper_in_process("class", "--tasks", tasks, "-o", locked, "--jobs", "1")
    finally:
        subprocess.run(["chattr", "-i", str(locked / "1-a")], check=True)
    assert status == 2 and err.splitlines()[0] == (
        f"shaper: error: 1-a: cannot write {locked / '1-a' / '.class-stamp'}: permission denied")


def test_a_file_where_a_students_folder_goes_is_named_and_kept(tmp_path):
    """A file of a student's folder name: 'cannot write F: File exists', the system's words
    (hunt, 1 December); now what is in the way and what to do, the file kept. With no
    student written, the earlier run's answer key stays (it was replaced by one of nobody)."""
    tasks = tmp_path / "tasks.csv"
    tasks.write_text(ROW, encoding="utf-8")
    out = tmp_path / "class"
    out.mkdir()
    (out / "1-a").write_text("mine")
    (out / "answer-key.json").write_text("[an earlier run's key]\n")
    status, text, err = shaper_in_process("class", "--tasks", tasks, "-o", out, "--jobs", "1")
    assert text.endswith(f"; tasks.pdf in {out}; no answer key, as no student was written (an earlier one is "
                         "left as it was)\n"), text
    assert (out / "answer-key.json").read_text() == "[an earlier run's key]\n"     # not a key of nobody
    assert not (out / "answer-key.pdf").exists()
    assert status == 2 and err.splitlines()[0] == (
        f"shaper: error: 1-a: cannot make the folder {out / '1-a'}: a file of that name is in the way; move it, "
        "then run the class again")
    assert (out / "1-a").read_text() == "mine"
