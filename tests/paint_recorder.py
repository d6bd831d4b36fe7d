"""A QPainter that records what the polygon painter draws, in device pixels: the ink box
of every text run (from the font's own metrics, not from the painter's layout) and the
box of every filled polygon drawn under the drawing's y-up transform (the arrowheads),
and the lines drawn there (the vectors). Used by the polygon tests and the layout probe."""
from __future__ import annotations

from PySide6.QtCore import QLineF, QPointF, QRectF
from PySide6.QtGui import QFontMetricsF, QPainter


class PaintRecorder(QPainter):
    def __init__(self, device) -> None:
        super().__init__(device)
        self.texts: list[tuple[str, QRectF]] = []
        self.heads: list[QRectF] = []
        self.lines: list[QLineF] = []

    def drawText(self, *args):
        metrics = QFontMetricsF(self.font(), self.device())
        if isinstance(args[0], QPointF) and isinstance(args[1], str):
            text = args[1]
            ink = metrics.tightBoundingRect(text).translated(args[0])
        elif isinstance(args[0], QRectF):
            text = args[-1]
            ink = metrics.boundingRect(args[0], int(args[1]), text)
        else:               # pragma: no cover - the painter uses the two forms above
            raise AssertionError(f"unexpected drawText{args!r}")
        if text.strip():
            self.texts.append((text, self.transform().mapRect(ink)))
        return super().drawText(*args)

    def drawPolygon(self, *args):
        if self.transform().m22() < 0:
            self.heads.append(self.transform().map(args[0]).boundingRect())
        return super().drawPolygon(*args)

    def drawLine(self, *args):
        if self.transform().m22() < 0:
            self.lines.append(self.transform().map(args[0] if len(args) == 1 else QLineF(*args)))
        return super().drawLine(*args)


def overlapping(boxes: list[tuple[str, QRectF]], slack: float = 0.5) -> list[tuple[str, str]]:
    """Pairs of texts whose ink boxes (each shrunk by ``slack`` px) overlap."""
    shrunk = [(t, b.adjusted(slack, slack, -slack, -slack)) for t, b in boxes]
    return [(a, b) for i, (a, ra) in enumerate(shrunk) for b, rb in shrunk[i + 1:] if ra.intersects(rb)]


def drawing_box(lines: list[QLineF]) -> QRectF:
    """The box of the vectors drawn (device px)."""
    xs = [p.x() for line in lines for p in (line.p1(), line.p2())]
    ys = [p.y() for line in lines for p in (line.p1(), line.p2())]
    return QRectF(min(xs), min(ys), max(xs) - min(xs), max(ys) - min(ys)) if xs else QRectF()
