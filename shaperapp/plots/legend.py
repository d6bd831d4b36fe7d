"""The legend of one group of stacked plots: an optional title over entries that wrap.

The legend is a row of its own above its plots, so it never hides a curve, and it
wraps into as many columns as the view's width holds (pyqtgraph's LegendItem
``setColumnCount``), so 16 speeds stay readable in a narrow pane instead of
pushing the plots out of it. An entry stands for every curve with its label: a
click on it hides or shows all of them (``on_toggle``); keys that are not curves
(line styles, shaded bands) only explain and cannot be switched off.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtGui import QColor

from shaperapp.widgets.legend_wrap import wrap_legend
from shaperapp.widgets.style import TEXT

from .axes import AXIS_WIDTH

ROW_HEIGHT = 20          # px per legend row (the samples are 20 px high)
ENTRY_GAP = 14           # px between two entries on a row
KEY_WIDTH = 1.6


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
        self.head.setContentsMargins(AXIS_WIDTH, 0, 0, 0)
        self.head.setSpacing(0)
        self._title = pg.LabelItem(color=TEXT, size="9pt", justify="left")
        self._unit = pg.LabelItem(color=TEXT, size="9pt", justify="left")
        self._legend = _Legend(labelTextColor=TEXT, frame=False, horSpacing=ENTRY_GAP // 2)
        self.head.addItem(self._title, row=0, col=0, colspan=2)
        self.head.addItem(self._unit, row=1, col=0)
        # The keys (line styles, bands) on rows of their own under the curves': in one grid
        # the long key names widened every column, and 16 speeds took 6 rows instead of 4.
        self._keys = _Legend(labelTextColor=TEXT, frame=False, horSpacing=ENTRY_GAP // 2)
        self.head.addItem(self._legend, row=1, col=1)
        self.head.addItem(self._keys, row=2, col=1)
        for legend in (self._legend, self._keys):
            self.head.layout.setAlignment(legend, Qt.AlignmentFlag.AlignLeft)
            legend.sigSampleClicked.connect(self._on_clicked)
        self.head.layout.setAlignment(self._unit, Qt.AlignmentFlag.AlignTop)
        self._names: list[str] = []
        self._on_toggle = on_toggle
        self._signature: tuple = ()
        self._labels: dict[object, str] = {}        # sample item → label of the curves it keys
        self._width = 0.0
        self._columns = 0
        self._key_columns = 0
        self.set_title("")

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
        """Wrap the entries, then the keys, into as many columns as ``width`` px (the
        view's) holds."""
        self._width = width
        unit = self._unit.minimumWidth() + ENTRY_GAP if self._unit.isVisible() else 0.0
        room = width - AXIS_WIDTH - 8.0 - unit
        self._columns = wrap_legend(self._legend, room, self._columns)
        self._key_columns = wrap_legend(self._keys, room, self._key_columns)
        self._fit_height()

    def _fit_height(self) -> None:
        row = max([ROW_HEIGHT] + [label.minimumHeight() for legend in (self._legend, self._keys)
                                  for _, label in legend.items])
        height = 0
        for legend, columns in ((self._legend, self._columns), (self._keys, self._key_columns)):
            own = math.ceil(len(legend.items) / max(columns, 1)) * row
            legend.setMinimumHeight(own)
            legend.setMaximumHeight(own)
            height += own
        title = ROW_HEIGHT if self._title.isVisible() else 0
        self.head.setMinimumHeight(height + title)
        self.head.setMaximumHeight(height + title)

    def _on_clicked(self, item) -> None:
        label = self._labels.get(item)
        if label is None:
            item.setVisible(True)       # a key, not a curve: stays drawn
            return
        self._on_toggle(label, item.isVisible())

