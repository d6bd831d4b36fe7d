"""The suite keeps away from the user's files (tests/conftest.py gives it a private home)."""
import os
import tempfile
from pathlib import Path

from PySide6.QtCore import QSettings

from core.library.store import default_path


def test_default_library_and_settings_are_private_to_the_run(qtbot):
    private = Path(os.environ["XDG_DATA_HOME"]).parent
    assert private.name.startswith("shaper-tests-") and private.parent == Path(tempfile.gettempdir())
    assert default_path().is_relative_to(private)
    assert Path(QSettings("ShaperDesigner", "shaperapp").fileName()).is_relative_to(private)


def test_a_chinese_command_in_the_tests_process_leaves_english_behind(qtbot, monkeypatch):
    """``shaper_in_process`` runs a command in the test's process; one with ``--lang zh``
    set the process's language to Chinese, and a later test in the same worker (the order
    is random) read Chinese where it expected English (test_gui_gear_sheet.py's tooltip after
    test_chinese_sheets.py)."""
    from PySide6.QtCore import QCoreApplication

    import core.cli
    from cli_runner import shaper_in_process
    from shaperapp.widgets.command_line import start_qt

    def chinese_command(args):
        start_qt("zh", needs_font=False)
        assert QCoreApplication.translate("MainWindow", "&File") != "&File"   # Chinese is on
        return 0

    monkeypatch.setattr(core.cli, "main", chinese_command)
    assert shaper_in_process("anything")[0] == 0
    assert QCoreApplication.translate("MainWindow", "&File") == "&File"
