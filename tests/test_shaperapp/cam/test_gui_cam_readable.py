"""The Cam tab readable in a narrow pane, in Chinese (issue 34 item 8): at 1280 × 720 the
four plots got 60 px of δ each and their labels ran together ("100200300"), the
two-word Chinese y titles were cut, and the line over the cam lost its ψ at the right."""
from __future__ import annotations

import math

import pytest
from PySide6.QtCore import QRectF
from PySide6.QtGui import QImage

from shaperapp.cam.model import CamModel
from shaperapp.cam.plots import CamPlots
from shaperapp.cam.profile_view import CamProfileView
from shaperapp.widgets import i18n

from gui_helpers import shown
from layout_checks import overlap
from layout_probe import tick_labels
from paint_recorder import PaintRecorder


@pytest.fixture
def chinese(qapp):
    i18n.set_language("zh_CN")
    yield
    i18n.set_language("en")


def spread(boxes):
    return not any(overlap(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1:])


@pytest.mark.parametrize("width", [260, 520])
def test_plots_keep_three_labels_apart_and_titles_off_them(qtbot, chinese, model, width):
    cam_model = CamModel(model)
    cam_model.set_active(True)
    model.set_rpms([20.0 + 5.0 * i for i in range(16)])
    plots = shown(qtbot, CamPlots(cam_model), width, 260)       # the pane at 1280 × 720: 260 px
    plots.retranslate()
    # pyqtgraph fits y at its next paint, and the axes follow on a zero timer: a fixed 100 ms
    # ended before that chain on a loaded machine. Wait until every plot has y labels and
    # the axes are as wide as they need, then a while for any further change.
    def fitted() -> bool:
        axes = [plot.getAxis("left") for plot in plots.plots]
        width = max(math.ceil(axis.needed_width()) for axis in axes)
        return all(len(tick_labels(axis)) >= 3 and axis.fixedWidth == width for axis in axes)
    qtbot.waitUntil(fitted, timeout=10_000)
    qtbot.wait(100)
    for plot in plots.plots:
        bottom, left = plot.getAxis("bottom"), plot.getAxis("left")
        x_ticks, y_ticks = tick_labels(bottom), tick_labels(left)
        assert len(x_ticks) >= 3 and spread(x_ticks), x_ticks           # 0 labels before
        assert len(y_ticks) >= 3 and spread(y_ticks), y_ticks
        title = left.label.sceneBoundingRect()
        title_box = [title.x(), title.y(), title.width(), title.height()]
        assert not [t for t in y_ticks if overlap(title_box, t)], (left.label.toPlainText(), left.fixedWidth, left.needed_width(), title_box, left.range)
        view = plot.getPlotItem().vb.sceneBoundingRect()
        assert title.height() <= view.height() + 2, left.label.toPlainText()   # not cut at its ends


def test_the_line_over_the_cam_is_never_cut(qtbot, chinese, model):
    cam_model = CamModel(model)
    cam_model.set_active(True)
    view = shown(qtbot, CamProfileView(cam_model), 240, 300)
    image = QImage(240, 300, QImage.Format.Format_ARGB32)
    painter = PaintRecorder(image)
    view.render_cam(painter, QRectF(0, 0, 240, 300))
    painter.end()
    heads = [(text, box) for text, box in painter.texts if "δ" in text]
    assert heads and "ψ" in heads[0][0]
    box = heads[0][1]
    assert box.left() >= 0 and box.right() <= 240, box                   # ran out at the right
