"""A saved gear pair that core cannot make gets one paragraph in the report saying why, in
the report's language: the Chinese report printed core's English refusal
("无法设计该齿轮副：centre = 200: makes the tip of gear 1 pointed …") and so did the drawing
dialog's tooltip, since only the Gear tab knew the gear's refusals."""
from __future__ import annotations

import re

import pytest

from core.base.errors import DesignError
from core.gear import design_pair
from core.gear.file import gear_from_dict
from shaperapp.report.blocks import Paragraph
from shaperapp.report.gear import gear_blocks
from shaperapp.widgets import i18n

from language_checks import english_words

# Valid inputs (the file reader takes them) whose shifts make the pinion's tip pointed.
POINTED = {"z1": 13, "z2": 40, "module_mm": 6, "centre_mm": 200}


@pytest.fixture
def chinese(qapp):
    i18n.set_language("zh_CN")
    yield
    i18n.set_language("en")


def _paragraphs(blocks) -> str:
    return " ".join(re.sub(r"<[^>]+>", "", b.html) for b in blocks if isinstance(b, Paragraph))


def test_the_refusal_is_core_s_and_is_said_in_chinese(chinese):
    inputs = gear_from_dict(POINTED)
    with pytest.raises(DesignError):              # the case is one core refuses
        design_pair(inputs)
    text = _paragraphs(gear_blocks(inputs, 9, "zh_CN"))
    assert "0.2396" in text                        # the refusal's number is there
    assert english_words(text, {"x1"}) == []


def test_the_refusal_in_english_is_core_s_own(qapp):
    inputs = gear_from_dict(POINTED)
    with pytest.raises(DesignError) as refused:
        design_pair(inputs)
    text = _paragraphs(gear_blocks(inputs, 9, "en"))
    assert "makes the tip of gear 1 pointed (x = 0.2396)" in text
    advice = re.search(r"give a′ ≤ \S+ mm, for a tip at least 1\.5 mm thick", str(refused.value))
    assert advice and advice.group(0) in text          # the value is tested in test_gear_amounts
