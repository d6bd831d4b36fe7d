"""The dialogs' title filter (``dialog_titles``) sees every event of the application, so
only the window, which shows dialogs, installs it: a headless writer translating its
report or sheets (``start_qt``, an export's child) paid it on every event, about a tenth
of its CPU, for dialogs it never shows (docs/performance.md, "The suite's margin,
30 November (night)")."""
from __future__ import annotations

from PySide6.QtWidgets import QApplication, QInputDialog

from shaperapp.widgets import dialog_titles, i18n
from shaperapp.widgets.command_line import start_qt


def test_a_headless_writer_installs_no_filter(qapp):
    dialog_titles.uninstall()
    try:
        start_qt("zh", needs_font=False)        # what shaper report/course/drawing/class do first
        i18n.set_language("en")                 # what an export's child does
        assert dialog_titles._fitter is None
    finally:
        i18n.set_language("en")


def test_the_window_installs_it_and_its_dialogs_fit_their_titles(window, qtbot):
    dialog_titles.uninstall()
    window.set_language("en")
    assert dialog_titles._fitter is not None and dialog_titles._fitter.parent() is QApplication.instance()
    dialog = QInputDialog(window)
    qtbot.addWidget(dialog)
    dialog.setWindowTitle("Go to crank angle, a title longer than the dialog's own width")
    dialog.show()
    QApplication.processEvents()
    assert dialog.width() >= dialog_titles.title_width(dialog)
    dialog.close()
