"""A polygon's caption keeps its scale: on the English A3 sheets the velocity, acceleration and
force polygons' captions ran wider than their cells even at 2.5 mm and were cut with "…"
("Acceleration polygon, φ = 120°, μa = 0.15 (m/…", "Force polygon of the lever (link 4),
φ = 1…"), so a teacher could not measure the polygon. Each caption must be whole (every word of
its template, the scale with its unit), inside its cell and clear of the other captions."""
from __future__ import annotations

import pytest

from core.drawing.forces import ENGLISH as FORCE_WORDS, forces_sheet
from core.drawing.motion import ENGLISH as MOTION_WORDS
from core.drawing.sheet import Text, paper
from core.forces.masses import MassProperties, masses_for_design
from core.linkage.geometry import synthesize
from motion_sheets import motion_drawn

ROD = synthesize(100.0, 1.46, 312.0, rod_ratio=0.3)
BLOCK = synthesize(100.0, 1.4, 300.0)


def _words(template: str) -> list[str]:
    """The template's fixed words, the placeholders and the index marks left out."""
    plain = template
    for name in ("{angle}", "{mu_f}", "{mu}"):
        plain = plain.replace(name, " ")
    plain = plain.replace("_", "")
    return [w for w in plain.replace(",", " ").split() if w not in ("=",)]


def _captions(items, template: str) -> list[list[Text]]:
    """Each caption of ``template`` among ``items``: its first line (found by the template's
    first word) and any line hanging under it on the same centre."""
    texts = [t for t in items if isinstance(t, Text)]
    tops = [t for t in texts if t.text.startswith(_words(template)[0])]
    return [[top] + [t for t in texts if t is not top and abs(t.position[0] - top.position[0]) < 1e-6
                     and 0 < top.position[1] - t.position[1] < 2.5 * top.height] for top in tops]


def _check(items, template: str, cell, count: int) -> None:
    """``count`` captions of ``template`` in ``items``, each whole and inside ``cell``."""
    captions = _captions(items, template)
    assert len(captions) == count, [[t.text for t in c] for c in captions]
    for lines in captions:
        text = " ".join(t.text for t in lines)
        assert "…" not in text, text
        for word in _words(template):
            assert word in text, (word, text)
        others = [o.box() for o in items if isinstance(o, Text) and all(o is not t for t in lines)]
        for t in lines:
            x0, y0, x1, y1 = t.box()
            assert cell[0] - 1e-6 <= x0 and x1 <= cell[2] + 1e-6 and y1 <= cell[3] + 1e-6, (t.text, cell)
            clash = [o for o in others if o[0] < x1 and x0 < o[2] and o[1] < y1 and y0 < o[3]]
            assert not clash, (t.text, clash)


@pytest.mark.parametrize("size", ["A3", "A1"])
@pytest.mark.parametrize("design", [ROD, BLOCK], ids=["rod", "block"])
def test_the_motion_sheets_polygon_captions_are_whole(design, size):
    cell, items = motion_drawn(design, 40.0, size).areas["polygons"]
    for kind in ("velocity", "acceleration"):
        _check(items, MOTION_WORDS[kind], cell, 2)


@pytest.mark.parametrize("size", ["A3", "A1"])
def test_the_forces_sheets_polygon_captions_are_whole(size):
    loads = masses_for_design(ROD, MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                                                  cut_force_N=7000.0, cut_height_mm=80.0))
    drawn = forces_sheet(ROD, 60.0, loads, paper(size))
    for area, key in (("ram polygon 1", "polygon_ram"), ("ram polygon 2", "polygon_ram"),
                      ("lever polygon 1", "polygon_lever"), ("lever polygon 2", "polygon_lever")):
        cell, items = drawn.areas[area]
        _check(items, FORCE_WORDS[key], cell, 1)
