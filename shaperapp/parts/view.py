"""What every part's drawing does, written once: paint the part to scale at the animation's
crank angle, its geometry computed once per part (``cached``) and dropped when the part
changes, and a repaint when the angle moves only while the drawing is shown."""
from __future__ import annotations

from typing import Any, Callable

from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QPainter
from PySide6.QtWidgets import QWidget

from .model import PartModel


class PartView(QWidget):
    """The base of a part's drawing: ``build()`` gives the part's geometry (``shapes``),
    ``render_part(painter, rect)`` paints the part into ``rect`` (on screen and in exports)."""

    def __init__(self, part_model: PartModel, least: tuple[int, int], build: Callable[[], Any],
                 parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = part_model
        self.setMinimumSize(*least)
        # paintEvent fills every pixel: the window, the tabs, the splitter are not painted
        # under it first (six paints of the parents a cam edit made for nothing)
        self.setAttribute(Qt.WidgetAttribute.WA_OpaquePaintEvent)
        self._build = build
        self._geometry: Any = None
        part_model.valueChanged.connect(self._reset)
        part_model.design_model.angleChanged.connect(self._angle_moved)

    def shapes(self) -> Any:
        """The part's geometry: built once per part, kept until the part changes."""
        if self._geometry is None:
            self._geometry = self._build()
        return self._geometry

    def render_part(self, painter: QPainter, rect: QRectF) -> None:
        raise NotImplementedError

    def paintEvent(self, event) -> None:  # noqa: N802 - Qt's name
        painter = QPainter(self)
        painter.fillRect(self.rect(), Qt.GlobalColor.white)
        self.render_part(painter, QRectF(self.rect()))
        painter.end()

    def _angle_moved(self, _index: int) -> None:
        if self.isVisible():
            self.update()

    def _reset(self) -> None:
        self._geometry = None
        self.update()
