"""A section's heading is printed on the page of its first table or figure: a teacher
circles a heading, or a heading with its one-line introduction, at a page's foot while
what it introduces starts the next page.

Found in a class run (王八's report: section 7 at the foot of page 9, its table on page 10)
and reduced to the rod design below (方案 I's loads, cam and gear; L1, L2, L3 = 110, 380,
540 mm, L4/L3 = 0.3, 60 r/min): section 7's heading and its sentence on the flywheel
ended page 9, the table of torque, power and flywheel began page 10. The page of each
text is read from the laid-out PDF (``pdftotext``, one page per form feed)."""
from __future__ import annotations

import re
import shutil
import subprocess

import pytest

from core.cam.file import cam_from_dict
from core.forces.masses import MassProperties
from core.gear import GearPairInputs
from core.linkage.spec import Spec
from shaperapp.report.blocks import Figure, Heading, Paragraph, Table
from shaperapp.report.content import Options, build
from shaperapp.report.pdf import pdf_bytes
from shaperapp.widgets import i18n

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(shutil.which("pdftotext") is None, reason="pdftotext not installed")]
G = 9.81
SPEC = Spec(mode="dimensions", crank=110.0, frame=380.0, lever=540.0, variant="rod", rod_input="ratio",
            rod_ratio=0.3)
LOADS = MassProperties(lever_mass_kg=200 / G, lever_inertia_kg_m2=1.1, ram_mass_kg=700 / G,
                       cut_force_N=7000, cut_height_mm=80)
CAM, _ = cam_from_dict({"arm_mm": 125, "swing_deg": 15, "pressure_deg": 40, "rise_deg": 75, "dwell_deg": 10,
                        "return_deg": 75})
GEAR = GearPairInputs(z1=13, z2=40, module_mm=6.0)


def flat(text: str) -> str:
    """``text`` without markup and white space, as it can be found in a page's text."""
    return re.sub(r"\s+", "", re.sub(r"<[^>]+>", "", text))


@pytest.fixture(scope="module")
def printed(qapp, tmp_path_factory):
    i18n.set_language("zh_CN")
    try:
        report = build(SPEC, [60.0], LOADS, "Keep", "2026-01-01", "zh_CN",
                       Options(cam=(CAM, None), gear=GEAR))
    finally:
        i18n.set_language("en")
    path = tmp_path_factory.mktemp("keep") / "report.pdf"
    path.write_bytes(pdf_bytes(report)[0])
    text = subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True,
                          check=True).stdout
    raw = text.split("\f")
    body = ["\n".join(line for line in page.splitlines() if ". . ." not in line) for page in raw]
    return report, [flat(page) for page in body], raw       # the pages without the contents' lines


def opened_sections(report) -> list[tuple[str, str]]:
    """(heading, first line of what it introduces) for each section that opens with
    paragraphs and then a captioned table or figure."""
    found = []
    blocks = report.blocks
    for i, block in enumerate(blocks):
        if not isinstance(block, Heading):
            continue
        j = i + 1
        while j < len(blocks) and isinstance(blocks[j], Paragraph):
            j += 1
        if j < len(blocks) and isinstance(blocks[j], (Table, Figure)) and blocks[j].caption:
            found.append((block.text, blocks[j].caption))
    return found


def page_of(pages: list[str], text: str) -> int:
    hits = [n for n, page in enumerate(pages, 1) if flat(text)[:24] in page]
    assert hits, text
    return hits[0]


def test_a_heading_is_on_the_page_of_what_it_introduces(printed):
    report, pages, _ = printed
    sections = opened_sections(report)
    assert any(heading.startswith("7 ") for heading, _ in sections)      # the case that failed
    apart = [(heading, page_of(pages, heading), first, page_of(pages, first))
             for heading, first in sections if page_of(pages, heading) != page_of(pages, first)]
    assert apart == []


def test_the_contents_give_each_sections_page(printed):
    """The contents under the cover list every section in order with the page its heading
    is printed on (a course report has contents; this one had none)."""
    report, _, raw = printed
    headings = [b.text for b in report.blocks if isinstance(b, Heading)]
    listed = re.findall(r"^\s*(\d+ \S.*?)\s*(?:\. )+\.?\s*(\d+)\s*$", raw[0], re.M)
    assert [text for text, _ in listed] == headings
    printed_on = {}
    for n, page in enumerate(raw, 1):
        for line in page.splitlines():
            if line.strip() in headings and ". ." not in line:
                printed_on.setdefault(line.strip(), n)
    assert {text: int(page) for text, page in listed} == printed_on
