"""A label whose new text lays its column out again only when the label's size changes.

Why: ``setText`` on a word-wrapped rich-text QLabel tells its layout that its geometry may
have changed, and the layout then asks it for its size hints and its heights for a width,
each a layout of the rich text, and lays out the column in its scroll area again: ~10 ms
of each Cam edit (issue 40 item 5) for a table of figures whose
size rarely changes. Here the label sits in a holder with no layout of its own, so its
request stops at the holder, which passes it on only when its height at the width it has
(or its size policy) changed. Its least size is not compared: a rich-text label's is a
layout of the text at no width, ~7 ms, and it only matters in a column narrower than the
text's longest word, which a table of figures in its form's column never is.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, QSize
from PySide6.QtWidgets import QLabel, QWidget


class SteadyLabel(QWidget):
    """Stands in for its QLabel (``label``) in a layout: the label's size hints, height for
    width and size policy, the label filling it."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.label = QLabel(self)
        self._seen: tuple | None = None       # the size policy and height the layout last read

    def sizeHint(self) -> QSize:  # noqa: N802 - Qt's name
        return self.label.sizeHint()

    def minimumSizeHint(self) -> QSize:  # noqa: N802 - Qt's name
        return self.label.minimumSizeHint()

    def hasHeightForWidth(self) -> bool:  # noqa: N802 - Qt's name
        return self.label.sizePolicy().hasHeightForWidth()

    def heightForWidth(self, width: int) -> int:  # noqa: N802 - Qt's name
        return self.label.heightForWidth(width)

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        self.label.setGeometry(self.rect())

    def showEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().showEvent(event)
        self._pass_on()                         # a text set while hidden sent no request

    def event(self, event: QEvent) -> bool:
        if event.type() == QEvent.Type.LayoutRequest:      # the label's, after a new text
            self._pass_on()
            return True
        return super().event(event)

    def _shape(self) -> tuple:
        policy = self.label.sizePolicy()
        height = self.label.heightForWidth(self.width()) if policy.hasHeightForWidth() else self.label.sizeHint()
        return policy, height

    def _pass_on(self) -> None:
        """Tell the layout only when the label's height (or size policy) changed."""
        shape = self._shape()
        if shape != self._seen:
            self._seen = shape
            self.setSizePolicy(shape[0])
            self.updateGeometry()
