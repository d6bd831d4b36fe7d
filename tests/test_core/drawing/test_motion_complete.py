"""The motion sheet carries what a motion sheet carries (issue 32, item 2): θ at O4 with its
value, the mechanism's dimensions as dimension lines and as DIMENSION entities that CAD
measures at true length, the tool path numbered as the crank positions are, and φ axes
whose tick labels are the degrees their title promises.

Expected values come from the synthesis formulas (θ = 180°(K − 1)/(K + 1),
L2 = L1/sin(θ/2), L3 = H/(2 sin(θ/2)), the chord rule's guide L3·cos(θ/2)), not from the
drawing's code; positions from their definition, φ_k = (k − 1)·360°/N.
"""
from __future__ import annotations

import io
import math

import ezdxf
import numpy as np
import pytest
from ezdxf.entities import DimStyleOverride

from dxf_checks import measurement
from motion_sheets import motion_drawn

from core.drawing import mechanism as mech
from core.drawing.dxf import DIMENSIONS, THIN, dxf_text
from core.drawing.sheet import Polyline, Text
from core.drawing.sheet_dims import segments, text_crossings
from core.drawing.sheet_dxf import sheet_document
from core.linkage.geometry import synthesize
from core.linkage.kinematics import shape
from sheet_checks import assert_laid_out

CASES = {   # (L1, K, H, rod ratio or None)
    "block": (100.0, 1.4, 300.0, None),
    "rod": (100.0, 1.46, 312.0, 0.3),
    "K near 1": (100.0, 1.05, 300.0, None),
    "K near 3": (100.0, 2.9, 600.0, None),
    "K near 3, rod": (100.0, 2.9, 600.0, 0.5),
    "long stroke": (100.0, 1.4, 900.0, None),
    "short crank": (30.0, 1.4, 300.0, None),
}


def design_of(case: str):
    l1, k, h, ratio = CASES[case]
    return synthesize(l1, k, h) if ratio is None else synthesize(l1, k, h, rod_ratio=ratio)


def drawn_sheet(case: str, rpm: float, size: str, count: int = 12):
    """The motion sheet of ``case``, built once per process (tests/motion_sheets.py): several
    tests read the same sheet (θ, the dimensions, the tool path's numbers and the clear texts
    all look at the A1 sheet at 40 r/min; the sheet checks and the tool path the 6 and 24
    positions at 60), and so does test_sheet.py. The tests only read it."""
    return motion_drawn(design_of(case), rpm, size, count)


def expected(case: str) -> dict[str, float]:
    """The dimensions' true values from the synthesis formulas."""
    l1, k, h, ratio = CASES[case]
    theta = math.pi * (k - 1.0) / (k + 1.0)
    l2 = l1 / math.sin(theta / 2.0)
    l3 = h / (2.0 * math.sin(theta / 2.0))
    values = {"L1": l1, "L2": l2, "L3": l3, "H": h, "h": l3 * math.cos(theta / 2.0) - l2,
              "θ": math.degrees(theta)}
    if ratio is not None:
        values["L4"] = ratio * l3
    return values


def shown(text: str) -> tuple[str, float]:
    """'L1 = 100' → ('L1', 100.0); 'θ = 30°' → ('θ', 30.0)."""
    name, value = text.split(" = ")
    return name, float(value.rstrip("°"))


@pytest.mark.parametrize("case", ["block", "rod", "K near 1", "K near 3"])
def test_theta_at_o4_with_its_value(case):
    drawn = drawn_sheet(case, 40.0, "A1")
    o4 = np.asarray(drawn.placement([0.0, 0.0]))
    thetas = [t for t in drawn.sheet.items if isinstance(t, Text) and t.text.startswith("θ = ")]
    assert len(thetas) == 1
    assert shown(thetas[0].text)[1] == pytest.approx(expected(case)["θ"], abs=0.006)
    assert math.dist(thetas[0].position, o4) < 50.0          # at O4, not in the table


@pytest.mark.parametrize("size", ["A1", "A3"])
@pytest.mark.parametrize("case", sorted(CASES))
def test_every_dimension_shows_the_design_and_cad_measures_it_at_true_length(case, size):
    """On the paper: one text per dimension with the true value to its 2 decimals. In the
    DXF: one DIMENSION per dimension, on the dimensions' layer, with that text, whose own
    measurement (from its definition points, in paper mm) times its DIMLFAC is the true
    value."""
    drawn = drawn_sheet(case, 40.0, size)
    want = expected(case)
    texts = [shown(t.text) for t in drawn.sheet.items if isinstance(t, Text) and t.layer == DIMENSIONS]
    assert sorted(name for name, _ in texts) == sorted(want)
    for name, value in texts:
        assert value == pytest.approx(want[name], abs=0.0051), name
    doc = ezdxf.read(io.StringIO(dxf_text(sheet_document(drawn.sheet))))
    dims = doc.modelspace().query("DIMENSION")
    assert len(dims) == len(want)
    for dim in dims:
        name, value = shown(dim.dxf.text)             # the true value as text: LibreCAD ignores DIMLFAC
        assert value == pytest.approx(want[name], abs=0.0051) and dim.dxf.layer == DIMENSIONS
        factor = DimStyleOverride(dim).get("dimlfac", 1.0) if name != "θ" else 1.0
        assert measurement(dim) * factor == pytest.approx(want[name], rel=1e-9), name
    if size == "A3":                    # a 1:n sheet: the factor is the scale, not 1
        assert drawn.scale > 1.0
    # each picture is replaced by its DIMENSION, not written twice
    written = {e.dxf.text for e in doc.modelspace().query("TEXT MTEXT")}
    assert not any(" = " in t and t.split(" = ")[0] in want for t in written)


# The speed of the A1 sheet each count's tool path is read from: the one another test of this
# file builds anyway (the dimensions at 40 r/min and 12 positions, the sheet checks at 60 r/min
# and 6 or 24). The mechanism's area does not depend on the speed: its items and placement were
# the same at 40 and 60 r/min for all twelve sheets of this test (compared once, by repr).
TOOL_PATH_RPM = {6: 60.0, 12: 40.0, 24: 60.0}


@pytest.mark.parametrize("count", [6, 12, 24])
@pytest.mark.parametrize("case", ["block", "rod", "K near 3", "long stroke"])
def test_tool_path_numbered_at_the_ram_positions(case, count):
    """Each number k (2.5 mm, in the mechanism's area) stands at the tick of position k on
    the tool path (x of the ram joint C at φ_k, plus the tool's offset), or is led there by
    a thin line from that tick (a number moved by 0.3 mm or less stands at it)."""
    design = design_of(case)
    drawn = drawn_sheet(case, TOOL_PATH_RPM[count], "A1", count)
    items = drawn.areas["mechanism"][1]
    phi = np.radians(np.arange(count) * 360.0 / count)
    ticks = drawn.placement(shape(design, phi).ram_joint.T)[:, 0] + mech.TOOL_AHEAD
    leaders = [np.asarray(p.points) for p in items if isinstance(p, Polyline) and p.layer == THIN
               and len(p.points) == 2]
    for k in range(1, count + 1):
        # a crank position's number (3.5 mm) may be drawn one standard height smaller, 2.5 mm,
        # where labels' placement found no room for it at 3.5: one of the 2.5 mm k's is the path's
        labels = [t for t in items if isinstance(t, Text) and t.height == 2.5 and t.text == str(k)]
        x = ticks[k - 1]
        assert any(abs(label.position[0] - x) <= 0.3 + 1e-9
                   or any(abs(seg[0, 0] - x) < 1e-6 and abs(seg[1, 0] - label.position[0]) < 1e-6
                          for seg in leaders) for label in labels), k


@pytest.mark.parametrize("count", [6, 12, 24])
def test_phi_axes_ticks_are_degrees_and_the_positions_are_numbered(count):
    """Under each φ/(°) axis the tick labels are the positions' angles in degrees (none a
    position number), and under the s axis a row numbers the same ticks 1 … N."""
    drawn = drawn_sheet("block", 40.0, "A1", count)
    items = drawn.areas["curves"][1]
    assert sum(isinstance(t, Text) and t.text == "φ/(°)" for t in items) == 3
    ticks = [p for p in items if isinstance(p, Polyline) and len(p.points) == 2
             and abs(p.points[0, 0] - p.points[1, 0]) < 1e-9
             and abs(abs(p.points[1, 1] - p.points[0, 1]) - 3.0) < 1e-9]
    rows: dict[float, list] = {}
    for tick in ticks:
        rows.setdefault(round(float(tick.points[:, 1].mean()), 6), []).append(float(tick.points[0, 0]))
    x_ticks = [sorted(xs) for xs in rows.values() if len(xs) == count]
    assert len(x_ticks) == 3                             # s, v and a
    degrees = [f"{round(k * 360.0 / count, 1):g}" for k in range(count)]
    small = [t for t in items if isinstance(t, Text) and t.height == 2.5 and t.align == "ct"]
    for xs in x_ticks:
        labelled = 0
        for k, x in enumerate(xs):
            # a degree the axis or a curve runs through under its tick stands 0.5 mm beside it
            # (charts.chart, labels' placement), "lt" right of it or "rt" left of it
            under = sorted((t for t in items if isinstance(t, Text) and t.height == 2.5
                            and ((abs(t.position[0] - x) < 1e-6 and t.align == "ct")
                                 or (t.align, round(t.position[0] - x, 6)) in (("lt", 0.5), ("rt", -0.5)))),
                           key=lambda t: -t.position[1])
            if under and under[0].position[1] > min(p.points[:, 1].min() for p in ticks
                                                     if abs(p.points[0, 0] - x) < 1e-9) - 6.0:
                assert under[0].text == degrees[k]
                labelled += 1
        assert labelled >= count // 2
    numbered = [t for t in items if isinstance(t, Text) and t.height == 2.5 and t.text == "Position"]
    assert len(numbered) == 1
    row = numbered[0].position[1]
    in_row = {t.text: t.position[0] for t in small if abs(t.position[1] - row) < 1e-6}
    s_ticks = max(x_ticks, key=lambda xs: max(p.points[:, 1].max() for p in ticks
                                              if abs(p.points[0, 0] - xs[0]) < 1e-9))
    for k in range(1, count + 1):
        if str(k) in in_row:
            assert in_row[str(k)] == pytest.approx(s_ticks[k - 1], abs=1e-6)
    assert len(in_row) >= count // 2


# A1 and A3: the paper the course uses and the most crowded one (A0 and A2 lie between;
# test_labels' random designs draw every paper). All four took 110 s of the suite.
@pytest.mark.parametrize("size", ["A1", "A3"])
@pytest.mark.parametrize("case", sorted(CASES))
def test_sheet_checks_hold_with_the_dimensions(case, size):
    for count in (6, 24):
        drawn = drawn_sheet(case, 60.0, size, count)        # the tool path test reads the A1 ones
        assert_laid_out(drawn.sheet, drawn.areas)


@pytest.mark.parametrize("size", ["A0", "A1", "A2"])
@pytest.mark.parametrize("case", ["block", "rod", "long stroke", "short crank"])
def test_dimension_texts_are_clear_of_every_line(case, size):
    """A local check (the sheet's own check compares texts with texts): no line of the
    mechanism's area runs through a dimension's text, in the text's own frame."""
    drawn = drawn_sheet(case, 40.0, size)
    segs = segments(drawn.areas["mechanism"][1])
    crossed = [dim.name for dim in drawn.dimensions if text_crossings(dim.text, segs)]
    assert crossed == []
