"""A class's task table (``core.cli.tasks``, issue 41 item 3 and issue 42's attacks): read as
a spreadsheet saves it (UTF-8 with or without BOM, GBK, comma or semicolon), each row
parsed by ``shaper design``'s own parser, a bad row named by its line and column, the
folder names safe, a table that cannot be used refused whole; the answer key's JSON is
each command's own --json, and its CSV guards formulas."""
from __future__ import annotations

import csv
import io
import json
import math
import os
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cli_runner import shaper_in_process
from core.cli.answers import COMMANDS, answer_entry, key_csv
from core.files.io import csv_text as guarded
from core.cli.tasks import (MAX_FOLDER_BYTES, MAX_STUDENTS, MAX_TABLE_BYTES, TableError, column_actions,
                            design_parser, folder_name, read_tasks)

BASE = ("--arm", "125", "--swing", "15", "--pressure", "40", "--rise", "75", "--dwell", "10", "--return", "75",
        "--z1", "13", "--z2", "40", "--module", "6", "--rpm", "60", "--lever-mass", "20", "--lever-inertia", "1",
        "--ram-mass", "70", "--cut-force", "7000")
HEADER = "student,student-number,dims,rod-ratio,guide,rpm,lever-mass,lever-inertia,ram-mass,cut-force,cut-height"
# 孙桓《机械原理》(高等教育出版社) 课程设计指导书, 牛头刨床导杆机构的设计, 方案 I–III: n2, l_O2A,
# l_O2O4, l_O4B, l_BC/l_O4B, G4, J_S4, G6, P, y_P; the weights as masses G/9.81 (no weight option yet).
CLASSIC = ((60, 110, 380, 540, 0.25, 200, 1.1, 700, 7000, 80), (64, 90, 350, 580, 0.3, 220, 1.2, 800, 9000, 80),
           (72, 110, 430, 810, 0.36, 220, 1.2, 620, 8000, 100))


def classic_rows() -> list[str]:
    rows = []
    for k, (n, l1, l2, l3, rod, g4, j4, g6, p, yp) in enumerate(CLASSIC, start=1):
        rows.append(f"方案{'I' * k},S0{k},\"{l1},{l2},{l3}\",{rod},sagitta,{n},{g4 / 9.81!r},{j4},"
                    f"{g6 / 9.81!r},{p},{yp}")
    return rows


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    path = tmp_path_factory.mktemp("base") / "base.shaper.json"
    status, _, err = shaper_in_process("design", "--crank", "100", "--K", "1.4", "--stroke", "300", *BASE, "-o", path)
    assert status == 0, err
    return str(path)


def table(tmp_path, lines, name="tasks.csv", encoding="utf-8", sep=","):
    path = tmp_path / name
    path.write_bytes("\n".join(line.replace(",", sep) if sep != "," else line for line in lines).encode(encoding))
    return str(path)


def test_the_classic_data_sets_become_design_files(tmp_path, base):
    students, encoding = read_tasks(table(tmp_path, [HEADER, *classic_rows()]), base)
    assert encoding == "UTF-8" and [s.error for s in students] == ["", "", ""]
    for s, (n, l1, l2, l3, rod, g4, j4, g6, p, yp) in zip(students, CLASSIC):
        spec, forces = s.document["spec"], s.document["forces"]
        assert (spec["crank"], spec["frame"], spec["lever"], spec["rod_ratio"]) == (l1, l2, l3, rod)
        assert s.document["rpm"] == [n]
        assert forces["lever_mass_kg"] * 9.81 == pytest.approx(g4) and forces["ram_mass_kg"] * 9.81 == pytest.approx(g6)
        assert (forces["lever_inertia_kg_m2"], forces["cut_force_N"], forces["cut_height_mm"]) == (j4, p, yp)
        assert s.document["cam"]["arm_mm"] == 125.0 and s.document["gear"]["z1"] == 13   # from --base
    assert [s.folder for s in students] == ["S01-方案I", "S02-方案II", "S03-方案III"]


def test_gbk_bom_and_semicolons_are_read(tmp_path, base):
    lines = [HEADER, *classic_rows()]
    gbk = read_tasks(table(tmp_path, lines, "gbk.csv", "gbk"), base)
    bom = read_tasks(table(tmp_path, lines, "bom.csv", "utf-8-sig"), base)
    assert gbk[1] == "GBK" and bom[1] == "UTF-8"
    assert [s.document for s in gbk[0]] == [s.document for s in bom[0]]
    assert [s.name for s in gbk[0]] == ["方案I", "方案II", "方案III"]
    semi_lines = ["student;student-number;dims;rod-ratio;rpm", "张三;1;110,380,540;0.3;60 72"]
    students, _ = read_tasks(table(tmp_path, semi_lines, "semi.csv"), base)
    assert students[0].error == "" and students[0].document["rpm"] == [60.0, 72.0]
    assert students[0].document["spec"]["lever"] == 540.0


def test_text_in_neither_encoding_is_refused_by_name(tmp_path, base):
    path = tmp_path / "latin.csv"
    path.write_bytes(b"student,student-number\n\xff\xfe\x80\x81,1\n\x81")
    with pytest.raises(TableError, match=r"latin.csv: not UTF-8 or GBK"):
        read_tasks(str(path), base)


def test_a_bad_row_is_named_by_its_line_and_column(tmp_path, base):
    lines = [HEADER, *classic_rows(),
             '坏,S09,"110,380,540",0.3,sagitta,60,20,1.1,70,-5,80',
             '"两行\n的名字",S10,"110,380,540",0.3,sagitta,60,20,1.1,70,5,80',
             'x,S11,"110,380",0.3,sagitta,60,20,1.1,70,5,80',
             'y,S12,"110,380,540",0.3,upward,60,20,1.1,70,5,80',
             'z,S13,"110,380,540",0.3,sagitta,60 0,20,1.1,70,5,80']
    students, _ = read_tasks(table(tmp_path, lines), base)
    errors = [s.error for s in students[3:]]
    assert errors[0] == "tasks.csv line 5, column cut-force: must be ≥ 0 and ≤ 1e+09 N (got -5)"
    assert errors[1] == "tasks.csv line 6, column student: must be one line of text without control characters"
    assert errors[2].startswith("tasks.csv line 8, column dims: must be L1,L2,L3")
    assert errors[3].startswith("tasks.csv line 9, column guide: must be a number")
    assert errors[4].startswith("tasks.csv line 10, column rpm:")
    assert all("\n" not in e for e in errors)
    assert [s.error for s in students[:3]] == ["", "", ""]


def test_a_value_of_the_base_file_at_fault_is_named_as_the_bases(tmp_path, base):
    """A row whose K leaves the base's cam (rise + dwell + return = 160°) too little of the
    turn outside the cut: the value at fault is the base file's, which the teacher gave as
    --base; the line named it as '--design (cam.rise_deg)', an option nobody typed. The
    row's own design file is named as its column."""
    (tmp_path / "own.json").write_bytes(open(base, "rb").read())
    lines = ["student,student-number,crank,K,stroke,design", "a,1,100,2.9,600,", "b,2,100,2.9,600,own.json"]
    students, _ = read_tasks(table(tmp_path, lines), base)
    assert students[0].error.startswith("tasks.csv line 2: --base (cam.rise_deg): rise + outer dwell + return")
    assert students[1].error.startswith("tasks.csv line 3, column design (cam.rise_deg): rise + outer dwell")


def test_a_design_column_names_a_file_beside_the_table_only(tmp_path, base):
    inside = tmp_path / "class"
    inside.mkdir()
    (inside / "own.json").write_bytes(open(base, "rb").read())
    outside = tmp_path / "secret.json"
    outside.write_bytes(open(base, "rb").read())
    os.symlink(outside, inside / "link.json")
    lines = ["student,student-number,design,crank", "a,1,own.json,90", "b,2,../secret.json,",
             f"c,3,{outside},", "d,4,link.json,", f"e,5,{inside / 'own.json'},"]
    students, _ = read_tasks(table(inside, lines), None)
    assert students[0].error == "" and students[0].document["spec"]["crank"] == 90.0
    for s, shown in zip(students[1:4], ("../secret.json", str(outside), "link.json")):
        assert s.error == (f"tasks.csv line {s.line}, column design: {shown!r} is outside the table's folder; "
                           "put the design file beside the table")
    assert students[4].error == ""        # an absolute path that is inside is fine


def test_unknown_or_missing_columns_and_two_numbers_refuse_the_table(tmp_path, base):
    with pytest.raises(TableError, match=r"tasks.csv line 1, column k: not a column; did you mean K\?"):
        read_tasks(table(tmp_path, ["student,student-number,k", "a,1,1.4"]), base)
    with pytest.raises(TableError, match=r"line 1: no column student-number"):
        read_tasks(table(tmp_path, ["student,crank", "a,100"]), base)
    with pytest.raises(TableError, match=r"tasks.csv line 4, column student-number: 7 is also on line 2"):
        read_tasks(table(tmp_path, ["student,student-number", "a,7", "b,8", "c,7"]), base)
    # two numbers that differ, but whose folders are one ("7/" and "7:" both become "7_")
    with pytest.raises(TableError, match=r"tasks.csv line 3: the folder 7_-a is also line 2's"):
        read_tasks(table(tmp_path, ["student,student-number", "A,7/", "a,7:"]), base)



@pytest.mark.parametrize("rows, changed", [(["A,7/", "a,7:"], "a,8:"), (["A,7a", "a,7A"], "a,7b")])
def test_two_folders_made_one_are_told_what_number_makes_them_two(tmp_path, base, rows, changed):
    """The numbers differ already ('give the students different numbers' was no help): the
    advice says how they must differ, and a number changed so is taken."""
    with pytest.raises(TableError, match=r"give one of them a number that differs in more than letter case and "
                                         r"the characters a folder name cannot hold$"):
        read_tasks(table(tmp_path, ["student,student-number", *rows]), base)
    students, _ = read_tasks(table(tmp_path, ["student,student-number", rows[0], changed]), base)
    assert len({s.folder.casefold() for s in students}) == 2


def test_ten_thousand_rows_are_refused_at_once_and_nothing_parsed(tmp_path, base):
    lines = [HEADER] + [f'n{k},{k},"110,380,540",0.3,sagitta,60,20,1.1,70,7000,80' for k in range(10_000)]
    path = table(tmp_path, lines)
    start = time.perf_counter()
    with pytest.raises(TableError, match=rf"more than {MAX_STUDENTS} students"):
        read_tasks(path, base)
    assert time.perf_counter() - start < 2.0


@given(st.text(min_size=1, max_size=300), st.text(min_size=1, max_size=40))
@settings(max_examples=300, deadline=None)
def test_folder_names_are_safe_and_keep_letters(student, number):
    name = folder_name(number, student)
    assert name and "/" not in name and "\\" not in name and ".." not in name and "\x00" not in name
    assert not name.startswith(".") and not name.endswith((".", " "))
    assert len(name.encode("utf-8")) <= MAX_FOLDER_BYTES + 1
    assert name.split(".")[0].upper() not in {"CON", "PRN", "AUX", "NUL", "COM1", "LPT1"}
    assert not any(ord(c) < 32 for c in name)


def test_folder_names_examples():
    assert folder_name("2021001", "张三") == "2021001-张三"
    assert folder_name("1", "../../etc") == "1-____etc"
    assert folder_name("1", "a\\b:c*?") == "1-a_b_c__"
    assert folder_name("1", "x. ") == "1-x"
    assert folder_name(".", "") == "_.-"
    assert folder_name("2", "Ünïcødé ñame") == "2-Ünïcødé ñame"


def test_every_option_of_the_analysis_commands_is_a_column():
    """The columns come from the parsers themselves: every input option of synth, analyze,
    dynamics, cam and gear is one (a new option there is a column without a change)."""
    from core.cli import _command_modules, build_parser
    columns = column_actions(design_parser())
    outputs = {"json", "csv", "dxf", "help", "sheet", "lang", "step", "angles", "idle", "rpm", "design",
               "cad-font"}     # how a DXF writes its texts: an output option, not the design
    for command in COMMANDS:
        parser = build_parser(_command_modules(command))
        sub = next(a for a in parser._actions if a.dest == "command").choices[command]
        for action in sub._actions:
            for flag in action.option_strings:
                if flag.startswith("--") and flag[2:] not in outputs:
                    assert flag[2:] in columns, (command, flag)


def test_answer_json_is_what_each_command_prints(tmp_path, base):
    students, _ = read_tasks(table(tmp_path, [HEADER, *classic_rows()]), base)
    path = tmp_path / "s.shaper.json"
    from core.cli.cmd_design import design_text
    path.write_text(design_text(students[2].document), encoding="utf-8")
    entry = answer_entry("方案III", "S03", "S03-方案III", str(path))
    for command in COMMANDS:
        status, out, err = shaper_in_process(command, "--design", path, "--json")
        assert status == 0 and json.loads(out) == entry[command], command


def test_random_rows_give_the_synthesis_formulas(tmp_path, base):
    """Random L1, K, H: the answer key's L2 = L1/sin(θ/2), L3 = H/(2 sin(θ/2)), θ = 180°(K−1)/(K+1)."""
    rng = np.random.default_rng(41)
    rows = []
    for k in range(6):
        crank, ratio = rng.uniform(60, 140), rng.uniform(1.2, 1.8)
        half = math.radians(90.0 * (ratio - 1) / (ratio + 1))
        # the pin stays on the lever and the ram clears the crank: L3·cos(θ/2) > L1 + L2
        stroke = 2 * crank * (1 + math.sin(half)) / math.cos(half) * rng.uniform(1.05, 1.6)
        rows.append(f"r{k},R{k},{crank:.3f},{ratio:.4f},{stroke:.2f}")
    students, _ = read_tasks(table(tmp_path, ["student,student-number,crank,K,stroke", *rows]), base)
    from core.cli.cmd_design import design_text
    for s in students:
        assert s.error == ""
        path = tmp_path / f"{s.folder}.json"
        path.write_text(design_text(s.document), encoding="utf-8")
        got = answer_entry(s.name, s.number, s.folder, str(path))["synth"]
        spec = s.document["spec"]
        half = math.radians(90.0 * (spec["time_ratio"] - 1) / (spec["time_ratio"] + 1))
        assert got["frame_mm"] == pytest.approx(spec["crank"] / math.sin(half), rel=1e-12)
        assert got["lever_mm"] == pytest.approx(spec["stroke"] / (2 * math.sin(half)), rel=1e-12)


def test_a_name_that_is_a_formula_is_text_in_the_answer_key():
    assert guarded("=HYPERLINK(\"x\")") == "'=HYPERLINK(\"x\")" and guarded("+1") == "'+1"
    assert guarded("@SUM(A1)") == "'@SUM(A1)" and guarded("-2") == "'-2" and guarded("张三") == "张三"
    entry = json.loads(json.dumps(_entry("=cmd|' /C calc'!A0", "+8613800000000")))
    text = key_csv([entry], ["=1+1"])
    row = next(csv.reader(io.StringIO(text.split("\n", 1)[1])))
    assert row[:3] == ["'=cmd|' /C calc'!A0", "'+8613800000000", "'=1+1"]
    assert all(not cell.startswith(("=", "+", "@")) for cell in row)
    # a piece after a separator a spreadsheet splits on is guarded too (issue 42 item 2)
    row = next(csv.reader(io.StringIO(key_csv([_entry("a;=cmd", "1")], ["b|@x"]).split("\n", 1)[1])))
    assert row[0] == "a;'=cmd" and row[2] == "b|'@x"


def _entry(student, number):
    """A made-up answer entry with every figure the CSV reads."""
    speed = {"rpm": 60.0, "v_work_max_m_s": 1.0, "v_return_max_m_s": 2.0, "a_max_m_s2": 3.0}
    forces = {"rpm": 60.0, "max_torque_N_m": 4.0, "mean_torque_N_m": 5.0, "energy_fluctuation_J": 6.0,
              "flywheel_inertia_kg_m2": 7.0, "flywheel_inertia_needed_kg_m2": 6.5}
    synth = {"theta_deg": 30.0, "crank_mm": 1.0, "frame_mm": 2.0, "lever_mm": 3.0, "rod_mm": None, "h_mm": 4.0}
    return {"student": student, "student_number": number, "folder": "f", "synth": synth,
            "analyze": {"K": 1.4, "stroke_mm": 300.0, "speeds": [speed]}, "dynamics": {"speeds": [forces]},
            "cam": {"base_radius_mm": 1.0, "center_distance_mm": 2.0, "roller_mm": 3.0, "within_allowance": False},
            "gear": {"gear1": {"shift_factor": 0.1}, "gear2": {"shift_factor": -0.1},
                     "pair": {"centre_mm": 1.0, "working_pressure_angle_deg": 20.0, "contact_ratio": 1.1},
                     "checks": [{"name": "contact", "ok": False}]}}


def test_ten_thousand_rows_take_bounded_memory_and_a_huge_file_is_refused_unread(tmp_path, base):
    """Issue 41 gap 5: a table of 10 000 rows is refused with the memory of a few copies of
    its text (not 10 000 parsed rows); a 1 GB file is refused by its size, never read."""
    import tracemalloc
    lines = [HEADER] + [f'n{k},{k},"110,380,540",0.3,sagitta,60,20,1.1,70,7000,80' for k in range(10_000)]
    path = table(tmp_path, lines)
    size = os.path.getsize(path)
    tracemalloc.start()
    try:
        with pytest.raises(TableError, match=rf"more than {MAX_STUDENTS} students"):
            read_tasks(path, base)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    # at most the read buffer (MAX_TABLE_BYTES + 1), the text and the first 1001 rows' cells
    assert peak < 2 * MAX_TABLE_BYTES + 8 * size, (peak, size)
    huge = tmp_path / "huge.csv"
    with open(huge, "wb") as handle:          # sparse: 1 GB on paper, nothing on the disk
        handle.truncate(1_000_000_000)
    start = time.perf_counter()
    with pytest.raises(TableError, match=r"huge.csv: larger than 5 MB"):
        read_tasks(str(huge), base)
    assert time.perf_counter() - start < 1.0


def test_hostile_student_names_give_distinct_folders_that_can_be_made(tmp_path, base):
    """Slashes, "..", NUL, 150 ideographs (450 bytes), Windows device names (CON, nul.txt),
    a formula: each good row's folder is one plain name that mkdir makes inside the class's
    folder, no two alike; the NUL row is refused by its line and column."""
    names = ["../../x", "a/b\\c", "张" * 150, "CON", "=HYPERLINK(\"http://x\")", "a\x00b"]
    numbers = ["1", "2", "3", "CON", "nul.txt", "6"]
    lines = ["student,student-number"] + [f'"{n.replace(chr(34), chr(34) * 2)}",{k}' for n, k in zip(names, numbers)]
    students, _ = read_tasks(table(tmp_path, lines), base)
    assert students[5].error == "tasks.csv line 7, column student: must be one line of text without control characters"
    good = [s for s in students if not s.error]
    assert len(good) == 5 and len({s.folder.casefold() for s in good}) == 5
    out = tmp_path / "class"
    out.mkdir()
    for s in good:
        assert os.path.basename(s.folder) == s.folder and s.folder not in (".", "..")
        assert len(s.folder.encode("utf-8")) <= MAX_FOLDER_BYTES
        assert s.folder.split(".")[0].split("-")[0].upper() not in {"CON", "NUL"} or "-" in s.folder
        (out / s.folder).mkdir()
        assert (out / s.folder).resolve().parent == out.resolve()
    assert good[2].folder == "3-" + "张" * ((MAX_FOLDER_BYTES - 2) // 3)      # whole characters kept
    assert good[4].folder.startswith("_nul.txt-")                            # a device name with a suffix


def test_the_answer_key_gives_the_flywheel_to_add_beside_the_rotating_parts(tmp_path):
    """A student whose design has other rotating parts (a motor's rotor, J = 0.5 kg·m² at the
    crank's speed) answers the flywheel to add, J_F − J_c: the key has both columns, J_F and
    J_F_needed, and the second is J_F less J_c = J·ratio² (0.5), from the data typed."""
    from core.cli.answers import key_values, PER_SPEED, FIGURES
    design = tmp_path / "d.json"
    status, _, err = shaper_in_process("design", "--crank", "100", "--K", "1.4", "--stroke", "300",
                                       "--ram-mass", "60", "--lever-mass", "20", "--lever-inertia", "1.1",
                                       "--cut-force", "7000", "--rotor", "0.5:1", "--rpm", "60", "-o", design)
    assert status == 0, err
    status, out, err = shaper_in_process("dynamics", "--json", "--design", design)
    assert status == 0, err
    entry = _entry("x", "1")
    entry["dynamics"] = json.loads(out)
    row = key_values(entry, "", 1)
    names = [name for name, _, _ in PER_SPEED]
    at = 4 + len(FIGURES) + 1
    j_f, needed = row[at + names.index("J_F")], row[at + names.index("J_F_needed")]
    assert j_f > 1.0 and needed == pytest.approx(j_f - 0.5, rel=1e-12)
    header = key_csv([entry], [""]).splitlines()[0].split(",")
    assert "J_F_1 (kg·m²)" in header and "J_F_needed_1 (kg·m²)" in header


def test_a_rotor_cell_gives_every_rotating_part_it_names(tmp_path, base):
    """The task book's other rotating parts are several (the crank shaft, the pinion's shaft,
    the motor's rotor), and the command line repeats --rotor for them; a table's cell holds
    them separated by spaces. The cell was one option, refused as 'must be a number (got
    1 0.02:gear)'. J:gear takes the base's gear pair's ratio, z2/z1 = 40/13."""
    lines = ["student,student-number,rotor", "a,1,0.5:1 0.02:gear", "b,2,0.5:1", "c,3,0.5:1 x"]
    students, _ = read_tasks(table(tmp_path, lines), base)
    assert [s.error for s in students[:2]] == ["", ""]
    rotors = [[(r["J_kg_m2"], r["speed_ratio"]) for r in s.document["forces"]["rotors"]] for s in students[:2]]
    assert rotors[0] == [(0.5, 1.0), (0.02, pytest.approx(40 / 13, rel=1e-15))]
    assert rotors[1] == [(0.5, 1.0)]
    assert students[2].error.startswith("tasks.csv line 4, column rotor: must be J:RATIO") and "(got x)" in students[2].error


def test_a_value_left_to_the_base_is_named_as_the_column_that_sets_it(tmp_path, base):
    """A row's crank and K under the base's stroke of 300 mm, too short for them: the line
    named '--stroke', an option the teacher never typed and no column of the table; it
    names the column stroke and whose value it was (the Class dialog's translation reads
    the line's column and its "(got …)"). Its advice, typed into that column as
    printed, passes."""
    import re
    lines = ["student,student-number,crank,K", "a,1,119,1.48"]
    students, _ = read_tasks(table(tmp_path, lines), base)
    error = students[0].error
    assert error.startswith("tasks.csv line 2, column stroke: must be > ") and error.endswith("(got 300 from --base)")
    bound = re.search(r"must be > ([\d.]+) mm", error).group(1)
    fixed, _ = read_tasks(table(tmp_path, ["student,student-number,crank,K,stroke", f"a,1,119,1.48,{bound}"]), base)
    assert fixed[0].error == "" and fixed[0].document["spec"]["stroke"] == float(bound)


def test_a_row_without_the_parts_of_a_course_design_is_bad_and_its_advice_helps(tmp_path):
    """A table without --base whose rows give the linkage only: each row passed, each
    student then failed ('1-a: CourseError: --design: design.shaper.json has no "forces"
    …', a file the teacher never named), left a folder holding only its design file, and
    the task sheets were printed for them. The row is bad, named by its line with the
    columns to add; the row with those columns passes."""
    lines = ["student,student-number,crank,K,stroke", "a,1,100,1.4,300"]
    students, _ = read_tasks(table(tmp_path, lines), None)
    assert students[0].error == (
        "tasks.csv line 2: lacks the loads (columns lever-weight, lever-inertia, ram-weight, cut-force …), the feed "
        "cam (columns arm, swing, pressure, rise, dwell, return) and the gear pair (columns z1, z2, module), which "
        "the course design needs; give them as columns or in --base")
    columns = "lever-weight,lever-inertia,ram-weight,cut-force,arm,swing,pressure,rise,dwell,return,z1,z2,module"
    fixed = [f"{lines[0]},{columns}", f"{lines[1]},200,1.1,700,7000,125,15,40,75,10,75,13,40,6"]
    students, _ = read_tasks(table(tmp_path, fixed), None)
    assert students[0].error == "" and {"forces", "cam", "gear"} <= set(students[0].document)
    only_gear = [f"{lines[0]},{columns}", f"{lines[1]},200,1.1,700,7000,125,15,40,75,10,75,,,"]
    students, _ = read_tasks(table(tmp_path, only_gear), None)
    assert students[0].error.endswith("lacks the gear pair (columns z1, z2, module), which the course design "
                                      "needs; give them as columns or in --base")


def test_a_student_number_a_spreadsheet_shortened_is_refused_by_name(tmp_path, base):
    """Excel keeps a 12-digit student number typed into a number column as 2.02301E+11 and
    saves it so in its CSV: the digits are gone. It passed as the number, so the folder,
    the cover, every title block and the answer key said 2.02301E+11 (and two such
    students were told they share one number). The row is bad, saying why and what to do;
    a number that merely holds an E stays a number."""
    lines = ["student,student-number", "a,2.02301E+11", "b,2.02301e+11", "c,20230101E1", "d,S1E+2", "e,2.02301E+11"]
    students, _ = read_tasks(table(tmp_path, lines), base)
    assert students[0].error == ("tasks.csv line 2, column student-number: 2.02301E+11 is a number a spreadsheet "
                                 "wrote short, its digits lost; format the column as text and save the table again")
    assert students[1].error.startswith("tasks.csv line 3, column student-number: 2.02301e+11 is a number")
    assert [s.error for s in students[2:4]] == ["", ""] and students[4].error.startswith("tasks.csv line 6, column")


@pytest.mark.parametrize("heading, column", [("学生", "student"), ("姓名", "student"), ("学号", "student-number"),
                                             ("班级", "class")])
def test_a_chinese_heading_of_a_name_column_is_told_its_name(tmp_path, base, heading, column):
    """A Chinese teacher heads the columns 学生, 学号, 班级: refused with no hint ('see shaper
    design --help', which lists no such column); the refusal names the column to write,
    and the table with it passes."""
    headings = {"student": "student", "student-number": "student-number", "class": "class"}
    headings[column] = heading
    lines = [",".join(headings.values()) + ",crank", "张三,2021001,机械2101,100"]
    with pytest.raises(TableError) as refused:
        read_tasks(table(tmp_path, lines), base)
    assert str(refused.value) == f"tasks.csv line 1, column {heading}: not a column; did you mean {column}?"
    fixed = [lines[0].replace(heading, column), lines[1]]
    assert read_tasks(table(tmp_path, fixed), base)[0][0].error == ""


def test_no_in_the_no_gravity_column_turns_gravity_on_over_a_base_without_it(tmp_path, base):
    """`no-gravity` = no kept a --base without gravity as it was, so the student's forces,
    flywheel and answer key left the links' weights out though the row said no (hunt,
    1 December): 'no' now means gravity on, 'yes' off, an empty cell the base's."""
    weightless = tmp_path / "weightless.shaper.json"
    status, _, err = shaper_in_process("design", "--design", base, "--no-gravity", "-o", weightless)
    assert status == 0, err
    rows = table(tmp_path, ["student,student-number,no-gravity", "A,1,no", "B,2,yes", "C,3,", "D,4,否"])
    for source, expected in ((str(weightless), [True, False, False, True]), (base, [True, False, True, True])):
        students, _ = read_tasks(rows, source)
        assert [s.error for s in students] == [""] * 4
        assert [s.document["forces"]["gravity"] for s in students] == expected, source
