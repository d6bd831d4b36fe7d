"""The cam and gear sheets' tables print each figure as ``shaper cam`` and ``shaper gear`` do
(and the report and the answer key, which print those commands' texts): the gear sheet wrote
x1 = 0.2396, α′ = 20.0000°, a′ = 159.000 and ε = 1.5275 beside the report's and the answer key's
0.239644, 20.000000, 159.0000 and 1.527479, and the cam sheet the largest pressure angles as
40.00° / 65.20° beside 40.000 ° / 65.198 °. A teacher comparing the printouts sees one number
for one figure. Each decimal number of a table must be one the command prints, whole."""
from __future__ import annotations

import re

import pytest

from cli_runner import shaper_in_process
from core.cam import CamInputs, Program, design_cam
from core.drawing.cam_sheet import cam_sheet
from core.drawing.gear_sheet import gear_sheet
from core.drawing.sheet import Text, paper
from core.gear import GearPairInputs, design_pair
from core.linkage.geometry import from_dimensions

DECIMAL = re.compile(r"-?\d+\.\d+")
GEARS = {"rule": dict(z1=13, z2=40, module_mm=6.0), "centre": dict(z1=13, z2=40, module_mm=6.0, centre_mm=162.0),
         "given": dict(z1=17, z2=120, module_mm=4.0, x1=0.1, x2=0.0)}
OPTION = {"z1": "--z1", "z2": "--z2", "module_mm": "--module", "centre_mm": "--centre", "x1": "--x1", "x2": "--x2"}


def _table_numbers(drawn) -> list[str]:
    texts = [t.text for t in drawn.areas["figures"][1] if isinstance(t, Text)]
    assert not [t for t in texts if "…" in t]
    return [n for t in texts for n in DECIMAL.findall(t)]


@pytest.mark.parametrize("size", ["A1", "A3"])
@pytest.mark.parametrize("name", sorted(GEARS))
def test_the_gear_sheets_figures_are_shaper_gears(name, size):
    given = GEARS[name]
    status, out, err = shaper_in_process("gear", *(a for k, v in given.items() for a in (OPTION[k], v)))
    assert status == 0, err
    printed = set(DECIMAL.findall(out)) | {"1.2"}       # the least contact ratio its check quotes: an input
    numbers = _table_numbers(gear_sheet(design_pair(GearPairInputs(**given)), paper(size)))
    assert len(numbers) > 30
    assert [n for n in numbers if n not in printed] == []


@pytest.mark.parametrize("size", ["A1", "A3"])
def test_the_cam_sheets_figures_are_shaper_cams(size):
    """方案 I's linkage with the task book's cam (l = 125 mm, ψmax 15°, [α] 40°, 75°/10°/75°)."""
    status, out, err = shaper_in_process("cam", "--arm", "125", "--swing", "15", "--pressure", "40", "--rise", "75",
                                         "--dwell", "10", "--return", "75", "--dims", "110,380,540",
                                         "--rod-ratio", "0.25", "--guide", "sagitta", "--rpm", "60")
    assert status == 0, err
    printed = set(DECIMAL.findall(out))
    linkage = from_dimensions(110.0, 380.0, 540.0, rod=135.0, guide="sagitta")
    cam = design_cam(CamInputs(125.0, Program(15.0, 75.0, 10.0, 75.0, "sine", "sine"), 40.0), linkage)
    assert [n for n in _table_numbers(cam_sheet(cam, 60.0, paper(size))) if n not in printed] == []


@pytest.mark.parametrize("size", ["A1", "A3"])
def test_every_length_on_the_gear_sheet_names_its_unit(size):
    """The gear sheet's table wrote the diameters, thicknesses, a′, pb and the lines of
    action as bare numbers ('Reference diameter d  78.000  240.000'), where the module row
    said 'mm' and the cam and motion sheets write 'mm' after each length. Every row of a
    length must name mm: after each number, or once after a pair of them."""
    from core.drawing.gear_sheet import ENGLISH
    drawn = gear_sheet(design_pair(GearPairInputs(**GEARS["centre"])), paper(size))
    lengths = [ENGLISH[k] for k in ("d", "db", "da", "df", "dw", "s", "e", "sa", "centre", "pb", "lines")]
    rows = {row[0]: row[1:] for row in drawn.rows}
    together = (ENGLISH["lines"], ENGLISH["centre"])      # "54.3812, 27.0559 mm", "162.0000 (159.0000) mm"
    for label in lengths:
        cells = " ".join(rows[label])
        numbers = DECIMAL.findall(cells)
        assert numbers and len(re.findall(r"\d\)? mm", cells)) >= (1 if label in together else len(numbers)), \
            (label, cells)
