"""After a language switch no widget of the window still shows a text of the other language.

The catalogue tests (test_translations.py) prove that every string has a Chinese
translation; this proves that each text on screen is set again when the language
changes. The Compare tab's hint stayed in English when the app started in Chinese
(the window is built in English, then switched), because only its buttons were
retranslated. Every tab and pane is visited, so lazily filled views are included.
"""
from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from PySide6.QtCore import QAbstractListModel, QModelIndex, Qt
from PySide6.QtWidgets import (QAbstractButton, QAbstractItemView, QComboBox, QDockWidget,
                               QGroupBox, QLabel, QLineEdit, QMenu, QTabWidget, QWidget)

from shaperapp.widgets.lazy import LazyPage

from gui_helpers import main_window
from locations import ROOT

TS = ROOT / "resources" / "shaperapp_zh_CN.ts"


def catalogue() -> dict[str, str]:
    """Source → Chinese, for the messages whose two texts differ."""
    pairs = {}
    for message in ET.parse(TS).getroot().iter("message"):
        source, translation = message.findtext("source"), message.findtext("translation")
        if source and translation and source != translation:
            pairs[source] = translation
    return pairs


def shown_texts(window: QWidget) -> list[tuple[str, str]]:
    """(where, text) of every text a user can read in the window's widgets."""
    out = []
    for widget in window.findChildren(QWidget):
        name = f"{type(widget).__name__} {widget.objectName()!r}"
        if isinstance(widget, (QLabel, QAbstractButton)):
            out.append((name, widget.text()))
        if isinstance(widget, QGroupBox):
            out.append((name, widget.title()))
        if isinstance(widget, QLineEdit):
            out.append((name, widget.placeholderText()))
        if isinstance(widget, QTabWidget):
            out += [(name, widget.tabText(i)) for i in range(widget.count())]
        if isinstance(widget, (QDockWidget, QMenu)):
            out.append((name, widget.windowTitle() if isinstance(widget, QDockWidget) else widget.title()))
        if isinstance(widget, QComboBox):
            out += [(name, widget.itemText(i)) for i in range(widget.count())]
        if isinstance(widget, QAbstractItemView) and widget.model() is not None:
            model = widget.model()
            rows = model.rowCount(QModelIndex())
            columns = 1 if isinstance(model, QAbstractListModel) else model.columnCount(QModelIndex())
            for orientation, count in ((Qt.Orientation.Horizontal, columns),
                                       (Qt.Orientation.Vertical, rows)):
                out += [(name + " header", str(model.headerData(i, orientation) or ""))
                        for i in range(min(count, 200))]
            out += [(name + " cell", str(model.index(r, c).data() or ""))
                    for r in range(min(rows, 200)) for c in range(min(columns, 20))]
        out.append((name + " tooltip", widget.toolTip()))
    for action in window.findChildren(type(window.act_save)):
        out.append((f"action {action.objectName()!r}", action.text().replace("&", "")))
    return [(where, text) for where, text in out if text]


def visit_every_tab(qtbot, window) -> None:
    """Each tab shown until its view is built: a lazy page builds on a zero timer after its
    show, which a loaded machine's 10 ms wait could end before, leaving its texts out."""
    for tabs in window.findChildren(QTabWidget):
        for i in range(tabs.count()):
            tabs.setCurrentIndex(i)
            page = QTabWidget.widget(tabs, i)           # the LazyPage itself: never builds it
            qtbot.waitUntil(lambda: not isinstance(page, LazyPage) or page.is_built(), timeout=10_000)
            qtbot.wait(10)


@pytest.mark.parametrize("first, then", [("en", "zh_CN"), ("zh_CN", "en")])
def test_no_text_stays_in_the_language_before_a_switch(qtbot, tmp_path, first, then):
    pairs = catalogue()
    stale = set(pairs) if then == "zh_CN" else set(pairs.values())
    with main_window(tmp_path) as window:
        window.set_language(first)
        visit_every_tab(qtbot, window)
        window.set_language(then)
        visit_every_tab(qtbot, window)
        qtbot.wait(50)
        texts = shown_texts(window)
        left = [(where, text) for where, text in texts if text in stale]
        assert left == [], left[:10]
        # The harvest reaches buttons, table headers, combo items and the hint itself.
        now = {text for _, text in texts}
        for source in ("Show forces", "Value", "Crank length L1", "Pick 2 to 6 designs: select them "
                       "in the library and press Compare, or add the design on screen or design files here."):
            assert (pairs[source] if then == "zh_CN" else source) in now, source
