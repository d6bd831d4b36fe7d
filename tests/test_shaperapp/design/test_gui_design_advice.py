"""The design form's refusals that name a bound, followed as the form shows them: the bound
typed into the marked field is taken (the chord rule's guide: the stroke or the lever named,
not the guide, which the rule sets; 409f94c marked the guide and said only 'must be more
than L2 + L1', and the stroke it named before that left the guide low)."""
from __future__ import annotations

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
