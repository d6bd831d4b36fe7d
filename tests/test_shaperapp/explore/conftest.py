"""The Explore tab as a user sees it, for the tests of this folder that need no design of
their own (test_gui_explore sets one in its own fixture)."""
import pytest

from shaperapp.explore.view import ExploreView
from shaperapp.widgets import i18n

from gui_helpers import shown


@pytest.fixture
def view(qtbot, model):
    """The tab shown at 760 × 820 px; the language is English again afterwards."""
    widget = shown(qtbot, ExploreView(model), 760, 820)
    yield widget
    widget.shutdown()
    i18n.set_language("en")
