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
