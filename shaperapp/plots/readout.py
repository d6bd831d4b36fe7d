"""The read-out line under a plot stack: what the curves are worth under the mouse, or
at the crank's cursor once the crank moved since.

It is a widget of its own beside the stack because its state (which plot the mouse
is over, a throttle so the animation rewrites it at most 10 times a second) and its
HTML (entries kept whole where the line wraps) have nothing to do with drawing the
plots; the stack only tells it where the mouse is and when the plots are current.

It never takes more than READOUT_LINES lines: with 16 speeds the full entries took 5
lines and pushed the lowest plot below the window. Where they do not fit, the entries
drop their repeated units ("10: 2.499", the unit once), then the last entries give
way to "… +N"; the whole read-out is then in the tooltip.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from PySide6.QtCore import QCoreApplication, Qt, QTimer
from PySide6.QtGui import QTextDocument, QTextDocumentFragment
from PySide6.QtWidgets import QLabel, QSizePolicy, QWidget

from shaperapp.design.model import DesignModel
from shaperapp.widgets.style import fmt

from .curves import Curve, PlotSlots
from .series import StackSource

READOUT_DELAY_MS = 100   # the cursor read-out follows the animation at most 10 times a second
READOUT_LINES = 2        # the read-out's most lines, whatever the number of speeds


def nbsp(text: str) -> str:
    """Spaces that never break: the read-out wraps between entries, not inside one."""
    return text.replace(" ", "&nbsp;").replace("/", "/&#8288;")    # no break after "r/"


def readout_html(parts: list[str], group_title: str, unit: str,
                 values: Sequence[tuple[Curve, float | None]], compact: bool = False,
                 left_out: int = 0) -> str:
    """The read-out line: the plot's name and x (``parts``), the legend's title, then each
    curve's value in its colour, entries kept whole when the line wraps. ``compact``: the
    unit once, each curve by its legend's short name; ``left_out`` more entries not shown."""
    parts = list(parts)
    if group_title:
        parts.append(group_title + ":")
    if compact:
        parts.append(nbsp(f"({unit})"))
    for curve, value in values:
        number = "—" if value is None else fmt(value, ".4g")
        text = number if compact or value is None else f"{number} {unit}"
        name = (curve.short or curve.label) if compact else curve.label
        parts.append(f"<span style='color:{curve.colour.name()}'>{nbsp(name)}:</span>"
                     f"&nbsp;{nbsp(text)}")
    if left_out:
        parts.append(f"…&nbsp;+{left_out}")
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
        self._index = model.angle_index                  # the crank's, when last followed
        self.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.setWordWrap(True)
        self.setContentsMargins(6, 2, 6, 2)
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(READOUT_DELAY_MS)
        self._timer.timeout.connect(self.update_text)
        self._tip = ""
        self._fitted = 0        # how many compact entries fitted last (the first guess next)

    def retranslate(self) -> None:
        # The stack's context: these texts were the stack's and keep their translations.
        self._tip = QCoreApplication.translate(
            "PlotStack", "Values under the mouse, or at the cursor while the crank moves; "
            "click a plot to move the mechanism to that crank position")
        self.setToolTip(self._tip)

    def hover(self, hit: tuple[str, float] | None) -> None:
        """The mouse moved: over plot ``hit[0]`` at x ``hit[1]``, or off every plot (None)."""
        self._hover = hit
        if hit is not None:
            self._key = hit[0]
            self.update_text()

    def follow_cursor(self, index: int) -> None:
        """The model's crank is at ``index`` (after an edit too): when it moved, read at the
        cursor soon, until the mouse moves over a plot again. (It kept the value under the
        mouse where the mouse had last been: clicked at 216° and stepped on with the keys,
        it said 216° beside the animation's 217°.) Unmoved, the mouse keeps its values."""
        if index != self._index:
            self._index, self._hover = index, None
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
            # read at the cursor now: a throttled read-out still pending would only write
            # the same text again (after an edit, within the user's next keystroke)
            self._timer.stop()
            plot = self._plot(self._key)
            xs = self._source.cursor_x(self._model.angle_index)
            x = xs if isinstance(xs, float) else next(iter(xs.values()), 0.0)
            cursor = QCoreApplication.translate("PlotStack", "cursor {0}")
            parts = [f"<b>{plot.series.name()}</b>", nbsp(cursor.format(self._source.x_text(x)))]
            values = plot.values_at(xs)
        self._show(parts, self._group_title(plot.series.group), plot.series.unit, list(values))

    def _show(self, parts: list[str], title: str, unit: str,
              values: list[tuple[Curve, float | None]]) -> None:
        """The full read-out if it fits READOUT_LINES lines, else the compact one with as
        many entries as fit (the full one in the tooltip)."""
        full = readout_html(parts, title, unit, values)
        # READOUT_LINES lines of this text's own fonts (a Chinese line is taller than a Latin one)
        head = readout_html(parts, title, unit, [])
        room = self._text_height("<br>".join([head] * READOUT_LINES)) + 1.0
        margins = self.contentsMargins()
        self.setMaximumHeight(math.ceil(room) + margins.top() + margins.bottom())
        if self._text_height(full) <= room or self.contentsRect().width() < 50:
            self.setText(full)
            self.setToolTip(self._tip)
            return
        def fits(n: int) -> bool:
            return self._text_height(readout_html(parts, title, unit, values[:n], True, len(values) - n)) <= room
        lo = self._most_that_fit(fits, len(values))
        self.setText(readout_html(parts, title, unit, values[:lo], True, len(values) - lo))
        plain = QTextDocumentFragment.fromHtml(full).toPlainText().replace("\u2060", "")
        self.setToolTip(plain.replace("\u00a0", " ") + "\n\n" + self._tip)

    def _most_that_fit(self, fits: Callable[[int], bool], count: int) -> int:
        """The most entries (of ``count``) that fit: the number that fitted last if it
        still does and one more does not (an edit or the cursor changes the values, not
        their number: two layouts instead of a bisection's four or five), else a bisection."""
        guess = min(self._fitted, count)
        if (guess == 0 or fits(guess)) and (guess == count or not fits(guess + 1)):
            return guess
        lo, hi = 0, count
        while lo < hi:
            n = (lo + hi + 1) // 2
            if fits(n):
                lo = n
            else:
                hi = n - 1
        self._fitted = lo
        return lo

    def _text_height(self, html: str) -> float:
        """The height ``html`` takes in the read-out's present width."""
        document = QTextDocument()
        document.setDefaultFont(self.font())
        document.setDocumentMargin(0)
        document.setHtml(html)
        document.setTextWidth(max(self.contentsRect().width(), 1))
        return document.size().height()


    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        if event.oldSize().width() != event.size().width() and self.text():
            self.update_text()               # wrapped again: as many entries as now fit

    def plain_text(self) -> str:
        """The read-out as plain text (spaces for non-breaking ones, no word joiners)."""
        plain = QTextDocumentFragment.fromHtml(self.text()).toPlainText()
        return plain.replace("\u00a0", " ").replace("\u2060", "")
