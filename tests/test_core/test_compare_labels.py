"""The inputs that tell a design from the others compared (issue 34, item 7): a label made
of them never reads the same for two designs that differ in a number they use."""
from dataclasses import replace

from core.space.compare import distinguishing_inputs
from core.linkage.spec import Spec


def test_synthesis_names_k_and_what_differs():
    base = Spec(time_ratio=1.4)
    assert distinguishing_inputs(base, []) == "K 1.4"
    assert distinguishing_inputs(replace(base, crank=90.0), [base]) == "K 1.4, L1 90 mm"
    assert distinguishing_inputs(replace(base, stroke=320.0), [base, Spec(time_ratio=1.6)]) \
        == "K 1.4, H 320 mm"


def test_dimensions_and_rod_inputs():
    dims = Spec(mode="dimensions", crank=100.0, frame=380.0, lever=600.0)
    assert distinguishing_inputs(dims, [replace(dims, frame=400.0)]) == "L1 100 mm, L2 380 mm"
    rod = replace(dims, variant="rod", rod_ratio=0.35)
    # the block design has no rod: the rod's input tells them apart
    assert distinguishing_inputs(rod, [dims]) == "L1 100 mm, L4/L3 0.35"
    assert distinguishing_inputs(replace(dims, guide_rule="height", guide_height=470.0), [dims]) \
        == "L1 100 mm, guide 470 mm"


def test_choices_that_numbers_do_not_show():
    from core.space.compare import Candidate, distinguishing_choices
    from core.forces.masses import MassProperties
    rod = Spec(variant="rod", guide_rule="sagitta")
    leading = replace(rod, rod_side="leading")
    chord = replace(rod, guide_rule="chord")
    assert distinguishing_inputs(leading, [rod]) == distinguishing_inputs(rod, [leading])
    assert distinguishing_choices(Candidate("", leading), [Candidate("", rod)]) == ("leading",)
    assert distinguishing_choices(Candidate("", chord), [Candidate("", rod)]) == ("chord",)
    heavy = Candidate("", rod, MassProperties(ram_mass_kg=90.0))
    assert distinguishing_choices(heavy, [Candidate("", rod, MassProperties())]) == ("loads",)
    assert distinguishing_choices(Candidate("", rod), [Candidate("", rod)]) == ()
