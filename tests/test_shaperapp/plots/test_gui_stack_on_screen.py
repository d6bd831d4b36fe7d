"""Every kinematics plot and the lowest one's x tick labels on screen on a laptop (issue 34
item 8): with 16 speeds the legend took 4 rows (5 in time mode) above the plots, and the
acceleration plot fell below the pane at 1280 × 720 (at 1366 × 768 its x tick labels did).
The stack scrolled instead of showing it. Now a legend that would push a plot out of the
pane stands beside the plots, and a long y title breaks into lines instead of making its
plot taller.

The window is the size it takes on those screens (the layout probe's frame: 1268 × 672 and
1354 × 720 px inside it), so the docks take their default sizes."""
from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QRect, QRectF

from shaperapp.plots.kinematics import ANGLE, TIME

from gui_helpers import main_window
from layout_probe import drawn_ticks

SIXTEEN = [20.0 + 5.0 * i for i in range(16)]
WINDOWS = {"1280x720": (1268, 672), "1366x768": (1354, 720)}


@pytest.fixture(scope="module", params=list(WINDOWS))
def window(request, qapp, tmp_path_factory):
    """One window of each size for the module's cases (a window takes 1.5 s to make)."""
    with main_window(tmp_path_factory.mktemp("stack")) as win:
        win.resize(*WINDOWS[request.param])
        yield win


def tick_boxes(axis) -> list[QRectF]:
    """The boxes (scene px) of the tick labels the axis draws now."""
    return [axis.mapRectToScene(rect) for rect, _ in drawn_ticks(axis)]


def on_screen(stack, window, box: QRectF) -> bool:
    """Whether a scene box of the stack lies in the part of its scroll area shown, and
    so in the window."""
    view, port = stack._view, stack._scroll.viewport()
    shown = QRect(port.mapTo(window, QPoint(0, 0)), port.size())
    top_left = view.mapTo(window, view.mapFromScene(box.topLeft()))
    bottom_right = view.mapTo(window, view.mapFromScene(box.bottomRight()))
    return (shown.contains(top_left) and shown.contains(bottom_right)
            and window.rect().contains(QRect(top_left, bottom_right)))


@pytest.mark.parametrize("lang", ["en", "zh_CN"])
@pytest.mark.parametrize("speeds", [[40.0], SIXTEEN], ids=["1 speed", "16 speeds"])
def test_every_plot_and_the_x_ticks_on_screen(qtbot, window, lang, speeds):
    qtbot.waitExposed(window)
    window.set_language(lang)
    window.model.set_rpms(speeds)
    view = window.plots
    stack = view._stack
    for mode in (ANGLE, TIME):
        view.set_x_mode(mode)
        qtbot.wait(20)
        stack.ensure_current()
        plots = [stack._plots[s.key].item for s in stack._series if stack.plot_visible(s.key)]
        assert len(plots) == 3
        for item in plots:
            assert on_screen(stack, window, item.vb.sceneBoundingRect()), (mode, item.vb.sceneBoundingRect())
        ticks = tick_boxes(plots[-1].getAxis("bottom"))
        assert len(ticks) >= 3, mode
        cut = [box for box in ticks if not on_screen(stack, window, box)]
        assert cut == [], (mode, cut)
        # the legend shows every speed, whole, and covers no plot
        legend = stack.legend("main")
        assert len(legend.names()) == len(speeds) + (2 if mode == TIME else 0)
        head = legend.head.sceneBoundingRect()
        assert on_screen(stack, window, head), (mode, head)
        assert not [item for item in plots if item.sceneBoundingRect().intersects(head)], mode


@pytest.mark.parametrize("lang", ["en", "zh_CN"])
def test_forces_legends_beside_with_sixteen_speeds(qtbot, window, lang):
    """Issue 40: the Forces tab's four plots with 16 speeds. In Chinese their longer y titles
    make them taller than the pane with the legends above (they stayed above, and the
    joint-force plot scrolled off at 1366 × 768). The legends now go beside the plots
    whenever above they would push a plot out: at 1366 × 768 every plot is on screen; at
    1280 × 720, where the plots alone are taller than the pane, the stack is the plots
    alone and the joint-force plot's upper half is on screen without scrolling."""
    qtbot.waitExposed(window)
    window.set_language(lang)
    window.model.set_rpms(SIXTEEN)
    window.tabs.setCurrentIndex(1)
    qtbot.wait(50)
    stack = window.forces.stack()
    stack.ensure_current()
    qtbot.wait(20)
    plots = [stack._plots[s.key].item for s in stack._series if stack.plot_visible(s.key)]
    assert len(plots) == 4
    for group in ("speeds", "joints"):
        head = stack.legend(group).head.sceneBoundingRect()
        assert not [item for item in plots if item.vb.sceneBoundingRect().intersects(head)], group
    port = stack._scroll.viewport().height()
    if window.width() >= WINDOWS["1366x768"][0]:
        for item in plots:
            assert on_screen(stack, window, item.vb.sceneBoundingRect()), (lang, item.vb.sceneBoundingRect())
    else:
        assert stack._side, lang                    # beside: the stack is the plots alone
        force = plots[-1].vb.sceneBoundingRect()
        top = QRectF(force.left(), force.top(), force.width(), force.height() / 2.0)
        assert on_screen(stack, window, top), (lang, force)    # its upper half unscrolled
