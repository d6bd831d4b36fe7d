"""The Cam tab's figures: a cam edit that keeps their size lays nothing out again (issue 40
item 5: the rich-text table asked for its size hints and heights again on every edit, and
its column laid out, ~10 ms of a Cam edit), and figures that gain or lose a row still
take their height in the column."""
from __future__ import annotations

from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QApplication

from shaperapp.cam.tab import CamTab

from gui_helpers import shown


class Requests(QObject):
    """Counts the layout requests a widget receives."""

    def __init__(self, widget) -> None:
        super().__init__(widget)
        self.count = 0
        widget.installEventFilter(self)

    def eventFilter(self, watched, event) -> bool:  # noqa: N802 - Qt's name
        if event.type() == QEvent.Type.LayoutRequest:
            self.count += 1
        return False


def settle() -> None:
    for _ in range(3):
        QApplication.processEvents()


def test_an_edit_that_keeps_the_figures_size_lays_out_nothing(qtbot, model):
    tab = shown(qtbot, CamTab(model), 1000, 650)
    settle()
    requests, height, text = Requests(tab.form.parentWidget()), tab.figures.height(), tab.figures.text()
    tab.cam_model.set_fields(rise=61.0)
    qtbot.waitUntil(lambda: tab.figures.text() != text)
    settle()
    assert tab.figures.height() == height
    assert requests.count == 0


def test_figures_that_gain_a_row_take_their_height(qtbot, model):
    tab = shown(qtbot, CamTab(model), 1000, 650)
    settle()
    low = tab.figures.height()
    tab.cam_model.set_fields(hub=45.0, boss=45.0)       # the base radius raised: one more row
    qtbot.waitUntil(lambda: "raised" in tab.figures.text())
    qtbot.waitUntil(lambda: tab.figures.height() > low)
    assert tab.figures.height() == tab.figures.heightForWidth(tab.figures.width())
    tab.cam_model.set_fields(hub=20.0, boss=20.0)
    qtbot.waitUntil(lambda: tab.figures.height() == low)
    assert tab.figures.width() == tab.form.width()
