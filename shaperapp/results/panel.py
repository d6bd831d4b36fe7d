"""The results pane: dimensions, measured cycle, per-speed figures, forces and flywheel.

Four tables (``result_table.ResultTable``: every row shown, titles with units, cells
selectable and copyable). Everything shown is read from the model's design, metrics
and dynamics summary; the pane only formats numbers. A hidden pane (a closed or
tabbed-away dock) does nothing on an edit and catches up when shown; reading a value
(``value_text``, ``table_text``) always gives the current results.
"""
from __future__ import annotations

import math

from PySide6.QtCore import QCoreApplication, QEvent, QPoint
from PySide6.QtWidgets import QAbstractScrollArea, QGroupBox, QVBoxLayout, QWidget

from core.base.figure_text import figure_text

from shaperapp.design.model import DesignModel
from shaperapp.widgets.result_table import ResultTable

DIMENSIONS = ("theta", "frame", "lever", "rod", "guide", "h", "K_nominal", "H_nominal")
CYCLE = ("K", "stroke", "work_angle", "return_angle", "pressure")
# the per-speed rows' kinds of figure (core.base.figure_text: one precision per kind everywhere)
_SPEED_KINDS = {"cycle_time_s": "time", "work_time_s": "time", "return_time_s": "time",
                "v_work_max_m_s": "speed", "v_work_mean_m_s": "speed", "v_return_max_m_s": "speed",
                "a_max_m_s2": "acceleration", "lever_omega_max_rad_s": "angular_speed",
                "lever_alpha_max_rad_s2": "angular_speed"}
UNITS = {"theta": "°", "frame": "mm", "lever": "mm", "rod": "mm", "guide": "mm", "h": "mm",
         "K_nominal": "", "H_nominal": "mm", "K": "", "stroke": "mm", "work_angle": "°",
         "return_angle": "°", "pressure": "°"}


class MetricsPanel(QWidget):
    """Read-only results: dimensions, measured cycle, and per-speed kinematic and load figures."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._stale = self._forces_stale = True
        self._watched: QWidget | None = None        # the scroll area followed, once shown
        self._placeholders: tuple | None = None     # (row titles, headings) shown with "…"
        self._dim_box, self._dim_table = self._section()
        self._cycle_box, self._cycle_table = self._section()
        self._speed_box, self._table = self._section()
        self._forces_box, self._forces_table = self._section()
        self._forces_table.before_read = self._catch_up      # a copy never takes placeholders
        layout = QVBoxLayout(self)
        layout.setContentsMargins(2, 2, 2, 2)
        for box in (self._dim_box, self._cycle_box, self._speed_box, self._forces_box):
            layout.addWidget(box)
        layout.addStretch(1)
        model.resultsChanged.connect(self._on_results)
        model.forcesChanged.connect(self._on_forces)
        self._retranslate()

    def _section(self) -> tuple[QGroupBox, ResultTable]:
        box = QGroupBox(self)
        table = ResultTable(box)
        column = QVBoxLayout(box)
        column.setContentsMargins(4, 4, 4, 4)
        column.addWidget(table)
        return box, table

    # ---- public --------------------------------------------------------------
    def tables(self) -> list[ResultTable]:
        """The four tables, top to bottom."""
        return [self._dim_table, self._cycle_table, self._table, self._forces_table]

    def value_text(self, key: str) -> str:
        """The number shown for one dimension or cycle value (its unit is in the row title)."""
        self._catch_up()
        if key in DIMENSIONS:
            return self._dim_table.text(DIMENSIONS.index(key), 0)
        return self._cycle_table.text(CYCLE.index(key), 0)

    def row_title(self, key: str) -> str:
        """The title of one dimension or cycle row, with its unit."""
        table, keys = (self._dim_table, DIMENSIONS) if key in DIMENSIONS else (self._cycle_table, CYCLE)
        return table.verticalHeaderItem(keys.index(key)).text()

    def table_text(self, row: int, column: int, forces: bool = False) -> str:
        """A cell of the per-speed table (or of the forces and flywheel table)."""
        self._catch_up()
        return (self._forces_table if forces else self._table).text(row, column)

    # ---- lazy updates --------------------------------------------------------
    def _on_results(self) -> None:
        self._show_title()               # cheap, and a closed pane shows the right title when opened
        self._stale = True               # the forces table waits for forcesChanged, which follows
        if self.isVisible():
            self._catch_up(unseen=False)

    def _on_forces(self) -> None:
        self._forces_stale = True
        if self.isVisible():
            self._catch_up(unseen=False)

    def _catch_up(self, unseen: bool = True) -> None:
        """Fill what is stale. The forces table only where it can be seen (``unseen``
        fills it anyway, for read-backs): it is usually scrolled below the fold, and
        filling it solves the cycle summary, the largest part of an edit."""
        if self._stale:
            self._stale = False
            self._show()
        if self._forces_stale and (unseen or not self._forces_table.visibleRegion().isEmpty()):
            self._forces_stale = False
            self._show_forces()
        elif self._forces_stale:
            self._shape_forces()

    def showEvent(self, event) -> None:
        super().showEvent(event)
        self._watch_scrolling()
        self._catch_up(unseen=False)

    def _watch_scrolling(self) -> None:
        """Follow the pane's scroll area, so that the forces table is filled as it is
        scrolled into view (before the scrolled pane is painted)."""
        area = self.parentWidget()
        while area is not None and not isinstance(area, QAbstractScrollArea):
            area = area.parentWidget()
        if area is None or area is self._watched:
            return
        self._watched = area
        for bar in (area.verticalScrollBar(), area.horizontalScrollBar()):
            bar.valueChanged.connect(lambda _: self._catch_up(unseen=False))
        area.verticalScrollBar().valueChanged.connect(self._pin_headers)

    def _pin_headers(self) -> None:
        """Each table's column titles stay in view while the pane scrolls its rows."""
        port = self._watched.viewport()
        for table in self.tables():
            table.pin_header(-table.mapTo(port, QPoint(0, 0)).y())

    def paintEvent(self, event) -> None:
        """Any other way into view (the pane resized, a layout change) repaints the pane
        before its tables: fill the forces table first."""
        if self._forces_stale:
            self._catch_up(unseen=False)
        super().paintEvent(event)

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
        """(attribute, title, scale, kind of ``core.base.figure_text``) of the per-speed load values."""
        return [
            ("mean_torque_N_m", self.tr("Mean crank torque, N·m"), 1.0, "torque"),
            ("max_torque_N_m", self.tr("Max crank torque, N·m"), 1.0, "torque"),
            ("mean_power_W", self.tr("Motor power (before efficiency), kW"), 1e-3, "power"),
            ("max_power_W", self.tr("Peak input power, kW"), 1e-3, "power"),
            ("energy_fluctuation_J", self.tr("Energy fluctuation ΔW_max, J"), 1.0, "energy"),
            ("flywheel_inertia_kg_m2", self.tr("Flywheel J_F on crank shaft, kg·m²"), 1.0, "inertia"),
        ] + ([("flywheel_inertia_net_kg_m2", self.tr("J_F less mechanism's own, kg·m²"), 1.0, "inertia")]
             if not self._model.masses.rotors else
             # with the other rotating parts (Loads › Rotating parts) the net value subtracts
             # J_c too: shown as "J_F less mechanism's own" it read 1831 beside J_F 1838 and
             # J_e 0.93 (J_c 5.5); the rows are shaper dynamics's, the flywheel needed first
             [("flywheel_inertia_needed_kg_m2", self.tr("Flywheel needed J_F − J_c, kg·m²"), 1.0, "inertia"),
              ("flywheel_inertia_net_kg_m2", self.tr("J_F − J_c − J_e (net), kg·m²"), 1.0, "inertia")])

    def _names(self) -> dict[str, tuple[str, str]]:
        """(title, tooltip) of every dimension and cycle row."""
        return {
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

    def _retranslate(self) -> None:
        self._cycle_box.setTitle(self.tr("Measured cycle"))
        self._speed_box.setTitle(self.tr("Per crank speed"))
        self._forces_box.setTitle(self.tr("Forces and flywheel"))
        self._forces_box.setToolTip(self.tr("Constant crank speed; loads as set in the Loads inputs"))
        self._forces_stale = True        # its row titles are translated too
        self._on_results()

    def _show_title(self) -> None:
        self._dim_box.setTitle(self.tr("Synthesized dimensions") if self._model.valid_spec.mode == "synthesis"
                               else self.tr("Dimensions"))

    def _show(self) -> None:
        design, metrics = self._model.design, self._model.metrics
        values = {
            "theta": figure_text("angle", math.degrees(design.theta)),
            "frame": figure_text("length", design.frame),
            "lever": figure_text("length", design.lever),
            "rod": figure_text("length", design.rod) if design.rod is not None else "—",
            "guide": figure_text("length", design.guide),
            "h": figure_text("length", design.guide_above_crank),
            "K_nominal": figure_text("ratio", design.time_ratio),
            "H_nominal": figure_text("length", design.stroke),
            "K": figure_text("ratio", metrics.time_ratio),
            "stroke": figure_text("length", metrics.stroke_mm),
            "work_angle": figure_text("angle", metrics.work_angle_deg),
            "return_angle": figure_text("angle", metrics.return_angle_deg),
            "pressure": (figure_text("angle", metrics.pressure_angle_max_deg)
                         if metrics.pressure_angle_max_deg is not None else "—"),
        }
        names = self._names()
        with_unit = self.tr("%1, %2")
        for table, keys in ((self._dim_table, DIMENSIONS), (self._cycle_table, CYCLE)):
            titles = [with_unit.replace("%1", names[k][0]).replace("%2", UNITS[k]) if UNITS[k]
                      else names[k][0] for k in keys]
            table.set_content(titles, [self.tr("Value")], [[values[k]] for k in keys],
                              [names[k][1] for k in keys])
        rows = [(attr, title, 1.0, _SPEED_KINDS[attr]) for attr, title in self._row_titles()]
        self._fill(self._table, rows, metrics.speeds)

    def _show_forces(self) -> None:
        self._placeholders = None
        self._fill(self._forces_table, self._force_rows(), self._model.dynamics_summary.speeds)

    def _shape_forces(self) -> None:
        """The forces table's rows and columns with placeholders, without solving the
        summary: the pane keeps its size and scroll range while the numbers wait until
        the table comes into view (they are filled before it is painted)."""
        rows = self._force_rows()
        heads = self._heads(self._model.rpms)
        titles = [title for _, title, _, _ in rows]
        if (titles, heads) == self._placeholders:
            return                          # already this shape, with placeholders
        self._forces_table.set_content(titles, heads, [["…"] * len(heads) for _ in rows])
        self._placeholders = (titles, heads)

    def _heads(self, rpms) -> list[str]:
        return [self.tr("%1 r/min").replace("%1", f"{rpm:g}") for rpm in rpms]

    def _fill(self, table: ResultTable, rows: list[tuple[str, str, float, str]], speeds) -> None:
        """One column per crank speed, one row per value."""
        heads = self._heads(s.rpm for s in speeds)
        none = QCoreApplication.translate("Report", "none needed (J_c ≥ J_F)")     # the report's words
        cells = [[none if attr == "flywheel_inertia_needed_kg_m2" and getattr(speed, attr) == 0.0 else
                  figure_text(kind, getattr(speed, attr) * scale)     # undefined: "—", never "nan"
                  for speed in speeds]
                 for attr, _, scale, kind in rows]
        table.set_content([title for _, title, _, _ in rows], heads, cells)
