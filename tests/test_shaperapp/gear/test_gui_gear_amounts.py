"""The Gear tab shows each failing check's advice and a pointed tip's refusal with the value
to type (core.gear.amounts), in English as core words it and in Chinese with the same
numbers and no English; a value typed as the tab prints it makes the check pass there.
(1de6048 showed 'a smaller a′', 'give a smaller centre distance': no number to type.)"""
from __future__ import annotations

import re

import pytest
from PySide6.QtGui import QTextDocument

from core.base.errors import DesignError
from core.gear import design_pair, pair_checks
from shaperapp.gear.tab import GearTab
from shaperapp.widgets import i18n

from gui_helpers import shown
from language_checks import english_words

A_PRIME = re.compile(r"a′ (?:to )?≤ (\d+\.\d+) mm")


@pytest.fixture(params=["en", "zh_CN"])
def language(request, qapp):
    i18n.set_language(request.param)
    yield request.param
    i18n.set_language("en")


def plain(html: str) -> str:
    page = QTextDocument()
    page.setHtml(html)
    return page.toPlainText()


def test_a_failing_check_shows_the_value_and_typing_it_passes(qtbot, model, language):
    tab = shown(qtbot, GearTab(model), 1000, 650)
    gm = tab.gear_model
    gm.set_fields(mode="centre", centre=170.0)              # z 13/40, m 6: ε and gear 2's root fail
    failing = {c.name: c for c in pair_checks(gm.pair) if not c.ok}
    assert set(failing) == {"contact", "interference2"}
    shown_text = plain(tab.results.checks.text())
    contact = failing["contact"]
    bound = contact.moves[0].to[0]                          # 'lower a′ to ≤ V mm', designed by core
    assert contact.moves[0].name == "centre" and bound in shown_text
    if language == "en":
        assert contact.advice in shown_text
    else:
        assert f"将 a′ 减小到 ≤ {bound} mm" in shown_text
        assert [w for w in english_words(shown_text, {"zmin"})] == []
    typed = float(A_PRIME.search(contact.advice).group(1))
    gm.set_fields(centre=typed)                             # typed as printed
    assert {c.name: c for c in pair_checks(gm.pair)}["contact"].ok
    assert "✗ " + ("Contact ratio" if language == "en" else "重合度") not in plain(tab.results.checks.text())


def test_a_pointed_tip_is_refused_with_the_centre_distance_that_mends_it(qtbot, model, language):
    tab = shown(qtbot, GearTab(model), 1000, 650)
    gm = tab.gear_model
    gm.set_fields(mode="centre", centre=200.0)
    with pytest.raises(DesignError) as refused:
        design_pair(gm.pair.inputs.__class__(z1=13, z2=40, module_mm=6.0, centre_mm=200.0))
    bound = A_PRIME.search(refused.value.allowed).group(1)
    text = tab.form.error_label.text()
    assert tab.form.error_label.isVisible()
    if language == "en":
        assert f"give a′ ≤ {bound} mm, for a tip at least 1.5 mm thick" in text
    else:
        assert f"请取 a′ ≤ {bound} mm，使齿顶厚不小于 1.5 mm" in text
        assert english_words(text, {"zmin"}) == []
    gm.set_fields(centre=float(bound))
    assert not tab.form.error_label.isVisible()
    assert {c.name: c for c in pair_checks(gm.pair)}["tip1"].ok
