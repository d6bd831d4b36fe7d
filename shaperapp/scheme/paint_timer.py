"""Work timed by a widget's paints and layouts: just before its next paint, in the turn
after one, or once the layouts posted are done.

Split from view.py: the scheme places its labels by these times (a show's before the plot
draws, a rebuild's after the new mechanism is on screen: issue 40 item 5; a new language's
for the view its texts lay out), and when is a matter of Qt's events, apart from what is
placed.
"""
from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QTimer
from PySide6.QtWidgets import QWidget


LAYOUT_LEVELS = 6           # the posted layout requests sent this many levels deep (after_relayout)


class PaintTimer(QObject):
    """Watches ``widget``'s paints. After ``at_next_paint``, its next paint first calls
    ``before_paint`` (ahead of the drawing); after ``after_next_paint``, ``after_paint`` is
    called in the turn after its next paint, or ``late_ms`` later if none comes (a widget
    not drawn on screen); after ``after_relayout``, ``before_paint`` once laid out."""

    def __init__(self, widget: QWidget, before_paint: Callable[[], None], after_paint: Callable[[], None],
                 late_ms: int, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._before_paint = before_paint
        self._at_paint = False
        self._late_ms = late_ms
        self._timer = QTimer(self, singleShot=True, interval=late_ms)
        self._timer.timeout.connect(after_paint)
        widget.installEventFilter(self)

    def at_next_paint(self) -> None:
        self._at_paint = True

    def after_next_paint(self) -> None:
        self._timer.start(self._late_ms)

    def after_relayout(self) -> None:
        """``before_paint`` in the next turn, for the layout then. The relayout comes as
        posted layout requests, each level's posted while the one above is done, and a paint
        or a zero timer can come between them (CI's log: labels placed for the old view,
        then again): they are sent then, a few levels deep, before ``before_paint``."""
        QTimer.singleShot(0, self, self._relaid_out)

    def _relaid_out(self) -> None:
        for _ in range(LAYOUT_LEVELS):
            QCoreApplication.sendPostedEvents(None, QEvent.Type.LayoutRequest)
        self._before_paint()

    def waiting(self) -> bool:
        """An ``after_paint`` is due (its paint, or its late time, still to come)."""
        return self._timer.isActive()

    def cancel(self) -> None:
        """The due ``after_paint`` is not called (done by other means)."""
        self._timer.stop()

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:  # noqa: N802 - Qt's name
        if event.type() == QEvent.Type.Paint and self._at_paint:
            self._at_paint = False
            self._before_paint()
        elif event.type() == QEvent.Type.Paint and self._timer.isActive():
            self._timer.start(0)
        return super().eventFilter(watched, event)
