"""One link numbering everywhere, the task book's (issue 41): 1 frame, 2 crank, 3 block,
4 lever, 5 rod, 6 ram (docs/methods.md#link-numbers-and-symbols). Every text a user reads
is scanned for a symbol of the old numbering (1 crank … 5 ram: ω3, J3, G5 on the ram,
v_A3A2, R_3B …; see ``tests/numbering_checks.py``): the docs and the help, every UI string
and its Chinese, the CLI's text, CSV and JSON, the report's and the sheets' text as
pdftotext reads them, in English and Chinese. And each link's own labels carry its number."""
from __future__ import annotations

import json
import re
import shutil
import subprocess
import types
import xml.etree.ElementTree as ET

import pytest
from cli_runner import shaper_run_in_process as shaper
from locations import ROOT
from numbering_checks import offending, old_symbols

DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")),
        *sorted((ROOT / "resources" / "help").glob("*.html"))]
TS = ROOT / "resources" / "shaperapp_zh_CN.ts"
DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300"]
ROD = DESIGN + ["--rod-ratio", "0.3"]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000",
         "--cut-height", "80"]


def _catalogue() -> dict[tuple[str, str], str]:
    """(context, English source) → Chinese translation, from the .ts the .qm is built from."""
    out = {}
    for context in ET.parse(TS).getroot().iter("context"):
        name = context.find("name").text
        for message in context.iter("message"):
            out[(name, message.find("source").text)] = message.find("translation").text or ""
    return out


@pytest.mark.parametrize("page", DOCS, ids=lambda p: p.name)
def test_docs_and_help_use_the_task_books_numbering(page):
    assert not offending(page.read_text(encoding="utf-8").splitlines(), page.name)


def test_every_ui_string_and_its_chinese_use_the_task_books_numbering():
    found = []
    for (context, source), chinese in _catalogue().items():
        found += offending([source], f"{context} source") + offending([chinese], f"{context} zh")
    assert not found


def test_each_links_labels_carry_its_number():
    """The lever's ω, α, mass and inertia are 4 (ω4, m4, J_S4), the rod's 5, the ram's 6,
    in English and in Chinese: the labels a course-design teacher reads first."""
    from shaperapp.design.loads_form import LoadsForm
    from shaperapp.widgets.column_titles import column_titles
    zh = _catalogue()
    columns = column_titles()
    loads = {key: label for key, (label, _tip) in
             LoadsForm._field_texts(types.SimpleNamespace(tr=lambda text: text)).items()}
    expected = [("Columns", columns, {"lever_omega_rad_s": "ω4", "lever_alpha_rad_s2": "α4",
                                      "rod_omega_rad_s": "ω5", "rod_alpha_rad_s2": "α5",
                                      "slide_v_m_s": "v_A3A4"}),
                ("LoadsForm", loads, {"lever_mass_kg": "m4", "lever_inertia_kg_m2": "J_S4",
                                      "rod_mass_kg": "m5", "ram_mass_kg": "m6"})]
    for context, labels, symbols in expected:
        for key, symbol in symbols.items():
            english = labels[key]
            assert re.search(rf"{symbol}(?![0-9])", english), (key, english)
            assert re.search(rf"{symbol}(?![0-9])", zh[(context, english)]), (key, zh[(context, english)])


def test_the_polygons_name_forces_by_their_links():
    """The block variant has no rod, so no force of link 5: the ram's are G_6 and F_I6."""
    from core.forces.masses import MassProperties
    from core.linkage.geometry import synthesize
    from core.forces.polygons import force_polygon, lever_force_polygon
    masses = MassProperties(lever_mass_kg=20, ram_mass_kg=70, rod_mass_kg=5, cut_force_N=7000)
    block = synthesize(100, 1.4, 300)
    rod = synthesize(100, 1.4, 300, rod_ratio=0.3)
    keys = lambda polygon: [v.key for v in polygon.vectors]   # noqa: E731
    no_rod = MassProperties(lever_mass_kg=20, ram_mass_kg=70, cut_force_N=7000)
    assert keys(force_polygon(block, 90.0, 60.0, no_rod)) == ["P", "G_6", "F_I6", "N", "R_B"]
    assert keys(force_polygon(rod, 90.0, 60.0, masses)) == ["P", "G_6", "F_I6", "G_5", "F_I5", "N", "R_B"]
    assert keys(lever_force_polygon(rod, 90.0, 60.0, masses)) == ["G_4", "F_I4", "R_A", "R_O4", "R_4B"]


@pytest.mark.parametrize("args", [
    ("table", *ROD, "--rpm", "40", *LOADS, "--rod-mass", "5"),
    ("table", *DESIGN, "--rpm", "40", *LOADS, "--csv", "-"),
    ("curves", *ROD, "--rpm", "40", "--step", "30", "--csv", "-"),
    ("dynamics", *ROD, "--rpm", "40", *LOADS, "--step", "30", "--csv", "-"),
    ("dynamics", *ROD, "--rpm", "40", *LOADS, "--step", "30", "--json"),
    ("analyze", *ROD, "--rpm", "40", "--json"),
], ids=["table", "table-csv", "curves", "dynamics-csv", "dynamics-json", "analyze"])
def test_the_cli_output_uses_the_task_books_numbering(args):
    """What the command prints, through ``core.cli.main`` in this process: the text is the
    same as a process prints (tests/test_core/cli/test_cli.py runs the console script)."""
    run = shaper(*args)
    assert run.returncode == 0, run.stderr
    text = run.stdout
    if text.lstrip().startswith("{"):
        keys: list[str] = []
        walk = [json.loads(text)]
        while walk:
            item = walk.pop()
            if isinstance(item, dict):
                keys += item
                walk += item.values()
            elif isinstance(item, list):
                walk += item
        units = keys
    else:
        units = text.splitlines()[:60]     # the titles; the rows below are numbers
    assert not offending(units, args[0])


def _write_in_process(*args) -> None:
    """``shaper *args`` (a Qt command: report, drawing) through main() in this process, the
    UI's English put back after it. The test reads what is printed, not how a process
    starts, so the six runs need no interpreters of their own: about 11 s of CPU less
    (docs/performance.md, "The test suite's time (29 November, afternoon)")."""
    from cli_runner import shaper_in_process
    from shaperapp.widgets import i18n
    try:
        status, _, err = shaper_in_process(*args)
    finally:
        i18n.set_language("en")
    assert status == 0, err


def _pdf_lines(path) -> list[str]:
    return subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True,
                          check=True).stdout.splitlines()


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="needs poppler-utils")
@pytest.mark.parametrize("language", ["en", "zh"])
def test_the_report_and_the_sheets_use_the_task_books_numbering(tmp_path, language):
    report = tmp_path / "report.pdf"
    _write_in_process("report", *ROD, "--rpm", "40", *LOADS, "--rod-mass", "5", "--lang", language,
                      "-o", report)
    lines = _pdf_lines(report)
    found = offending(lines, f"report {language}")
    if language == "zh":
        assert any("设计名称" in line for line in lines[:20])    # the cover's label
    for content, design in (("forces", DESIGN), ("motion", ROD)):
        sheet = tmp_path / f"{content}.pdf"
        _write_in_process("drawing", *design, "--rpm", "40", *LOADS, "--content", content, "--sheet", "A1",
                          "--lang", language, "-o", sheet)
        lines = _pdf_lines(sheet)
        found += offending(lines, f"{content} sheet {language}")
        if content == "forces":     # the block variant: the ram's forces are 6, no link 5 drawn
            words = " ".join(lines).split()
            assert "G6" in words and "FI6" in words and "R4B" in words
            assert not {"G5", "FI5"} & set(words)
    assert not found
    assert not old_symbols("")


TORQUE_AS_T = re.compile(r"(?<![A-Za-z/])T_m\b|∮T\b|\(T −|(?<![A-Za-z])T·ω|driving torque T\b")


def test_the_torque_is_written_m_everywhere():
    """Issue 40: the torque was T and T_m in the formulas, M and M_m in the tables and
    sheets. One symbol, the sheets' and the Chinese textbooks' (驱动力矩 M, 平均 M_m)."""
    units = [line for page in DOCS for line in page.read_text(encoding="utf-8").splitlines()]
    units += [text for pair in _catalogue().items() for text in (pair[0][1], pair[1])]
    assert not [u[:120] for u in units if TORQUE_AS_T.search(u)]


def test_the_chinese_report_words_of_issue_40():
    """The cover named the design's name 设计 ("design") and the force paragraph had a
    stray space in 作用于工作行程的 空刀量·H."""
    zh = _catalogue()
    assert zh[("Report", "Design name")] == "设计名称"
    forces = next(text for (context, source), text in zh.items()
                  if context == "Report" and source.startswith("<b>Forces.</b>"))
    assert "作用于工作行程的空刀量·H" in forces
    assert not re.search(r"[\u4e00-\u9fff] +空刀量", forces)
