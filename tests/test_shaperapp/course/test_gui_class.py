"""File › Class course design… (issue 41, item 5): the table's rows shown with their errors
marked before anything runs, a run of ``shaper class`` with a progress bar, and Cancel,
which leaves only complete files; the menu entry in both languages."""
from __future__ import annotations

import signal
import subprocess

import pytest

from cli_runner import shaper_in_process
from language_checks import check_file_menu_entry

BASE = ("--arm", "125", "--swing", "15", "--pressure", "40", "--rise", "75", "--dwell", "10", "--return", "75",
        "--z1", "13", "--z2", "40", "--module", "6", "--rpm", "60", "--lever-mass", "20", "--lever-inertia", "1.1",
        "--ram-mass", "70", "--cut-force", "7000", "--crank", "100", "--K", "1.4", "--stroke", "300")


@pytest.fixture
def class_files(tmp_path):
    status, _, err = shaper_in_process("design", *BASE, "-o", tmp_path / "base.json")
    assert status == 0, err
    tasks = tmp_path / "tasks.csv"
    tasks.write_text("student,student-number,crank,K\n张三,1,100,1.4\n李四,2,105,1.45\n坏,3,100,0.9\n王五,4,95,1.4\n",
                     encoding="utf-8")
    return tasks, tmp_path / "base.json", tmp_path / "out"


def test_the_menu_has_the_class_in_both_languages(window, qtbot):
    check_file_menu_entry(window, qtbot, window.act_class, "C&lass course design…")


def test_the_rows_are_shown_with_their_errors_before_running(qtbot, class_files):
    from shaperapp.course.class_dialog import BAD, ClassDialog
    tasks, base, out = class_files
    dialog = ClassDialog("en")
    qtbot.addWidget(dialog)
    assert not dialog.run_button.isEnabled()
    dialog.tasks.setText(str(tasks))
    dialog.base.setText(str(base))
    dialog.check()
    assert dialog.table.rowCount() == 4
    cells = [[dialog.table.item(r, c).text() for c in range(4)] for r in range(4)]
    assert [row[:3] for row in cells] == [["2", "张三", "1"], ["3", "李四", "2"], ["4", "坏", "3"], ["5", "王五", "4"]]
    # the Line column is the row's first number: Qt's own row numbers (1, 2, …) stood before it (1 | 2)
    dialog.show()
    qtbot.waitExposed(dialog)
    assert dialog.table.viewport().geometry().left() == dialog.table.frameWidth()
    # core's "must be > 1 and ≤ 5" in the words every form of the GUI gives it (widgets.messages)
    assert cells[2][3] == "tasks.csv line 4, column K: must be greater than 1 and at most 5 (got 0.9)"
    assert dialog.table.item(2, 3).background().color() == BAD
    assert dialog.table.item(0, 3).background().color() != BAD and cells[0][3] == "ready"
    assert "3 students ready, 1 rows with errors" in dialog.summary.text()
    assert not dialog.run_button.isEnabled()           # no folder yet
    dialog.folder.setText(str(out))
    assert dialog.run_button.isEnabled() and not out.exists()       # nothing written before Run


@pytest.mark.slow
def test_cancel_leaves_only_complete_files(qtbot, class_files):
    """Cancel stops the class (its answer key never written) with every file left whole,
    also from a GUI started with SIGINT ignored (a shell's background job without job
    control, as CI runs the suite): its child still takes the Cancel's SIGINT."""
    tasks, base, out = class_files
    before = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        _cancel_a_class(qtbot, tasks, base, out)
    finally:
        signal.signal(signal.SIGINT, before)


def _cancel_a_class(qtbot, tasks, base, out) -> None:
    from shaperapp.course.class_dialog import ClassDialog
    # eight students: with three, a loaded CI worker saw the whole class written between
    # the first PDF and the cancel; eight cannot be, the two being written finish
    tasks.write_text("student,student-number,crank,K\n"
                     + "".join(f"S{i},{i},{95 + i},1.4\n" for i in range(1, 9)), encoding="utf-8")
    dialog = ClassDialog("en")
    qtbot.addWidget(dialog)
    dialog.tasks.setText(str(tasks))
    dialog.base.setText(str(base))
    dialog.folder.setText(str(out))
    dialog.sheet.setCurrentText("A3")
    dialog.check()
    dialog.run()
    assert dialog.progress.maximum() == 8
    qtbot.waitUntil(lambda: any(out.glob("*/*.pdf")), timeout=300_000)
    dialog.cancel()
    qtbot.waitUntil(lambda: dialog._process is None, timeout=300_000)
    assert dialog.summary.text().startswith("Cancelled: ")
    assert dialog.open_button.isEnabled()
    assert not list(out.rglob("*.tmp"))
    for pdf in out.rglob("*.pdf"):          # every file left opens whole
        assert subprocess.run(["pdfinfo", str(pdf)], capture_output=True).returncode == 0, pdf
    assert not (out / "answer-key.json").exists()     # the class did not finish


def test_the_rows_errors_are_chinese_in_the_chinese_dialog(window, qtbot, tmp_path):
    """Gap 2 of issue 41: a bad row's message (core's English) is given in Chinese, as the
    other refusals of core are; the table's name, the columns and the values typed stay."""
    from language_checks import assert_chinese_text

    from shaperapp.course.class_dialog import ClassDialog
    window.set_language("zh_CN")
    tasks = tmp_path / "tasks.csv"
    tasks.write_text("student,student-number,crank,K,stroke,cut-force,design\n"
                     "甲,1,100,0.9,300,5,\n乙,2,100,abc,300,5,\n丙,3,,1.4,300,5,\n丁,4,100,1.4,300,-5,\n"
                     "戊,5,100,1.4,300,5,../x.json\n", encoding="utf-8")
    dialog = ClassDialog("zh_CN")
    qtbot.addWidget(dialog)
    dialog.tasks.setText(str(tasks))
    dialog.check()
    errors = [dialog.table.item(r, 3).text() for r in range(5)]
    assert errors[0].startswith("tasks.csv 第 2 行，K 列：") and errors[0].endswith("0.9）"), errors[0]
    allowed = {"tasks", "csv", "design", "crank", "dims", "abc", "json", "cut", "force"}
    for text in errors:
        assert_chinese_text(text, allowed, text)
    tasks.write_text("student,student-number,cranky\n甲,1,100\n", encoding="utf-8")
    dialog.check()
    assert_chinese_text(dialog.summary.text(), allowed | {"cranky"}, dialog.summary.text())


# the four kinds of note shaper class prints, and a key its --base file lacked twice
NOTES = ("tasks.csv read as GBK", "--base: /x/base.json gives no cam.hub_mm; 12.5 mm taken",
         "out/1-x: removed 01-motion.dxf, 04-gear.dxf of an earlier run, drawn from its data; this run writes no "
         "DXF (--dxf)",
         "--base: /x/base.json gives no cam.clearance_mm; 3 mm taken",
         "out/2-x holds an earlier run's files, not made from this table (its row, line 4, is bad) and not in its "
         "answer key; left as it was",
         "out/3-x holds an earlier run's files, not made from this table (tasks.csv has no row for it) and not in "
         "its answer key; left as it was")


def _finished(dialog, folder, status: int, stderr: str, key_before: int | None) -> str:
    """The dialog's summary once a run that printed ``stderr`` ended with ``status``."""
    dialog.folder.setText(str(folder))
    dialog._process, dialog._errors, dialog._key_before, dialog._finished = object(), stderr, key_before, 3
    dialog._done(status, None)
    return dialog.summary.text()


def test_an_earlier_runs_answer_key_is_not_this_runs_success(qtbot, tmp_path):
    """A run refused at once (another run writes into the folder) left the earlier run's
    answer key there: the dialog said "Done: 0 students written" on exit status 2."""
    from shaperapp.course.class_dialog import ClassDialog, _stamp
    dialog = ClassDialog("en")
    qtbot.addWidget(dialog)
    key = tmp_path / "answer-key.json"
    key.write_text("{}", encoding="utf-8")
    refusal = "shaper: error: --output: another 'shaper class' is writing into out; let it finish, then run this one\n"
    text = _finished(dialog, tmp_path, 2, refusal, _stamp(str(key)))
    assert text == "Failed: --output: another 'shaper class' is writing into out; let it finish, then run this one"


def test_a_run_with_bad_rows_says_how_many_were_not_written_and_its_notes(qtbot, tmp_path):
    from shaperapp.course.class_dialog import ClassDialog
    dialog = ClassDialog("en")
    qtbot.addWidget(dialog)
    (tmp_path / "answer-key.json").write_text("{}", encoding="utf-8")       # this run's (none before)
    notes = "".join(f"shaper: note: out/{i}-x holds an earlier run's files; left as it was\n" for i in range(7))
    text = _finished(dialog, tmp_path, 2, notes + "shaper: error: 2 of 5 students not written (1 bad rows, 1 failed)\n",
                     None)
    lines = text.splitlines()
    assert lines[0] == ("Done: 3 students written; the task sheets and the answer key are in the folder. "
                        "2 of 5 students not written (1 bad rows, 1 failed).")
    assert lines[1] == "Notes (7):"
    assert lines[2:] == [f"out/{i}-x holds an earlier run's files; left as it was" for i in range(5)] + ["…"]


def test_the_finish_and_a_rows_missing_parts_are_chinese_in_the_chinese_dialog(window, qtbot, tmp_path):
    """The count of students not written, and a row lacking the parts a course design needs
    (core.cli.tasks: "lacks the loads (…) and the gear pair (…) …"), in Chinese."""
    from language_checks import assert_chinese_text

    from shaperapp.course.class_dialog import ClassDialog
    window.set_language("zh_CN")
    dialog = ClassDialog("zh_CN")
    qtbot.addWidget(dialog)
    (tmp_path / "answer-key.json").write_text("{}", encoding="utf-8")
    text = _finished(dialog, tmp_path, 2, "shaper: error: 1 of 4 students not written (1 bad rows, 0 failed)\n", None)
    assert_chinese_text(text, set(), text)
    # the run's notes, as shaper class prints them (they were shown in English)
    text = _finished(dialog, tmp_path, 2, "".join("shaper: note: " + note + "\n" for note in NOTES)
                     + "shaper: error: 1 of 4 students not written (1 bad rows, 0 failed)\n", None)
    assert_chinese_text(text, {"tasks", "csv", "GBK", "base", "json", "cam", "hub", "mm", "clearance", "out", "motion",
                               "dxf", "gear"}, text)
    # a run refused at once (another run writes into the folder): its reason, in Chinese too
    refusal = "shaper: error: --output: another 'shaper class' is writing into out; let it finish, then run this one\n"
    text = _finished(dialog, tmp_path / "none", 2, refusal, None)
    assert text.startswith("失败：--output：") and "out" in text, text
    assert_chinese_text(text, {"output", "shaper", "class", "out"}, text)
    text = _finished(dialog, tmp_path, 2, "".join("shaper: note: " + note + "\n" for note in NOTES)
                     + "shaper: error: 1 of 4 students not written (1 bad rows, 0 failed)\n", None)
    lines = text.splitlines()
    assert lines[2] == "base.json 未给出 cam.hub_mm = 12.5 mm, cam.clearance_mm = 3 mm；已按这些值取用。", lines[2]
    assert "01-motion.dxf, 04-gear.dxf" in lines[4] and "out/2-x" in lines[5] and "第 4 行" in lines[5], lines
    tasks = tmp_path / "tasks.csv"
    tasks.write_text("student,student-number,crank,K,stroke\n甲,1,100,1.4,300\n", encoding="utf-8")
    dialog.tasks.setText(str(tasks))
    dialog.check()
    error = dialog.table.item(0, 3).text()
    assert "lever-weight" in error and "z1" in error, error         # the columns to add, as core names them
    assert_chinese_text(error, {"tasks", "csv", "rpm", "lever", "weight", "inertia", "ram", "cut", "force", "arm",
                                "swing", "pressure", "rise", "dwell", "return", "z1", "z2", "module", "base"}, error)


class PrintedProcess:
    """Stands for the ``shaper class`` process: what it printed, read in the pieces given
    (a line may end in the next piece)."""

    def __init__(self, out: list[str], err: list[str]) -> None:
        self.out, self.err = [p.encode() for p in out], [p.encode() for p in err]

    def readAllStandardOutput(self) -> bytes:       # noqa: N802 (Qt's name)
        return self.out.pop(0) if self.out else b""

    def readAllStandardError(self) -> bytes:        # noqa: N802 (Qt's name)
        return self.err.pop(0) if self.err else b""


def checks(dialog) -> list[str]:
    return [dialog.table.item(r, 3).text() for r in range(dialog.table.rowCount())]


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_after_a_run_each_row_says_what_happened_to_its_student(window, qtbot, class_files, language):
    """The rows said "ready" after the run had written or failed them. Now each says what
    the command said of its student: written, up to date (not written again), failed with
    the command's reason (red), or, for one the run never reached, not written; a bad row
    keeps its error. The lines are the command's own (``student_line``, ``failure_line``)."""
    from shaperapp.course.class_dialog import BAD, ClassDialog
    from shaperapp.course.class_run import failure_line, student_line
    window.set_language(language)
    tasks, base, out = class_files
    tasks.write_text("student,student-number,crank,K\n张三,1,100,1.4\n李四,2,105,1.45\n坏,3,100,0.9\n王五,4,95,1.4\n"
                     "赵六,5,98,1.4\n", encoding="utf-8")
    dialog = ClassDialog(language)
    qtbot.addWidget(dialog)
    dialog.tasks.setText(str(tasks))
    dialog.base.setText(str(base))
    dialog.check()
    bad_row = checks(dialog)[2]
    from core.cli.tasks import read_tasks
    folders = [s.folder for s in read_tasks(str(tasks), str(base))[0] if not s.error]   # 张三, 李四, 王五, 赵六
    printed = student_line(folders[0], False, 4.2) + "\n" + student_line(folders[2], True, 0.1) + "\n"
    failure = "shaper: error: " + failure_line(folders[1], "OSError: [Errno 28] No space left on device") + "\n"
    dialog._process = PrintedProcess([printed[:9], printed[9:]], [failure[:20], failure[20:]])
    dialog._errors = ""
    for _ in range(2):
        dialog._read()
        dialog._read_errors()
    assert dialog.progress.value() == 3
    dialog._done(2, None)                        # the run ended without reaching 赵六
    words = {"en": ("written", "up to date, not written again", "failed: ", "not written"),
             "zh_CN": ("已写入", "已是最新，未重写", "失败：", "未写入")}[language]
    assert checks(dialog) == [words[0], words[2] + "OSError: [Errno 28] No space left on device", bad_row, words[1],
                              words[3]]
    assert dialog.table.item(1, 3).background().color() == BAD
    assert dialog.table.item(0, 3).background().color() != BAD
    window.set_language("en")


def test_chinese_sentences_of_the_finish_follow_each_other_without_a_space(window, qtbot, tmp_path):
    """"完成：…在文件夹中。 5 名学生中有 2 名未写入…": Chinese sentences follow each other
    without a space (the English ones with one)."""
    from shaperapp.course.class_dialog import ClassDialog
    (tmp_path / "answer-key.json").write_text("{}", encoding="utf-8")
    count = "shaper: error: 2 of 5 students not written (1 bad rows, 1 failed)\n"
    for language in ("zh_CN", "en"):
        window.set_language(language)
        dialog = ClassDialog(language)
        qtbot.addWidget(dialog)
        first = _finished(dialog, tmp_path, 2, count, None).splitlines()[0]
        if language == "zh_CN":
            assert first.startswith("完成：已写入 3 名学生；") and "。" in first and "。 " not in first, first
        else:
            assert "folder. 2 of 5 students" in first, first
    window.set_language("en")
