"""Compare's plots keep their y tick labels on a laptop (issue 34, every view readable at
1280×720): in Chinese with two entries the row of the speed and the exports took 30 px
and left the ram acceleration plot 71 px tall, with the single y tick label "0". The
speed now stands under the list and the exports beside the entry buttons.

The window is the size it takes on those screens (as in test_gui_stack_on_screen)."""
from __future__ import annotations

import pytest

from gui_helpers import main_window
from layout_probe import drawn_ticks

PLOTS = ("ram_x_mm", "ram_v_m_s", "ram_a_m_s2", "crank_torque_N_m")


def labelled_ticks(axis) -> list[str]:
    """The tick label texts the axis draws at its present size."""
    return [text for _, text in drawn_ticks(axis)]


@pytest.mark.parametrize("lang", ["en", "zh_CN"])
def test_every_plot_keeps_two_y_labels_at_1280x720(qtbot, qapp, tmp_path, lang):
    with main_window(tmp_path) as win:
        win.resize(1268, 672)
        qtbot.waitExposed(win)
        win.set_language(lang)
        win.tabs.setCurrentWidget(win.compare)
        view = win.compare
        assert view.add_current()
        win.model.set_spec(time_ratio=1.6)
        assert view.add_current()
        qtbot.wait(30)
        for key in PLOTS:
            labels = labelled_ticks(view.plots.item(key).getAxis("left"))
            assert len(labels) >= 2, (key, labels, view.plots.item(key).vb.height())
        # the table still shows two whole rows, and the list both entries
        table = view.table
        assert table.rowCount() > 2
        assert table.viewport().height() >= 2 * table.rowHeight(0), table.viewport().height()
        assert view.list.viewport().height() >= 2 * view.list.sizeHintForRow(0)
