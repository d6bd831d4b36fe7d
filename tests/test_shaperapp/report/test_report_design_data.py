"""The report's design data lists the loads as the task book states them, the cam's and the
gear's inputs (issue 40 item 3), and section 7 states the flywheel with the rotating parts
(issue 41 item 2). Read from the report's blocks, the values checked against the inputs."""
from __future__ import annotations

import pytest

from core.cam import CamInputs
from core.forces.masses import MassProperties
from core.forces.flywheel import summarize
from core.gear import GearPairInputs
from core.linkage.spec import Spec
from shaperapp.report.blocks import KeyValues, Paragraph, Table
from shaperapp.report.content import Options, build

pytestmark = pytest.mark.slow
LOADS = MassProperties(lever_weight_N=200.0, lever_inertia_kg_m2=1.1, ram_weight_N=700.0,
                       ram_cg_mm=(-12.0, 30.0), cut_force_N=7000.0, cut_height_mm=80.0,
                       rotors=((0.5, 1.0), (0.02, 15.0)), guide_length_mm=450.0)


@pytest.fixture(scope="module")
def report(qapp):
    return build(Spec(), [60.0], LOADS, "Data", "2026-01-01", "en",
                 Options(cam=(CamInputs(arm_mm=120.0), 30.0), gear=GearPairInputs(z1=17, z2=68, module_mm=4.0)))


def test_design_inputs_hold_the_loads_the_cam_and_the_gear(report):
    inputs = dict(next(b for b in report.blocks if isinstance(b, KeyValues)).rows)
    assert inputs["Lever weight G_4"] == "200 N"
    assert inputs["Ram weight G_6 (with the tool)"] == "700 N"
    assert inputs["Lever inertia J_S4 (about S_4)"] == "1.1 kg·m²"
    assert inputs["Ram centre of mass x_S6, y_S6 (from C, x along the cut, y up)"] == "-12 mm, 30 mm"
    assert inputs["Ram guide length"] == "450 mm"
    assert inputs["Other rotating parts (J, speed)"] == "J = 0.5 kg·m² at 1·ω2; J = 0.02 kg·m² at 15·ω2"
    assert inputs["Cam: follower arm l, swing ψmax"] == f"120 mm, {CamInputs().program.swing_deg:g}°"
    assert inputs["Cam: allowed pressure angle, rise / return"] == "40° / 70°"
    assert inputs["Cam: rise at crank angle"] == "30°"
    assert inputs["Gears: teeth z_1, z_2, module m"] == "17, 68, 4 mm"


def test_section_7_states_the_flywheel_less_the_rotating_parts(report):
    texts = [b.html for b in report.blocks if isinstance(b, Paragraph)]
    assert any("J<sub>c</sub> = Σ J<sub>i</sub>·(ω<sub>i</sub>/ω<sub>2</sub>)<sup>2</sup>" in t for t in texts)
    table = next(b for b in report.blocks if isinstance(b, Table)
                 and b.caption == "Torque, power and flywheel per crank speed")
    rows = {row[0]: row[1] for row in table.rows}
    s = summarize(Spec().design(), [60.0], LOADS).speeds[0]
    assert rows["Rotating parts at the crank J_c"] == "5.000 kg·m²"     # 4 significant digits
    assert rows["Flywheel needed J_F − J_c"] == f"{s.flywheel_inertia_kg_m2 - 5.0:.4g} kg·m²"
