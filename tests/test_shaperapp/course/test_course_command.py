"""``shaper course``: one design file in, the report and every sheet out, numbered, each
file complete; refused with one line and nothing written when the file lacks a part."""
import json
import re
import os
import shutil
import signal
import subprocess
import sys

import ezdxf
import pytest

from cli_runner import shaper_in_process
from core.files.io import design_document, masses_to_dict
from core.linkage.spec import Spec
from language_checks import assert_chinese_text, has_pdftotext, pdf_text

# the report's formulas and its command line (as test_report_chinese_text allows them)
FORMULAS = {"sin", "cos", "tan", "shaper"}
needs_poppler = pytest.mark.skipif(not has_pdftotext(), reason="poppler-utils not installed")
CAM = {"arm_mm": 120.0, "swing_deg": 15.0, "rise_deg": 60.0, "dwell_deg": 10.0, "return_deg": 60.0,
       "pressure_deg": 40.0, "return_pressure_deg": 70.0}
GEAR = {"z1": 13, "z2": 40, "module_mm": 6.0, "centre_mm": 162.0}
NAMES = ["00-report.pdf", "01-motion.pdf", "02-kinetostatic.pdf", "03-cam.pdf", "04-gear.pdf"]
WITH_DXF = ["00-report.pdf", "01-motion.dxf", "01-motion.pdf", "02-kinetostatic.dxf",
            "02-kinetostatic.pdf", "03-cam.dxf", "03-cam.pdf", "04-gear.dxf", "04-gear.pdf"]
# what each file's first page says it is (the report's cover, each sheet's title block)
TITLES = {"00-report.pdf": "Design report", "01-motion.pdf": "Motion analysis",
          "02-kinetostatic.pdf": "Kinetostatic analysis", "03-cam.pdf": "Feed cam",
          "04-gear.pdf": "Gear meshing"}


def design_file(folder, drop=(), name="design.shaper.json", speeds=(40.0,)):
    from core.forces.masses import MassProperties
    loads = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                           cut_force_N=7000.0, cut_height_mm=80.0)
    doc = design_document(Spec(), speeds, 1.0, {"forces": masses_to_dict(loads), "cam": CAM, "gear": GEAR})
    path = folder / name
    path.write_text(json.dumps({k: v for k, v in doc.items() if k not in drop}), encoding="utf-8")
    return path


def listing(folder) -> dict:
    return {p.name: (p.stat().st_size, p.stat().st_mtime_ns) for p in folder.iterdir()}


def course(*args):
    return shaper_in_process("course", *args, "--sheet", "A3", "--date", "2026-01-01")


SLOW = pytest.mark.slow     # one run of the whole course (≈ 3 s alone) shared by the tests marked so
LONG = "d" * 228 + ".shaper.json"     # a design file's name of 240 bytes (the system allows 255)


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """One run of the whole course (A3, one speed, DXF too) into a folder that already
    holds an older 01-motion.pdf and a file of the user's; the design file has a long name."""
    folder = tmp_path_factory.mktemp("course")
    out = folder / "out"
    out.mkdir()
    (out / "01-motion.pdf").write_bytes(b"an older sheet")
    (out / "notes.txt").write_text("mine")
    source = design_file(folder, name=LONG)
    status, stdout, err = course("--design", source, "-o", out, "--dxf")
    assert status == 0, err
    return source, out, stdout, err


@SLOW
@needs_poppler
def test_the_files_are_written_numbered_and_complete(written):
    _, out, stdout, _ = written
    assert sorted(os.listdir(out)) == sorted(WITH_DXF + ["notes.txt"])
    lines = stdout.splitlines()
    assert [os.path.basename(line) for line in lines[:-1]] == \
        ["00-report.pdf", "01-motion.pdf", "01-motion.dxf", "02-kinetostatic.pdf", "02-kinetostatic.dxf",
         "03-cam.pdf", "03-cam.dxf", "04-gear.pdf", "04-gear.dxf"]
    assert all(os.path.isfile(line) for line in lines[:-1]) and lines[-1].startswith("9 files in ")
    for name, title in TITLES.items():
        assert title in " ".join(pdf_text(out / name).split()), name
    info = subprocess.run(["pdfinfo", str(out / "00-report.pdf")], capture_output=True, text=True).stdout
    assert "A4" in info and int(info.split("Pages:")[1].split()[0]) > 5
    for name in WITH_DXF:
        if name.endswith(".dxf"):
            doc = ezdxf.readfile(out / name)
            assert len(doc.modelspace()) > 100 and not doc.audit().has_errors, name


@SLOW
def test_files_of_the_same_names_are_replaced_and_others_left_alone(written):
    """A file of one of the course's names is replaced, and said so (a teacher's own
    01-motion.pdf went without a word); the others are left alone and not named."""
    _, out, _, err = written
    assert (out / "01-motion.pdf").read_bytes().startswith(b"%PDF")
    assert (out / "notes.txt").read_text() == "mine"
    notes = [line for line in err.splitlines() if "replaced" in line]
    assert notes == [f"shaper: note: {out} holds 1 of these files already, replaced now: 01-motion.pdf"]


@SLOW
@needs_poppler
def test_a_long_design_name_is_cut_in_the_title_block_not_refused(written):
    """The 228-letter name (without its types) is printed cut with "…" (to the 200
    characters a title takes, and to the title block's field); the files keep their names."""
    _, out, _, _ = written
    for name in ("00-report.pdf", "03-cam.pdf"):
        text = "".join(pdf_text(out / name).split())
        assert re.search("d{10,}…", text) and "d" * 201 not in text, name


@SLOW
@needs_poppler
def test_the_report_has_the_gear_section_of_the_file(written):
    """Issue 35, item 5: the course's report carries the file's gear pair, its figures those
    of ``shaper gear --design`` of the same file."""
    source, out, _, _ = written
    status, js, err = shaper_in_process("gear", "--design", source, "--json")
    assert status == 0, err
    pair = json.loads(js)["pair"]
    text = " ".join(pdf_text(out / "00-report.pdf").split())
    assert "10 The gear pair" in text
    for value in (f"{pair['contact_ratio']:.6f}", f"{pair['working_pressure_angle_deg']:.6f}",
                  f"{pair['centre_mm']:.4f} mm"):
        assert value in text, value


@SLOW
@needs_poppler
def test_the_sheets_are_those_of_shaper_drawing(written, tmp_path):
    """The course's cam sheet reads as ``shaper drawing --content cam`` of the same file."""
    source, out, _, _ = written
    status, _, err = shaper_in_process("drawing", "--design", source, "--content", "cam", "--sheet", "A3",
                                       "--date", "2026-01-01", "-o", tmp_path / "cam.pdf")
    assert status == 0, err
    assert pdf_text(out / "03-cam.pdf") == pdf_text(tmp_path / "cam.pdf")


@pytest.mark.parametrize("drop, named", [(("forces",), '"forces"'), (("cam",), '"cam"'),
                                         (("rpm",), '"rpm"'), (("gear",), '"gear"')])
def test_a_file_without_a_part_is_refused_and_nothing_is_written(drop, named, tmp_path):
    source = design_file(tmp_path, drop)
    out = tmp_path / "out"
    out.mkdir()
    (out / "01-motion.pdf").write_bytes(b"an older sheet")
    before = listing(tmp_path), listing(out)
    status, stdout, err = course("--design", source, "-o", out, "--dxf")
    assert status == 2 and stdout == ""
    assert len(err.strip().splitlines()) == 1 and err.startswith("shaper: error: --design: ")
    assert named in err and "sheet" in err
    assert (listing(tmp_path), listing(out)) == before


def test_a_bad_option_or_folder_is_refused_before_anything_is_written(tmp_path):
    source = design_file(tmp_path)
    before = listing(tmp_path)
    for args, option in [(["-o", tmp_path / "out", "--sheet", "A5"], "--sheet"),
                         (["-o", tmp_path / "out", "--student", "a\nb"], "--student"),
                         (["-o", source], "--output"),
                         (["-o", tmp_path / "none" / "out"], "--output")]:
        status, _, err = shaper_in_process("course", "--design", source, *args)
        assert status == 2 and err.startswith(f"shaper: error: {option}: "), err
        assert len(err.strip().splitlines()) == 1
    assert listing(tmp_path) == before


@pytest.mark.slow          # a real process killed part-way
@needs_poppler
# Killed after the report, a sheet's PDF and its DXF, while the next sheet is made: each kind
# of file is there to be checked complete. A kill right after the report (after=1, dropped
# for the suite's time) stopped the same stage, a sheet being made; the report's own stage
# is test_a_run_killed_during_the_report_leaves_no_temporary_folder's.
@pytest.mark.parametrize("after", [3])
def test_a_run_killed_part_way_leaves_only_complete_files(after, tmp_path):
    """SIGKILL once ``after`` files are reported: every file there is complete (pdfinfo and
    ezdxf read it); the one being written is at most a hidden temporary file."""
    out = tmp_path / "out"
    command = [sys.executable, "-m", "core", "course", "--design", str(design_file(tmp_path)),
               "-o", str(out), "--sheet", "A3", "--dxf"]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, text=True)
    for _ in range(after):
        assert process.stdout.readline()
    process.send_signal(signal.SIGKILL)
    process.wait(timeout=60)
    shown = [name for name in os.listdir(out) if not name.startswith(".")]
    assert len(shown) >= after
    for name in shown:
        if name.endswith(".pdf"):
            done = subprocess.run(["pdfinfo", str(out / name)], capture_output=True)
            assert done.returncode == 0, name
        else:
            assert len(ezdxf.readfile(out / name).modelspace()) > 100
    assert all(n.endswith(".tmp") for n in os.listdir(out) if n.startswith("."))


@pytest.mark.slow          # the report and three sheets in Chinese
@needs_poppler
def test_chinese_files_have_no_english_word(tmp_path):
    out = tmp_path / "课程设计"
    try:
        status, _, err = course("--design", design_file(tmp_path, name="设计.shaper.json"), "-o", out,
                                "--lang", "zh", "--student", "张三", "--school", "机械工程学院")
    finally:
        from shaperapp.widgets import i18n
        i18n.set_language("en")         # the in-process run set the process's language
    assert status == 0, err
    for name in NAMES:
        assert_chinese_text(pdf_text(out / name), FORMULAS, what=name)


def _course_process(tmp_path, out, **popen):
    """``shaper course`` as a real process whose temporary files go to tmp_path/tmp."""
    temp = tmp_path / "tmp"
    temp.mkdir(exist_ok=True)
    env = dict(os.environ, TMPDIR=str(temp))
    command = [sys.executable, "-m", "core", "course", "--design", str(design_file(tmp_path)),
               "-o", str(out), "--sheet", "A3"]
    return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=env, **popen), temp


@pytest.mark.slow          # a real process killed during the report
def test_a_run_killed_during_the_report_leaves_no_temporary_folder(tmp_path):
    """Issue 42: every kill during the report stage left $TMPDIR/shaper-report-XXXXXXXX (its
    SVG figures, up to 400 KB) that no later run removed. Killed as soon as such a folder
    appears, or once the report is written (the report is the first file)."""
    import select
    import time
    process, temp = _course_process(tmp_path, tmp_path / "out")
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and process.poll() is None:
        if any(p.name.startswith("shaper-report-") for p in temp.iterdir()):
            break
        if select.select([process.stdout], [], [], 0.02)[0]:
            break                        # the report is written: its stage is over
    process.send_signal(signal.SIGKILL)
    process.wait(timeout=60)
    assert list(temp.iterdir()) == []


@pytest.mark.slow          # the report written under a file size limit
def test_a_failed_write_names_the_users_file_not_a_temporary_one(tmp_path):
    """Issue 42: with ulimit -f 300 the run said "--output: [Errno 27] could not write
    $TMPDIR/shaper-report-…/forces.svg: File too large"; docs/file-formats.md promises the
    message names your path, never the temporary file."""
    import resource
    limit = 300 * 1024
    process, temp = _course_process(
        tmp_path, tmp_path / "out",
        preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit)))
    _, err = process.communicate(timeout=300)
    assert process.returncode != 0
    line = err.strip()
    assert line.count("\n") == 0 and line.startswith("shaper: error: --output: cannot write ")
    assert str(tmp_path / "out") in line and "File too large" in line
    assert "shaper-report" not in line and str(temp) not in line and ".tmp" not in line
    assert list(temp.iterdir()) == []


@pytest.mark.skipif(shutil.which("chattr") is None or os.geteuid() != 0,
                    reason="chattr +i needs root and e2fsprogs")
def test_an_immutable_target_is_found_before_the_first_file_is_written(tmp_path):
    """Issue 42: an immutable 01-motion.pdf in the folder made course write 00-report.pdf and
    then fail: every target is checked before the first is written."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "01-motion.pdf").write_bytes(b"%PDF old")
    if subprocess.run(["chattr", "+i", str(out / "01-motion.pdf")], capture_output=True).returncode:
        pytest.skip("this file system has no immutable flag")
    try:
        status, _, err = course("--design", design_file(tmp_path), "-o", out)
        assert status != 0 and err.count("\n") == 1
        assert err.startswith(f"shaper: error: --output: cannot replace {out / '01-motion.pdf'}: it is immutable")
        assert sorted(p.name for p in out.iterdir()) == ["01-motion.pdf"]
    finally:
        subprocess.run(["chattr", "-i", str(out / "01-motion.pdf")])
