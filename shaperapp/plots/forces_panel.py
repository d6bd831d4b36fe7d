"""Forces view: the loads form beside the force plots.

Only assembles two widgets that know nothing of each other: the loads form
(loads_form.py) edits the model's loads, the force plots (forces.py)
draw the model's dynamics. They meet only in the model.
"""
from __future__ import annotations

from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QPainter
from PySide6.QtWidgets import QFrame, QHBoxLayout, QScrollArea, QSplitter, QWidget

from shaperapp.design.loads_form import LoadsForm
from shaperapp.design.model import DesignModel

from .forces import ForcePlots

FORM_WIDTH = 285


class ForcesPanel(QWidget):
    """Load inputs (``loads``) and torque, power, energy and joint-force plots (``plots``)."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.loads = LoadsForm(model)
        self.plots = ForcePlots(model)
        scroll = QScrollArea(self)
        scroll.setWidget(self.loads)
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        # Never narrower than its fields (nothing clipped); the splitter still lets the
        # user fold the form away completely to give the plots room.
        scroll.setMinimumWidth(self.loads.minimumSizeHint().width()
                               + scroll.verticalScrollBar().sizeHint().width())
        self.splitter = QSplitter(Qt.Orientation.Horizontal)
        self.splitter.addWidget(scroll)
        self.splitter.addWidget(self.plots)
        self.splitter.setStretchFactor(0, 0)
        self.splitter.setStretchFactor(1, 1)
        self.splitter.setSizes([FORM_WIDTH, 4 * FORM_WIDTH])
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.splitter)

    def export_image(self, path: str) -> None:
        """Write the force plots to ``path`` (PNG, SVG …); see ForcePlots.export_image."""
        self.plots.export_image(path)

    def svg_bytes(self) -> bytes:
        """The SVG :meth:`export_image` writes, in memory."""
        return self.plots.svg_bytes()

    def render(self, painter: QPainter, target: QRectF) -> None:
        """Paint the force plots into ``target`` of any QPainter (vector output)."""
        self.plots.render(painter, target)
