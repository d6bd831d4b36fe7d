"""What both plot views (kinematics and forces) are besides their series: one PlotStack.

Each view configures a :class:`plot_stack.PlotStack` with its own series and
answers the stack's questions (``StackSource``); the stack's read-out, items,
image export and vector rendering are the same for both, so they live here once.
"""
from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication, QEvent, QRectF
from PySide6.QtGui import QColor, QPainter
from PySide6.QtWidgets import QWidget

from .stack import PlotStack

WHITE = QColor("#ffffff")


class StackView(QWidget):
    """A view drawn by one PlotStack, which the subclass creates as ``self._stack``."""

    _stack: PlotStack

    def _retranslate(self) -> None:
        """Set every text again (the subclass's), on a language change."""

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def stack(self) -> PlotStack:
        return self._stack

    def catch_up(self) -> None:
        """Draw now, while hidden, what the first show would draw (``LazyPage.catch_up``:
        the window calls it while idle): the items made and filled, so the visit only paints."""
        self._stack.ensure_current()

    def readout_text(self) -> str:
        """The mouse read-out (plain text)."""
        return self._stack.readout_text()

    def plot_item(self, name: str) -> pg.PlotItem:
        """The pyqtgraph plot ``name`` (in the scene only while shown)."""
        return self._stack.plot(name).item

    def export_image(self, path: str) -> None:
        """Write the shown plots to ``path``: SVG for ``.svg``, else a raster image (PNG …)
        at least 1600 px wide; ValueError for an unknown type, OSError for a bad folder."""
        from shaperapp.widgets.image_export import export_scene   # QtSvg: not before the first paint
        scene, rect, title, caching_off = self._stack.export_view()
        export_scene(scene, rect, path, title, WHITE, caching_off)

    def svg_bytes(self) -> bytes:
        """The SVG :meth:`export_image` writes, in memory."""
        from shaperapp.widgets.image_export import scene_svg
        scene, rect, title, caching_off = self._stack.export_view()
        return scene_svg(scene, rect, title, WHITE, caching_off)

    def render(self, painter: QPainter, target: QRectF) -> None:
        """Paint the shown plots into ``target`` of any QPainter (vector output)."""
        from shaperapp.widgets.image_export import render_scene
        scene, rect, _title, caching_off = self._stack.export_view()
        render_scene(scene, rect, painter, target, WHITE, caching_off)

    def speed_name(self, rpm: float) -> str:
        """A crank speed as the legends, read-out and choices name it: "40 r/min"."""
        # An explicit context: self.tr in a base class would look up the subclass's.
        return QCoreApplication.translate("StackView", "{0} r/min").format(f"{rpm:g}")
