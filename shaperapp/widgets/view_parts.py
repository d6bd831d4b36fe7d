"""Parts shared by the views that show one crank speed at a time: the speed box and
the bar-above-body layout."""
from __future__ import annotations

from typing import Sequence

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QComboBox, QHBoxLayout, QVBoxLayout, QWidget


def fill_speed_combo(combo: QComboBox, rpms: Sequence[float]) -> None:
    """List ``rpms`` as 'n r/min' without emitting signals; keep the chosen speed when it
    still exists, else the first."""
    values = [float(r) for r in rpms]
    texts = [QCoreApplication.translate("SpeedCombo", "%1 r/min").replace("%1", f"{rpm:g}") for rpm in values]
    if [combo.itemData(i) for i in range(combo.count())] == values and \
            [combo.itemText(i) for i in range(combo.count())] == texts:
        return                          # the same speeds: nothing to redo on an edit
    chosen = combo.currentData()
    combo.blockSignals(True)
    combo.clear()
    for rpm, text in zip(values, texts):
        combo.addItem(text, rpm)
    combo.setCurrentIndex(values.index(chosen) if chosen in values else 0)
    combo.blockSignals(False)


def bar_over_body(owner: QWidget, left: Sequence[QWidget], right: QWidget, body: QWidget,
                  second: Sequence[QWidget] = ()) -> None:
    """Lay out ``owner``: a row of controls (``left`` …, stretch, ``right``) above ``body``;
    ``second`` controls go in a second row, so that a narrow pane holds them all."""
    layout = QVBoxLayout(owner)
    layout.setContentsMargins(4, 4, 4, 4)
    for widgets, end in ((left, right), (second, None)):
        if not widgets:
            continue
        bar = QHBoxLayout()
        for widget in widgets:
            bar.addWidget(widget)
        bar.addStretch(1)
        if end is not None:
            bar.addWidget(end)
        layout.addLayout(bar)
    layout.addWidget(body, 1)
