"""The Optimize group's message follows a language switch (issue 32, item 5): it was set
once, in the language of the moment, and stayed English in the Chinese window."""
import re

from PySide6.QtCore import QCoreApplication

from language_checks import english_words
from shaperapp.widgets import i18n


def test_the_free_parameters_message_is_retranslated(qtbot, view):
    view.axis_names[1].setCurrentIndex(view.axis_names[0].currentIndex())    # one parameter twice
    view.box.optimize.click()
    english = view.box.optimum.text()
    assert english == "Choose one or two different free parameters."
    assert i18n.set_language("zh_CN")
    qtbot.waitUntil(lambda: view.box.optimum.text() != english, timeout=10_000)
    assert view.box.optimum.text() == QCoreApplication.translate(
        "ExploreView", "Choose one or two different free parameters.")
    assert english_words(view.box.optimum.text()) == []
    i18n.set_language("en")
    qtbot.waitUntil(lambda: view.box.optimum.text() == english, timeout=10_000)


def test_the_proposal_is_retranslated(qtbot, view, model):
    model.set_spec(variant="rod", rod_input="ratio", rod_ratio=0.3, time_ratio=1.46, stroke=312.0)
    view.lows[0].setValue(0.3)
    view.highs[0].setValue(1.0)
    view.lows[1].setValue(480.0)
    view.highs[1].setValue(620.0)
    view.box.optimize.click()
    qtbot.waitUntil(lambda: view.runner.job is None and view.box.optimum.text() != "", timeout=60_000)
    english = view.box.optimum.text()
    assert english.startswith("Proposal")
    assert i18n.set_language("zh_CN")
    qtbot.waitUntil(lambda: view.box.optimum.text() != english, timeout=10_000)
    chinese = view.box.optimum.text()
    assert english_words(chinese, {"span", "style", "color", "br"}) == [], chinese
    numbers = re.compile(r"\d+\.\d+")                 # the optimum, the design before, the values
    assert set(numbers.findall(english)) == set(numbers.findall(chinese)) != set()
