"""The read-out line under a plot stack: what the curves are worth under the mouse, or
at the crank's cursor once the crank moved since.

It is a widget of its own beside the stack because its state (which plot the mouse
is over, a throttle so the animation rewrites it at most 10 times a second) and its
HTML (entries kept whole where the line wraps) have nothing to do with drawing the
plots; the stack only tells it where the mouse is and when the plots are current.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence

from PySide6.QtCore import QCoreApplication, Qt, QTimer
from PySide6.QtGui import QTextDocumentFragment
from PySide6.QtWidgets import QLabel, QSizePolicy, QWidget

from shaperapp.design.model import DesignModel
from shaperapp.widgets.style import fmt

from .curves import Curve, PlotSlots
from .series import StackSource

READOUT_DELAY_MS = 100   # the cursor read-out follows the animation at most 10 times a second


def nbsp(text: str) -> str:
    """Spaces that never break: the read-out wraps between entries, not inside one."""
    return text.replace(" ", "&nbsp;").replace("/", "/&#8288;")    # no break after "r/"


def readout_html(parts: list[str], group_title: str, unit: str,
                 values: Sequence[tuple[Curve, float | None]]) -> str:
    """The read-out line: the plot's name and x (``parts``), the legend's title, then each
    curve's value in its colour, entries kept whole when the line wraps."""
    parts = list(parts)
    if group_title:
        parts.append(group_title + ":")
    for curve, value in values:
        text = "—" if value is None else f"{fmt(value, '.4g')} {unit}"
        parts.append(f"<span style='color:{curve.colour.name()}'>{nbsp(curve.label)}:</span>"
                     f"&nbsp;{nbsp(text)}")
    return "&nbsp;&nbsp; ".join(parts)


class Readout(QLabel):
    """The stack's read-out: ``plot(key)`` gives a plot of the stack, ``group_title(group)``
    its legend's title, and ``ready()`` whether the plots match the model (no text else)."""

    def __init__(self, model: DesignModel, source: StackSource, first_key: str,
                 plot: Callable[[str], PlotSlots], group_title: Callable[[str], str],
                 ready: Callable[[], bool], parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model, self._source = model, source
        self._plot, self._group_title, self._ready = plot, group_title, ready
        self._hover: tuple[str, float] | None = None    # plot and x under the mouse
        self._key = first_key                            # the plot read at the cursor
        self.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.setWordWrap(True)
        self.setContentsMargins(6, 2, 6, 2)
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(READOUT_DELAY_MS)
        self._timer.timeout.connect(self.update_text)

    def retranslate(self) -> None:
        # The stack's context: these texts were the stack's and keep their translations.
        self.setToolTip(QCoreApplication.translate(
            "PlotStack", "Values under the mouse, or at the cursor while the crank moves; "
            "click a plot to move the mechanism to that crank position"))

    def hover(self, hit: tuple[str, float] | None) -> None:
        """The mouse moved: over plot ``hit[0]`` at x ``hit[1]``, or off every plot (None)."""
        self._hover = hit
        if hit is not None:
            self._key = hit[0]
            self.update_text()

    def follow_cursor(self) -> None:
        """The crank moved: read at the cursor soon, unless the mouse is over a plot."""
        if self._hover is None and not self._timer.isActive():
            self._timer.start()

    def update_text(self) -> None:
        """Values under the mouse, or at the cursor once the crank moved since."""
        if not self._ready():
            return
        if self._hover is not None:
            key, x = self._hover
            plot = self._plot(key)
            parts = [f"<b>{plot.series.name()}</b>", nbsp(self._source.x_text(x))]
            values = plot.values_at(x)
        else:
            plot = self._plot(self._key)
            xs = self._source.cursor_x(self._model.angle_index)
            x = xs if isinstance(xs, float) else next(iter(xs.values()), 0.0)
            cursor = QCoreApplication.translate("PlotStack", "cursor {0}")
            parts = [f"<b>{plot.series.name()}</b>", nbsp(cursor.format(self._source.x_text(x)))]
            values = plot.values_at(xs)
        self.setText(readout_html(parts, self._group_title(plot.series.group),
                                  plot.series.unit, values))

    def plain_text(self) -> str:
        """The read-out as plain text (spaces for non-breaking ones, no word joiners)."""
        plain = QTextDocumentFragment.fromHtml(self.text()).toPlainText()
        return plain.replace("\u00a0", " ").replace("\u2060", "")
