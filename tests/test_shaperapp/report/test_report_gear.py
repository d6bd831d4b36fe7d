"""Issue 35, item 5: the report's gear section. Its numbers are core.gear's (read back from
the PDF's text layer) and obey the involute identities; it names the shift rule that applied
and why; every failing check says what to change; the Chinese section has no English; the
pair in mesh is printed at the scale its caption states (the centres measured on the page).
On 55087ce the report had no gear section (``Options`` had no ``gear``)."""
from __future__ import annotations

import math
import re
import shutil
import subprocess

import numpy as np
import pytest
from PySide6.QtGui import QImage

from core.gear import GearPairInputs, design_pair, pair_checks
from core.linkage.spec import Spec
from shaperapp.report.content import Options, build
from shaperapp.report.pdf import page_boxes, pdf_bytes
from shaperapp.widgets import i18n

from figure_checks import pixels
from language_checks import english_words

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(shutil.which("pdftotext") is None or shutil.which("pdftoppm") is None,
                                 reason="poppler-utils not installed")]
RULE = GearPairInputs(z1=10, z2=14, module_mm=5.0)          # the rule's positive pair; ε < 1.2 fails
EQUAL = GearPairInputs(z1=12, z2=12, module_mm=8.0, x1=0.3, x2=0.3)   # both gears whole in the figure
# Functions the formulas write in Latin letters (the gear's notation is language_checks.NOTATION's)
SYMBOLS = {"tan", "sin", "cos"}
DPI = 150


def _printed(inputs: GearPairInputs, language: str, parts=("text", "figure")):
    """The report and its PDF, printed in ``language`` (the footer is translated as it is painted)."""
    i18n.set_language(language)
    try:
        report = build(Spec(), [40.0], None, "刨床", "2026-01-01", language, Options(gear=inputs))
        return report, pdf_bytes(report)[0], pdf_bytes(report, parts)[0]
    finally:
        i18n.set_language("en")


def _text(data: bytes, folder, stem: str) -> str:
    path = folder / f"{stem}.pdf"
    path.write_bytes(data)
    return subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True,
                          check=True).stdout


@pytest.fixture(scope="module", params=["en", "zh_CN"])
def printed(request, qapp, tmp_path_factory):
    language = request.param
    _, data, _ = _printed(RULE, language)
    text = _text(data, tmp_path_factory.mktemp("gear"), language)
    return language, gear_section(text)


def gear_section(text: str) -> str:
    """The text from the gear section's heading (the last section) to the end."""
    heading = re.search(r"\n\s*9 (The gear pair|齿轮机构) *\n", text)     # the heading, not its line in the contents
    assert heading is not None
    return text[heading.start():]


def numbers(text: str) -> list[str]:
    return re.findall(r"−?\d+\.\d+", text)


def test_the_numbers_are_core_gears(printed):
    _, section = printed
    pair = design_pair(RULE)
    printed_numbers = numbers(section)
    expected = [f"{pair.centre_mm:.4f}", f"{pair.reference_centre_mm:.4f}",
                f"{math.degrees(pair.alpha_w):.6f}", f"{pair.y:.6f}", f"{pair.dy:.6f}",
                f"{pair.n1n2:.4f}", f"{pair.b1b2:.4f}", f"{pair.pb:.4f}", f"{pair.contact_ratio:.6f}"]
    for gear in (pair.gear1, pair.gear2):
        expected += [f"{gear.shift:.6f}", f"{gear.least_shift:.6f}"]
        expected += [f"{getattr(gear, k):.4f}" for k in ("r", "rb", "ra", "rf", "rw", "s", "e", "sa")]
        expected.append(f"{math.degrees(gear.alpha_a):.4f}")
    assert [v for v in expected if v not in printed_numbers] == []


def _row(section: str, label: str) -> list[float]:
    line = next(line for line in section.splitlines() if re.match(rf"\s*{label}", line))
    return [float(v) for v in numbers(line)]


def test_the_printed_lengths_obey_the_involute_identities(printed):
    """Independent of core: r = m z/2, rb = r cos α, r + e/… and a′ cos α′ = a cos α, s + e = π m,
    ε = B1B2/pb, from the printed numbers alone (to their printed digits)."""
    language, section = printed
    m, alpha = RULE.module_mm, math.radians(20.0)
    label = {"en": ("Reference radius", "Base radius", "Tooth thickness", "Space e", "Centre distance",
                    "Working pressure", "Line of action", "Base pitch", "Contact ratio ε  "),
             "zh_CN": ("分度圆半径", "基圆半径", "分度圆齿厚", "分度圆齿槽宽", "中心距 a′",
                       "啮合角", "理论啮合线", "基圆齿距", "重合度 ε  ")}[language]
    r, rb, s, e = (_row(section, k) for k in label[:4])
    assert r == [m * z / 2 for z in (RULE.z1, RULE.z2)]
    assert rb == pytest.approx([v * math.cos(alpha) for v in r], abs=6e-5)
    assert [a + b for a, b in zip(s, e)] == pytest.approx([math.pi * m] * 2, abs=1.1e-4)
    (centre, a), (alpha_w,) = _row(section, label[4]), _row(section, label[5])
    assert a == m * (RULE.z1 + RULE.z2) / 2
    assert centre * math.cos(math.radians(alpha_w)) == pytest.approx(a * math.cos(alpha), abs=1e-4)
    (n1n2, b1b2), (pb,), (eps,) = (_row(section, k) for k in label[6:9])
    assert pb == pytest.approx(math.pi * m * math.cos(alpha), abs=6e-5)
    assert n1n2 == pytest.approx(centre * math.sin(math.radians(alpha_w)), abs=1e-4)
    assert eps == pytest.approx(b1b2 / pb, abs=1e-5)


def test_the_shift_rule_is_named_with_its_reason(printed):
    language, section = printed
    flat = re.sub(r"\s+", " ", section)
    z_min2 = 2 * 2.0 / math.sin(math.radians(20.0)) ** 2          # 2 zmin = 4 h*a / sin² α
    assert f"= 24 < 2" in flat and f"{z_min2:.4f}" in flat
    assert ("rounded up to a multiple of 0.5 mm" if language == "en" else "按 0.5 mm") in flat
    assert "63.0000" in flat                                         # a′ = 62.6… rounded up


def test_each_failing_check_says_what_to_change(printed):
    language, section = printed
    failing = [c.name for c in pair_checks(design_pair(RULE)) if not c.ok]
    assert failing == ["contact"]
    flat = re.sub(r"\s+", " ", section)
    # the advice names what helps in the rule's mode, with the a′ to type (core.gear.amounts,
    # whose value test_gear_amounts follows); 1de6048 said "a smaller a′", by no amount
    words = {"en": ("fails", "ε is too small: lower a′ to ≤ "), "zh_CN": ("不合格", "ε 过小：将 a′ 减小到 ≤ ")}
    assert flat.count(words[language][0]) == 1 and words[language][1] in flat


def test_the_chinese_section_has_no_english(printed):
    language, section = printed
    if language == "en":
        pytest.skip("the Chinese report")
    assert english_words(section, SYMBOLS) == []
    for term in ("啮合角", "重合度", "变位系数", "中心距", "基圆齿距", "齿顶圆", "节圆"):   # glossary.tsv
        assert term in section, term


def _fitted_centre(points: np.ndarray) -> tuple[np.ndarray, float]:
    """The least-squares circle (Kåsa) through ``points`` (x, y), refitted without the points
    more than 1.5 px off it (a label or a line beside the circle)."""
    keep = np.ones(len(points), bool)
    for _ in range(4):
        x, y = points[keep].T
        a = np.column_stack([x, y, np.ones_like(x)])
        cx, cy, c = np.linalg.lstsq(a, x * x + y * y, rcond=None)[0]
        centre = np.array([cx / 2, cy / 2])
        radius = math.sqrt(c + centre @ centre)
        keep = np.abs(np.hypot(*(points - centre).T) - radius) < 1.5
    assert keep.sum() > 0.6 * len(points)
    return centre, radius


def test_the_pair_in_mesh_is_at_the_stated_scale(qapp, tmp_path):
    """The centres O1 and O2, fitted to the two tip circles on the page at 150 dpi (the
    pinion's left edge row by row, the gear's right edge), lie a′/μ apart, μ read from the
    caption."""
    report, data, figures = _printed(EQUAL, "en", ("figure",))
    pair = design_pair(EQUAL)
    text = re.sub(r"\s+", " ", _text(data, tmp_path, "text"))
    ratio = re.search(r"in mesh at a′ = ([\d.]+) mm, to scale (?:1:([\d.]+)|([\d.]+):1)", text)
    assert ratio is not None and float(ratio[1]) == pytest.approx(pair.centre_mm, abs=1e-4)
    mu = float(ratio[2]) if ratio[2] else 1 / float(ratio[3])
    (tmp_path / "figures.pdf").write_bytes(figures)
    boxes = page_boxes(report)
    page, box = [(n, b) for n, placed in enumerate(boxes) for kind, b in placed if kind == "figure"][-1]
    subprocess.run(["pdftoppm", "-r", str(DPI), "-f", str(page + 1), "-l", str(page + 1), "-png",
                    str(tmp_path / "figures.pdf"), str(tmp_path / "page")], check=True)
    image = pixels(QImage(str(next(tmp_path.glob("page-*.png")))))
    px = DPI / 25.4
    top, bottom = int(box.top() * px), int(box.bottom() * px)
    ink = (image[top:bottom] < 200).any(axis=2)
    rows = np.flatnonzero(ink.any(axis=1))
    centre_row = rows[np.argmax(ink[rows].sum(axis=1))]            # the centre line: the longest row
    rows = rows[np.abs(rows - centre_row) > 3]
    # the outer edge of each tip circle: the left side of the leftmost inked pixel, the right
    # side of the rightmost (pixel k spans k … k + 1)
    left = np.array([(np.flatnonzero(ink[r])[0], r + 0.5) for r in rows], float)
    right = np.array([(np.flatnonzero(ink[r])[-1] + 1.0, r + 0.5) for r in rows], float)
    (o1, r1), (o2, r2) = _fitted_centre(left), _fitted_centre(right)
    assert abs(o1[1] - o2[1]) < 1.0                                  # both on the centre line
    expected = pair.centre_mm / mu * px
    assert math.dist(o1, o2) == pytest.approx(expected, abs=1.0), (mu, o1, o2)   # 0.25 %
    assert (r1 + r2) / 2 == pytest.approx(pair.gear1.ra / mu * px, abs=1.5)   # the tip circles' size


@pytest.mark.parametrize("inputs", [RULE, EQUAL, GearPairInputs(z1=13, z2=40, module_mm=6.0, centre_mm=162.0),
                                    GearPairInputs(z1=17, z2=60, module_mm=3.0)])
def test_no_label_of_the_figure_is_crossed(qapp, inputs):
    """The figure's labels (O1, O2, P, N1, N2, B1, B2, α′) clear of every line and of each
    other, by the sheets' own check, and every item inside the figure."""
    from core.drawing.checks import overlapping_texts
    from shaperapp.report.gear_figure import gear_figure
    from sheet_checks import crossed_texts, inside
    from core.drawing.sheet import item_box
    figure = gear_figure(design_pair(inputs), "en")
    sheet = figure.sheet
    texts = [t.text for t in sheet.items if hasattr(t, "text")]
    assert {"O1", "P", "N1", "N2", "B1", "B2"} <= set(texts), texts
    assert overlapping_texts(sheet) == [] and crossed_texts(sheet) == []
    frame = (0.0, 0.0, sheet.paper.width, sheet.paper.height)
    assert [item for item in sheet.items if not inside(item_box(item), frame)] == []


def test_the_checks_write_each_figure_as_the_pair_rows_do(printed):
    """The checks' table wrote every value and limit to 4 decimals, so ε read 1.5275 there and
    1.527479 two rows above it (and in ``shaper gear`` and the answer key), and an undercut
    check x1 ≥ x1min could read '0.2396 ≥ 0.2396 fails'. Shift factors and ε now have the 6
    decimals of their rows, lengths (mm) the 4 of theirs."""
    language, section = printed
    checks = {c.name: c for c in pair_checks(design_pair(RULE))}
    label = {"en": {"undercut1": "No undercut of gear 1", "undercut2": "No undercut of gear 2",
                    "contact": "Contact ratio ε ≥", "tip1": "Tip thickness of gear 1"},
             "zh_CN": {"undercut1": "齿轮 1 不根切", "undercut2": "齿轮 2 不根切", "contact": "重合度 ε ≥",
                       "tip1": "齿轮 1 的齿顶厚"}}[language]
    lines = section.splitlines()
    for name, decimals in (("undercut1", 6), ("undercut2", 6), ("contact", 6), ("tip1", 4)):
        row = next(line for line in lines if line.strip().startswith(label[name]))
        check = checks[name]
        expected = [f"{check.value:.{decimals}f}".replace("-", "−"), f"{check.limit:.{decimals}f}".replace("-", "−")]
        assert all(v in numbers(row) or v.replace("−", "-") in row for v in expected), (name, expected, row)
