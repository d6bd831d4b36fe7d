"""The legend of one group of stacked plots: an optional title over entries that wrap.

The legend is a row of its own above its plots, so it never hides a curve, and it
wraps into as many columns as the view's width holds (pyqtgraph's LegendItem
``setColumnCount``), so 16 speeds stay readable in a narrow pane instead of
pushing the plots out of it. Where the rows above the plots would push the lowest
plot below the pane (16 speeds on a laptop), the stack puts the legend beside its
plots instead (``set_side``), in as few columns as its plots' height allows. An entry stands for every curve with its label: a
click on it hides or shows all of them (``on_toggle``); keys that are not curves
(line styles, shaded bands) only explain and cannot be switched off.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass

import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtGui import QColor

from shaperapp.widgets.legend_wrap import legend_columns, wrap_legend
from shaperapp.widgets.style import TEXT

from .axes import AXIS_WIDTH

ROW_HEIGHT = 20          # px per legend row (the samples are 20 px high)
ENTRY_GAP = 14           # px between two entries on a row
KEY_WIDTH = 1.6
SIDE_MARGIN = 6          # px between the plots and a legend beside them
UNLIMITED = 16777215     # Qt's QWIDGETSIZE_MAX


@dataclass(frozen=True)
class LegendKey:
    """A legend entry that is not a curve: a line style (``pen``) or a band (``brush``)."""

    label: str
    colour: QColor
    style: Qt.PenStyle = Qt.PenStyle.SolidLine
    band: bool = False


class _Legend(pg.LegendItem):
    """pyqtgraph's legend without dragging: it sits in the layout, not over a plot."""

    def hoverEvent(self, ev) -> None:
        pass

    def mouseDragEvent(self, ev) -> None:
        ev.ignore()


class GroupLegend:
    """Title and wrapped entries of one plot group, as one item of the stack's layout."""

    def __init__(self, on_toggle: Callable[[str, bool], None]) -> None:
        self.head = pg.GraphicsLayout()
        self.head.setSpacing(0)
        self._title = pg.LabelItem(color=TEXT, size="9pt", justify="left")
        self._unit = pg.LabelItem(color=TEXT, size="9pt", justify="left")
        self._legend = _Legend(labelTextColor=TEXT, frame=False, horSpacing=ENTRY_GAP // 2)
        # The keys (line styles, bands) on rows of their own under the curves': in one grid
        # the long key names widened every column, and 16 speeds took 6 rows instead of 4.
        self._keys = _Legend(labelTextColor=TEXT, frame=False, horSpacing=ENTRY_GAP // 2)
        for legend in (self._legend, self._keys):
            legend.sigSampleClicked.connect(self._on_clicked)
        self._side = False
        self._arrange()
        self._names: list[str] = []
        self._on_toggle = on_toggle
        self._signature: tuple = ()
        self._labels: dict[object, str] = {}        # sample item → label of the curves it keys
        self._width = 0.0
        self._columns = 0
        self._key_columns = 0
        self.set_title("")

    def _parts(self) -> Iterator[pg.GraphicsWidget]:
        return iter((self._title, self._unit, self._legend, self._keys))

    def _arrange(self) -> None:
        """Above the plots: the title over the unit beside the entries, the keys under
        them. Beside the plots: title, unit, entries and keys one under the other."""
        for item in self._parts():
            if item in self.head.items:
                self.head.removeItem(item)
        if self._side:
            self.head.setContentsMargins(SIDE_MARGIN, 0, 0, 0)
            for row, item in enumerate(self._parts()):
                self.head.addItem(item, row=row, col=0)
        else:
            self.head.setContentsMargins(AXIS_WIDTH, 0, 0, 0)
            self.head.addItem(self._title, row=0, col=0, colspan=2)
            self.head.addItem(self._unit, row=1, col=0)
            self.head.addItem(self._legend, row=1, col=1)
            self.head.addItem(self._keys, row=2, col=1)
        for item in self._parts():
            self.head.layout.setAlignment(item, Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        self.head.setMinimumWidth(0)
        self.head.setMaximumWidth(UNLIMITED)

    def side(self) -> bool:
        """Whether the legend stands beside its plots (else above them)."""
        return self._side

    def set_side(self, side: bool) -> None:
        if side != self._side:
            self._side = side
            self._columns = self._key_columns = 0
            self._arrange()
            self._fit_height()

    def set_title(self, text: str) -> None:
        if self._title.isVisible() == bool(text) and (not text or self._title.text == text):
            return                      # unchanged: setText would lay the head out again
        self._title.setText(text)
        height = ROW_HEIGHT if text else 0
        self._title.setMinimumHeight(height)
        self._title.setMaximumHeight(height)
        self._title.setVisible(bool(text))
        self._fit_height()

    def set_unit(self, text: str) -> None:
        """A short text left of the entries (the speeds' unit, so entries can read "40")."""
        if text != self._unit.text:
            self._unit.setText(text)
            self._unit.setVisible(bool(text))
            self._unit.setMaximumWidth(self._unit.minimumWidth() if text else 0)
            self.fit_width(self._width)

    def title(self) -> str:
        return self._title.text if self._title.isVisible() else ""

    def set_entries(self, entries: list[tuple[str, str, QColor, float]], keys: list[LegendKey],
                    hidden: set[str]) -> bool:
        """Curve entries (label, text shown, colour, pen width) then keys; rebuilt only when
        they change (then True: the legend has new items)."""
        signature = (tuple((label, text, colour.rgba(), width) for label, text, colour, width in entries),
                     tuple(keys))
        if signature == self._signature:
            return False
        self._signature = signature
        self._legend.clear()
        self._keys.clear()
        self._labels.clear()
        self._names = [label for label, *_ in entries] + [key.label for key in keys]
        for label, text, colour, width in entries:
            sample = pg.PlotCurveItem(pen=pg.mkPen(colour, width=width))
            sample.setVisible(label not in hidden)
            self._labels[sample] = label
            self._legend.addItem(sample, text)
        for key in keys:
            if key.band:
                sample = pg.BarGraphItem(x=[0], height=[1], width=1, brush=key.colour,
                                         pen=pg.mkPen(None))
            else:
                sample = pg.PlotCurveItem(pen=pg.mkPen(key.colour, width=KEY_WIDTH, style=key.style))
            self._keys.addItem(sample, key.label)
        self._keys.setVisible(bool(keys))
        self._columns = self._key_columns = 0
        self.fit_width(self._width)
        return True

    def names(self) -> list[str]:
        """The entries' labels (the curves' full labels, then the keys)."""
        return list(self._names)

    def columns(self) -> int:
        return self._columns

    def fit_width(self, width: float) -> None:
        """Above the plots: wrap the entries, then the keys, into as many columns as
        ``width`` px (the view's) holds."""
        self._width = width
        if self._side:
            return
        room = self._room(width)
        self._columns = wrap_legend(self._legend, room, self._columns)
        self._key_columns = wrap_legend(self._keys, room, self._key_columns)
        self._fit_height()

    def top_height(self, width: float) -> float:
        """The height the legend takes above its plots in a view ``width`` px wide."""
        room = self._room(width)
        rows = [math.ceil(len(legend.items) / max(legend_columns(legend, room), 1))
                for legend in (self._legend, self._keys)]
        return self._title_height() + sum(rows) * self._row()

    def fit_side(self, height: float) -> float:
        """Beside plots ``height`` px tall: the entries in the fewest columns whose rows fit
        that height (the keys one a row); the width the legend then takes."""
        count = len(self._legend.items)
        fixed = self._title_height() + (self._row() if self._unit.isVisible() else 0.0)
        fixed += len(self._keys.items) * self._row()
        columns = next((c for c in range(1, count + 1)
                        if fixed + math.ceil(count / c) * self._row() <= height), max(count, 1))
        self._columns = wrap_legend(self._legend, math.inf, self._columns, columns)
        self._key_columns = wrap_legend(self._keys, math.inf, self._key_columns, 1)
        parts = [(self._legend, bool(self._legend.items)), (self._keys, bool(self._keys.items)),
                 (self._unit, self._unit.isVisible()), (self._title, self._title.isVisible())]
        width = SIDE_MARGIN + max([0.0] + [part.maximumWidth() if isinstance(part, pg.LegendItem)
                                           else part.minimumWidth() for part, shown in parts if shown])
        self.head.setMinimumWidth(width)
        self.head.setMaximumWidth(width)
        self._fit_height()
        return width

    def _room(self, width: float) -> float:
        unit = self._unit.minimumWidth() + ENTRY_GAP if self._unit.isVisible() else 0.0
        return width - AXIS_WIDTH - 8.0 - unit

    def _row(self) -> float:
        return max([ROW_HEIGHT] + [label.minimumHeight() for legend in (self._legend, self._keys)
                                   for _, label in legend.items])

    def _title_height(self) -> float:
        return ROW_HEIGHT if self._title.isVisible() else 0.0

    def _fit_height(self) -> None:
        row = self._row()
        height = self._title_height()
        if self._side and self._unit.isVisible():
            height += row                   # the unit over the entries, not beside them
        for legend, columns in ((self._legend, self._columns), (self._keys, self._key_columns)):
            own = math.ceil(len(legend.items) / max(columns, 1)) * row
            legend.setMinimumHeight(own)
            legend.setMaximumHeight(own)
            height += own
        self.head.setMinimumHeight(height)
        self.head.setMaximumHeight(height)

    def _on_clicked(self, item) -> None:
        label = self._labels.get(item)
        if label is None:
            item.setVisible(True)       # a key, not a curve: stays drawn
            return
        self._on_toggle(label, item.isVisible())

