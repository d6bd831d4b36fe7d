"""The frameless vertical scroll area the panes put their columns in (the inputs, the cam's plots)."""
from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QFrame, QScrollArea, QVBoxLayout, QWidget


def vertical_scroll(widget: QWidget | None = None, owner: QWidget | None = None) -> QScrollArea:
    """``widget`` in a frameless scroll area that scrolls up and down only (it follows the
    area's width); with ``owner``, the area fills ``owner`` without margins. Without a
    widget, the caller sets it (after keeping the area, if the widget's events need it)."""
    area = QScrollArea()
    if widget is not None:
        area.setWidget(widget)
    area.setWidgetResizable(True)
    area.setFrameShape(QFrame.Shape.NoFrame)
    area.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
    if owner is not None:
        layout = QVBoxLayout(owner)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(area)
    return area
