"""The report's figures, drawn by the app's own views: never a second drawing of anything.

The scheme, the s/v/a plots and the force plots are exported by their widgets'
public ``export_image`` to SVG (the comparison's curves by ``ComparePlots.svg``)
and replayed with ``QSvgRenderer`` (vector in the PDF); the polygons are painted by ``polygon_paint.paint_polygon``. The
views read a private :class:`DesignModel` whose angle grid holds both limit
positions exactly, so the scheme is drawn at the limits, not next to them.
"""
from __future__ import annotations

import math
import tempfile
from pathlib import Path
from typing import Callable, Sequence

from PySide6.QtCore import QByteArray, QCoreApplication, QEvent, QRectF, Qt
from PySide6.QtGui import QFontMetricsF, QPainter
from PySide6.QtSvg import QSvgRenderer
from PySide6.QtWidgets import QWidget

from core.compare import Comparison
from core.dynamics import MassProperties
from core.geometry import Design
from core.metrics import CycleMetrics
from core.polygons import polygons
from core.spec import Spec
from ..compare_plots import ComparePlots
from ..forces_panel import ForcesPanel
from ..model import DesignModel
from ..plots import PlotsWidget
from ..polygon_paint import auto_scale, paint_polygon
from ..scheme import SchemeWidget
from .fonts import report_font

Paint = Callable[[QPainter, QRectF, float], None]
FINE_STEP_DEG = 0.25


def _fit(renderer: QSvgRenderer, rect: QRectF) -> QRectF:
    """The largest rect of the drawing's aspect ratio centred in ``rect``."""
    box = renderer.viewBoxF()
    scale = min(rect.width() / box.width(), rect.height() / box.height())
    w, h = box.width() * scale, box.height() * scale
    return QRectF(rect.center().x() - w / 2, rect.center().y() - h / 2, w, h)


def svg_paint(svgs: Sequence[bytes], captions: Sequence[str] = ()) -> Paint:
    """Replay SVG drawings side by side (with a caption under each) into the figure's rect."""
    renderers = [QSvgRenderer(QByteArray(data)) for data in svgs]

    def paint(painter: QPainter, rect: QRectF, _px_per_mm: float) -> None:
        line = QFontMetricsF(painter.font(), painter.device()).height() if captions else 0.0
        width = rect.width() / len(renderers)
        for i, renderer in enumerate(renderers):
            cell = QRectF(rect.left() + i * width, rect.top(), width, rect.height() - 1.4 * line)
            drawn = _fit(renderer, cell.adjusted(2, 2, -2, -2))
            renderer.render(painter, drawn)
            if captions:
                painter.drawText(QRectF(cell.left(), drawn.bottom(), width, 1.4 * line),
                                 Qt.AlignmentFlag.AlignCenter, captions[i])
    return paint


class ReportViews:
    """Offscreen scheme and plot widgets on a private model of the design."""

    def __init__(self, spec: Spec, rpms: Sequence[float], masses: MassProperties | None,
                 metrics: CycleMetrics) -> None:
        work = metrics.work_angle_deg
        self._end_index = math.ceil(work / FINE_STEP_DEG)
        step = work / self._end_index                      # both limits on the grid
        self.model = DesignModel()
        self.model.load_state(spec, rpms, step, masses=masses)
        self.metrics = metrics
        self._dir = tempfile.TemporaryDirectory(prefix="shaper-report-")
        self._widgets: list[QWidget] = []

    def _show(self, widget: QWidget, width: int, height: int) -> QWidget:
        widget.setAttribute(Qt.WidgetAttribute.WA_DontShowOnScreen)
        widget.resize(width, height)
        widget.show()
        self._widgets.append(widget)
        return widget

    def _svg(self, widget, name: str) -> bytes:
        # pending layout first (legend rows, group titles): a command-line run has no event
        # loop, and a view exported unlaid-out put its legend on its tick labels
        QCoreApplication.processEvents()
        path = Path(self._dir.name) / f"{name}.svg"
        widget.export_image(str(path))
        return path.read_bytes()

    def limit_schemes(self) -> Paint:
        scheme = self._show(SchemeWidget(self.model), 760, 620)
        svgs = []
        for index in (0, self._end_index):
            self.model.set_angle_index(index)
            scheme.fit()
            svgs.append(self._svg(scheme, f"scheme{index}"))
        self.model.set_angle_index(0)
        caption = QCoreApplication.translate("Report", "φ = %1° (limit position)")
        return svg_paint(svgs, [caption.replace("%1", f"{self.metrics.work_start_deg:.2f}"),
                                caption.replace("%1", f"{self.metrics.work_end_deg:.2f}")])

    def curves(self) -> Paint:
        return svg_paint([self._svg(self._show(PlotsWidget(self.model), 900, 800), "curves")])

    def forces(self) -> Paint:
        return svg_paint([self._svg(self._show(ForcesPanel(self.model), 1100, 1100), "forces")])

    def comparison_curves(self, result: Comparison) -> Paint:
        """The Compare tab's overlay curves of ``result``."""
        plots = self._show(ComparePlots(), 900, 880)
        plots.show_comparison(result)
        return svg_paint([plots.svg(QCoreApplication.translate("Report", "Design comparison"))])

    def close(self) -> None:
        for widget in self._widgets:
            widget.close()
            widget.deleteLater()
        self._widgets.clear()
        # Delete them now: a command-line run has no event loop to do it later, and Qt
        # objects left for interpreter shutdown can outlive the application and crash it.
        QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
        self._dir.cleanup()


def polygon_paint(design: Design, crank_deg: float, rpm: float, masses: MassProperties | None,
                  kind: str, language: str) -> Paint:
    """One polygon at true scale on the page, with the round μ that fills the figure."""
    polygon = polygons(design, crank_deg, rpm, masses)[kind]

    def paint(painter: QPainter, rect: QRectF, px_per_mm: float) -> None:
        font = report_font(language, 8.0)
        metrics = QFontMetricsF(font, painter.device())
        scale = auto_scale(polygon, rect, metrics, px_per_mm)
        paint_polygon(painter, rect, polygon, scale, px_per_mm=px_per_mm, font=font)
    return paint
