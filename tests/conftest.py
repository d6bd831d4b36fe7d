"""Every test runs headless: Qt draws offscreen, so no screen is needed."""
import os

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

import pytest  # noqa: E402

from shaperapp.model import DesignModel  # noqa: E402
from shaperapp.scheme import SchemeWidget  # noqa: E402


@pytest.fixture
def model(qtbot) -> DesignModel:
    """A fresh model on the default design (L1 = 100 mm, K = 1.4, H = 300 mm); qtbot
    makes sure a QApplication exists for its signals."""
    return DesignModel()


@pytest.fixture
def scheme(qtbot, model) -> SchemeWidget:
    """The scheme widget shown at a realistic size."""
    widget = SchemeWidget(model)
    qtbot.addWidget(widget)
    widget.resize(900, 650)
    widget.show()
    qtbot.waitExposed(widget)
    return widget
