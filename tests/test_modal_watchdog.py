"""The suite's guard against unanswered modal dialogs (modal_watchdog) really closes one."""
from PySide6.QtWidgets import QMessageBox

from modal_watchdog import ModalWatchdog


def test_an_unanswered_question_is_rejected_and_named(qtbot):
    watchdog = ModalWatchdog(limit_s=0.3)
    watchdog.start()
    try:
        answer = QMessageBox.question(None, "Unsaved changes", "Save them first?",
                                      QMessageBox.StandardButton.Save | QMessageBox.StandardButton.Cancel)
    finally:
        watchdog.stop()
    assert answer != QMessageBox.StandardButton.Save         # rejected, never accepted
    assert watchdog.closed == ["QMessageBox 'Unsaved changes': 'Save them first?'"]


def test_no_dialog_no_complaint(qtbot):
    watchdog = ModalWatchdog(limit_s=0.1)
    watchdog.start()
    qtbot.wait(400)
    watchdog.stop()
    assert watchdog.closed == []


def test_a_progress_dialog_whose_bar_moves_is_left_open_and_a_stuck_one_closed(qtbot):
    """A long export's progress dialog is modal for as long as the work takes: while its
    bar moves it waits for no answer; once the bar stops it is an unanswered dialog."""
    import time

    from PySide6.QtCore import Qt
    from PySide6.QtWidgets import QApplication, QProgressDialog
    dialog = QProgressDialog("Writing…", "Cancel", 0, 100)
    qtbot.addWidget(dialog)
    dialog.setWindowModality(Qt.WindowModality.ApplicationModal)
    dialog.setMinimumDuration(0)
    dialog.show()
    watchdog = ModalWatchdog(limit_s=0.4)
    watchdog.start()
    try:
        for value in range(12):                 # 1.2 s of work, the bar moving every 0.1 s
            dialog.setValue(value)
            end = time.monotonic() + 0.1
            while time.monotonic() < end:
                QApplication.processEvents()
        assert watchdog.closed == [] and not dialog.wasCanceled()
        qtbot.waitUntil(lambda: watchdog.closed != [], timeout=10_000)     # stuck: closed
    finally:
        watchdog.stop()
    assert watchdog.closed == ["QProgressDialog '': ''"]
