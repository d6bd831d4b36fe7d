"""Force diagrams: what the loads cost the motor over one crank revolution.

The forces view configures the shared plot stack (stack.py) with crank torque
(with each speed's mean as a dashed line), input power and the cumulative energy
ΔE(φ), one curve per crank speed, and the joint-force magnitudes of one chosen
speed; the cutting zone is shaded. Everything drawn comes from ``model.dynamics``
and ``model.cycle_summary(peaks=False)``; this module only converts units, takes
|F| = hypot(Fx, Fy) and finds where the cutting force is on.
"""
from __future__ import annotations

import math

import numpy as np
from PySide6.QtCore import Qt
from PySide6.QtGui import QColor
from PySide6.QtWidgets import QComboBox, QLabel, QVBoxLayout, QWidget

from core.forces.dynamics import Dynamics

from shaperapp.design.model import DesignModel
from shaperapp.widgets.style import crank_text, speed_colour

from .curves import Band, Curve
from .legend import LegendKey
from .series import Series
from .stack import PlotStack
from .stack_view import StackView

SPEED_PLOTS = ("torque", "power", "energy")      # one curve per crank speed
PLOT_NAMES = SPEED_PLOTS + ("force",)
UNITS = {"torque": "N·m", "power": "kW", "energy": "J", "force": "kN"}
JOINTS = ("O2", "A", "O4", "B", "C", "guide")
JOINT_COLOURS = {"O2": QColor("#6a3d9a"), "A": QColor("#1f78b4"), "O4": QColor("#33a02c"),
                 "B": QColor("#ff7f00"), "C": QColor("#e31a1c"), "guide": QColor("#455a64")}
# A carries O2's force when the block is light, C nearly B's when the rod is: dashed,
# so the curve beneath shows through the gaps.
JOINT_STYLES = {"A": Qt.PenStyle.DashLine, "C": Qt.PenStyle.DashLine, "guide": Qt.PenStyle.DotLine}
CUT_FILL = QColor(239, 108, 0, 30)       # light orange band where the tool cuts
CUT_TEXT = QColor(191, 54, 12)
KEY = QColor("#616161")
MEAN_WIDTH = 1.2


def cutting_spans(angle_deg: np.ndarray, cut: np.ndarray) -> list[tuple[float, float]]:
    """(first, last) crank angle of each contiguous run of grid points with a cutting force."""
    on = np.concatenate(([0], (np.asarray(cut) != 0.0).astype(np.int8), [0]))
    edges = np.flatnonzero(np.diff(on))
    return [(float(angle_deg[s]), float(angle_deg[e - 1])) for s, e in zip(edges[::2], edges[1::2])]


def joint_forces(dyn: Dynamics, speed: int) -> dict[str, np.ndarray | None]:
    """|F| in kN of every joint at one speed; None for C in the block variant.

    The guide is a signed normal force in core; its magnitude is drawn so the
    plot reads as one family of |F| curves."""
    pairs = {"O2": (dyn.o2_x, dyn.o2_y), "A": (dyn.a_x, dyn.a_y), "O4": (dyn.o4_x, dyn.o4_y),
             "B": (dyn.b_x, dyn.b_y), "C": (dyn.c_x, dyn.c_y)}
    out: dict[str, np.ndarray | None] = {
        name: None if x is None else np.hypot(x[speed], y[speed]) * 1e-3
        for name, (x, y) in pairs.items()}
    out["guide"] = np.abs(dyn.guide_normal[speed]) * 1e-3
    return out


class ForcePlots(StackView):
    """Torque, power, energy and joint-force plots over one revolution."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._names = self._axis_titles = {}
        self._retranslate_names()
        series = [Series(name, UNITS[name], lambda n=name: self._names[n],
                         lambda n=name: self._axis_titles[n], lambda model, n=name: self._curves(n),
                         group="joints" if name == "force" else "speeds")
                  for name in PLOT_NAMES]
        self._stack = PlotStack(model, self, series, lambda: self.tr("Shaper forces and torque"))
        self._speed_label = QLabel()
        self._speed_combo = QComboBox()
        self._speed_combo.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToContents)
        self._stack.add_tool(self._speed_label)
        self._stack.add_tool(self._speed_combo)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self._stack)
        self._speed_combo.currentIndexChanged.connect(self._stack.invalidate)
        self._stack.clicked.connect(model.set_angle_deg)
        model.forcesChanged.connect(self._on_forces)
        self._retranslate()
        self._on_forces()

    # ---- public API ----------------------------------------------------
    def curve_data(self, name: str) -> list[tuple[np.ndarray, np.ndarray]]:
        """(x in °, y) as drawn.

        ``torque`` (N·m), ``power`` (kW), ``energy`` (J): one pair per speed;
        ``force:O2`` … ``force:guide`` (kN): one pair for the selected speed, none
        for ``force:C`` in the block variant."""
        if name.startswith("force:"):
            label = self._joint_symbols()[name.split(":", 1)[1]]
            return [(c.x, c.y) for c in self._stack.plot("force").curves if c.label == label]
        return self._stack.plot(name).data()

    def mean_torque_lines(self) -> list[float]:
        """y of the dashed mean-torque lines, one per speed, N·m."""
        return [float(y[0]) for _, y in self._stack.plot("torque").data("mean")]

    def cut_spans(self) -> list[tuple[float, float]]:
        """Shaded cutting zones, (start, end) in °."""
        return self._stack.plot("torque").bands()

    def selected_speed(self) -> int:
        """Index of the speed whose joint forces are drawn."""
        return max(self._speed_combo.currentIndex(), 0)

    def set_selected_speed(self, index: int) -> None:
        self._speed_combo.setCurrentIndex(index)

    def speed_names(self) -> list[str]:
        return [self._speed_combo.itemText(i) for i in range(self._speed_combo.count())]

    def legend_names(self, which: str = "speeds") -> list[str]:
        """Legend entries of the speed plots (``speeds``) or the joint-force plot (``joints``)."""
        return self._stack.legend(which).names()

    def cursor_value(self) -> float:
        """Crank angle of the cursor lines, °."""
        return self._stack.plot("torque").cursor_positions()[0]

    # ---- what the stack draws -------------------------------------------
    def _curves(self, name: str) -> list[Curve]:
        dyn, summary = self._model.dynamics, self._model.cycle_summary(peaks=False)
        degrees = np.degrees(dyn.crank_angle)
        labels = [self.speed_name(float(r)) for r in dyn.rpm]
        if name == "force":
            speed = min(self.selected_speed(), dyn.rpm.size - 1)
            symbols = self._joint_symbols()
            return [Curve(degrees, values, symbols[joint], JOINT_COLOURS[joint],
                          JOINT_STYLES.get(joint, Qt.PenStyle.SolidLine))
                    for joint, values in joint_forces(dyn, speed).items() if values is not None]
        if name == "energy":
            x, rows = np.degrees(summary.crank_angle), summary.energy
        else:
            x, rows = degrees, dyn.crank_torque if name == "torque" else dyn.power * 1e-3
        curves = [Curve(x, row, label, speed_colour(i), short=f"{float(rpm):g}")
                  for i, (row, label, rpm) in enumerate(zip(rows, labels, dyn.rpm))]
        if name == "torque":        # each speed's mean torque, dashed in its colour
            ends = np.array([0.0, 360.0])
            curves += [Curve(ends, np.full(2, s.mean_torque_N_m), label, speed_colour(i),
                             Qt.PenStyle.DashLine, MEAN_WIDTH, legend=False, readout=False,
                             role="mean")
                       for i, (s, label) in enumerate(zip(summary.speeds, labels))]
        return curves

    def bands(self) -> list[Band]:
        """The cutting zone; the longest span carries the label."""
        dyn = self._model.dynamics
        spans = cutting_spans(np.degrees(dyn.crank_angle), dyn.cut_force[0])
        longest = max(range(len(spans)), key=lambda i: spans[i][1] - spans[i][0], default=-1)
        return [Band(a, b, CUT_FILL, self.tr("cutting") if i == longest else "", CUT_TEXT)
                for i, (a, b) in enumerate(spans)]

    def legend_keys(self) -> dict[str, list[LegendKey]]:
        return {"speeds": [LegendKey(self.tr("mean torque"), KEY, Qt.PenStyle.DashLine),
                           LegendKey(self.tr("cutting"), CUT_FILL, band=True)]}

    def group_titles(self) -> dict[str, str]:
        dyn = self._model.dynamics
        speed = min(self.selected_speed(), dyn.rpm.size - 1)
        return {"joints": self.tr("Joint forces at {0}").format(self.speed_name(float(dyn.rpm[speed])))}

    def legend_units(self) -> dict[str, str]:
        return {"speeds": self.tr("r/min:")}

    def x_axis(self) -> tuple[str, float, float, bool]:
        return self.tr("Crank angle φ (°)"), 0.0, 360.0, True

    def x_text(self, x: float) -> str:
        return self.tr("φ = {0}°").format(crank_text(x))

    def cursor_x(self, index: int) -> float:
        return math.degrees(float(self._model.motion.crank_angle[index]))

    # ---- model → view --------------------------------------------------
    def _on_forces(self) -> None:
        """List the speeds (keeping the chosen one while it exists), then redraw when shown."""
        rpms = [float(r) for r in self._model.dynamics.rpm]
        combo = self._speed_combo
        if [combo.itemData(i) for i in range(combo.count())] != rpms:
            chosen = combo.currentData()
            combo.blockSignals(True)
            combo.clear()
            for rpm in rpms:
                combo.addItem(self.speed_name(rpm), rpm)
            combo.setCurrentIndex(rpms.index(chosen) if chosen in rpms else 0)
            combo.blockSignals(False)
        self._stack.invalidate()

    # ---- text ----------------------------------------------------------
    def _retranslate_names(self) -> None:
        # Full names for the read-out; axis titles short enough for a plot ~120 px tall.
        self._names = {"torque": self.tr("Crank driving torque"), "power": self.tr("Input power"),
                       "energy": self.tr("Cumulative excess energy ΔE"),
                       "force": self.tr("Joint force magnitudes")}
        self._axis_titles = {"torque": self.tr("Crank torque"), "power": self.tr("Input power"),
                             "energy": self.tr("Energy ΔE"), "force": self.tr("Joint force |F|")}

    def _joint_symbols(self) -> dict[str, str]:
        """Legend names: the joints as the scheme labels them."""
        return {"O2": "O₂", "A": "A", "O4": "O₄", "B": "B", "C": "C", "guide": self.tr("guide")}

    def _retranslate(self) -> None:
        self._retranslate_names()
        self._speed_label.setText(self.tr("Joint forces at:"))
        self._speed_combo.setToolTip(self.tr("Crank speed whose joint forces are plotted"))
        for i in range(self._speed_combo.count()):
            self._speed_combo.setItemText(i, self.speed_name(self._speed_combo.itemData(i)))
        self._stack.retranslate()
