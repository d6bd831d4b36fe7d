"""The design report: ``shaper report`` runs whose text layer carries the CLI's numbers. The
runs are ``core.cli.main`` in the test's process (``shaper_run_in_process``): the console
script as a process of its own is the README's example's (tests/docs)."""
import json
import re
import shutil
import stat
import subprocess
import unicodedata
from html.parser import HTMLParser

import numpy as np
import pytest

from cli_runner import shaper_run_in_process
from core.course_design.positions import display_values
from report_numbers import cli_values, column_text

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rod-ratio", "0.3"]
SPEEDS = ["--rpm", "40", "60"]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70",
         "--cut-force", "7000", "--cut-height", "80"]
needs_pdftotext = pytest.mark.skipif(shutil.which("pdftotext") is None, reason="pdftotext not installed")


def squash(text: str) -> str:
    return re.sub(r"\s+", " ", text)


def table_values() -> list[str]:
    """A sample of the positions table as the report must print it."""
    result = shaper_run_in_process("table", *DESIGN, *SPEEDS, *LOADS, "--json")
    records = json.loads(result.stdout)
    columns = [k for k in records[0] if k not in ("position", "name")]
    data = np.array([[np.nan if r[c] is None else r[c] for c in columns] for r in records])
    shown = display_values(data)
    k = len(records) // 2                         # rows per speed: each speed's own columns
    picks = [(3, "ram_v_m_s"), (3, "lever_omega_rad_s"), (16, "ram_v_m_s"), (16, "crank_torque_N_m"),
             (20, "O4_x_N"), (23, "coriolis_m_s2"), (14, "crank_deg"), (15, "pressure_angle_deg")]
    return [column_text(list(shown[row // k * k:(row // k + 1) * k, columns.index(col)]),
                        shown[row, columns.index(col)]) for row, col in picks]


@pytest.fixture(scope="module")
def expected():
    values = cli_values("synth", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod-ratio", "0.3")
    values += cli_values("analyze", *DESIGN, *SPEEDS)
    values += cli_values("dynamics", *DESIGN, *SPEEDS, *LOADS)
    values += table_values()
    assert len(values) > 30
    return values


@pytest.fixture(scope="module")
def reports(tmp_path_factory):
    folder = tmp_path_factory.mktemp("reports")
    out = {}
    for name, extra in (("en.pdf", []), ("zh.pdf", ["--lang", "zh"]), ("en.html", ["--html"])):
        result = shaper_run_in_process("report", *DESIGN, *SPEEDS, *LOADS, "-o", folder / name,
                                       "--title", "Classic",
                        *extra)
        assert result.returncode == 0, result.stderr
        assert result.stderr == ""
        out[name] = folder / name
    return out


def pdf_text(path) -> str:
    return subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True,
                          check=True).stdout


@needs_pdftotext
@pytest.mark.parametrize("name", ["en.pdf", "zh.pdf"])
def test_pdf_text_layer_has_the_cli_numbers(reports, expected, name):
    text = squash(pdf_text(reports[name]))
    missing = [v for v in expected if v not in text]
    assert missing == []
    assert "Classic" in text
    pages = re.findall(r"(\d+) / (\d+)", text)
    assert pages and pages[-1][0] == pages[-1][1] and int(pages[-1][1]) >= 8


@needs_pdftotext
def test_chinese_report_is_in_chinese(reports):
    # pdftotext writes some characters as Kangxi radicals (⽜ for 牛); NFKC folds them back
    text = re.sub(r"\s+", "", unicodedata.normalize("NFKC", pdf_text(reports["zh.pdf"])))
    for radical, char in (("\u2ec6", "角"), ("\u2ed3", "长"), ("\u2edc", "飞"), ("\u2eda", "页")):
        text = text.replace(radical, char)          # radicals NFKC leaves alone
    for word in ("牛头刨床导杆机构设计说明书", "极位夹角", "行程速比系数", "速度多边形", "加速度多边形",
                 "哥氏加速度", "飞轮", "曲柄驱动力矩"):
        assert word in text, word
    assert "Design inputs" not in text


def test_html_report_has_the_same_numbers_and_figures(reports, expected):
    html = reports["en.html"].read_text(encoding="utf-8")
    text = squash(re.sub(r"<[^>]+>", " ", html.split("<body>", 1)[1]).replace("&#x27;", "'"))
    missing = [v for v in expected if v not in text]
    assert missing == []
    assert html.count("<svg") >= 8              # two schemes… curves, 6 polygons, forces
    assert "μv = " in html or "v = " in html


class _Links(HTMLParser):
    """The HTML's contents (each link's text and target) and its section headings (id → text)."""

    def __init__(self) -> None:
        super().__init__()
        self.links: list[tuple[str, str]] = []
        self.ids: dict[str, str] = {}
        self._open: tuple[str, str] | None = None       # (kind, key) of the element being read
        self._text = ""

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "a" and attrs.get("href", "").startswith("#"):
            self._open, self._text = ("link", attrs["href"][1:]), ""
        elif tag == "h2" and "id" in attrs:
            self._open, self._text = ("id", attrs["id"]), ""

    def handle_data(self, data):
        self._text += data

    def handle_endtag(self, tag):
        if self._open and tag in ("a", "h2"):
            kind, key = self._open
            if kind == "link":
                self.links.append((self._text, key))
            else:
                self.ids[key] = self._text
            self._open = None


@needs_pdftotext
def test_html_report_has_the_pdfs_contents_with_links(reports):
    """The PDF has a contents page after its cover; the HTML had none. Its contents list the
    same sections in the same order as the PDF's, each a link to its heading."""
    lines = pdf_text(reports["en.pdf"]).splitlines()
    start = next(k for k, line in enumerate(lines) if line.strip() == "Contents")
    entries = []
    for line in lines[start + 1:]:
        found = re.match(r"\s*(\S.*?)\s*(?:\. )+\.?\s*(\d+)$", line)
        if found is None:
            break
        entries.append(unicodedata.normalize("NFKC", found.group(1)))      # pdftotext's "ﬂ"
    assert len(entries) >= 8 and entries[0].startswith("1 ")
    page = _Links()
    page.feed(reports["en.html"].read_text(encoding="utf-8"))
    assert [text for text, _ in page.links] == entries
    assert [page.ids.get(target) for _, target in page.links] == entries


def test_pdf_is_exactly_a4_on_every_page(reports):
    """ISO 216 A4 is 210 × 297 mm; QPdfWriter alone wrote 595 × 842 pt (209.90 × 297.04 mm)."""
    import pikepdf
    assert reports["en.pdf"].read_bytes().startswith(b"%PDF")
    with pikepdf.open(reports["en.pdf"]) as pdf:
        assert len(pdf.pages) >= 8
        for page in pdf.pages:
            for box in (page.MediaBox, page.TrimBox):
                x0, y0, x1, y1 = (float(v) for v in box)
                assert (x1 - x0) * 25.4 / 72 == pytest.approx(210.0, abs=1e-3)
                assert (y1 - y0) * 25.4 / 72 == pytest.approx(297.0, abs=1e-3)


@pytest.mark.parametrize("words, option", [
    (["--K", "0.9", "--crank", "100", "--stroke", "300"], "--K"),
    (DESIGN + ["--positions", "0"], "--positions"),
    (DESIGN + ["--diagrams", "10"], "--diagrams"),
    (DESIGN + ["--lang", "fr"], "--lang"),
])
def test_bad_input_is_one_line(tmp_path, words, option):
    result = shaper_run_in_process("report", *words, "-o", tmp_path / "r.pdf")
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0]
    assert not (tmp_path / "r.pdf").exists()


def test_missing_output_folder(tmp_path):
    result = shaper_run_in_process("report", *DESIGN, "-o", tmp_path / "nope" / "r.pdf")
    assert result.returncode == 2 and "--output" in result.stderr


@pytest.mark.parametrize("name, extra, reason", [
    ("r.docx", [], "must end in .pdf, .html or .htm"),     # was a PDF named r.docx
    ("report", [], "must end in .pdf, .html or .htm"),
    ("", [], "must end in .pdf, .html or .htm"),           # was an internal error
    ("r.pdf", ["--html"], "names a PDF"),
    ("folder.pdf", [], "it is a folder"),                  # was an internal error, exit 1
    ("sub/", [], "must end in"),
])
def test_bad_output_name_is_one_line_and_writes_nothing(tmp_path, name, extra, reason):
    (tmp_path / "folder.pdf").mkdir()
    (tmp_path / "sub").mkdir()
    before = sorted(p.name for p in tmp_path.rglob("*"))
    target = str(tmp_path / name) if name else ""
    result = shaper_run_in_process("report", *DESIGN, *extra, "-o", target)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("shaper: error: --output: ") and reason in lines[0]
    assert sorted(p.name for p in tmp_path.rglob("*")) == before


def test_the_name_chooses_the_type_and_a_save_keeps_the_files_mode(tmp_path):
    """R.HTM is HTML without --html (it was a PDF under an HTML name); an existing report
    is replaced whole (core.files.atomic) and keeps its permission bits, with no temp left."""
    page = tmp_path / "R.HTM"
    page.write_text("old")
    page.chmod(0o640)
    result = shaper_run_in_process("report", *DESIGN, "-o", page)
    assert result.returncode == 0, result.stderr
    assert "(HTML)" in result.stdout
    text = page.read_text(encoding="utf-8")
    assert text.lstrip().lower().startswith("<!doctype html") and "<svg" in text
    assert stat.S_IMODE(page.stat().st_mode) == 0o640
    assert sorted(p.name for p in tmp_path.iterdir()) == ["R.HTM"]


def test_no_chinese_font_names_the_package(qtbot, monkeypatch, tmp_path, capsys):
    from core.cli import main
    from shaperapp.widgets import i18n
    from shaperapp.widgets import fonts
    monkeypatch.setattr(fonts, "cjk_family", lambda: None)
    try:
        status = main(["report", *DESIGN, "--lang", "zh", "-o", str(tmp_path / "r.pdf")])
    finally:
        i18n.set_language("en")
    err = capsys.readouterr().err.strip().splitlines()
    assert status == 2 and len(err) == 1 and "fonts-noto-cjk" in err[0]
    assert not (tmp_path / "r.pdf").exists()


# ---- the comparison section (issue 10 in the report) -----------------------------
OTHER = ["--crank", "100", "--K", "1.6", "--stroke", "300", "--rod-ratio", "0.3", "--rpm", "40"]


@pytest.fixture(scope="module")
def compared(tmp_path_factory):
    """A library with the report's design ("Classic"), a loaded rod design and a block
    design without loads; a design file; the report comparing them, in English and Chinese."""
    folder = tmp_path_factory.mktemp("compare")
    lib = folder / "lib.sqlite"
    for name, words in (("Classic", DESIGN + SPEEDS + LOADS), ("rod 1.6", OTHER + LOADS),
                        ("no loads", ["--crank", "110", "--K", "1.4", "--stroke", "300"])):
        assert shaper_run_in_process("library", "add", *words, "--name", name, "--library", lib).returncode == 0
    design = folder / "wide.shaper.json"
    assert shaper_run_in_process("library", "add", "--crank", "90", "--K", "1.5", "--stroke", "320", "--name", "x",
                                 "--library", folder / "other.sqlite").returncode == 0
    assert shaper_run_in_process("library", "export", "x", "-o", design,
                                 "--library", folder / "other.sqlite").returncode == 0
    out = {}
    for name, extra in (("en.pdf", []), ("zh.pdf", ["--lang", "zh"]), ("en.html", ["--html"])):
        result = shaper_run_in_process("report", *DESIGN, *SPEEDS, *LOADS, "--title", "Classic", "--compare",
                                       "rod 1.6", "no loads", "--compare-file", design, "--library", lib,
                                       "-o", folder / name, *extra)
        assert result.returncode == 0, result.stderr
        out[name] = folder / name
    table = shaper_run_in_process("library", "compare", "Classic", "rod 1.6", "no loads", "--file", design,
                                  "--rpm", SPEEDS[1], "--library", lib)
    assert table.returncode == 0, table.stderr
    return out, table.stdout, lib, design


def compare_cells(text: str) -> list[str]:
    """Every number-bearing cell 'shaper library compare' prints (best marks dropped)."""
    cells = []
    for line in text.splitlines()[2:]:                 # the header and the rpm row
        if line.startswith("("):
            break
        cells += [c.removesuffix(" *") for c in re.split(r"\s{2,}", line.strip())[1:]
                  if re.search(r"\d", c)]
    return cells


@needs_pdftotext
@pytest.mark.parametrize("name", ["en.pdf", "zh.pdf"])
def test_comparison_section_has_library_compares_numbers(compared, name):
    reports, table, _, _ = compared
    cells = compare_cells(table)
    assert len(cells) > 40 and any("(-" in c for c in cells) and any("(+" in c for c in cells)
    text = squash(pdf_text(reports[name]))
    missing = [c for c in cells if c not in text]
    assert missing == []
    assert text.count("★") >= 3                      # a best in the |a|, torque and J_F rows


def test_comparison_in_html_and_its_title(compared):
    reports, table, _, _ = compared
    html = reports["en.html"].read_text(encoding="utf-8")
    text = squash(re.sub(r"<[^>]+>", " ", html.split("<body>", 1)[1]))
    assert "Comparison with other designs" in text and "“rod 1.6”" in text and "“wide”" in text
    assert [c for c in compare_cells(table) if c not in text] == []


@pytest.mark.parametrize("words, option", [
    (["--compare", "nobody"], "--compare"),
    (["--compare", "rod 1.6", "rod 1.6"], "--compare"),
    (["--compare", "rod 1.6", "no loads", "Classic", "rod 1.6", "no loads", "Classic"], "--compare"),
    (["--compare-file", "missing.json"], "--compare-file"),
])
def test_bad_comparison_is_one_line(compared, tmp_path, words, option):
    _, _, lib, _ = compared
    result = shaper_run_in_process("report", *DESIGN, *words, "--library", lib, "-o", tmp_path / "r.pdf")
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"shaper: error: {option}")
    assert not (tmp_path / "r.pdf").exists()


def test_comparison_from_a_missing_library_names_it(tmp_path):
    result = shaper_run_in_process("report", *DESIGN, "--compare", "a", "--library", tmp_path / "none.sqlite",
                                   "-o", tmp_path / "r.pdf")
    assert result.returncode == 2 and result.stderr.startswith("shaper: error: --library")
    assert not (tmp_path / "none.sqlite").exists() and not (tmp_path / "r.pdf").exists()


@needs_pdftotext
def test_cover_block_from_the_command_line(tmp_path):
    out = tmp_path / "r.pdf"
    result = shaper_run_in_process("report", *DESIGN, "--rpm", "40", "-o", out, "--student", "Li Ming",
                                   "--student-number", "2021-07", "--class", "ME 21", "--school", "SME",
                                   "--supervisor", "Prof. Wang", "--date", "2026-06-30")
    assert result.returncode == 0, result.stderr
    first = squash(pdf_text(out).split("\f")[0])
    for text in ("Student Li Ming", "Student number 2021-07", "Class ME 21", "School SME",
                 "Supervisor Prof. Wang", "Date 2026-06-30"):
        assert text in first
    assert "L1 100 mm, K 1.4, H 300 mm, L4/L3 0.3" in first and "Untitled" not in first


@pytest.mark.parametrize("words, option", [
    (["--student", "a\nb"], "--student"), (["--class", "x" * 201], "--class"),
    (["--title", "a\tb"], "--title")])
def test_bad_cover_text_is_one_line(tmp_path, words, option):
    result = shaper_run_in_process("report", *DESIGN, *words, "-o", tmp_path / "r.pdf")
    assert result.returncode == 2
    assert result.stderr.startswith(f"shaper: error: {option}:") and result.stderr.count("\n") == 1
    assert not (tmp_path / "r.pdf").exists()


def test_drawing_scales_are_the_standard_series():
    from shaperapp.report.figures import NICE_SCALES, round_scale
    for value in (0.013, 0.9, 1.0, 1.2, 7.3, 11.0, 14.2, 15.0, 16.0, 333.0):
        mu = round_scale(value)
        mantissa = mu / 10 ** np.floor(np.log10(mu))
        assert mu >= value * (1 - 1e-12) and any(np.isclose(mantissa, n) for n in NICE_SCALES)
        smaller = [n * 10 ** k for n in NICE_SCALES for k in range(-3, 4) if n * 10 ** k < mu]
        assert all(s < value for s in smaller)                  # the smallest that fits


@needs_pdftotext
@pytest.mark.parametrize("name", ["en.pdf", "zh.pdf"])
def test_schemes_state_their_scale_and_mark_theta(reports, name):
    text = squash(pdf_text(reports[name]))
    scales = re.findall(r"μ\s?l = (\d+(?:\.\d+)?) m/mm \(1:(\d+(?:\.\d+)?)\)", text)   # as the sheets
    assert len(scales) == 2 and scales[0] == scales[1]
    assert float(scales[0][0]) * 1000 == pytest.approx(float(scales[0][1]))       # μl in m/mm, 1:d
    theta = shaper_run_in_process("synth", *DESIGN).stdout.split("extreme-position angle θ")[1].split()[0].rstrip("°")
    # one mark per scheme, written as a drawing's dimension (2 places, trailing zeros dropped)
    assert text.count(f"θ = {float(theta):.2f}".rstrip("0").rstrip(".") + "°") == 2


def test_scheme_marks_sit_on_the_design(qtbot):
    """The marks are placed through SchemeWidget.export_point: O4 to a lever tip limit
    position measures L3 in design mm, at the same scale across and up (aspect locked)."""
    import math

    from shaperapp.design.model import DesignModel
    from shaperapp.scheme.view import SchemeWidget
    model = DesignModel()
    scheme = SchemeWidget(model)
    qtbot.addWidget(scheme)
    scheme.resize(620, 700)
    scheme.show()
    design = model.design
    o4, across, up = (scheme.export_point(*p) for p in ((0, 0), (100, 0), (0, 100)))
    mm_per_px = 100 / (across.x() - o4.x())
    assert (o4.y() - up.y()) * mm_per_px == pytest.approx(100, rel=1e-9)
    half = design.theta / 2
    tip = scheme.export_point(design.lever * math.sin(half), design.lever * math.cos(half))
    assert math.dist((o4.x(), o4.y()), (tip.x(), tip.y())) * mm_per_px == pytest.approx(design.lever)


@pytest.mark.parametrize("language", ["en", "zh"])
def test_formulas_are_typeset(tmp_path, language):
    out = tmp_path / "r.html"
    assert shaper_run_in_process("report", *DESIGN, "--rpm", "40", "--lang", language, "--html",
                                 "-o", out).returncode == 0
    page = out.read_text(encoding="utf-8")
    formulas = page[re.search(r"<h2[^>]*>8" + (" " if language == "en" else ""), page).start():]   # the section
    for marked in ("a<sup>k</sup><sub>A4A3</sub>", "v<sub>A4</sub>", "ω<sub>4</sub>", "S<sub>4</sub>", "J<sub>F</sub>",
                   "ΔW<sub>max</sub>", "O<sub>4</sub>", "L<sub>3</sub>", "(<sup>1</sup>⁄<sub>2π</sub>)"):
        assert marked in formulas, marked
    text = re.sub(r"<[^>]+>", "", formulas)
    assert "^" not in text and not re.search(r"[A-Za-zΔ]_[A-Za-z0-9]", text)


@pytest.mark.parametrize("design, says, not_says", [
    (["--crank", "100", "--K", "1.4", "--stroke", "300", "--guide", "sagitta"],
     "midway along the sagitta", "extreme positions at"),
    (["--crank", "100", "--K", "1.4", "--stroke", "300"], "extreme positions at", "sagitta"),
    (["--dims", "100,386.37,579.56", "--guide", "540"], "at the height given", "Synthesis."),
])
def test_formulas_state_the_guide_rule_of_the_design(tmp_path, design, says, not_says):
    """The formulas section printed the chord rule for every design, a sagitta one too."""
    out = tmp_path / "r.html"
    run = shaper_run_in_process("report", *design, "--rpm", "40", "-o", str(out))
    assert run.returncode == 0, run.stderr
    html = out.read_text(encoding="utf-8")
    formulas = html.split("Conventions and formulas", 1)[1]
    text = re.sub(r"<[^>]+>", "", formulas)
    assert says in text and not_says not in text
    assert "ω4 and α4 are positive clockwise" in text
