"""``shaper class`` (issue 41, item 3): a class's table in, every student's folder, the task
sheets and the answer key out; a bad row named and left out (exit 2); a run killed half-way
finished by a rerun that does not redo a complete, current student; the answer key's JSON
each student's real ``shaper COMMAND --json --design`` output."""
from __future__ import annotations

import csv
import io
import json
import math
import os
import re
import signal
import subprocess
import sys

import numpy as np
import pytest

from cli_runner import shaper, shaper_in_process
from language_checks import has_pdftotext, pdf_text

pytestmark = [pytest.mark.slow, pytest.mark.skipif(not has_pdftotext(), reason="poppler-utils not installed")]

COURSE = ["design.shaper.json", "00-report.pdf", "01-motion.pdf", "02-kinetostatic.pdf", "03-cam.pdf", "04-gear.pdf"]
BASE = ("--arm", "125", "--swing", "15", "--pressure", "40", "--rise", "75", "--dwell", "10", "--return", "75",
        "--z1", "13", "--z2", "40", "--module", "6", "--rpm", "60", "--guide", "sagitta")
HEADER = "student,student-number,class,dims,rod-ratio,rpm,lever-mass,lever-inertia,ram-mass,cut-force,cut-height"
# 孙桓《机械原理》(高等教育出版社) 课程设计指导书, 牛头刨床导杆机构, 方案 I–III (n2, l_O2A, l_O2O4,
# l_O4B, l_BC/l_O4B, G4 N, J_S4 kg·m², G6 N, P N, y_P mm); weights entered as masses G/9.81.
CLASSIC = ((60, 110, 380, 540, 0.25, 200, 1.1, 700, 7000, 80), (64, 90, 350, 580, 0.3, 220, 1.2, 800, 9000, 80),
           (72, 110, 430, 810, 0.36, 220, 1.2, 620, 8000, 100))
CMD = [sys.executable, "-m", "core"]


def _rows() -> list[str]:
    rows = [f"方案{'I' * k},S0{k},机械2101,\"{l1},{l2},{l3}\",{rod},{n},{g4 / 9.81!r},{j4},{g6 / 9.81!r},{p},{yp}"
            for k, (n, l1, l2, l3, rod, g4, j4, g6, p, yp) in enumerate(CLASSIC, start=1)]
    rng = np.random.default_rng(2041)             # a random student between the classic ones
    l1, l2 = rng.uniform(90, 115), rng.uniform(360, 420)
    l3 = (l2 + l1) / math.cos(math.asin(l1 / l2)) * rng.uniform(1.2, 1.4)   # the ram clears the crank
    rows.append(f"Random Student,R01,,\"{l1:.2f},{l2:.2f},{l3:.2f}\",0.3,60 72,20,1.1,70,7000,80")
    rows.append('坏 行,S09,,"110,380,540",0.3,60,20,1.1,70,-5,80')
    return rows


def _class(tasks, out, *extra):
    return [*CMD, "class", "--tasks", str(tasks), "-o", str(out), "--base", str(tasks.parent / "base.json"),
            "--sheet", "A3", "--jobs", "2", "--date", "2026-01-01", "--school", "机械学院", *extra]


def _listing(folder):
    return {p.relative_to(folder).as_posix(): p.stat().st_mtime_ns for p in folder.rglob("*") if p.is_file()}


@pytest.fixture(scope="module")
def classroom(tmp_path_factory):
    """Run 1 killed after its first finished student; run 2 finishes the class; run 3 finds
    everything current. The class's folder and its parents did not exist."""
    home = tmp_path_factory.mktemp("class")
    status, _, err = shaper_in_process("design", "--crank", "100", "--K", "1.4", "--stroke", "300", *BASE,
                                       "-o", home / "base.json")
    assert status == 0, err
    tasks = home / "tasks.csv"
    tasks.write_text("\n".join([HEADER, *_rows()]) + "\n", encoding="utf-8-sig")
    out = home / "deep" / "er" / "class"
    first = subprocess.Popen(_class(tasks, out), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             start_new_session=True)
    line = first.stdout.readline()
    os.killpg(first.pid, signal.SIGKILL)
    first.wait(timeout=60)
    killed = dict(_listing(out))
    second = subprocess.run(_class(tasks, out), capture_output=True, text=True, timeout=900)
    after_second = _listing(out)
    third = subprocess.run(_class(tasks, out), capture_output=True, text=True, timeout=900)
    return home, out, line, killed, second, after_second, third


def test_every_good_row_has_its_folder_and_the_bad_one_none(classroom):
    _, out, _, _, second, _, _ = classroom
    folders = sorted(p.name for p in out.iterdir() if p.is_dir())
    assert folders == ["R01-Random Student", "S01-方案I", "S02-方案II", "S03-方案III"]
    for folder in folders:
        names = sorted(os.listdir(out / folder))
        assert names == sorted(COURSE + [".class-stamp"]), folder        # no temporary file left
    assert sorted(p.name for p in out.iterdir() if p.is_file()) == \
        ["answer-key.csv", "answer-key.json", "answer-key.pdf", "tasks.pdf"]
    assert second.returncode == 2
    errors = second.stderr.splitlines()
    assert "shaper: error: tasks.csv line 6, column cut-force: must be ≥ 0 and ≤ 1e+09 N (got -5)" in errors
    assert errors[-1] == "shaper: error: 1 of 5 students not written (1 bad rows, 0 failed)"


def test_a_killed_run_is_finished_and_a_complete_student_not_redone(classroom):
    _, out, line, killed, second, after_second, third = classroom
    done = line.split()[0]                              # the student run 1 finished before the kill
    assert line.split()[1] == "written"
    assert f"{done}  up to date" in second.stdout
    assert {k: v for k, v in after_second.items() if k.startswith(done + "/")} == \
        {k: v for k, v in killed.items() if k.startswith(done + "/")}
    # run 3: nothing to do, nothing touched but the class's own four files
    assert third.stdout.count("up to date") == 4 and "written" not in third.stdout
    students = {k: v for k, v in _listing(out).items() if "/" in k}
    assert students == {k: v for k, v in after_second.items() if "/" in k}


def test_the_answer_key_json_is_each_commands_own_output(classroom):
    _, out, _, _, _, _, _ = classroom
    entries = json.loads((out / "answer-key.json").read_text(encoding="utf-8"))
    assert [e["student_number"] for e in entries] == ["S01", "S02", "S03", "R01"]
    for entry in entries:
        assert set(entry) == {"student", "student_number", "folder", "synth", "analyze", "dynamics", "cam", "gear"}
        design = out / entry["folder"] / "design.shaper.json"
        for command in ("synth", "analyze", "dynamics", "cam", "gear"):
            # the command's main() in this process: the same output as the console script,
            # without starting 20 interpreters (test_cli.py runs the console script itself)
            status, stdout, stderr = shaper_in_process(command, "--json", "--design", design)
            assert status == 0 and json.loads(stdout) == entry[command], (entry["folder"], command, stderr)


def test_the_answer_key_csv_holds_the_json_figures(classroom):
    _, out, _, _, _, _, _ = classroom
    raw = (out / "answer-key.csv").read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")
    rows = list(csv.DictReader(io.StringIO(raw.decode("utf-8-sig"))))
    entries = json.loads((out / "answer-key.json").read_text(encoding="utf-8"))
    assert [r["student"] for r in rows] == ["方案I", "方案II", "方案III", "Random Student"]
    for row, entry in zip(rows, entries):
        assert float(row["theta (deg)"]) == entry["synth"]["theta_deg"]
        assert float(row["J_F_1 (kg·m²)"]) == entry["dynamics"]["speeds"][0]["flywheel_inertia_kg_m2"]
        assert float(row["J_F_needed_1 (kg·m²)"]) == entry["dynamics"]["speeds"][0]["flywheel_inertia_needed_kg_m2"]
        assert float(row["epsilon"]) == entry["gear"]["pair"]["contact_ratio"]
        assert row["class"] == ("机械2101" if row["student_number"].startswith("S") else "")
    assert rows[3]["n2 (r/min)"] == "72.0" and rows[0]["n2 (r/min)"] == ""      # the random row's two speeds


def test_the_answer_key_pdf_prints_each_figure_as_the_cli_does(classroom):
    """Gap 1 of issue 41: the answer key's PDF writes a figure in the one precision of its
    kind (core.base.figure_text), the very text ``shaper synth/analyze/dynamics/gear`` print for the
    student's design file: K = 1.4600, not 1.46."""
    from core.base.figure_text import figure_text
    _, out, _, _, _, _, _ = classroom
    cells = set(pdf_text(out / "answer-key.pdf").split())
    for entry in json.loads((out / "answer-key.json").read_text(encoding="utf-8")):
        design = out / entry["folder"] / "design.shaper.json"
        printed = {}
        for command in ("synth", "analyze", "dynamics", "gear"):
            # main() in this process, as the JSON test above: the console script's very text
            # without 16 interpreters (13 s of the suite; test_cli.py runs the script itself)
            status, printed[command], stderr = shaper_in_process(command, "--design", design)
            assert status == 0, (entry["folder"], command, stderr)
        speed, forces = entry["analyze"]["speeds"][0], entry["dynamics"]["speeds"][0]
        for command, kind, value in (
                ("synth", "angle", entry["synth"]["theta_deg"]), ("synth", "length", entry["synth"]["lever_mm"]),
                ("analyze", "ratio", entry["analyze"]["K"]), ("analyze", "speed", speed["v_work_max_m_s"]),
                ("analyze", "acceleration", speed["a_max_m_s2"]), ("dynamics", "torque", forces["max_torque_N_m"]),
                ("dynamics", "inertia", forces["flywheel_inertia_kg_m2"]),
                ("gear", "gear_factor", entry["gear"]["gear1"]["shift_factor"]),
                ("gear", "gear_factor", entry["gear"]["pair"]["contact_ratio"]),
                ("gear", "gear_length", entry["gear"]["pair"]["centre_mm"])):
            text = figure_text(kind, value)
            assert text in printed[command], (entry["folder"], command, text)
            assert text in cells, (entry["folder"], kind, text)


def test_covers_and_title_blocks_carry_the_row(classroom):
    _, out, _, _, _, _, _ = classroom
    report = pdf_text(out / "S02-方案II" / "00-report.pdf")
    sheet = pdf_text(out / "S02-方案II" / "01-motion.pdf")
    for text in (report, sheet):
        assert "方案II" in text and "S02" in text and "机械2101" in text and "机械学院" in text


def test_the_task_sheets_one_page_per_student(classroom):
    _, out, _, _, _, _, _ = classroom
    info = subprocess.run(["pdfinfo", str(out / "tasks.pdf")], capture_output=True, text=True).stdout
    assert re.search(r"Pages:\s+4\n", info) and "595.276 x 841.89 pts (A4)" in info
    pages = pdf_text(out / "tasks.pdf").split("\f")
    for page, (name, number) in zip(pages, (("方案I", "S01"), ("方案II", "S02"), ("方案III", "S03"),
                                             ("Random Student", "R01"))):
        assert name in page and number in page and "Course design task sheet" in page
    assert "580" in pages[1] and "9000" in pages[1] and "0.3" in pages[1]       # 方案 II's own data


def test_the_sketch_is_drawn(classroom, tmp_path):
    """Pixels: the sketch's box (the upper middle of the page) holds the linkage's lines."""
    _, out, _, _, _, _, _ = classroom
    from PIL import Image
    subprocess.run(["pdftoppm", "-r", "40", "-f", "1", "-l", "1", "-png", str(out / "tasks.pdf"),
                    str(tmp_path / "p")], check=True)
    image = np.asarray(Image.open(next(tmp_path.glob("p*.png"))).convert("L"))
    h, w = image.shape
    sketch = image[int(h * 0.17):int(h * 0.44), int(w * 0.15):int(w * 0.9)]
    assert (sketch < 128).sum() > 200


def test_two_rows_with_one_number_write_nothing(tmp_path):
    tasks = tmp_path / "tasks.csv"
    tasks.write_text("student,student-number,crank,K,stroke\na,1,100,1.4,300\nb,1,100,1.4,300\n", encoding="utf-8")
    done = shaper("class", "--tasks", tasks, "-o", tmp_path / "out")
    assert done.returncode == 2 and not (tmp_path / "out").exists()
    assert done.stderr == "shaper: error: tasks.csv line 3, column student-number: 1 is also on line 2; " \
                          "each student needs a number of their own\n"


def test_a_table_of_bad_rows_only_names_each_and_exits_2(tmp_path):
    """Every row bad (here a base radius the arm cannot reach): each named, the count, exit 2,
    no task sheet nor answer key for nobody; it was 'internal error (IndexError …)', exit 1."""
    tasks = tmp_path / "tasks.csv"
    tasks.write_text("student,student-number,crank,K,stroke,arm,swing,pressure,rise,dwell,return,base,distance\n"
                     "a,1,100,1.4,300,125,15,40,75,10,75,20,100\n", encoding="utf-8")
    done = shaper("class", "--tasks", tasks, "-o", tmp_path / "out")
    assert done.returncode == 2, done.stderr
    assert done.stderr.splitlines() == [
        "shaper: error: tasks.csv line 2, column base: must be between |a − l| = 25 mm and a + l = 225 mm "
        "for the arm to reach the cam (got 20)",
        "shaper: error: 1 of 1 students not written (1 bad rows, 0 failed)"]
    assert done.stdout == "" and not (tmp_path / "out").exists()      # not even an empty folder
