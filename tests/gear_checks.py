"""What the Gear tab shows, read back: its tables' cells, and checks that the tables are a
given pair (core's) and that the shift fields its mode does not use (greyed) read that
pair. Shared by the Gear tab's tests and the GUI fuzz."""
from __future__ import annotations

import math

import pytest


def cells(table):
    return {table.verticalHeaderItem(r).text(): [table.item(r, c).text() for c in range(table.columnCount())]
            for r in range(table.rowCount())}


def assert_table_is(tab, want):
    gears, pair = cells(tab.results.gears), cells(tab.results.pair)
    for g, col in ((want.gear1, 0), (want.gear2, 1)):
        assert float(gears["z"][col]) == g.teeth
        assert float(gears["x"][col]) == pytest.approx(g.shift, abs=5e-7)
        assert float(gears["da, mm"][col]) == pytest.approx(2 * g.ra, abs=5e-5)
        assert float(gears["df, mm"][col]) == pytest.approx(2 * g.rf, abs=5e-5)
        assert float(gears["d′, mm"][col]) == pytest.approx(2 * g.rw, abs=5e-5)
        assert float(gears["sa, mm"][col]) == pytest.approx(g.sa, abs=5e-5)
    assert float(pair["a′, mm"][0]) == pytest.approx(want.centre_mm, abs=5e-5)
    assert float(pair["α′, °"][0]) == pytest.approx(math.degrees(want.alpha_w), abs=5e-7)
    assert float(pair["ε"][0]) == pytest.approx(want.contact_ratio, abs=5e-7)


def table_shift(tab, col):
    rows = [tab.results.gears.verticalHeaderItem(r).text() for r in range(tab.results.gears.rowCount())]
    return float(tab.results.gears.item(rows.index("x"), col).text())


def assert_fields_follow(tab, want):
    """The greyed fields read (to their 7 digits) the pair the table shows, which is ``want``."""
    f = tab.form.fields
    assert table_shift(tab, 0) == pytest.approx(want.gear1.shift, abs=5e-7)
    assert table_shift(tab, 1) == pytest.approx(want.gear2.shift, abs=5e-7)
    for name, value in (("x1", want.gear1.shift), ("x2", want.gear2.shift), ("centre", want.centre_mm)):
        if f[name].isEnabled():
            continue                                     # typed: shows what was typed
        assert float(f[name].edit.text()) == pytest.approx(value, rel=1e-6, abs=1e-6), name
        assert float(f[name].edit.toolTip()) == value, name
