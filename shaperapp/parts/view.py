"""What every part's drawing does, written once: paint the part to scale at the animation's
crank angle, its geometry computed once per part (``cached``) and dropped when the part
changes, a repaint when the angle moves only while the drawing is shown, and, while this
design's part cannot be made, why instead of the part of the design opened before."""
from __future__ import annotations

from typing import Any, Callable

from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QColor, QPainter
from PySide6.QtWidgets import QWidget

from core.base.errors import DesignError

from .model import PartModel

UNMADE_TEXT = QColor("#b71c1c")      # the error lines' colour (widgets.messages.ERROR_TEXT_STYLE)


class PartView(QWidget):
    """The base of a part's drawing: ``build()`` gives the part's geometry (``shapes``),
    ``render_part(painter, rect)`` paints the part into ``rect`` (on screen and in exports)."""

    def __init__(self, part_model: PartModel, least: tuple[int, int], build: Callable[[], Any],
                 describe: Callable[[DesignError], str], parent: QWidget | None = None) -> None:
        """``describe``: a refusal in the current language, as the part's form says it."""
        super().__init__(parent)
        self._model = part_model
        self._describe = describe
        self.setMinimumSize(*least)
        # paintEvent fills every pixel: the window, the tabs, the splitter are not painted
        # under it first (six paints of the parents a cam edit made for nothing)
        self.setAttribute(Qt.WidgetAttribute.WA_OpaquePaintEvent)
        self._build = build
        self._geometry: Any = None
        part_model.valueChanged.connect(self._reset)
        part_model.errorChanged.connect(self.update)      # own_value may have changed
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
        if self._model.own_value:
            self.render_part(painter, QRectF(self.rect()))
        else:           # the part held is an earlier design's: drawn, it would pass for this one's
            self.paint_unmade(painter, QRectF(self.rect()))
        painter.end()

    def paint_unmade(self, painter: QPainter, rect: QRectF) -> None:
        """Why this design has no part, where the part would be drawn: the form's words."""
        error = self._model.error
        text = self._model.unmade_text()
        if error is not None:
            text = "⚠ " + self._describe(error) + "\n" + text
        painter.setPen(UNMADE_TEXT)
        margin = 0.08 * min(rect.width(), rect.height())
        painter.drawText(rect.adjusted(margin, margin, -margin, -margin),
                         int(Qt.AlignmentFlag.AlignCenter | Qt.TextFlag.TextWordWrap), text)

    def _angle_moved(self, _index: int) -> None:
        if self.isVisible():
            self.update()

    def _reset(self) -> None:
        self._geometry = None
        self.update()
