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
