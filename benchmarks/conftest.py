"""Every test runs headless: Qt draws offscreen, so no screen is needed."""
import os

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")


import pytest


@pytest.fixture(autouse=True, scope="session")
def _app_look():
    """What the user sees: the app's pyqtgraph look (antialiased, white), not its defaults."""
    from shaperapp.widgets.style import configure_plots
    configure_plots()
