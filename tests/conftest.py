"""Every test runs headless: Qt draws offscreen, so no screen is needed."""
import os

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

from typing import Iterator  # noqa: E402

import pytest  # noqa: E402

from shaperapp.main_window import MainWindow  # noqa: E402
from shaperapp.model import DesignModel  # noqa: E402
from shaperapp.scheme import SchemeWidget  # noqa: E402

from gui_helpers import main_window, shown  # noqa: E402


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
