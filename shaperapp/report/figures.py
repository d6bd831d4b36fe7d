"""The report's figures, drawn by the app's own views: never a second drawing of anything.

The scheme, the s/v/a plots and the force plots are exported by their widgets'
public ``export_image`` to SVG (the comparison's curves by ``ComparePlots.svg``)
and replayed with ``QSvgRenderer`` (vector in the PDF); the polygons are painted by ``polygon_paint.paint_polygon``. The
views read a private :class:`DesignModel` whose angle grid holds both limit
positions exactly, so the scheme is drawn at the limits, not next to them.
"""
from __future__ import annotations

import html
import math
from typing import Callable, Sequence

from PySide6.QtCore import QByteArray, QCoreApplication, QPointF, QRectF, QSizeF, Qt
from PySide6.QtGui import QColor, QFont, QFontInfo, QFontMetricsF, QPainter, QTextDocument
from PySide6.QtSvg import QSvgRenderer
from PySide6.QtWidgets import QWidget

from core.cam import Cam, CamInputs
from core.space.compare import Comparison
from core.forces.masses import MassProperties
from core.linkage.geometry import Design
from core.linkage.metrics import CycleMetrics
from core.forces.polygons import lever_force_polygon, polygons
from core.linkage.spec import Spec
from core.drawing.scales import number_text
from shaperapp.cam.model import CamModel, typed_from
from shaperapp.cam.plots import CamPlots
from shaperapp.cam.profile_view import cam_span, paint_cam
from shaperapp.compare.plots import ComparePlots
from shaperapp.design.model import DesignModel
from shaperapp.plots.forces_panel import ForcesPanel
from shaperapp.plots.kinematics import PlotsWidget
from shaperapp.report.kept_views import delete_widgets, kept
from shaperapp.report.theta_mark import SchemeShot, mark_theta
from shaperapp.scheme.view import SchemeWidget
from shaperapp.vectors.paint import auto_scale, paint_polygon, titles

from shaperapp.widgets.fonts import report_font
from shaperapp.widgets.image_export import painting_bytes

Paint = Callable[[QPainter, QRectF, float], None]
FINE_STEP_DEG = 0.25
SCHEME_PX = (330, 370)  # the scheme's view as exported for the report (its text at this size)


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


NICE_SCALES = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0)    # GB/T 14690's reduction scales


def round_scale(value: float) -> float:
    """The smallest drawing scale μ_l of the standard series (NICE_SCALES × 10^k) ≥ ``value``."""
    power = 10.0 ** math.floor(math.log10(value))
    return next((n * power for n in NICE_SCALES + (10.0,) if n * power >= value * (1 - 1e-9)))


def scale_text(mu: float) -> str:
    """μ_l as the sheets state it (``core.drawing``): design metres per mm on the page, and
    as a ratio; ``mu`` is design mm per mm. The report wrote 15 mm/mm beside the sheets'
    0.015 m/mm for one design."""
    ratio = f"1:{mu:g}" if mu >= 1 else f"{1 / mu:g}:1"
    return f"μ<sub>l</sub> = {number_text(mu / 1000.0)} m/mm ({ratio})"


def scheme_paint(shots: Sequence[SchemeShot], captions: Sequence[str], theta_deg: float) -> Paint:
    """The schemes side by side, all at one round μ_l that fits them, with θ and the
    lever's limit positions marked, and under each its caption and μ_l."""
    renderers = [QSvgRenderer(QByteArray(s.svg)) for s in shots]

    def paint(painter: QPainter, rect: QRectF, px_per_mm: float) -> None:
        line = QFontMetricsF(painter.font(), painter.device()).height()
        cell_w, cell_h = rect.width() / len(shots), rect.height() - 2.6 * line
        fit = max(max(r.viewBoxF().width() * s.mm_per_px / (cell_w - 4),
                      r.viewBoxF().height() * s.mm_per_px / cell_h) for r, s in zip(renderers, shots))
        mu = round_scale(fit * px_per_mm)            # design mm per page mm
        for i, (renderer, shot) in enumerate(zip(renderers, shots)):
            k = shot.mm_per_px / mu * px_per_mm      # device units per SVG px
            box = renderer.viewBoxF()
            drawn = QRectF(0, 0, box.width() * k, box.height() * k)
            drawn.moveCenter(QPointF(rect.left() + (i + 0.5) * cell_w, rect.top() + cell_h / 2))
            renderer.render(painter, drawn)
            painter.save()
            font = QFont(painter.font())             # θ on the scale of the dimensions beside it
            font.setPixelSize(max(round(shot.text_px * k), 1))
            painter.setFont(font)
            mark_theta(painter, drawn.topLeft(), k, shot, theta_deg, renderer)
            painter.restore()
            _note(painter, f"{html.escape(captions[i])}<br>{scale_text(mu)}",
                  QPointF(rect.left() + i * cell_w, drawn.bottom() + 0.2 * line), cell_w)
    return paint


def _note(painter: QPainter, rich: str, at: QPointF, width: float) -> None:
    """Centred rich text (a caption with μ<sub>l</sub>) in the painter's font, from ``at``."""
    doc = QTextDocument()
    doc.setDefaultFont(painter.font())
    doc.documentLayout().setPaintDevice(painter.device())
    doc.setHtml(f'<p align="center">{rich}</p>')
    doc.setTextWidth(width)
    painter.save()
    painter.translate(at)
    doc.drawContents(painter)
    painter.restore()


def cam_paint(cam: Cam) -> Paint:
    """The cam at the start of the rise, at the round scale μ_l that fits the figure, the
    scale stated under it (a drawing "to scale" names its scale)."""
    def paint(painter: QPainter, rect: QRectF, px_per_mm: float) -> None:
        line = QFontMetricsF(painter.font(), painter.device()).height()
        room = QRectF(rect.left(), rect.top(), rect.width(), rect.height() - 1.6 * line)
        span = cam_span(cam, 0.0)
        mu = round_scale(max(span[0] / room.width(), span[1] / room.height()) * px_per_mm)
        paint_cam(painter, room, cam, 0.0, scale=px_per_mm / mu)
        below = room.center().y() + span[1] / 2 * px_per_mm / mu     # the scale right under the cam
        _note(painter, scale_text(mu), QPointF(rect.left(), below + 0.2 * line), rect.width())
    return paint


def _export_box(scheme: SchemeWidget, box: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
    """A box of the scheme in mm (left, right, bottom, top) in the px of its export (left,
    right, top, bottom; y down), to 1e-6 px: a class's kept view reads the same box as a
    new one to the last bits only (56.32596212325399 and …3966), and θ's place, which these
    boxes decide, must not depend on which view drew the scheme."""
    a, b = scheme.export_point(box[0], box[2]), scheme.export_point(box[1], box[3])
    return tuple(round(v, 6) for v in (min(a.x(), b.x()), max(a.x(), b.x()), min(a.y(), b.y()),
                                       max(a.y(), b.y())))


class ReportViews:
    """Offscreen scheme and plot widgets on a private model of the design (the process's
    kept views and their model after :func:`kept_views.keep_plot_views`)."""

    def __init__(self, spec: Spec, rpms: Sequence[float], masses: MassProperties | None,
                 metrics: CycleMetrics) -> None:
        work = metrics.work_angle_deg
        self._end_index = math.ceil(work / FINE_STEP_DEG)
        step = work / self._end_index                      # both limits on the grid
        self._kept = kept()
        if self._kept is None:
            self.model = DesignModel()
            self.model.load_state(spec, rpms, step, masses=masses)
        else:                               # the design loaded once, into the kept views' model
            self._kept.load(spec, rpms, step, masses)
            self.model = self._kept.model
        self.metrics = metrics
        self._widgets: list[QWidget] = []

    def _show(self, widget: QWidget, width: int, height: int, kept: bool = False) -> QWidget:
        widget.setAttribute(Qt.WidgetAttribute.WA_DontShowOnScreen)
        # never painted: each export renders the scene (or the widget) into its SVG itself,
        # and a paint in the event processing before it was thrown away (some 4 % of a
        # course); the scheme places its labels for the export as it would at a paint
        widget.setUpdatesEnabled(False)
        widget.resize(width, height)
        widget.show()
        if not kept:                      # closed with the report's views
            self._widgets.append(widget)
        return widget

    def _plot_view(self, kind: str, make: Callable[[DesignModel], QWidget], width: int, height: int,
                   fit: Callable[[QWidget], None]) -> QWidget:
        """A view of the design: new, or the process's kept one (made and shown the first
        time; after that fitted by ``fit``, as a new one fits itself when shown; the scheme
        is fitted for each of its shots)."""
        if self._kept is None:
            return self._show(make(self.model), width, height)
        view = self._kept.views.get(kind)
        if view is None:
            view = self._kept.views[kind] = self._show(make(self.model), width, height, kept=True)
        else:
            fit(view)
        return view

    def _svg(self, widget) -> bytes:
        """The SVG the widget's export writes, rendered in memory: no temporary folder that
        a killed run leaves behind, nor a failed write naming a temporary file (issue 42)."""
        # pending layout first (legend rows, group titles): a command-line run has no event
        # loop, and a view exported unlaid-out put its legend on its tick labels (no paint:
        # the views' updates are off, see _show)
        QCoreApplication.processEvents()
        return widget.svg_bytes()

    def limit_schemes(self, step: Callable[[], None] = lambda: None) -> Paint:
        """Both limit positions side by side at one round scale μ_l, each with the lever's
        two limit positions (dashed) and the angle θ between them marked at O4. ``step()``
        once the view is up and after the first position (each places the scheme's labels,
        the report's longest pieces of work: the window hears Cancel between them)."""
        scheme = self._plot_view("scheme", SchemeWidget, *SCHEME_PX, QWidget.show)
        step()
        design = self.model.design
        half = design.theta / 2.0
        tips = ((-design.lever * math.sin(half), design.lever * math.cos(half)),
                (design.lever * math.sin(half), design.lever * math.cos(half)))
        shots = []
        for index in (0, self._end_index):
            self.model.set_angle_index(index)
            scheme.fit()
            svg = self._svg(scheme)
            o4, across = scheme.export_point(0.0, 0.0), scheme.export_point(100.0, 0.0)
            texts = tuple((_export_box(scheme, box), turned) for box, turned in scheme.text_boxes())
            shots.append(SchemeShot(svg, o4, tuple(scheme.export_point(*tip) for tip in tips),
                                    100.0 / (across.x() - o4.x()), QFontInfo(scheme.font()).pixelSize(), texts))
            if len(shots) == 1:
                step()
        self.model.set_angle_index(0)
        caption = QCoreApplication.translate("Report", "φ = %1° (limit position)")
        return scheme_paint(shots, [caption.replace("%1", f"{self.metrics.work_start_deg:.2f}"),
                                    caption.replace("%1", f"{self.metrics.work_end_deg:.2f}")],
                            math.degrees(design.theta))

    def curves(self) -> Paint:
        return svg_paint([self._svg(self._plot_view("curves", PlotsWidget, 900, 680,
                                                    lambda view: view.stack().fit()))])

    def forces(self) -> Paint:
        return svg_paint([self._svg(self._plot_view("forces", ForcesPanel, 1450, 1050,
                                                    lambda view: view.plots.stack().fit()))])

    def cam_curves(self, inputs: CamInputs, phase: float | None) -> Paint:
        """The Cam tab's plots of the follower's ψ, ω, α and the pressure angle against the
        cam angle δ, for the cam of ``inputs`` on this design."""
        if self._kept is None:
            cam_model = CamModel(self.model)
        else:               # one CamModel on the kept model: each one made listens to it
            cam_model = self._kept.cam_model = self._kept.cam_model or CamModel(self.model)
        cam_model.set_fields(**typed_from(inputs, phase).dict)
        plots = self._plot_view("cam", lambda _model: CamPlots(cam_model), 680, 450, lambda view: None)
        plots.fit_axes()                # one axis width: the δ axes line up, no tick text on a curve
        QCoreApplication.processEvents()
        svg = painting_bytes("svg", QSizeF(680, 450), plots.render,
                             QCoreApplication.translate("Report", "Feed cam"), QColor("white"))
        return svg_paint([svg])

    def comparison_curves(self, result: Comparison) -> Paint:
        """The Compare tab's overlay curves of ``result``."""
        plots = self._show(ComparePlots(), 900, 880)
        plots.show_comparison(result)
        return svg_paint([plots.svg(QCoreApplication.translate("Report", "Design comparison"))])

    def close(self) -> None:
        delete_widgets(self._widgets)
        self._widgets.clear()


def polygon_paint(design: Design, crank_deg: float, rpm: float, masses: MassProperties | None,
                  kind: str, language: str) -> Paint:
    """One polygon at true scale on the page, with the round μ that fills the figure;
    ``kind`` "lever" is the lever's force polygon (the kinetostatic sheet's too). Its name
    is the figure's caption (``polygon_caption``), numbered with the others."""
    if kind == "lever":
        polygon = lever_force_polygon(design, crank_deg, rpm, masses)
    else:
        polygon = polygons(design, crank_deg, rpm, masses)[kind]

    def paint(painter: QPainter, rect: QRectF, px_per_mm: float) -> None:
        font = report_font(language, 8.0)
        metrics = QFontMetricsF(font, painter.device())
        scale = auto_scale(polygon, rect, metrics, px_per_mm, title=False)
        paint_polygon(painter, rect, polygon, scale, px_per_mm=px_per_mm, font=font, title=False)
    return paint


def polygon_caption(kind: str, crank_deg: float) -> str:
    """A polygon's caption: its name (the kind's title, the lever's for "lever") and the
    crank angle; the drawing keeps the angle, the speed and μ above it."""
    return (QCoreApplication.translate("Report", "%1, φ = %2°").replace("%1", titles()[kind])
            .replace("%2", f"{crank_deg:.2f}"))
