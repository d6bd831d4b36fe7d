"""Chinese wording that read badly (issue 34 item 8): the special positions of the cut
said "切削开始（切削中）", the bracket repeating the name instead of saying what the
row holds (the cutting force acts there)."""
from __future__ import annotations

import pytest

from shaperapp.widgets import i18n
from shaperapp.widgets.column_titles import special_titles


@pytest.fixture
def chinese(qapp):
    i18n.set_language("zh_CN")
    yield
    i18n.set_language("en")


@pytest.mark.parametrize("key,name", [("cut_start", "切削开始"), ("cut_end", "切削结束")])
def test_the_cut_positions_say_the_force_acts(chinese, key, name):
    title = special_titles()[key]
    head, _, note = title.partition("（")
    assert head == name, title
    assert "切削力" in note and "切削中" not in note, title
