"""The kinetostatic sheet of a design with zero or partial loads (issue 33, item 1): a
sheet with the arrows that exist, none for a zero force, every arrow its force over μF."""
import math

import pytest

from core.drawing.forces import forces_sheet, joint_forces
from core.drawing.sheet import paper
from core.forces.masses import MassProperties
from core.linkage.geometry import synthesize
from sheet_checks import assert_laid_out

BLOCK = synthesize(100.0, 1.4, 300.0)
ROD = synthesize(100.0, 1.46, 312.0, rod_ratio=0.3)


@pytest.mark.parametrize("design", [BLOCK, ROD], ids=["block", "rod"])
@pytest.mark.parametrize("gravity", [True, False])
def test_zero_loads_give_a_sheet_without_arrows(design, gravity):
    """No mass and no cutting force: every joint force is 0, so nothing is drawn as an arrow
    (it crashed on the largest of no forces), and the sheet is still laid out."""
    drawn = forces_sheet(design, 40.0, MassProperties(gravity=gravity), paper("A2"))
    assert drawn.arrows == {}
    assert_laid_out(drawn.sheet, drawn.areas)


@pytest.mark.parametrize("design", [BLOCK, ROD], ids=["block", "rod"])
def test_partial_loads_draw_exactly_the_nonzero_forces_to_scale(design):
    """The cutting force alone: at the return-stroke position no force acts (it crashed
    there), at the working-stroke one the cut's. Each arrow drawn is a force of joint_forces,
    tail to head = force / μF, and every force of joint_forces that is not 0 has its arrow."""
    masses = MassProperties(cut_force_N=7000.0, gravity=False)
    drawn = forces_sheet(design, 40.0, masses, paper("A1"))
    counts = []
    for k, angle in enumerate(drawn.diagram_deg):
        forces = {name: f for name, _, f in joint_forces(design, 40.0, masses, angle)}
        assert {name for (i, name) in drawn.arrows if i == k} == set(forces)
        for name, force in forces.items():
            tail, head = drawn.arrows[(k, name)]
            assert math.dist(tail, head) == pytest.approx(math.hypot(*force) / drawn.force_scales[k],
                                                          rel=1e-9)
        counts.append(len(forces))
    assert counts[0] > 0 and counts[1] == 0      # cutting in the first, returning in the second


def test_zero_loads_are_drawn_at_unit_scales_not_at_round_off():
    """Nothing to draw has no scale of its own: the polygons and the torque and energy
    charts take 1 per mm, as the mechanism's μF does, instead of a μ of 8e-15 N/mm from the
    floor that keeps a line-shaped polygon's width from being 0."""
    drawn = forces_sheet(BLOCK, 40.0, MassProperties(gravity=False), paper("A2"))
    assert drawn.force_scales == (1.0, 1.0)
    assert drawn.polygon_scales == (1.0, 1.0, 1.0, 1.0)
    assert drawn.torque_chart[0] == 1.0 and drawn.energy_chart[0] == 1.0
    assert_laid_out(drawn.sheet, drawn.areas)
