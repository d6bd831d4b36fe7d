"""The design form's refusals that name a bound, followed as the form shows them: the bound
typed into the marked field is taken (the chord rule's guide: the stroke or the lever named,
not the guide, which the rule sets; 409f94c marked the guide and said only 'must be more
than L2 + L1', and the stroke it named before that left the guide low)."""
from __future__ import annotations

import math
import re

import pytest

from test_gui_inputs import setup, type_text  # noqa: F401  (the form's fixture)


@pytest.mark.parametrize("mode, typed, field", [
    ("synthesis", {"crank": "200", "time_ratio": "1.4", "stroke": "300"}, "stroke"),
    ("dimensions", {"crank": "100", "frame": "300", "lever": "390"}, "lever"),
])
def test_a_guide_the_rule_places_too_low_names_the_length_to_type(setup, mode, typed, field):
    model, form, _ = setup
    if mode == "dimensions":
        form._dims_radio.click()
    for name, text in typed.items():
        type_text(form, name, text)
    assert form.marked_fields() == [field], form.error_text()
    bound = re.search(r"must be more than (\S+) mm", form.error_text()).group(1)
    type_text(form, field, bound)
    assert model.error is None and form.marked_fields() == []
    design = model.design
    assert design.guide > design.frame + design.crank


def _choose(form, name, value):
    combo = form._combo(name)
    combo.setCurrentIndex(combo.findData(value))


@pytest.mark.parametrize("ratio", ["0.034", "0.035"])
def test_a_rod_given_as_l4_l3_at_a_dead_centre_is_told_the_ratio_that_clears_it(setup, ratio):
    """The dead centre's least rod, for a rod given as L4/L3, as a ratio (rounded up, 4 digits)
    in the ratio's own field; typed there, it is taken. 1de6048 said 'lengthen the rod or move
    the guide line', no amount."""
    model, form, _ = setup
    _choose(form, "variant", "rod")
    _choose(form, "guide_rule", "height")
    _choose(form, "rod_input", "ratio")
    type_text(form, "guide_height", "579.5")          # just below the tip's top, 579.555 mm
    type_text(form, "rod_ratio", ratio)
    assert form.marked_fields() == ["rod_ratio"], form.error_text()
    text = form.error_text()
    assert "mm" not in text
    bound = re.search(r"raise L4/L3 to at least (\S+) or move the guide line", text).group(1)
    assert float(bound) > float(ratio)
    type_text(form, "rod_ratio", bound)
    assert model.error is None and form.marked_fields() == []


@pytest.mark.parametrize("lever, guide", [("350", "350"), ("500", "600")])
def test_a_block_lever_and_guide_followed_in_the_form_give_a_design(setup, lever, guide):
    """The block variant in 'Direct dimensions', L2 + L1 = 400 mm: the refusals followed in
    the form, each bound typed into the field it marks (a strict one 0.1 mm past it), end in
    a design. 1de6048 marked the guide for ever: 'more than 400 mm', then 'at most the lever
    length 400 mm'."""
    model, form, _ = setup
    form._dims_radio.click()
    _choose(form, "guide_rule", "height")
    for name, text in (("crank", "100"), ("frame", "300"), ("lever", lever), ("guide_height", guide)):
        type_text(form, name, text)
    for _ in range(3):
        if model.error is None:
            break
        [field] = form.marked_fields()
        bound = re.search(r"must be more than (?:L2 \+ L1 = )?(\S+) mm", form.error_text()).group(1)
        type_text(form, field, f"{float(bound) + 0.1:g}")
    assert model.error is None and form.marked_fields() == []
    assert model.design.frame + model.design.crank < model.design.guide <= model.design.lever


def test_a_rod_given_as_l4_l3_too_short_to_reach_the_guide_is_told_a_ratio_that_reaches_it(setup):
    """The reach's bound as L4/L3, rounded up: 1de6048 rounded it to nearest, 'more than 0.03407'
    for the default design (the least is 0.0340742), and 0.03407 typed just past was refused
    again."""
    model, form, _ = setup
    _choose(form, "variant", "rod")
    _choose(form, "rod_input", "ratio")
    type_text(form, "rod_ratio", "0.01")
    bound = re.search(r"must be more than (\S+) to reach the guide line", form.error_text()).group(1)
    assert bound == "0.03408"
    type_text(form, "rod_ratio", repr(math.nextafter(float(bound), 1.0)))
    assert model.error is None and form.marked_fields() == []
