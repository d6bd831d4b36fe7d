"""Compare's legend fits the pane (issue 34 item 8): in English at 1366×768 the two
snapshot names sat on one row, 630 px wide in a 570 px pane, and the right plots were
cut. The legend now takes as many columns as the pane's width holds."""
from __future__ import annotations

import pytest
from PySide6.QtCore import QRectF

from shaperapp.compare.view import CompareView

from gui_helpers import shown


def scene_box(view, item) -> QRectF:
    return item.mapRectToScene(item.boundingRect())


@pytest.mark.parametrize("width", [530, 575])        # the tab's plots at 1280×720 and 1366×768
def test_long_names_wrap_and_every_plot_is_whole(qtbot, model, width):
    view = shown(qtbot, CompareView(model), width, 640)
    assert view.add_current()
    model.set_spec(time_ratio=1.6)
    assert view.add_current()
    qtbot.wait(20)
    plots = view.plots
    port = QRectF(plots.mapToScene(plots.viewport().rect()).boundingRect())
    labels = [label for _, label in plots._legend.items]
    assert len(labels) == 2 and all(len(label.text) > 30 for label in labels)
    for label in labels:
        box = scene_box(plots, label)
        assert port.left() <= box.left() and box.right() <= port.right(), (box, port)
    legend = scene_box(plots, plots._legend)
    for key in ("ram_x_mm", "ram_v_m_s", "ram_a_m_s2", "crank_torque_N_m"):
        box = plots.item(key).vb.sceneBoundingRect()
        assert port.contains(box), (key, box, port)
        assert box.top() >= legend.bottom() - 1, (key, box, legend)
    right = plots.item("ram_v_m_s").getAxis("bottom")   # its tick labels too, not only the box
    assert port.contains(right.sceneBoundingRect()), (right.sceneBoundingRect(), port)


def test_short_names_share_a_row_in_a_wide_pane(qtbot, model, tmp_path):
    view = shown(qtbot, CompareView(model), 1200, 640)
    assert view.add_current()
    model.set_spec(time_ratio=1.6)
    assert view.add_current()
    qtbot.wait(20)
    assert view.plots.legend_columns() == 2
    view.resize(520, 640)
    qtbot.wait(20)
    assert view.plots.legend_columns() == 1


def test_empty_plots_span_the_cycle_and_show_no_values(qtbot, model):
    """With no design to compare, the plots span the crank's cycle, 0 to 360°, and their
    value axes show no numbers (pyqtgraph's 0 to 1 read as an x of 0.2 mm); the first
    comparison brings the values and its own ranges."""
    view = shown(qtbot, CompareView(model), 575, 640)
    plots = view.plots
    keys = ("ram_x_mm", "ram_v_m_s", "ram_a_m_s2", "crank_torque_N_m")
    for key in keys:
        low, high = plots.item(key).vb.viewRange()[0]
        assert low <= 0.0 and high >= 360.0 and high - low < 400.0, (key, low, high)
        assert plots.item(key).getAxis("left").style["showValues"] is False
    assert view.add_current()
    model.set_spec(time_ratio=1.6)
    assert view.add_current()
    qtbot.wait(20)
    for key in keys[:3]:
        assert plots.item(key).getAxis("left").style["showValues"] is True
    assert plots.item("ram_x_mm").vb.viewRange()[1][1] > 250.0       # the stroke, 300 mm
