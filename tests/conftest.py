"""Every test runs headless: Qt draws offscreen, so no screen is needed."""
import os

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

from contextlib import contextmanager  # noqa: E402
from pathlib import Path  # noqa: E402
from typing import Iterator, TypeVar  # noqa: E402

import pytest  # noqa: E402
from PySide6.QtCore import QSettings  # noqa: E402
from PySide6.QtWidgets import QWidget  # noqa: E402

from shaperapp import i18n  # noqa: E402
from shaperapp.main_window import MainWindow  # noqa: E402
from shaperapp.model import DesignModel  # noqa: E402
from shaperapp.scheme import SchemeWidget  # noqa: E402

W = TypeVar("W", bound=QWidget)


def shown(qtbot, widget: W, width: int, height: int) -> W:
    """``widget`` handed to qtbot (closed after the test), at ``width`` × ``height``,
    shown and exposed: laid out and painted as a user would see it."""
    qtbot.addWidget(widget)
    widget.resize(width, height)
    widget.show()
    qtbot.waitExposed(widget)
    return widget


@contextmanager
def main_window(folder: Path) -> Iterator[MainWindow]:
    """The assembled window on the default design, shown, with its settings in ``folder``.
    Afterwards it closes without the unsaved-changes question and the language is English."""
    settings = QSettings(str(folder / "s.ini"), QSettings.Format.IniFormat)
    win = MainWindow(DesignModel(), settings)
    win.show()
    try:
        yield win
    finally:
        win.animation.play_action.setChecked(False)
        win.model.set_clean(win.model.path)
        win.close()
        win.deleteLater()
        i18n.set_language("en")


@pytest.fixture
def window(qtbot, tmp_path) -> Iterator[MainWindow]:
    """The assembled window (see :func:`main_window`), settings under ``tmp_path``."""
    with main_window(tmp_path) as win:
        yield win


@pytest.fixture
def model(qtbot) -> DesignModel:
    """A fresh model on the default design (L1 = 100 mm, K = 1.4, H = 300 mm); qtbot
    makes sure a QApplication exists for its signals."""
    return DesignModel()


@pytest.fixture
def scheme(qtbot, model) -> SchemeWidget:
    """The scheme widget shown at a realistic size."""
    return shown(qtbot, SchemeWidget(model), 900, 650)
