"""User text is data: hostile names come out as text in the HTML and PDF report and as
text (never a formula) in every CSV; round-off zeros are written as 0."""
import csv
import html.parser
import io
import re
import shutil
import subprocess

import numpy as np
import pytest

from cli_runner import shaper_in_process, shaper_run_in_process
from core.files.io import FORMULA_LEADS, csv_text, snap_zeros, table_csv

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

SCRIPT = "<script>alert(1)</script>"
FORMULA = '=HYPERLINK("http://x.example","y")'
BOLD = "<b>T&amp;</b> “q”"
FILE = '<img src=x onerror=alert(2)>'
DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300"]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000"]
COVER = ["--student", "<i>Li</i>", "--student-number", "=1+1", "--class", "<u>ME 21</u>",
         "--school", "@school", "--supervisor", "<s>Wang</s>"]


class Tags(html.parser.HTMLParser):
    """Start tags, and the text (entities resolved) of the document."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: set[str] = set()
        self.text: list[str] = []

    def handle_starttag(self, tag, attrs):
        self.tags.add(tag)

    def handle_data(self, data):
        self.text.append(data)


@pytest.fixture(scope="module")
def hostile(tmp_path_factory):
    """A library with hostile names, a design file with a hostile name, and the report of
    that file compared with them (HTML and PDF), titled by its file name."""
    folder = tmp_path_factory.mktemp("hostile")
    lib = folder / "lib.sqlite"
    for name, k in ((SCRIPT, "1.6"), (FORMULA, "1.5")):
        added = shaper_run_in_process("library", "add", "--crank", "100", "--K", k, "--stroke", "300",
                                      "--rpm", "40", *LOADS, "--name", name, "--library", lib)
        assert added.returncode == 0, added.stderr
    design = folder / f"{FILE}.shaper.json"
    assert shaper_run_in_process("library", "export", SCRIPT, "-o", design, "--library", lib).returncode == 0
    out = {}
    for target, title in (("r.html", []), ("r.pdf", []), ("t.html", ["--title", BOLD])):
        done = shaper_run_in_process("report", "--design", design, "--rpm", "40", *LOADS, *title, *COVER,
                                     "--compare", SCRIPT, FORMULA, "--library", lib, "-o", folder / target)
        assert done.returncode == 0, done.stderr
        out[target] = folder / target
    return out, lib


@pytest.mark.parametrize("target, name", [("r.html", FILE), ("t.html", BOLD)])
def test_html_report_prints_every_user_string_as_text(hostile, target, name):
    reports, _ = hostile
    page = reports[target].read_text(encoding="utf-8")
    parsed = Tags()
    parsed.feed(page)
    # the report's own markup has none of these; a user's name would have brought them
    assert not parsed.tags & {"script", "img", "i", "u", "s"}
    assert "<b>T" not in page
    text = "".join(parsed.text)
    head, body = page.split("<body>", 1)
    assert name in "".join(t for t in [head] for t in re.findall(r"<title>(.*?)</title>", t)) \
        .replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", '"').replace("&amp;", "&")
    # the title block, the comparison's prose, its table header and its legend (inline SVG)
    for user in (name, SCRIPT, FORMULA):
        assert text.count(user) >= 3, user
    assert f"“{name}”, beside “{SCRIPT}”, “{FORMULA}”" in text
    for cover in ("<i>Li</i>", "=1+1", "<u>ME 21</u>", "@school", "<s>Wang</s>"):
        assert cover in text


@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="pdftotext not installed")
def test_pdf_report_prints_user_strings_as_text(hostile):
    reports, _ = hostile
    text = subprocess.run(["pdftotext", str(reports["r.pdf"]), "-"], capture_output=True,
                          text=True, check=True).stdout
    squashed = re.sub(r"\s+", " ", text)
    assert f"“{FILE}”, beside “{SCRIPT}”" in squashed          # the comparison's prose
    assert squashed.count(FILE) >= 3                          # title block, prose, footers
    for cover in ("<i>Li</i>", "<u>ME 21</u>", "<s>Wang</s>", "=1+1", "@school"):
        assert cover in squashed


def test_csv_text_cells():
    for lead in FORMULA_LEADS:
        assert csv_text(lead + "1") == "'" + lead + "1"
    assert csv_text("rod 1.6") == "rod 1.6" and csv_text("") == ""
    assert csv_text("a=1") == "a=1"              # only the first character makes a formula


def test_library_compare_csv_writes_names_as_text(hostile, tmp_path):
    _, lib = hostile
    status, out, err = shaper_in_process("library", "compare", SCRIPT, FORMULA, "--rpm", "40",
                                         "--library", str(lib), "--csv", "-")
    assert status == 0, err
    rows = list(csv.reader(io.StringIO(out)))
    assert rows[0][3:5] == [SCRIPT, "'" + FORMULA]
    assert rows[0][5] == "'" + f"{FORMULA} - {SCRIPT}"
    cells = [c for r in rows for c in r]
    assert not [c for c in cells if c.startswith(FORMULA_LEADS) and not _number(c)]
    negatives = [c for r in rows[1:] for c in r[3:6] if c.startswith("-")]
    assert negatives and all(_number(c) for c in negatives)   # numbers keep their sign
    status, out, err = shaper_in_process("library", "compare", SCRIPT, FORMULA, "--rpm", "40",
                                         "--library", str(lib), "--curves-csv", "-")
    assert status == 0, err
    names = {r[0] for r in list(csv.reader(io.StringIO(out)))[1:]}
    assert names == {SCRIPT, "'" + FORMULA}


def _number(cell: str) -> bool:
    try:
        float(cell)
    except ValueError:
        return False
    return True


def test_round_off_zeros_are_written_as_zero():
    # The ram stands still at both limit positions (φ = 0 and 180° + θ = 210° for K = 1.4),
    # and the lever's ω is zero there: exactly 0, whatever the round-off of the closed form.
    status, out, err = shaper_in_process("curves", *DESIGN, "--rpm", "40", "60", "--step", "15")
    assert status == 0, err
    rows = list(csv.reader(io.StringIO(out)))
    head = rows[0]
    limits = [r for r in rows[1:] if float(r[1]) in (0.0, 210.0, 360.0)]
    assert len(limits) == 6
    for r in limits:
        assert r[head.index("ram_v_m_s")] == "0" and r[head.index("lever_omega_rad_s")] == "0"
    assert not [c for r in rows for c in r if re.fullmatch(r"-?\d(\.\d+)?e-1\d", c)]


def test_snap_zeros_keeps_small_true_values():
    data = np.array([[1.0, -4.8e-17, 3e-10], [-2.0, 1e-3, np.nan], [-0.0, 2.0, 1.0]])
    snapped = snap_zeros(data)
    assert snapped[0, 1] == 0.0 and not np.signbit(snapped[2, 0])
    assert snapped[0, 2] == 3e-10 and snapped[1, 1] == 1e-3 and np.isnan(snapped[1, 2])
    assert table_csv(("a", "b", "c"), data) == "a,b,c\n1,0,3e-10\n-2,0.001,\n0,2,1\n"
