"""No two texts of a sheet run together: numbers side by side stand a word space apart.

Found on an A3 motion sheet of 24 positions: the φ axes' degrees from 105° on read
"105120135150…". First the check itself (tests/sheet_checks.crowded_texts) on hand-made
sheets whose answer is plain arithmetic on GB/T 14691's spacing (word spacing e = 0.6 h;
a glyph's body is its box less 0.12 h each side), then the tick numbers' thinning, then
the sheet the issue found.
"""
import numpy as np
import pytest

from core.drawing.charts import Curve, chart, spaced_labels
from core.drawing.dxf import THIN
from core.drawing.sheet import Polyline, Sheet, Text, paper
from core.linkage.geometry import synthesize
from motion_sheets import motion_drawn
from sheet_checks import crowded_texts

A1 = paper("A1")


def crowded(*items) -> list[tuple[str, str]]:
    return [(a.text, b.text) for a, b, _ in crowded_texts(Sheet(A1, tuple(items)))]


# ---- the check ---------------------------------------------------------------------------

def test_two_numbers_side_by_side_need_a_word_space_between_their_bodies():
    """"105" 2.5 mm high is 6.54 mm wide (0.872 h a digit); its body is its box less 0.3 mm
    each side. Boxes touching leave 0.6 mm between the bodies, a letter space ("105120");
    0.85 mm between the boxes leaves 1.45 mm, under e = 1.5 mm; 0.95 mm leaves 1.55 mm."""
    first = Text("105", (100.0, 100.0), 2.5, "lb")
    assert crowded(first, Text("120", (106.54, 100.0), 2.5, "lb")) == [("105", "120")]
    assert crowded(first, Text("120", (106.54 + 0.85, 100.0), 2.5, "lb")) == [("105", "120")]
    assert crowded(first, Text("120", (106.54 + 0.95, 100.0), 2.5, "lb")) == []
    assert crowded(first, Text("120", (103.0, 100.0), 2.5, "lb")) == [("105", "120")]    # overlapping
    # the smaller text's word space counts: 1.5 mm beside a 5 mm one, not 3 mm
    assert crowded(first, Text("X", (106.54 + 0.95, 100.0), 5.0, "lb")) == []


def test_lines_one_over_another_may_stand_at_the_standards_line_spacing():
    """3.5 mm lines at GB/T 14691's smallest baseline spacing, 1.4 h = 4.9 mm, leave
    2.24 mm between their bodies (over 0.35 h = 1.225 mm); at 1.1 h (3.85 mm), 1.19 mm."""
    lower = Text("vB = 0.4911 m/s", (100.0, 100.0), 3.5, "lb")
    assert crowded(lower, Text("vC = 0.4904 m/s", (100.0, 104.9), 3.5, "lb")) == []
    assert crowded(lower, Text("vC = 0.4904 m/s", (100.0, 103.85), 3.5, "lb")) == [("vB = 0.4911 m/s",
                                                                                   "vC = 0.4904 m/s")]


def test_a_turned_text_counts_its_own_line():
    """Two texts turned 90° run along y: end to end along their baseline they are side by
    side (a word space, 1.5 mm between bodies), across it one over the other."""
    first = Text("105", (100.0, 100.0), 2.5, "lb", rotation=90.0)
    along = Text("120", (100.0, 106.54 + 0.85), 2.5, "lb", rotation=90.0)     # 1.45 mm: too near
    assert crowded(first, along) == [("105", "120")]
    across = Text("120", (100.0 - 2.5 * 1.4, 100.0), 2.5, "lb", rotation=90.0)   # at 1.4 h
    assert crowded(first, across) == []


def test_the_runs_of_one_text_are_not_two_texts():
    assert crowded(Text("aA4A3k = 0.1468", (100.0, 100.0), 3.5, "lb", subscripts=((1, 5),),
                        superscripts=((5, 6),))) == []


# ---- the tick numbers --------------------------------------------------------------------

def degrees(step_mm: float, count: int = 24) -> list[tuple[float, str]]:
    return [(100.0 + k * step_mm, f"{15 * k:g}") for k in range(count)]


def test_crowded_evenly_spaced_ticks_keep_every_second_number():
    """24 ticks 6 mm apart (A3, μφ = 2.5 °/mm): "105" … are 5.85 mm wide, 0.15 mm apart
    under their ticks, less than the 1 mm (0.4 h) a box keeps; every second stands."""
    kept = spaced_labels(degrees(6.0), 2.5)
    assert kept == [f"{15 * k:g}" if k % 2 == 0 else "" for k in range(24)]


def test_numbers_that_fit_all_stand_and_a_third_is_kept_where_a_second_is_not_enough():
    assert spaced_labels(degrees(12.0), 2.5) == [label for _, label in degrees(12.0)]
    # 3.3 mm apart: two apart is 6.6 mm, "105" to "135" 0.75 mm clear; three apart 9.9 mm
    kept = spaced_labels(degrees(3.3), 2.5)
    assert kept == [f"{15 * k:g}" if k % 3 == 0 else "" for k in range(24)]


def test_a_blank_label_keeps_its_place_in_the_pattern():
    """A degree a curve runs through is blanked by the caller and the chart drawn again with
    the labels it kept: the pattern stays."""
    ticks = [(x, "" if k in (0, 10) else label) for k, (x, label) in enumerate(degrees(6.0))]
    assert spaced_labels(ticks, 2.5) == [f"{15 * k:g}" if k % 2 == 0 and k not in (0, 10) else ""
                                         for k in range(24)]


def test_uneven_ticks_leave_out_each_number_too_near_the_last_one_written():
    """A cam's phase edges 0, 60, 70, 130, 360° at 0.4 mm/°: "70" stands 4 mm after "60"
    (3.9 mm wide): 0.1 mm clear, left out; the others stand."""
    ticks = [(100.0 + 0.4 * e, f"{e:g}") for e in (0, 60, 70, 130, 360)]
    assert spaced_labels(ticks, 2.5) == ["0", "60", "", "130", "360"]


def test_a_crowded_chart_keeps_every_tick_and_no_two_numbers_meet():
    """A chart 150 mm wide over 0 … 360° with 36 ticks: every tick mark is drawn, the
    numbers every third at most, none nearer another text than a word space."""
    phi = np.linspace(0.0, 360.0, 361)
    ticks = [(10.0 * k, f"{10 * k:g}") for k in range(36)]
    drawn = chart((0.0, 0.0, 150.0, 60.0), phi, [Curve(100.0 + 50.0 * np.sin(np.radians(phi)))], "φ/(°)", "s/mm",
                  ticks)
    left, zero = drawn.origin
    marks = [p for p in drawn.items if isinstance(p, Polyline) and p.layer == THIN and len(p.points) == 2
             and p.points[0, 0] == p.points[1, 0] and p.points[0, 1] < zero < p.points[1, 1]
             and abs(p.points[1, 1] - p.points[0, 1] - 3.0) < 1e-9]          # not the y axis
    assert sorted(round(float(p.points[0, 0]), 6) for p in marks) == sorted(
        round(left + 10.0 * k / drawn.x_scale, 6) for k in range(36))
    written = [t.text for t in drawn.items if isinstance(t, Text) and t.text.isdigit() and t.align != "rm"]
    assert 6 <= len(written) < 36
    assert crowded_texts(Sheet(A1, tuple(drawn.items))) == []


# ---- the sheet the issue found -----------------------------------------------------------

def test_the_a3_sheet_of_24_positions_writes_its_degrees_apart():
    """K = 2.9, H = 600, rod ratio 0.5 at 40 r/min, 24 positions on A3: the degrees under
    each φ axis every 30° (every second tick, 6 mm apart), all 24 ticks kept on each of the
    three charts, the position numbers all 24 (narrower, they fit), no two texts crowded."""
    drawn = motion_drawn(synthesize(100.0, 2.9, 600.0, rod_ratio=0.5), 40.0, "A3", 24)
    assert crowded_texts(drawn.sheet) == []
    _, items = drawn.areas["curves"]
    title = next(t for t in items if isinstance(t, Text) and t.text == "Position")
    numbers = [t for t in items if isinstance(t, Text) and t.text.isdigit() and t.align != "rm"]  # not y ticks
    row = sorted(int(t.text) for t in numbers if abs(t.position[1] - title.position[1]) < 1e-9)
    assert row == list(range(1, 25))
    written = [int(t.text) for t in numbers if abs(t.position[1] - title.position[1]) > 1e-9]
    assert len(written) >= 20 and all(n % 30 == 0 for n in written)      # every second tick
    marks = [p for p in items if isinstance(p, Polyline) and p.layer == THIN and len(p.points) == 2
             and abs(p.points[0, 0] - p.points[1, 0]) < 1e-9 and abs(p.points[1, 1] - p.points[0, 1] - 3.0) < 1e-9]
    assert len(marks) == 3 * 24


@pytest.mark.parametrize("count", [24, 36])
def test_the_position_row_thins_as_the_degrees_do(count):
    """36 positions on A3 (4 mm apart): "36" is 3.9 mm wide, so every second number."""
    drawn = motion_drawn(synthesize(100.0, 1.4, 300.0), 60.0, "A3", count)
    assert crowded_texts(drawn.sheet) == []
    _, items = drawn.areas["curves"]
    title = next(t for t in items if isinstance(t, Text) and t.text == "Position")
    row = sorted(int(t.text) for t in items if isinstance(t, Text) and t.text.isdigit()
                 and abs(t.position[1] - title.position[1]) < 1e-9)
    step = row[1] - row[0]
    assert row == list(range(1, count + 1, step)) and step <= 2


# ---- the polygons' captions on A3 --------------------------------------------------------

def test_an_a3_polygons_caption_keeps_its_scale_on_a_second_line():
    """On A3 "Acceleration polygon, φ = 135°, μ_a = 0.06 (m/s²)/mm" is wider than its cell
    even at 2.5 mm: it was cut to "… μa = 0.06 (m/…" (and the forces sheet's to "φ = 1…",
    angle and scale lost). Broken after a comma, each caption's lines hold its angle and
    its whole scale, the lines a GB/T 14691 line pitch apart, no two texts crowded."""
    from core.drawing.forces import forces_sheet
    from core.forces.masses import MassProperties, masses_for_design
    design = synthesize(100.0, 2.9, 600.0, rod_ratio=0.5)
    motion = motion_drawn(design, 40.0, "A3", 24)
    loads = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
                           cut_height_mm=80, rod_mass_kg=8.0)
    forces = forces_sheet(design, 40.0, masses_for_design(design, loads), paper("A3"))
    cases = ((motion, "polygons", r"(Velocity|Acceleration) polygon, φ = [\d.]+°,\s*μ[va] = [\d.]+ \(m/s²?\)/mm"),
             *((forces, f"{group} polygon {k}",
                r"Force polygon of the [a-z ()0-9]+, φ = [\d.]+°,\s*μF = [\d.]+ N/mm")
               for group in ("ram", "lever") for k in (1, 2)))
    import re
    broken = 0
    for drawn, area, pattern in cases:
        texts = [t for t in drawn.areas[area][1] if isinstance(t, Text)]
        assert not [t.text for t in drawn.sheet.items if isinstance(t, Text) and "…" in t.text]
        heads = [i for i, t in enumerate(texts) if "polygon" in t.text]
        assert heads, area
        for i in heads:
            if re.fullmatch(pattern, texts[i].text):        # on one line where it fits
                continue
            line_two = texts[i + 1]
            assert texts[i].height == line_two.height == 2.5
            assert texts[i].position[1] - line_two.position[1] == pytest.approx(1.5 * 2.5)
            assert re.fullmatch(pattern, texts[i].text + " " + line_two.text), (texts[i].text, line_two.text)
            broken += 1
        assert crowded_texts(drawn.sheet) == []
    assert broken >= 6          # the two acceleration polygons and the four force polygons
