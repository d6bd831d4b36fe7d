"""The class's hand-outs in both languages (issue 41): tasks.pdf's task sheet and the answer
key's PDF read back as text, Chinese without English words where the UI is Chinese; the
words of the sheets are all translated; the workers never more than fit in 600 MB."""
from __future__ import annotations

import json
import re

import pytest

from cli_runner import shaper_in_process
from core.cli.answers import answer_entry
from core.drawing.class_sheets import TASK_WORDS
from language_checks import has_pdftotext, pdf_text, radicals

BASE = ("--arm", "125", "--swing", "15", "--pressure", "40", "--rise", "75", "--dwell", "10", "--return", "75",
        "--z1", "13", "--z2", "40", "--module", "6", "--rpm", "60", "--lever-mass", "20.387", "--lever-inertia",
        "1.1", "--ram-mass", "71.356", "--cut-force", "7000", "--cut-height", "80", "--dims", "110,380,540",
        "--rod-ratio", "0.25", "--guide", "sagitta")
# what stays Latin on a Chinese sheet: symbols, units, file names, the student's own name
ALLOWED = {"pdf", "motion", "kinetostatic", "cam", "gear", "report", "min", "mm", "kg", "max", "No", "BC",
           "Mmax", "Wmax", "acam", "lBC"}     # M_max, ΔW_max, a_cam, l_BC as pdftotext reads them


@pytest.fixture
def made(tmp_path, qapp):
    path = tmp_path / "s.shaper.json"
    status, _, err = shaper_in_process("design", *BASE, "-o", path)
    assert status == 0, err
    doc = json.loads(path.read_text(encoding="utf-8"))
    return doc, answer_entry("张三", "2021001", "2021001-张三", str(path))


@pytest.mark.skipif(not has_pdftotext(), reason="poppler-utils not installed")
@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_task_sheet_and_answer_key_in_each_language(made, tmp_path, language):
    from shaperapp.course.class_files import write_answer_key, write_tasks
    from shaperapp.widgets import i18n
    doc, entry = made
    i18n.set_language(language)
    try:
        write_tasks(str(tmp_path / "tasks.pdf"), [(doc, {"student": "张三", "number": "2021001",
                                                         "group": "机械2101", "date": "2026-01-01"})], language)
        write_answer_key(str(tmp_path), [entry], ["机械2101"], language)
    finally:
        i18n.set_language("en")
    tasks, key = pdf_text(tmp_path / "tasks.pdf"), pdf_text(tmp_path / "answer-key.pdf")
    # 方案 I's data as the task book writes it: G4 = 200 N, G6 = 700 N from the masses
    for value in ("380", "110", "540", "0.25", "200", "700", "7000", "80", "125", "13", "40"):
        assert value in tasks, value
    assert "33.65" in key and "312.6" in key        # θ and H: 2·asin(110/380), 2·540·110/380
    if language == "en":
        assert "Course design task sheet" in tasks and "Answer key" in key
    else:
        assert "课程设计任务书" in tasks and "参考答案" in key
        assert radicals(tasks + key) == []           # searchable: ideographs, not radicals
        english = {w for w in re.findall(r"[A-Za-z]{3,}", tasks + key) if w not in ALLOWED}
        assert not english, english


def test_every_word_of_the_sheets_is_translated(qapp):
    from shaperapp.course.class_files import task_labels
    from shaperapp.widgets import i18n
    assert set(task_labels()) == set(TASK_WORDS)
    i18n.set_language("zh_CN")
    try:
        chinese = task_labels()
    finally:
        i18n.set_language("en")
    untranslated = [w for w in TASK_WORDS if chinese[w] == w and w not in ("page",)]
    assert not untranslated, untranslated


def test_the_workers_fit_in_600_mb_whatever_jobs():
    from core.cli.common import UsageError
    from shaperapp.course.class_command import MEMORY_MB, PARENT_MB, WORKER_MB, workers
    most = (MEMORY_MB - PARENT_MB) // WORKER_MB
    assert most == 2
    assert workers("64", 30) == most and workers(None, 30) <= most and workers("1", 30) == 1
    assert workers("8", 1) == 1
    with pytest.raises(UsageError, match="--jobs: must be a whole number from 1 to 256"):
        workers("0", 30)


@pytest.mark.skipif(not has_pdftotext(), reason="poppler-utils not installed")
@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_answer_keys_failed_checks_are_words_of_the_language_in_full(tmp_path, qapp, language):
    """A student whose pinion of 13 teeth is cut unshifted (x1 = 0 < (17 − 13)/17: undercut)
    and whose cam is given smaller than its allowance needs: the answer key named the checks by
    core's identifiers ('cam_pressure_angle undercut1…'), English in the Chinese key, and cut
    the third off. Each failed check must read in the key's language, and all of them."""
    from shaperapp.course.class_files import write_answer_key
    from shaperapp.widgets import i18n
    path = tmp_path / "s.shaper.json"
    status, _, err = shaper_in_process("design", *BASE, "--x1", "0", "--x2", "0", "--base", "30",
                                       "--distance", "100", "-o", path)
    assert status == 0, err
    entry = answer_entry("张三", "2021001", "2021001-张三", str(path))
    assert entry["cam"]["max_pressure_angle_rise_deg"] > 40.0            # over its allowance
    failing = [c["name"] for c in entry["gear"]["checks"] if not c["ok"]]
    assert "undercut1" in failing and len(failing) == 2
    i18n.set_language(language)
    try:
        write_answer_key(str(tmp_path), [entry], ["机械2101"], language)
    finally:
        i18n.set_language("en")
    key = " ".join(pdf_text(tmp_path / "answer-key.pdf").split())
    assert "…" not in key
    words = {"en": {"cam_pressure_angle": "cam pressure angle", "undercut1": "undercut 1",
                    "interference1": "interference 1"},
             "zh_CN": {"cam_pressure_angle": "凸轮压力角", "undercut1": "齿轮1根切", "interference1": "齿轮1干涉"}}
    for name in ["cam_pressure_angle", *failing]:
        assert words[language][name] in key, (name, key[-200:])
    if language == "zh_CN":
        english = {w for w in re.findall(r"[A-Za-z]{3,}", key) if w not in ALLOWED}
        assert not english, english


@pytest.mark.skipif(not has_pdftotext(), reason="poppler-utils not installed")
def test_the_answer_key_shows_each_students_number_and_name_whole(made, tmp_path):
    """Student numbers of 10 to 12 digits (a Chinese university's) were cut to '20210012…'
    in a 20 mm column, so two students read alike; a long name the same. Each number and
    each name up to 24 characters must be printed whole, in every table of the key."""
    from shaperapp.course.class_files import write_answer_key
    _, entry = made
    students = [("欧阳诸葛长风", "2021001234"), ("Maximilian Schwarzer", "202100123456"),
                ("张三", "7")]
    entries = [{**entry, "student": name, "student_number": number} for name, number in students]
    write_answer_key(str(tmp_path), entries, ["机械2101"] * 3, "en")
    key = pdf_text(tmp_path / "answer-key.pdf")
    assert "…" not in key
    words = key.split()
    for name, number in students:
        assert words.count(number) == 3, (number, words.count(number))      # one row in each table
        assert " ".join(key.split()).count(name) == 3, name
