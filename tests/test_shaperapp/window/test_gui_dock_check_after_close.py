"""The checks the docks queue for once the window is laid out (its default dock sizes; the
library shown under the plots) go with the window: queued without a context object, they
ran after it was deleted and raised "Internal C++ object already deleted" from the event
loop. Found looking for calls into objects Qt had already freed (a segfault at exit)."""
import shiboken6
from PySide6.QtCore import QSettings, Qt

from shaperapp.design.model import DesignModel
from shaperapp.window.main_window import MainWindow


def test_the_library_check_queued_at_showing_does_not_outlive_the_window(qtbot, tmp_path):
    win = MainWindow(DesignModel(), QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    win.show()
    qtbot.waitExposed(win)
    dock = win.docks["library"]
    dock.hide()
    win.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, dock)
    dock.show()                                  # queues Docks._fit_library for the next loop
    shiboken6.delete(win)                        # the window goes before the loop runs
    qtbot.wait(20)                               # the queued check would run (and raise) here
