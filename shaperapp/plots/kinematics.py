"""Motion diagrams: ram and lever motion over one crank revolution.

The kinematics view configures the shared plot stack (stack.py) with six
series — ram displacement, velocity, acceleration and the lever's angle, ω and α,
one curve per crank speed — and chooses the x axis: crank angle, with the strokes
shaded, or time, each speed on its own time scale with the return stroke dashed
and a cursor per speed. All numbers come from ``model.motion`` and
``model.metrics``; this module only chooses what to draw.
"""
from __future__ import annotations

import math

import numpy as np
from PySide6.QtGui import QAction, QColor, Qt
from PySide6.QtWidgets import QComboBox, QLabel, QMenu, QToolButton, QVBoxLayout, QWidget

from shaperapp.design.model import DesignModel
from shaperapp.widgets.style import RETURN_FILL, WORK_FILL, crank_text, fmt, speed_colour

from .curves import Band, Curve
from .legend import LegendKey
from .series import Series
from .stack import PlotStack
from .stack_view import StackView

PLOT_NAMES = ("ram_x", "ram_v", "ram_a", "lever_angle", "lever_omega", "lever_alpha")
LEVER_PLOTS = PLOT_NAMES[3:]
UNITS = {"ram_x": "mm", "ram_v": "m/s", "ram_a": "m/s²", "lever_angle": "°",
         "lever_omega": "rad/s", "lever_alpha": "rad/s²"}
SHARED_PLOTS = ("ram_x", "lever_angle")   # against the crank angle the same at every speed
ANGLE, TIME = "angle", "time"
TOLERANCE_DEG = 1e-6     # a limit within this of a grid angle counts as on it
SHARED = QColor("#37474f")   # curves that are the same at every speed (positions vs. angle)
KEY = QColor("#616161")
WORK_TEXT, RETURN_TEXT = QColor(46, 110, 50), QColor(170, 40, 40)


def motion_values(model: DesignModel, name: str) -> np.ndarray:
    """The (speeds, angles) array drawn in plot ``name``; the lever angle in degrees."""
    motion = model.motion
    m = motion.rpm.size
    if name == "ram_x":
        return np.broadcast_to(motion.ram_x, (m, motion.ram_x.size))
    if name == "lever_angle":
        return np.broadcast_to(np.degrees(motion.lever_angle), (m, motion.lever_angle.size))
    return getattr(motion, name)


class PlotsWidget(StackView):
    """Ram displacement, velocity, acceleration and optional lever plots of one cycle."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._mode = ANGLE
        self._names = self._axis_titles = {}
        series = [Series(name, UNITS[name], lambda n=name: self._names[n],
                         lambda n=name: self._axis_titles[n],
                         lambda model, n=name: self._curves(n)) for name in PLOT_NAMES]
        self._retranslate_names()
        self._stack = PlotStack(model, self, series, lambda: self.tr("Shaper motion diagrams"),
                                hidden=LEVER_PLOTS)

        self._x_label = QLabel()
        self._x_combo = QComboBox()
        self._x_combo.addItems(["", ""])
        self._lever_button = QToolButton()
        self._lever_button.setPopupMode(QToolButton.ToolButtonPopupMode.InstantPopup)
        # The style's menu arrow sits on the text's last letter; a ▾ after the text instead.
        self._lever_button.setStyleSheet("QToolButton::menu-indicator { image: none; width: 0px; }")
        self._lever_menu = QMenu(self)
        self._lever_actions: dict[str, QAction] = {}
        for name in LEVER_PLOTS:
            action = QAction(self)
            action.setCheckable(True)
            action.toggled.connect(lambda on, n=name: self.set_plot_visible(n, on))
            self._lever_menu.addAction(action)
            self._stack.add_menu_action(action)
            self._lever_actions[name] = action
        self._lever_button.setMenu(self._lever_menu)
        for widget in (self._x_label, self._x_combo, self._lever_button):
            self._stack.add_tool(widget)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self._stack)

        self._x_combo.currentIndexChanged.connect(
            lambda i: self.set_x_mode(TIME if i == 1 else ANGLE))
        self._stack.clicked.connect(self._on_click)
        model.resultsChanged.connect(self._stack.invalidate)
        self._retranslate()

    # ---- public API ----------------------------------------------------
    def x_mode(self) -> str:
        """``"angle"`` (crank angle, °) or ``"time"`` (s)."""
        return self._mode

    def set_x_mode(self, mode: str) -> None:
        """Plot against crank angle or time; each speed then uses its own time array."""
        if mode not in (ANGLE, TIME):
            raise ValueError(f"x mode must be {ANGLE!r} or {TIME!r}")
        self._x_combo.setCurrentIndex(1 if mode == TIME else 0)
        if mode != self._mode:
            self._mode = mode
            self._stack.invalidate()

    def plot_visible(self, name: str) -> bool:
        return self._stack.plot_visible(name)

    def set_plot_visible(self, name: str, visible: bool) -> None:
        """Show or hide one of the lever plots (the ram plots are always shown)."""
        if name not in LEVER_PLOTS:
            raise ValueError(f"only lever plots can be hidden, not {name!r}")
        action = self._lever_actions[name]
        if action.isChecked() != visible:
            action.setChecked(visible)   # re-enters through toggled
            return
        self._stack.set_plot_visible(name, visible)

    def curve_data(self, plot_name: str) -> list[tuple[np.ndarray, np.ndarray]]:
        """(x, y) drawn for each speed in ``plot_name`` (return stroke included in time mode)."""
        return self._stack.plot(plot_name).data()

    def cursor_value(self) -> float:
        """x of the (first speed's) cursor line: crank angle in ° or time in s."""
        return self._stack.plot("ram_x").cursor_positions()[0]

    def cursor_values(self, plot_name: str = "ram_v") -> list[float]:
        """x of every cursor line shown in ``plot_name``: one, or one per speed in time mode."""
        return self._stack.plot(plot_name).cursor_positions()

    def cursor_dots(self, plot_name: str) -> list[tuple[str, float, float]]:
        """(speed label, x, y) of the dots marking each speed's value at the cursor."""
        return self._stack.plot(plot_name).dots()

    def legend_names(self) -> list[str]:
        """Legend entries in order: the speeds, then in time mode the stroke key."""
        return self._stack.legend("main").names()

    def legend_columns(self) -> int:
        return self._stack.legend("main").columns()

    def work_span(self) -> tuple[float, float] | None:
        """Shaded working stroke (°) in angle mode; None in time mode (no shading)."""
        bands = self._stack.plot("ram_x").bands()
        return bands[0] if self._mode == ANGLE and bands else None

    # ---- what the stack draws -------------------------------------------
    def _curves(self, name: str) -> list[Curve]:
        motion = self._model.motion
        values = motion_values(self._model, name)
        labels = [self.speed_name(float(r)) for r in motion.rpm]
        shorts = [f"{float(r):g}" for r in motion.rpm]        # under the legend's "r/min"
        if self._mode == ANGLE:
            x = np.degrees(motion.crank_angle)
            if name in SHARED_PLOTS:      # one curve, not one per speed drawn on top of each other
                return [Curve(x, values[0], self.tr("every speed"), SHARED, legend=False, short="")]
            return [Curve(x, row, label, speed_colour(i), short=short)
                    for i, (row, label, short) in enumerate(zip(values, labels, shorts))]
        back = ~self._in_work(np.degrees(motion.crank_angle))
        return [Curve(motion.time[i], row, label, speed_colour(i), dashed=back, short=short)
                for i, (row, label, short) in enumerate(zip(values, labels, shorts))]

    def _in_work(self, degrees: np.ndarray) -> np.ndarray:
        """Grid points on the working stroke (a limit on the grid counts as working)."""
        metrics = self._model.metrics
        offset = (degrees - metrics.work_start_deg + TOLERANCE_DEG) % 360.0
        return offset <= metrics.work_angle_deg + 2 * TOLERANCE_DEG

    def bands(self) -> list[Band]:
        if self._mode != ANGLE:
            return []
        metrics = self._model.metrics
        start, end = metrics.work_start_deg, metrics.work_end_deg
        first = max(start, 0.0)   # bands kept inside 0…360°: an SVG export does not clip
        return [Band(first, end, WORK_FILL, self.tr("working stroke"), WORK_TEXT),
                Band(end, 360.0, RETURN_FILL, self.tr("return stroke"), RETURN_TEXT),
                Band(0.0, first, RETURN_FILL)]

    def legend_keys(self) -> dict[str, list[LegendKey]]:
        if self._mode == ANGLE:
            return {}
        return {"main": [LegendKey(self.tr("working stroke"), KEY),
                         LegendKey(self.tr("return stroke"), KEY, Qt.PenStyle.DashLine)]}

    def group_titles(self) -> dict[str, str]:
        return {}

    def legend_units(self) -> dict[str, str]:
        return {"main": self.tr("r/min:")}

    def x_axis(self) -> tuple[str, float, float, bool]:
        if self._mode == ANGLE:
            return self.tr("Crank angle φ (°)"), 0.0, 360.0, True
        return self.tr("Time t (s)"), 0.0, float(self._model.motion.time[:, -1].max()), False

    def x_text(self, x: float) -> str:
        if self._mode == ANGLE:
            return self.tr("φ = {0}°").format(crank_text(x))
        return self.tr("t = {0} s").format(fmt(x, ".4g"))

    def cursor_x(self, index: int) -> float | dict[str, float]:
        motion = self._model.motion
        if self._mode == ANGLE:
            return math.degrees(float(motion.crank_angle[index]))
        return {self.speed_name(float(rpm)): float(motion.time[i, index])
                for i, rpm in enumerate(motion.rpm)}

    def _on_click(self, x: float) -> None:
        """A click moves the animation to that crank angle (in time mode: of the first speed)."""
        if self._mode == TIME:
            x = math.degrees(x * float(self._model.motion.omega[0]))
        self._model.set_angle_deg(x)

    # ---- text ----------------------------------------------------------
    def _retranslate_names(self) -> None:
        # Full names for the menu and the read-out; axis titles short enough to stand
        # beside a plot about 100 px tall.
        self._names = {"ram_x": self.tr("Ram displacement"), "ram_v": self.tr("Ram velocity"),
                       "ram_a": self.tr("Ram acceleration"), "lever_angle": self.tr("Lever angle"),
                       "lever_omega": self.tr("Lever angular velocity"),
                       "lever_alpha": self.tr("Lever angular acceleration")}
        self._axis_titles = {"ram_x": self.tr("Ram displacement"), "ram_v": self.tr("Ram velocity"),
                             "ram_a": self.tr("Ram acceleration"),
                             "lever_angle": self.tr("Lever angle ψ"),
                             "lever_omega": self.tr("Lever ω"), "lever_alpha": self.tr("Lever α")}

    def _retranslate(self) -> None:
        self._retranslate_names()
        self._x_label.setText(self.tr("X axis:"))
        self._x_combo.setItemText(0, self.tr("Crank angle (°)"))
        self._x_combo.setItemText(1, self.tr("Time (s)"))
        # one literal per tr() call, so that lupdate sees the whole text
        self._x_combo.setToolTip(self.tr(
            "Plot against the crank angle (0–360°) or against time (each speed's own cycle)"))
        self._lever_button.setText(self.tr("Lever plots") + " ▾")
        self._lever_button.setToolTip(self.tr(
            "Show the slotted lever's angle, angular velocity or angular acceleration"))
        for name, action in self._lever_actions.items():
            action.setText(self._names[name])
        self._stack.retranslate()
