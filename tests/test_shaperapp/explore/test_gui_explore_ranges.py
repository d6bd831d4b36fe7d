"""A map over a range of one value (both ends typed alike) is refused with a line saying so,
and the map shown stays. It computed 40 × 40 designs, said "1600 of 1600 designs are valid",
and drew no cell: an image of zero height under the axes of the map before."""
from __future__ import annotations

import pytest

from shaperapp.widgets import i18n


@pytest.mark.parametrize("lang", ["en", "zh_CN"])
def test_a_range_of_one_value_maps_nothing_and_says_so(qtbot, view, lang):
    qtbot.waitUntil(lambda: view.result is not None and view.runner.job is None, timeout=20_000)
    i18n.set_language(lang)
    before = view.result
    view.lows[1].setValue(520.0)
    view.highs[1].setValue(520.0)
    view.start_map()
    assert view.runner.job is None and view.result is before
    assert view.status.text() == view.tr("Give each axis a range with two different ends.")
    if lang == "zh_CN":
        assert "两个不同的端值" in view.status.text()
