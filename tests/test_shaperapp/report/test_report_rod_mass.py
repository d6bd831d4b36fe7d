"""The report's loads name the rod's mass m₅ with its index as a subscript, as the other
symbols of the task book's numbering (G₄, J_S4, G₆): "Rod mass m5" printed m5 flat."""
from __future__ import annotations

import pytest

from core.forces.masses import MassProperties
from core.linkage.spec import Spec
from shaperapp.widgets.notation import typeset
from shaperapp.report.design_data import load_rows
from shaperapp.widgets import i18n


@pytest.mark.parametrize("language, words", [("en", "Rod mass "), ("zh_CN", "连杆质量 ")])
def test_the_rod_mass_is_m_with_5_below(qapp, language, words):
    design = Spec(variant="rod", rod_input="ratio", rod_ratio=0.3).design()
    masses = MassProperties(lever_mass_kg=20.0, ram_mass_kg=70.0, rod_mass_kg=5.0)
    i18n.set_language(language)
    try:
        labels = [typeset(label) for label, _ in load_rows(masses, design)]
    finally:
        i18n.set_language("en")
    assert f"{words}m<sub>5</sub>" in labels, labels
