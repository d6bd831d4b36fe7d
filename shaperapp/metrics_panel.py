"""Synthesized dimensions and measured cycle metrics, beside the form.

Everything shown is read from the model's design and metrics; the panel only
formats numbers. It updates when the model recomputes, so it lags the form by
the debounce only.
"""
from __future__ import annotations

import math

from PySide6.QtCore import QEvent, Qt
from PySide6.QtWidgets import (QAbstractItemView, QFormLayout, QGroupBox, QHeaderView, QLabel,
                               QTableWidget, QTableWidgetItem, QVBoxLayout, QWidget)

from .model import DesignModel
from .style import fmt


class MetricsPanel(QWidget):
    """Read-only view: dimensions (θ, L2, L3, L4, h, guide) and per-speed metrics."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._dim_box = QGroupBox(self)
        self._dim_form = QFormLayout(self._dim_box)
        self._cycle_box = QGroupBox(self)
        self._cycle_form = QFormLayout(self._cycle_box)
        self._labels: dict[str, QLabel] = {}
        self._values: dict[str, QLabel] = {}
        for key in ("theta", "frame", "lever", "rod", "guide", "h", "K_nominal", "H_nominal"):
            self._add_row(self._dim_form, key)
        for key in ("K", "stroke", "work_angle", "return_angle", "pressure"):
            self._add_row(self._cycle_form, key)
        self._table = self._make_table()
        self._forces_title = QLabel(self)
        self._forces_title.setStyleSheet("font-weight: 600; margin-top: 6px;")
        self._forces_table = self._make_table()
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self._dim_box)
        layout.addWidget(self._cycle_box)
        layout.addWidget(self._table)
        layout.addWidget(self._forces_title)
        layout.addWidget(self._forces_table)
        layout.addStretch(1)
        model.resultsChanged.connect(self._show)
        model.forcesChanged.connect(self._show_forces)
        self._retranslate()

    def _make_table(self) -> QTableWidget:
        table = QTableWidget(self)
        table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        table.setSelectionMode(QAbstractItemView.SelectionMode.NoSelection)
        table.verticalHeader().setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        table.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Stretch)
        table.setVerticalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        table.setSizeAdjustPolicy(QAbstractItemView.SizeAdjustPolicy.AdjustToContents)
        return table

    def _add_row(self, form: QFormLayout, key: str) -> None:
        label, value = QLabel(self), QLabel(self)
        value.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        value.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self._labels[key], self._values[key] = label, value
        form.addRow(label, value)

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _row_titles(self) -> list[tuple[str, str]]:
        return [
            ("cycle_time_s", self.tr("Cycle time, s")),
            ("work_time_s", self.tr("Working time, s")),
            ("return_time_s", self.tr("Return time, s")),
            ("v_work_max_m_s", self.tr("Max cutting speed, m/s")),
            ("v_work_mean_m_s", self.tr("Mean cutting speed, m/s")),
            ("v_return_max_m_s", self.tr("Max return speed, m/s")),
            ("a_max_m_s2", self.tr("Max |acceleration|, m/s²")),
            ("lever_omega_max_rad_s", self.tr("Max lever ω, rad/s")),
            ("lever_alpha_max_rad_s2", self.tr("Max lever α, rad/s²")),
        ]

    def _force_rows(self) -> list[tuple[str, str, float, str]]:
        """(attribute, title, scale, format) of the per-speed load values."""
        return [
            ("mean_torque_N_m", self.tr("Mean crank torque, N·m"), 1.0, ".1f"),
            ("max_torque_N_m", self.tr("Max crank torque, N·m"), 1.0, ".1f"),
            ("mean_power_W", self.tr("Motor power (before efficiency), kW"), 1e-3, ".3f"),
            ("max_power_W", self.tr("Peak input power, kW"), 1e-3, ".3f"),
            ("energy_fluctuation_J", self.tr("Energy fluctuation ΔW_max, J"), 1.0, ".1f"),
            ("flywheel_inertia_kg_m2", self.tr("Flywheel J_F on crank shaft, kg·m²"), 1.0, ".2f"),
            ("flywheel_inertia_net_kg_m2", self.tr("J_F less mechanism's own, kg·m²"), 1.0, ".2f"),
        ]

    def _retranslate(self) -> None:
        self._forces_title.setText(self.tr("Forces and flywheel"))
        self._forces_title.setToolTip(self.tr("Constant crank speed; loads as set in the Forces tab"))
        self._cycle_box.setTitle(self.tr("Measured cycle"))
        titles = {
            "theta": (self.tr("Extreme-position angle θ"), self.tr("Crank angle between the two limit positions; equals the lever swing")),
            "frame": (self.tr("Frame O2O4 L2"), self.tr("Distance from crank centre to lever pivot")),
            "lever": (self.tr("Lever O4B L3"), self.tr("Length of the slotted lever")),
            "rod": (self.tr("Rod BC L4"), self.tr("Connecting-rod length (rod variant)")),
            "guide": (self.tr("Guide above O4"), self.tr("Height of the ram guide line above the lever pivot")),
            "h": (self.tr("Guide above O2, h"), self.tr("Height of the ram guide line above the crank centre")),
            "K_nominal": (self.tr("K of the dimensions"), self.tr("(π + θ)/(π − θ)")),
            "H_nominal": (self.tr("H of the dimensions"), self.tr("2·L3·sin(θ/2)")),
            "K": (self.tr("Measured K"), self.tr("Working / return crank angle, from the ram's dead points")),
            "stroke": (self.tr("Measured stroke"), self.tr("Distance between the ram's dead points")),
            "work_angle": (self.tr("Working crank angle"), self.tr("Crank rotation during the cutting stroke")),
            "return_angle": (self.tr("Return crank angle"), self.tr("Crank rotation during the return stroke")),
            "pressure": (self.tr("Max pressure angle at ram"), self.tr("Largest angle between the rod and the guide")),
        }
        for key, (text, tip) in titles.items():
            self._labels[key].setText(text)
            self._labels[key].setToolTip(tip)
        self._show()
        self._show_forces()

    def _show(self) -> None:
        design, metrics = self._model.design, self._model.metrics
        self._dim_box.setTitle(self.tr("Synthesized dimensions") if self._model.valid_spec.mode == "synthesis"
                               else self.tr("Dimensions"))
        mm = self.tr("%1 mm")
        deg = self.tr("%1°")
        values = {
            "theta": deg.replace("%1", fmt(math.degrees(design.theta), ".3f")),
            "frame": mm.replace("%1", fmt(design.frame, ".2f")),
            "lever": mm.replace("%1", fmt(design.lever, ".2f")),
            "rod": mm.replace("%1", fmt(design.rod, ".2f")) if design.rod is not None else "—",
            "guide": mm.replace("%1", fmt(design.guide, ".2f")),
            "h": mm.replace("%1", fmt(design.guide_above_crank, ".2f")),
            "K_nominal": fmt(design.time_ratio, ".4f"),
            "H_nominal": mm.replace("%1", fmt(design.stroke, ".2f")),
            "K": fmt(metrics.time_ratio, ".4f"),
            "stroke": mm.replace("%1", fmt(metrics.stroke_mm, ".2f")),
            "work_angle": deg.replace("%1", fmt(metrics.work_angle_deg, ".2f")),
            "return_angle": deg.replace("%1", fmt(metrics.return_angle_deg, ".2f")),
            "pressure": (deg.replace("%1", fmt(metrics.pressure_angle_max_deg, ".2f"))
                         if metrics.pressure_angle_max_deg is not None else "—"),
        }
        for key, text in values.items():
            self._values[key].setText(text)
        rows = [(attr, title, 1.0, ".4f") for attr, title in self._row_titles()]
        self._fill(self._table, rows, metrics.speeds)

    def _show_forces(self) -> None:
        self._fill(self._forces_table, self._force_rows(), self._model.dynamics_summary.speeds)

    def _fill(self, table: QTableWidget, rows: list[tuple[str, str, float, str]], speeds) -> None:
        """One column per crank speed, one row per value, numbers right-aligned.

        Cells are created once and then only get new text: creating and announcing
        QTableWidgetItems one by one was the slowest part of an edit (about 10 ms)."""
        titles = [title for _, title, _, _ in rows]
        heads = [self.tr("%1 r/min").replace("%1", f"{s.rpm:g}") for s in speeds]
        if table.rowCount() != len(rows) or table.columnCount() != len(speeds):
            table.setRowCount(len(rows))
            table.setColumnCount(len(speeds))
        if [table.verticalHeaderItem(r) and table.verticalHeaderItem(r).text()
                for r in range(len(rows))] != titles:
            table.setVerticalHeaderLabels(titles)
        if [table.horizontalHeaderItem(c) and table.horizontalHeaderItem(c).text()
                for c in range(len(speeds))] != heads:
            table.setHorizontalHeaderLabels(heads)
        # New texts with the model's signals blocked, then one repaint: every single
        # dataChanged would re-measure the header (rows keep their one-line height).
        table.model().blockSignals(True)
        try:
            for col, speed in enumerate(speeds):
                for row, (attr, _, scale, spec) in enumerate(rows):
                    text = fmt(getattr(speed, attr) * scale, spec)
                    item = table.item(row, col)
                    if item is None:
                        item = QTableWidgetItem(text)
                        item.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
                        table.setItem(row, col, item)
                    elif item.text() != text:
                        item.setText(text)
        finally:
            table.model().blockSignals(False)
        table.viewport().update()

    def value_text(self, key: str) -> str:
        """The text shown for one dimension or cycle value (for tests)."""
        return self._values[key].text()

    def table_text(self, row: int, column: int, forces: bool = False) -> str:
        item = (self._forces_table if forces else self._table).item(row, column)
        return item.text() if item else ""
