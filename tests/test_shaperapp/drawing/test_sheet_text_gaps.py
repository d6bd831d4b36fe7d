"""The Chinese sheets keep their texts a word space apart too (the A3 motion sheet's
"105120135…" in any language): the task book's data sets 方案 I–III (孙桓《机械原理》
课程设计指导书, as tests/test_shaperapp/course/test_class_command.py enters them) and the
crowded K = 2.9 design on A3, each content in Chinese, laid out as every sheet
(tests/sheet_checks.assert_laid_out: no two texts crowded, no caption cut short).
The English sheets of the same kinds are swept in tests/test_core/drawing."""
import pytest

from sheet_checks import assert_laid_out

# (L1, L2, L3, rod ratio, n r/min, G4 N, J_S4 kg·m², G6 N, P N, y_P mm)
CLASSIC = {"I": (110, 380, 540, 0.25, 60, 200, 1.1, 700, 7000, 80),
           "II": (90, 350, 580, 0.3, 64, 220, 1.2, 800, 9000, 80),
           "III": (110, 430, 810, 0.36, 72, 220, 1.2, 620, 8000, 100)}


def classic(name: str):
    from core.forces.masses import MassProperties, masses_for_design
    from core.linkage.geometry import from_dimensions
    l1, l2, l3, rod, n, g4, j4, g6, p, yp = CLASSIC[name]
    design = from_dimensions(l1, l2, l3, rod_ratio=rod)
    loads = MassProperties(lever_mass_kg=g4 / 9.81, lever_inertia_kg_m2=j4, ram_mass_kg=g6 / 9.81,
                           cut_force_N=p, cut_height_mm=yp, rod_mass_kg=8.0)
    return design, float(n), masses_for_design(design, loads)


@pytest.fixture(scope="module")
def chinese(qapp):
    from shaperapp.widgets import i18n
    assert i18n.set_language("zh_CN")
    yield
    i18n.set_language("en")


@pytest.mark.parametrize("name, count", [("I", 36), ("K 2.9", 24)])
def test_the_chinese_a3_motion_sheets(chinese, name, count):
    from core.drawing.motion import motion_sheet
    from core.drawing.sheet import paper
    from core.linkage.geometry import synthesize
    from shaperapp.drawing.labels import motion_labels
    design, rpm = ((synthesize(100.0, 2.9, 600.0, rod_ratio=0.5), 40.0) if name == "K 2.9"
                   else classic(name)[:2])
    drawn = motion_sheet(design, rpm, paper("A3"), count=count, labels=motion_labels())
    assert_laid_out(drawn.sheet, drawn.areas)


def test_the_chinese_a3_kinetostatic_sheet(chinese):
    from core.drawing.forces import forces_sheet
    from core.drawing.sheet import paper
    from shaperapp.drawing.forces_labels import forces_labels
    design, rpm, masses = classic("II")
    drawn = forces_sheet(design, rpm, masses, paper("A3"), labels=forces_labels())
    assert_laid_out(drawn.sheet, drawn.areas)


def test_the_chinese_a3_cam_sheet(chinese):
    """A rise of 110° and an outer dwell of 24°: the phase edges 110° and 134° stood 0.9 mm
    apart (their 8 mm rule measured by an estimate of the chart's φ scale)."""
    from core.cam import CamInputs, Program, design_cam
    from core.drawing.cam_sheet import cam_sheet
    from core.drawing.sheet import paper
    from shaperapp.drawing.cam_labels import cam_labels
    design, rpm, _ = classic("III")
    cam = design_cam(CamInputs(125.0, Program(15.0, 110.0, 24.0, 60.0, "sine", "sine")), design)
    drawn = cam_sheet(cam, rpm, paper("A3"), labels=cam_labels())
    assert_laid_out(drawn.sheet, drawn.areas)
