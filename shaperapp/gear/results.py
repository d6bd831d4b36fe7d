"""The pair's results: per gear and for the pair, units in the row titles, and the checks,
each failing one with what to change (core's advice in the UI's language)."""
from __future__ import annotations

import math

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel, QVBoxLayout, QWidget

from core.gear import GearPair, pair_checks
from shaperapp.widgets.messages import ERROR_TEXT_STYLE
from shaperapp.widgets.column_titles import yes_no
from shaperapp.widgets.result_table import ResultTable

from shaperapp.widgets.gear_messages import check_advice, check_name, mode_text
from .model import GearModel


class GearResults(QWidget):
    """Two tables (the gears side by side, then the pair) and the shift rule; the checks'
    label, ``checks``, is placed by the tab."""

    def __init__(self, gear_model: GearModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = gear_model
        self.gears = ResultTable(self)
        self.pair = ResultTable(self)
        self.rule = QLabel(self)
        self.rule.setWordWrap(True)
        self.checks = QLabel(self)
        self.checks.setWordWrap(True)
        self.checks.setTextFormat(Qt.TextFormat.RichText)
        self.checks.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        column = QVBoxLayout(self)
        column.setContentsMargins(0, 0, 0, 0)
        column.addWidget(self.gears)
        column.addWidget(self.pair)
        column.addWidget(self.rule)
        column.addStretch(1)
        gear_model.pairChanged.connect(self.show_pair)
        self.show_pair()

    def gear_rows(self, pair: GearPair) -> list[tuple[str, str, str, str]]:
        """(title: symbol and unit, pinion, gear, the quantity's name) of every per-gear
        result; the short titles keep both gears' columns in view beside the drawing."""
        g = (pair.gear1, pair.gear2)

        def both(title: str, name: str, value) -> tuple[str, str, str, str]:
            return (title, value(g[0]), value(g[1]), name)
        return [both("z", self.tr("Teeth"), lambda x: str(x.teeth)),
                both("x", self.tr("Shift factor"), lambda x: f"{x.shift:.6f}"),
                both("xmin", self.tr("Least shift factor without undercut"), lambda x: f"{x.least_shift:.6f}"),
                both("d, mm", self.tr("Reference diameter"), lambda x: f"{2 * x.r:.4f}"),
                both("db, mm", self.tr("Base diameter"), lambda x: f"{2 * x.rb:.4f}"),
                both("da, mm", self.tr("Tip diameter"), lambda x: f"{2 * x.ra:.4f}"),
                both("df, mm", self.tr("Root diameter"), lambda x: f"{2 * x.rf:.4f}"),
                both("d′, mm", self.tr("Working pitch diameter"), lambda x: f"{2 * x.rw:.4f}"),
                both("s, mm", self.tr("Tooth thickness on the reference circle"), lambda x: f"{x.s:.4f}"),
                both("e, mm", self.tr("Space width on the reference circle"), lambda x: f"{x.e:.4f}"),
                both("sa, mm", self.tr("Tip thickness"), lambda x: f"{x.sa:.4f}"),
                both(self.tr("Undercut"), self.tr("Undercut by the rack (x < xmin)"),
                     lambda x: yes_no(x.undercut))]

    def pair_rows(self, pair: GearPair) -> list[tuple[str, str, str]]:
        """(title: symbol and unit, value, the quantity's name) of every result of the pair."""
        return [("a′, mm", f"{pair.centre_mm:.4f}", self.tr("Centre distance")),
                ("a, mm", f"{pair.reference_centre_mm:.4f}", self.tr("Standard centre distance")),
                ("α′, °", f"{math.degrees(pair.alpha_w):.6f}", self.tr("Working pressure angle")),
                ("y", f"{pair.y:.6f}", self.tr("Centre distance shift factor")),
                ("Δy", f"{pair.dy:.6f}", self.tr("Addendum reduction factor")),
                ("i = z2/z1", f"{pair.gear2.teeth / pair.gear1.teeth:.6f}", self.tr("Ratio")),
                ("pb, mm", f"{pair.pb:.4f}", self.tr("Base pitch")),
                ("N1N2, mm", f"{pair.n1n2:.4f}", self.tr("Line of action between the limit points")),
                ("B1B2, mm", f"{pair.b1b2:.4f}", self.tr("Actual line of action")),
                ("ε", f"{pair.contact_ratio:.6f}", self.tr("Contact ratio"))]

    def check_lines(self, pair: GearPair) -> list[tuple[bool, str]]:
        """(ok, text) per check: its name and value, and when it fails what to change."""
        lines = []
        for check in pair_checks(pair):
            text = check_name(check) + " — " + (self.tr("ok") if check.ok else self.tr("fails: %1")
                                                 .replace("%1", check_advice(check)))
            lines.append((check.ok, text))
        return lines

    def show_pair(self) -> None:
        pair = self._model.pair
        rows = self.gear_rows(pair)
        self.gears.set_content([r[0] for r in rows], [self.tr("Pinion 1"), self.tr("Gear 2")],
                               [r[1:3] for r in rows], [r[3] for r in rows])
        rows2 = self.pair_rows(pair)
        self.pair.set_content([r[0] for r in rows2], [self.tr("Pair")], [r[1:2] for r in rows2],
                              [r[2] for r in rows2])
        self.rule.setText(self.tr("Shifts: %1").replace("%1", mode_text(pair.mode)))
        cells = []
        for ok, text in self.check_lines(pair):
            style = "" if ok else f" style='{ERROR_TEXT_STYLE}'"
            cells.append(f"<div{style}>{'✓' if ok else '✗'} {_escape(text)}</div>")
        self.checks.setText("".join(cells))

    def retranslate(self) -> None:
        self.show_pair()


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
