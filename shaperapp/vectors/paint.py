"""The one painting function for vector polygons: screen, PNG/SVG and the report.

``paint_polygon`` draws a :class:`core.forces.polygons.Polygon` at a scale μ (unit per
drawing mm): every vector is one ``drawLine`` in drawing millimetres (value/μ,
y up) under a single painter transform, so what is drawn is exactly what
``core.forces.polygons.paper`` says — the tests record those lines. Because the
screen view, the image export and the report all call this function, they
cannot disagree.
"""
from __future__ import annotations

import math

from PySide6.QtCore import QCoreApplication, QLineF, QPointF, QRectF, QSizeF, Qt
from PySide6.QtGui import QColor, QFont, QFontMetricsF, QPainter, QPen, QPolygonF
from core.forces.polygons import FINE_MANTISSAS, Polygon, nice_scale, paper

from .labels import LabelPlacer

translate = QCoreApplication.translate   # lupdate extracts translate("Context", "text")

ROLE_COLOURS = {"absolute": "#263238", "relative": "#1565c0", "normal": "#2e7d32",
                "tangential": "#ef6c00", "coriolis": "#c2185b", "force": "#263238"}
FORCE_COLOURS = ("#c62828", "#6a1b9a", "#1565c0", "#00838f", "#2e7d32", "#ef6c00", "#263238")
PAD_LINES = 1.0          # free space around the drawing for its labels, in text lines
SMALL = 0.72             # super- and subscripts' size, × the symbol's
SUP_RAISE = 0.45         # a superscript's baseline above the symbol's, × the font's ascent
SUB_DROP = 0.9           # a subscript's baseline below the symbol's, × the font's descent
_SUB = str.maketrans("0123456789'", "₀₁₂₃₄₅₆₇₈₉′")


def titles() -> dict[str, str]:
    return {"velocity": translate("PolygonPainter", "Velocity polygon"), "acceleration": translate("PolygonPainter", "Acceleration polygon"),
            "force": translate("PolygonPainter", "Force polygon of the ram group"),
            "lever": translate("PolygonPainter", "Force polygon of the lever")}


def scale_caption(polygon: Polygon, scale: float) -> str:
    """e.g. 'μv = 0.01 (m/s)/mm'."""
    symbol = {"velocity": "μv", "acceleration": "μa", "force": "μF"}[polygon.kind]
    unit = "N" if polygon.kind == "force" else f"({polygon.unit})"
    return f"{symbol} = {scale:g} {unit}/mm"


def point_label(name: str) -> str:
    """a2 → a₂, n3' → n₃′."""
    return name.translate(_SUB)


def vector_colour(polygon: Polygon, index: int) -> QColor:
    if polygon.kind == "force":
        return QColor(FORCE_COLOURS[index % len(FORCE_COLOURS)])
    return QColor(ROLE_COLOURS[polygon.vectors[index].role])


def _split(key: str) -> tuple[str, str, str]:
    """'a^k_A4A3' → ('a', 'k', 'A4A3'); 'F_I6' → ('F', '', 'I6')."""
    base, _, sub = key.partition("_")
    base, _, sup = base.partition("^")
    return base, sup, sub


def symbol_extent(key: str, metrics: QFontMetricsF) -> tuple[float, float, float]:
    """(width, height above the baseline, depth below it) of a symbol drawn by
    ``draw_symbol`` in the font of ``metrics``, its super- and subscript included (the
    small font's metrics are SMALL × the font's: they scale with the point size)."""
    base, sup, sub = _split(key)
    width = metrics.horizontalAdvance(base) + SMALL * max(
        metrics.horizontalAdvance(sup) if sup else 0.0, metrics.horizontalAdvance(sub) if sub else 0.0)
    above = metrics.ascent() * (SUP_RAISE + SMALL) if sup else metrics.ascent()
    below = metrics.descent() * (SUB_DROP + SMALL) if sub else metrics.descent()
    return width + 1.0, max(above, metrics.ascent()), max(below, metrics.descent())


def draw_symbol(painter: QPainter, x: float, y: float, key: str, font: QFont) -> float:
    """Draw a vector symbol with its super- and subscript at baseline (x, y); returns its width."""
    base, sup, sub = _split(key)
    small = QFont(font)
    small.setPointSizeF(font.pointSizeF() * SMALL)
    big_m, small_m = QFontMetricsF(font, painter.device()), QFontMetricsF(small, painter.device())
    painter.setFont(font)
    painter.drawText(QPointF(x, y), base)
    x += big_m.horizontalAdvance(base)
    width = 0.0
    if sup:
        painter.setFont(small)
        painter.drawText(QPointF(x, y - big_m.ascent() * SUP_RAISE), sup)
        width = small_m.horizontalAdvance(sup)
    if sub:
        painter.setFont(small)
        painter.drawText(QPointF(x, y + big_m.descent() * SUB_DROP), sub)
        width = max(width, small_m.horizontalAdvance(sub))
    painter.setFont(font)
    return big_m.horizontalAdvance(base) + width


def _bounds(points: dict[str, tuple[float, float]]) -> QRectF:
    xs = [p[0] for p in points.values()]
    ys = [p[1] for p in points.values()]
    return QRectF(min(xs), min(ys), max(max(xs) - min(xs), 1e-9), max(max(ys) - min(ys), 1e-9))


def _arrow_head(tip: QPointF, direction: QPointF, size: float) -> QPolygonF:
    length = math.hypot(direction.x(), direction.y()) or 1.0
    dx, dy = direction.x() / length, direction.y() / length
    back = QPointF(tip.x() - dx * size, tip.y() - dy * size)
    side = QPointF(-dy * size * 0.32, dx * size * 0.32)
    return QPolygonF([tip, back + side, back - side])


def limit_note(polygon: Polygon) -> str:
    """Why a polygon looks degenerate at this position, or ''."""
    largest = polygon.largest()
    if largest <= 0.0:
        return translate("PolygonPainter", "Every vector is zero at this position.")
    at_rest = {v.key: v.magnitude <= 1e-9 * largest for v in polygon.vectors}
    if polygon.kind == "velocity" and at_rest.get("v_A4"):
        return translate("PolygonPainter", "Limit position: the lever is at rest (ω₄ = 0).")
    if polygon.kind == "acceleration" and at_rest.get("a^k_A4A3") and at_rest.get("a^n_A4"):
        return translate("PolygonPainter", "Limit position: ω₄ = 0, so aᵏ = aⁿ = 0.")
    return ""


def _caption(polygon: Polygon, scale: float, title: bool, heading: str | None = None) -> list[str]:
    place = f"φ = {polygon.crank_deg:.2f}°, {polygon.rpm:g} r/min"
    if title:
        return [f"{heading or titles()[polygon.kind]}   {place}", scale_caption(polygon, scale)]
    return [f"{place},  {scale_caption(polygon, scale)}"]


def _note_rect(rect: QRectF, top: float, note: str, metrics: QFontMetricsF) -> QRectF:
    if not note:
        return QRectF(rect.left(), top, rect.width(), 0.0)
    flags = int(Qt.AlignmentFlag.AlignLeft) | int(Qt.TextFlag.TextWordWrap)
    height = metrics.boundingRect(QRectF(0, 0, rect.width(), 1e6), flags, note).height()
    return QRectF(rect.left(), top, rect.width(), height)


def paint_polygon(painter: QPainter, rect: QRectF, polygon: Polygon, scale: float,
                  px_per_mm: float | None = None, font: QFont | None = None,
                  legend: bool = True, centre_mm: tuple[float, float] | None = None,
                  title: bool = True, heading: str | None = None) -> float:
    """Draw ``polygon`` at μ = ``scale`` into ``rect`` (device units).

    ``px_per_mm`` maps a drawing millimetre to device units (true scale on paper);
    None fits the drawing into the space left by the caption and legend.
    ``centre_mm`` is the point of the drawing (in mm at μ = 1, i.e. in the
    polygon's unit) put at the centre of the drawing area; default the centre
    of this polygon. ``title`` off: one caption line without the polygon's name
    (the screen names it in its selector); ``heading`` names it instead of its kind's
    title (the lever's force polygon). Returns the px-per-mm used.
    """
    font = QFont(font) if font is not None else QFont(painter.font())
    if font.pointSizeF() <= 0:
        font.setPointSizeF(9.0)
    metrics = QFontMetricsF(font, painter.device())
    line = metrics.height()
    painter.save()
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    painter.setFont(font)
    painter.setPen(QColor("#263238"))
    for i, text in enumerate(_caption(polygon, scale, title, heading)):
        painter.drawText(QPointF(rect.left(), rect.top() + i * line + metrics.ascent()), text)
    rows = _legend_rows(polygon)
    area, legend_box, note_box = layout(rect, polygon, metrics, legend, title)
    if note_box.height() > 0:
        painter.setPen(QColor("#b71c1c"))
        painter.drawText(note_box, int(Qt.AlignmentFlag.AlignLeft) | int(Qt.TextFlag.TextWordWrap),
                         limit_note(polygon))
        painter.setPen(QColor("#263238"))
    pts = paper(polygon, scale)
    box = _bounds(pts)
    pad = PAD_LINES * line
    if px_per_mm is None:
        px_per_mm = max(min((area.width() - 2 * pad) / box.width(),
                            (area.height() - 2 * pad) / box.height()), 1e-6)
    centre = area.center()
    mid = box.center() if centre_mm is None else QPointF(centre_mm[0] / scale, centre_mm[1] / scale)

    def to_device(p: tuple[float, float]) -> QPointF:
        return QPointF(centre.x() + (p[0] - mid.x()) * px_per_mm,
                       centre.y() - (p[1] - mid.y()) * px_per_mm)

    painter.save()
    painter.setClipRect(area)
    painter.translate(centre.x() - mid.x() * px_per_mm, centre.y() + mid.y() * px_per_mm)
    painter.scale(px_per_mm, -px_per_mm)            # drawing mm, y up
    head_mm = max(1.2 * line, 6.0) / px_per_mm
    heads: list[QRectF] = []
    segments: list[QLineF] = []
    for i, vec in enumerate(polygon.vectors):
        colour = vector_colour(polygon, i)
        pen = QPen(colour)
        pen.setCosmetic(True)
        pen.setWidthF(1.6 if vec.role in ("absolute", "force") else 1.3)
        if vec.role in ("normal", "tangential"):
            pen.setStyle(Qt.PenStyle.DashLine)
        painter.setPen(pen)
        tail, tip = QPointF(*pts[vec.tail]), QPointF(*pts[vec.head])
        if vec.magnitude == 0.0:
            continue
        painter.drawLine(QLineF(tail, tip))
        segments.append(QLineF(to_device(pts[vec.tail]), to_device(pts[vec.head])))
        length = math.hypot(tip.x() - tail.x(), tip.y() - tail.y())
        if length > 1e-9:
            painter.setBrush(colour)
            solid = QPen(colour)
            solid.setCosmetic(True)
            painter.setPen(solid)
            arrow = _arrow_head(tip, tip - tail, min(head_mm, 0.45 * length))
            painter.drawPolygon(arrow)
            heads.append(painter.transform().map(arrow).boundingRect())
    painter.restore()
    painter.setPen(QColor("#263238"))
    painter.setFont(font)
    fixed = heads + [QRectF(rect.left(), rect.top(), rect.width(), note_box.bottom() - rect.top())]
    if legend_box is not None:
        fixed.append(legend_box)
    named = [to_device(p) for p in pts.values()]
    if polygon.kind == "force":                 # the forces' names, at their middles
        named += [(to_device(pts[v.tail]) + to_device(pts[v.head])) / 2.0 for v in polygon.vectors]
    placer = LabelPlacer(area, line, fixed, segments, outer=rect, named=named)
    if polygon.kind == "force":
        _label_vectors(painter, polygon, pts, to_device, placer, font)
    else:
        _label_points(painter, pts, to_device, metrics, placer)
    if legend_box is not None:
        _draw_legend(painter, legend_box, polygon, rows, font)
    painter.restore()
    return px_per_mm


def _legend_pitch(polygon: Polygon, metrics: QFontMetricsF) -> float:
    """Distance between two legend rows: the tallest superscript of a row stays clear
    of the deepest subscript of the row above (they collided at one text line)."""
    extents = [symbol_extent(v.key, metrics) for v in polygon.vectors] or [(0.0, 0.0, 0.0)]
    return max(e[1] for e in extents) + max(e[2] for e in extents) + 0.12 * metrics.height()


def _legend_width(polygon: Polygon, metrics: QFontMetricsF) -> float:
    return max((symbol_extent(k, metrics)[0] + metrics.horizontalAdvance(t)
                for k, t in _legend_rows(polygon)), default=0.0) + 2.0 * metrics.height()


def layout(rect: QRectF, polygon: Polygon, metrics: QFontMetricsF,
           legend: bool = True, title: bool = True) -> tuple[QRectF, QRectF | None, QRectF]:
    """(drawing area, legend box or None, limit note box) of ``paint_polygon`` in
    ``rect``: the caption and any note on top, the legend beside the drawing when the
    space is wide, else below it."""
    line = metrics.height()
    note = _note_rect(rect, rect.top() + len(_caption(polygon, 1.0, title)) * line + 0.2 * line,
                      limit_note(polygon), metrics)
    top = note.bottom() + 0.3 * line
    area = QRectF(rect.left(), top, rect.width(), max(rect.bottom() - top, 1.0))
    if not legend:
        return area, None, note
    rows = _legend_rows(polygon)
    pitch = _legend_pitch(polygon, metrics)
    legend_w = _legend_width(polygon, metrics)
    tall = pitch * len(rows) + 0.4 * line
    if area.width() - legend_w > 0.9 * area.height():
        box = QRectF(area.right() - legend_w, area.top(), legend_w, tall)
        area.setRight(area.right() - legend_w - 0.5 * line)
    else:
        box = QRectF(area.left(), area.bottom() - tall, area.width(), tall)
        area.setBottom(box.top() - 0.3 * line)
    return area, box, note


def needed_height(polygon: Polygon, metrics: QFontMetricsF, rect: QRectF, title: bool = True) -> float:
    """How far below ``rect.top()`` ``paint_polygon`` draws in ``rect``: a legend beside
    the drawing may run on below ``rect``."""
    _, box, _ = layout(rect, polygon, metrics, True, title)
    return max(rect.bottom(), box.bottom() if box is not None else rect.bottom()) - rect.top()


def auto_scale(polygon: Polygon, rect: QRectF, metrics: QFontMetricsF, px_per_mm: float,
               title: bool = True) -> float:
    """The round μ at which ``paint_polygon`` fills ``rect`` with this polygon at true scale."""
    if not polygon.largest() > 0.0:         # no force at all (zero loads): 1 per mm
        return 1.0
    area, _, _ = layout(rect, polygon, metrics, True, title)
    return fit_scale(_bounds(paper(polygon, 1.0)), area, px_per_mm, PAD_LINES * metrics.height())


def fit_scale(extent: QRectF, area: QRectF, px_per_mm: float, pad: float) -> float:
    """The round μ at which a drawing of ``extent`` (in the polygon's unit) fits ``area``
    (device units, less ``pad`` on each side) at ``px_per_mm``."""
    width_mm = max(area.width() - 2 * pad, 1.0) / px_per_mm
    height_mm = max(area.height() - 2 * pad, 1.0) / px_per_mm
    need = max(extent.width() / width_mm, extent.height() / height_mm)
    return nice_scale(need, 1.0, FINE_MANTISSAS)


def _label_points(painter: QPainter, pts, to_device, metrics: QFontMetricsF,
                  placer: LabelPlacer) -> None:
    """Point letters, away from the drawing's centre where free; points closer than a
    text line on the page share one label ("p′, c′")."""
    line = metrics.height()
    groups: list[tuple[QPointF, tuple[float, float], list[str]]] = []
    for name, p in pts.items():
        dev = to_device(p)
        for anchor, _, names in groups:
            if math.hypot(dev.x() - anchor.x(), dev.y() - anchor.y()) < 0.9 * line:
                names.append(point_label(name))
                break
        else:
            groups.append((dev, p, [point_label(name)]))
    cx = sum(p[0] for p in pts.values()) / len(pts)
    cy = sum(p[1] for p in pts.values()) / len(pts)
    for dev, (x, y), names in groups:
        text = ", ".join(names)
        prefer = math.atan2(-(y - cy), x - cx) if (x, y) != (cx, cy) else -math.pi / 2
        size = QSizeF(metrics.horizontalAdvance(text), metrics.ascent() + metrics.descent())
        box = placer.place([dev], size, prefer)
        _draw_leader(painter, placer)
        painter.drawText(QPointF(box.left(), box.top() + metrics.ascent()), text)


def _label_vectors(painter: QPainter, polygon: Polygon, pts, to_device, placer: LabelPlacer,
                   font: QFont) -> None:
    """Each force's symbol beside its line, on the side away from the polygon's centre."""
    cx = sum(p[0] for p in pts.values()) / len(pts)
    cy = sum(p[1] for p in pts.values()) / len(pts)
    centre = to_device((cx, cy))
    for i, vec in enumerate(polygon.vectors):
        a, b = to_device(pts[vec.tail]), to_device(pts[vec.head])
        anchors = [a + (b - a) * t for t in (0.5, 0.3, 0.7)]
        mid = anchors[0]
        normal = math.atan2(b.y() - a.y(), b.x() - a.x()) + math.pi / 2
        if math.cos(normal) * (mid.x() - centre.x()) + math.sin(normal) * (mid.y() - centre.y()) < 0:
            normal += math.pi
        width, above, below = symbol_extent(vec.key, QFontMetricsF(font, painter.device()))
        box = placer.place(anchors, QSizeF(width, above + below), normal)
        painter.setPen(vector_colour(polygon, i))
        _draw_leader(painter, placer)
        draw_symbol(painter, box.left(), box.top() + above, vec.key, font)


def _draw_leader(painter: QPainter, placer: LabelPlacer) -> None:
    """The thin line tying the label just placed to its point, if it needed one (in the
    painter's current pen colour)."""
    if placer.leader is not None:
        pen = QPen(painter.pen())
        pen.setWidthF(0.6)
        painter.save()
        painter.setPen(pen)
        painter.drawLine(placer.leader)
        painter.restore()


def _legend_rows(polygon: Polygon) -> list[tuple[str, str]]:
    """(symbol, '= magnitude unit'); round-off noise (below 1e-9 of the largest) shows as 0."""
    floor = 1e-9 * polygon.largest()
    return [(v.key, f"= {v.magnitude if v.magnitude > floor else 0.0:.4g} {polygon.unit}")
            for v in polygon.vectors]


def _draw_legend(painter: QPainter, box: QRectF, polygon: Polygon, rows, font: QFont) -> None:
    metrics = QFontMetricsF(font, painter.device())
    line = metrics.height()
    pitch = _legend_pitch(polygon, metrics)
    above = max((symbol_extent(v.key, metrics)[1] for v in polygon.vectors), default=0.0)
    y = box.top() + 0.2 * line + above
    for i, (key, text) in enumerate(rows):
        colour = vector_colour(polygon, i)
        pen = QPen(colour)
        pen.setWidthF(1.5)
        if polygon.vectors[i].role in ("normal", "tangential"):
            pen.setStyle(Qt.PenStyle.DashLine)
        painter.setPen(pen)
        painter.drawLine(QLineF(box.left(), y - 0.3 * line, box.left() + 0.9 * line, y - 0.3 * line))
        painter.setPen(QColor("#263238"))
        width = draw_symbol(painter, box.left() + 1.2 * line, y, key, font)
        painter.drawText(QPointF(box.left() + 1.6 * line + width, y), text)
        y += pitch
