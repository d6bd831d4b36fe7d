"""Forces view: the loads the designer types and what they cost the motor.

Left, a compact form for ``MassProperties``; right, stacked plots of crank
torque, input power and the cumulative energy ΔE(φ) per crank speed, and the
joint-force magnitudes of one chosen speed. Everything drawn comes from
``model.dynamics`` / ``model.dynamics_summary``; the widget only converts
units, takes |F| = hypot(Fx, Fy) and finds where the cutting force is on.
Like the design form, text goes to the model as typed after a short pause,
so the model's validation names the field to mark.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pyqtgraph as pg
from pyqtgraph.GraphicsScene.mouseEvents import MouseClickEvent
from PySide6.QtCore import QEvent, QPointF, Qt, QTimer
from PySide6.QtGui import QColor
from PySide6.QtWidgets import (QCheckBox, QComboBox, QFormLayout, QFrame, QGroupBox, QHBoxLayout, QLabel, QLineEdit, QScrollArea,
                               QSizePolicy, QVBoxLayout, QWidget)

from core.dynamics import Dynamics
from core.errors import DesignError

from .form import DEBOUNCE_MS, _NumberField, format_number, parse_number
from .messages import ERROR_TEXT_STYLE, describe
from .model import DesignModel
from .plots import (AXIS_WIDTH, CURVE_WIDTH, LEGEND_HEIGHT, TEXT, add_cursor, cache_axes, export_layout, plot_under,
                    styled_plot_item)
from .style import speed_colour

# Input fields in form order: MassProperties names, except the two ram offsets
# (one pair in the model) and the idle margin (typed in %, stored as a fraction).
FIELD_UNITS = {
    "lever_mass_kg": "kg", "lever_cg_mm": "mm", "lever_inertia_kg_m2": "kg·m²",
    "ram_mass_kg": "kg", "ram_cg_dx": "mm", "ram_cg_dy": "mm",
    "rod_mass_kg": "kg", "block_mass_kg": "kg",
    "cut_force_N": "N", "cut_height_mm": "mm", "idle_percent": "%",
    "delta": "–",
}
GROUPS = (("lever", ("lever_mass_kg", "lever_cg_mm", "lever_inertia_kg_m2")),
          ("ram", ("ram_mass_kg", "ram_cg_dx", "ram_cg_dy")),
          ("links", ("rod_mass_kg", "block_mass_kg")),
          ("cutting", ("cut_force_N", "cut_height_mm", "idle_percent")),
          ("flywheel", ("gravity", "delta")))
SPEED_PLOTS = ("torque", "power", "energy")      # one curve per crank speed
PLOT_NAMES = SPEED_PLOTS + ("force",)
UNITS = {"torque": "N·m", "power": "kW", "energy": "J", "force": "kN"}
JOINTS = ("O2", "A", "O4", "B", "C", "guide")
JOINT_COLOURS = {"O2": QColor("#6a3d9a"), "A": QColor("#1f78b4"), "O4": QColor("#33a02c"),
                 "B": QColor("#ff7f00"), "C": QColor("#e31a1c"), "guide": QColor("#455a64")}
# A carries O2's force when the block is light, C nearly B's when the rod is: dashed,
# so the curve beneath shows through the gaps.
SOLID = Qt.PenStyle.SolidLine
JOINT_STYLES = {"A": Qt.PenStyle.DashLine, "C": Qt.PenStyle.DashLine, "guide": Qt.PenStyle.DotLine}
CUT_FILL = QColor(239, 108, 0, 30)       # light orange band where the tool cuts
CUT_TEXT = QColor(191, 54, 12)
KEY = QColor("#616161")
DELTA_DIGITS = 4                         # δ = 1/30 shows as 0.03333
FORM_WIDTH = 285
LEGEND_COLUMNS = 3                       # speed legend entries per row


def parse_ratio(text: str) -> float | str:
    """δ is usually quoted as a fraction (1/30): accept ``a/b`` as well as a decimal.

    Returns the float, or the text itself when it is not a number, so that the
    model's validation reports it like any other bad input."""
    if "/" not in text:
        return parse_number(text)
    top, _, bottom = text.partition("/")
    a, b = parse_number(top), parse_number(bottom)
    if isinstance(a, float) and isinstance(b, float) and b != 0.0:
        return a / b
    return text


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


@dataclass
class _Plot:
    """One stacked plot and the items that live in it."""

    item: pg.PlotItem
    cursor: pg.InfiniteLine
    cuts: list[pg.LinearRegionItem] = field(default_factory=list)
    curves: list[pg.PlotCurveItem] = field(default_factory=list)


class ForcesPanel(QWidget):
    """Load inputs, and torque, power, energy and joint-force plots over one revolution."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._pending: set[str] = set()       # fields typed into since the last commit
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(DEBOUNCE_MS)
        self._timer.timeout.connect(self._commit)

        self._fields = {name: _NumberField(unit) for name, unit in FIELD_UNITS.items()}
        self._gravity = QCheckBox(self)
        self._labels: dict[str, QLabel] = {}
        self._boxes: dict[str, QGroupBox] = {}
        self._error_label = QLabel(self)
        self._error_label.setWordWrap(True)
        self._error_label.setStyleSheet(ERROR_TEXT_STYLE)
        self._error_label.hide()

        self._speed_label = QLabel(self)
        self._speed_combo = QComboBox(self)
        self._speed_combo.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToContents)
        self._readout = QLabel(self)
        self._readout.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self._readout.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self._readout.setContentsMargins(6, 2, 6, 2)
        self._view = pg.GraphicsLayoutWidget()
        self._view.setBackground("w")
        self._view.ci.setSpacing(4)
        self._build_layout()
        self._build_plots()

        for name, number in self._fields.items():
            number.edited.connect(lambda n=name: self._on_edited(n))
            number.edit.editingFinished.connect(self._commit)
        self._gravity.toggled.connect(lambda on: self._model.set_masses(gravity=on))
        self._speed_combo.currentIndexChanged.connect(self._draw_forces)
        scene = self._view.scene()
        scene.sigMouseClicked.connect(self._on_click)
        self._mouse_proxy = pg.SignalProxy(scene.sigMouseMoved, rateLimit=60,
                                           slot=self._on_mouse_moved)
        model.forcesChanged.connect(self._on_forces)
        model.forcesErrorChanged.connect(self._show_error)
        model.angleChanged.connect(self._on_angle)
        self._retranslate()
        self._on_forces()

    # ---- public API ----------------------------------------------------
    def field(self, name: str) -> QLineEdit:
        """The line edit of an input: a MassProperties name, ``ram_cg_dx``/``ram_cg_dy``
        or ``idle_percent``."""
        return self._fields[name].edit

    def gravity_box(self) -> QCheckBox:
        return self._gravity

    def marked_fields(self) -> list[str]:
        """Names (as for :meth:`field`) of the inputs marked invalid."""
        return [name for name, number in self._fields.items() if number.edit.styleSheet()]

    def error_text(self) -> str:
        """The message under the form ('' while the loads are valid)."""
        return self._error_label.text() if self._model.forces_error is not None else ""

    def curve_data(self, name: str) -> list[tuple[np.ndarray, np.ndarray]]:
        """(x in °, y) as drawn, read back from the plot items.

        ``torque`` (N·m), ``power`` (kW), ``energy`` (J): one pair per speed;
        ``force:O2`` … ``force:guide`` (kN): one pair for the selected speed, none
        for ``force:C`` in the block variant."""
        if name.startswith("force:"):
            curves = [self._force_curves[name.split(":", 1)[1]]]
        else:
            curves = self._plots[name].curves
        out = []
        for curve in curves:
            x, y = curve.getData()
            if x is not None and len(x):
                out.append((np.asarray(x), np.asarray(y)))
        return out

    def mean_torque_lines(self) -> list[float]:
        """y of the dashed mean-torque lines, one per speed, N·m."""
        return [float(line.value()) for line in self._means]

    def cut_spans(self) -> list[tuple[float, float]]:
        """Shaded cutting zones, (start, end) in °."""
        return [tuple(float(v) for v in region.getRegion())
                for region in self._plots["torque"].cuts if region.isVisible()]

    def selected_speed(self) -> int:
        """Index of the speed whose joint forces are drawn."""
        return max(self._speed_combo.currentIndex(), 0)

    def set_selected_speed(self, index: int) -> None:
        self._speed_combo.setCurrentIndex(index)

    def speed_names(self) -> list[str]:
        return [self._speed_combo.itemText(i) for i in range(self._speed_combo.count())]

    def legend_names(self, which: str = "speeds") -> list[str]:
        """Legend entries of the speed plots (``speeds``) or the joint-force plot (``joints``)."""
        legend = self._speed_legend if which == "speeds" else self._joint_legend
        return [label.text for _, label in legend.items]

    def cursor_value(self) -> float:
        """Crank angle of the cursor lines, °."""
        return float(self._plots["torque"].cursor.value())

    def plot_item(self, name: str) -> pg.PlotItem:
        return self._plots[name].item

    def readout_text(self) -> str:
        return self._readout.text()

    def export_image(self, path: str) -> None:
        """Write the plots to ``path``: SVG for ``.svg``, else a raster image (PNG …)."""
        export_layout(self._view, path, self.tr("Shaper forces and torque"), self._cache_axes)

    # ---- construction --------------------------------------------------
    def _build_layout(self) -> None:
        form_widget = QWidget()
        column = QVBoxLayout(form_widget)
        column.setContentsMargins(4, 4, 4, 4)
        for key, names in GROUPS:
            box = QGroupBox(form_widget)
            form = QFormLayout(box)
            form.setFieldGrowthPolicy(QFormLayout.FieldGrowthPolicy.AllNonFixedFieldsGrow)
            for name in names:
                label = QLabel(box)
                self._labels[name] = label
                form.addRow(label, self._gravity if name == "gravity" else self._fields[name])
            self._boxes[key] = box
            column.addWidget(box)
        column.addWidget(self._error_label)
        column.addStretch(1)
        scroll = QScrollArea(self)
        scroll.setWidget(form_widget)
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        scroll.setFixedWidth(FORM_WIDTH)

        bar = QHBoxLayout()
        bar.setContentsMargins(4, 2, 4, 2)
        bar.addWidget(self._speed_label)
        bar.addWidget(self._speed_combo)
        bar.addStretch(1)
        right = QVBoxLayout()
        right.setContentsMargins(0, 0, 0, 0)
        right.setSpacing(0)
        right.addLayout(bar)
        right.addWidget(self._view, 1)
        right.addWidget(self._readout)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(scroll)
        layout.addLayout(right, 1)

    def _build_plots(self) -> None:
        """Rows: speed legend, torque, power, energy, joint legend, joint forces."""
        ci = self._view.ci
        self._plots = {name: self._make_plot() for name in PLOT_NAMES}
        self._speed_legend = self._make_legend()
        self._joint_legend = self._make_legend()
        ci.addItem(self._speed_legend, row=0, col=0)
        for row, name in enumerate(SPEED_PLOTS, 1):
            ci.addItem(self._plots[name].item, row=row, col=0)
        # The joint forces are of one speed: say which beside their legend (for exports).
        head = ci.addLayout(row=4, col=0)
        head.setContentsMargins(AXIS_WIDTH, 0, 0, 0)
        head.setMaximumHeight(2 * LEGEND_HEIGHT)
        self._force_title = pg.LabelItem(color=TEXT, size="9pt", justify="left")
        self._force_title.setMaximumHeight(LEGEND_HEIGHT)
        # Title above the legend, not beside it: side by side they need more width
        # than the tab has beside the load form.
        head.addItem(self._force_title, row=0, col=0)
        head.addItem(self._joint_legend, row=1, col=0)
        head.layout.setAlignment(self._joint_legend, Qt.AlignmentFlag.AlignRight)
        ci.addItem(self._plots["force"].item, row=5, col=0)
        ci.layout.setAlignment(self._speed_legend, Qt.AlignmentFlag.AlignRight)
        top = self._plots["torque"].item
        for name in PLOT_NAMES[1:]:
            self._plots[name].item.setXLink(top)
            self._plots[name].item.getAxis("bottom").setStyle(showValues=name == "force")
            self._plots[name].item.getAxis("bottom").showLabel(name == "force")
        top.getAxis("bottom").setStyle(showValues=False)
        top.getAxis("bottom").showLabel(False)
        top.setXRange(0.0, 360.0, padding=0.0)

        force = self._plots["force"]
        self._force_curves: dict[str, pg.PlotCurveItem] = {}
        for joint in JOINTS:
            curve = pg.PlotCurveItem(pen=pg.mkPen(JOINT_COLOURS[joint], width=CURVE_WIDTH,
                                                  style=JOINT_STYLES.get(joint, SOLID)))
            force.item.addItem(curve)
            self._force_curves[joint] = curve
            force.curves.append(curve)
        self._has_rod = False
        self._means: list[pg.InfiniteLine] = []
        self._mean_key = pg.PlotCurveItem(pen=pg.mkPen(KEY, width=1.4, style=Qt.PenStyle.DashLine))
        self._cut_key = pg.BarGraphItem(x=[0], height=[1], width=1, brush=CUT_FILL,
                                        pen=pg.mkPen(None))
        self._cut_text = pg.TextItem(color=CUT_TEXT, anchor=(0.5, 0))
        top.addItem(self._cut_text, ignoreBounds=True)
        top.vb.sigRangeChanged.connect(self._place_cut_text)
        self._speed_legend.sigSampleClicked.connect(self._on_speed_sample_clicked)
        self._cache_axes(True)

    def _make_legend(self) -> pg.LegendItem:
        """A legend in a row of its own, so it never hides a curve."""
        legend = pg.LegendItem(labelTextColor=TEXT, frame=False, horSpacing=4)
        legend.setMaximumHeight(LEGEND_HEIGHT)
        return legend

    @staticmethod
    def _make_plot() -> _Plot:
        """A plot styled like the motion diagrams, with 30° ticks."""
        item = styled_plot_item(0.08)
        item.getAxis("bottom").setTickSpacing(levels=[(30.0, 0.0)])
        return _Plot(item, add_cursor(item))

    def _cache_axes(self, on: bool) -> None:
        """Axis pixmaps make cursor moves cheap; off while exporting (a scaled pixmap blurs)."""
        cache_axes([plot.item for plot in self._plots.values()], on)

    # ---- text ----------------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _field_texts(self) -> dict[str, tuple[str, str]]:
        """(label, tooltip) of every input."""
        return {
            "lever_mass_kg": (self.tr("Mass m3"), self.tr("Mass of the slotted lever O4B, kg")),
            "lever_cg_mm": (self.tr("Centre of mass c"),
                            self.tr("Distance of the lever's centre of mass from O4 along O4B, mm; "
                                    "leave empty for L3/2")),
            "lever_inertia_kg_m2": (self.tr("Inertia J3"),
                                    self.tr("Moment of inertia of the lever about its centre of "
                                            "mass, kg·m²")),
            "ram_mass_kg": (self.tr("Mass m5"), self.tr("Mass of the ram with the tool, kg")),
            "ram_cg_dx": (self.tr("Centre of mass dx"),
                          self.tr("Horizontal offset of the ram's centre of mass from the ram "
                                  "joint C, mm (+ in the cutting direction)")),
            "ram_cg_dy": (self.tr("Centre of mass dy"),
                          self.tr("Vertical offset of the ram's centre of mass from the ram "
                                  "joint C, mm (+ up)")),
            "rod_mass_kg": (self.tr("Rod mass m4"),
                            self.tr("Mass of the connecting rod BC, a uniform bar, kg (rod "
                                    "variant only)")),
            "block_mass_kg": (self.tr("Block mass"),
                              self.tr("Mass of the sliding block at the crank pin A, kg")),
            "cut_force_N": (self.tr("Cutting force P"),
                            self.tr("Cutting resistance on the tool, against the cut, N")),
            "cut_height_mm": (self.tr("Tool below guide yP"),
                              self.tr("Height of the tool point below the ram guide line, mm "
                                      "(negative = above)")),
            "idle_percent": (self.tr("Idle margin"),
                             self.tr("Uncut run-in and run-out at each end of the working "
                                     "stroke, % of the stroke H (0 to under 50)")),
            "gravity": (self.tr("Gravity"),
                        self.tr("Include the weights of the links (g = 9.81 m/s²)")),
            "delta": (self.tr("Speed fluctuation δ"),
                      self.tr("Coefficient of speed fluctuation (ωmax − ωmin)/ωmean the "
                              "flywheel must hold, between 0 and 1; a fraction such as 1/30 "
                              "is accepted")),
        }

    def _plot_names(self) -> dict[str, str]:
        """Full names, for the read-out."""
        return {"torque": self.tr("Crank driving torque"), "power": self.tr("Input power"),
                "energy": self.tr("Cumulative excess energy ΔE"),
                "force": self.tr("Joint force magnitudes")}

    def _axis_titles(self) -> dict[str, str]:
        """Short enough to stand beside a plot about 120 px tall."""
        return {"torque": self.tr("Crank torque"), "power": self.tr("Input power"),
                "energy": self.tr("Energy ΔE"), "force": self.tr("Joint force |F|")}

    def _joint_names(self) -> dict[str, str]:
        """Full names, for the read-out and the legend's tooltips."""
        return {"O2": self.tr("O₂ crank bearing"), "A": self.tr("A block on lever"),
                "O4": self.tr("O₄ lever pivot"), "B": self.tr("B lever tip"),
                "C": self.tr("C rod on ram"), "guide": self.tr("Guide normal force")}

    def _joint_symbols(self) -> dict[str, str]:
        """Short legend names: the joints as the scheme labels them."""
        return {"O2": "O₂", "A": "A", "O4": "O₄", "B": "B", "C": "C", "guide": self.tr("guide")}

    def _speed_name(self, rpm: float) -> str:
        return self.tr("{0} r/min").format(f"{rpm:g}")

    def _retranslate(self) -> None:
        titles = {"lever": self.tr("Slotted lever"), "ram": self.tr("Ram and tool"),
                  "links": self.tr("Rod and block"), "cutting": self.tr("Cutting"),
                  "flywheel": self.tr("Flywheel")}
        for key, box in self._boxes.items():
            box.setTitle(titles[key])
        for name, (text, tip) in self._field_texts().items():
            self._labels[name].setText(text)
            self._labels[name].setToolTip(tip)
            (self._gravity if name == "gravity" else self._fields[name].edit).setToolTip(tip)
        self._gravity.setText(self.tr("include weights"))
        self._speed_label.setText(self.tr("Joint forces at:"))
        self._speed_combo.setToolTip(self.tr("Crank speed whose joint forces are plotted"))
        for i in range(self._speed_combo.count()):
            self._speed_combo.setItemText(i, self._speed_name(self._speed_combo.itemData(i)))
        if self._speed_combo.count():
            self._draw_forces()
        self._readout.setToolTip(self.tr(
            "Values under the mouse; click a plot to move the mechanism to that crank position"))
        self._readout.setText(
            self.tr("Point at a plot to read values; click to set the crank angle"))
        axis_titles = self._axis_titles()
        for name, plot in self._plots.items():
            plot.item.setLabel("left", f"{axis_titles[name]}<br>({UNITS[name]})",
                               color=TEXT.name(), **{"font-size": "9pt"})
            plot.item.setLabel("bottom", self.tr("Crank angle φ (°)"), color=TEXT.name(),
                               **{"font-size": "9pt"})
        self._plots["force"].item.getAxis("bottom").showLabel(True)
        for name in SPEED_PLOTS:
            self._plots[name].item.getAxis("bottom").showLabel(False)
        self._cut_text.setText(self.tr("cutting"))
        self._show_placeholder()
        self._rebuild_legends()
        self._show_error()
        self._align_labels()

    def _align_labels(self) -> None:
        """One label width in every group box, so the fields line up down the form."""
        width = max(label.sizeHint().width() for label in self._labels.values())
        for label in self._labels.values():
            label.setMinimumWidth(width)

    def _show_placeholder(self) -> None:
        half = format_number(self._model.design.lever / 2.0)
        self._fields["lever_cg_mm"].edit.setPlaceholderText(self.tr("L3/2 = {0}").format(half))

    def _rebuild_legends(self) -> None:
        """Speeds plus the mean-torque and cutting keys; the joints present in the variant."""
        legend = self._speed_legend
        legend.clear()
        entries = [(curve, self._speed_name(float(rpm)))
                   for curve, rpm in zip(self._plots["torque"].curves, self._model.dynamics.rpm)]
        entries += [(self._mean_key, self.tr("mean torque")), (self._cut_key, self.tr("cutting"))]
        columns = min(len(entries), LEGEND_COLUMNS)
        legend.setColumnCount(columns)
        legend.setMaximumHeight(LEGEND_HEIGHT * math.ceil(len(entries) / columns))
        for item, name in entries:
            legend.addItem(item, name)
        legend.setMaximumWidth(legend.layout.preferredWidth() + 12)
        legend = self._joint_legend
        legend.clear()
        names = self._joint_symbols()
        shown = [j for j in JOINTS if j != "C" or self._has_rod]
        legend.setColumnCount(len(shown))
        for joint in shown:
            legend.addItem(self._force_curves[joint], names[joint])
        legend.setMaximumWidth(legend.layout.preferredWidth() + 12)
        # Never narrower than the legends: a narrower view would clip the scene.
        self._view.setMinimumWidth(int(self._view.ci.effectiveSizeHint(Qt.SizeHint.MinimumSize).width()) + 4)

    def _on_speed_sample_clicked(self, item: pg.GraphicsObject) -> None:
        """The legend hid or showed the torque curve it keys: do the same for that
        speed in the power and energy plots; the mean and cutting keys stay drawn."""
        curves = self._plots["torque"].curves
        if item not in curves:
            item.setVisible(True)
            return
        i = curves.index(item)
        for thing in (self._plots["power"].curves[i], self._plots["energy"].curves[i],
                      self._means[i]):
            thing.setVisible(item.isVisible())

    # ---- model → panel -------------------------------------------------
    def _on_forces(self) -> None:
        """Redraw from the new dynamics; plot items are reused, added or dropped per speed."""
        dyn, summary = self._model.dynamics, self._model.dynamics_summary
        degrees = np.degrees(dyn.crank_angle)
        count = dyn.rpm.size
        resized = any(len(self._plots[n].curves) != count for n in SPEED_PLOTS)
        for name in SPEED_PLOTS:
            self._fit_curves(self._plots[name], count)
        self._fit_means(count)
        energy_x = np.degrees(summary.crank_angle)
        for i in range(count):
            self._plots["torque"].curves[i].setData(degrees, dyn.crank_torque[i])
            self._plots["power"].curves[i].setData(degrees, dyn.power[i] * 1e-3)
            self._plots["energy"].curves[i].setData(energy_x, summary.energy[i])
            self._means[i].setValue(summary.speeds[i].mean_torque_N_m)
        self._show_cuts(cutting_spans(degrees, dyn.cut_force[0]))
        self._fill_speed_combo()
        rod = self._model.design.rod is not None
        self._fields["rod_mass_kg"].setEnabled(rod)
        variant_changed, self._has_rod = rod != self._has_rod, rod
        self._draw_forces()
        self._show_inputs()
        self._show_placeholder()
        if resized or variant_changed:
            self._rebuild_legends()
        self._fit_y()
        self._place_cut_text()
        self._on_angle(self._model.angle_index)

    def _fit_curves(self, plot: _Plot, count: int) -> None:
        while len(plot.curves) > count:
            plot.item.removeItem(plot.curves.pop())
        while len(plot.curves) < count:
            i = len(plot.curves)
            curve = pg.PlotCurveItem(pen=pg.mkPen(speed_colour(i), width=CURVE_WIDTH))
            plot.item.addItem(curve)
            plot.curves.append(curve)

    def _fit_means(self, count: int) -> None:
        """One dashed mean-torque line per speed, in the speed's colour."""
        item = self._plots["torque"].item
        while len(self._means) > count:
            item.removeItem(self._means.pop())
        while len(self._means) < count:
            colour = speed_colour(len(self._means))
            line = pg.InfiniteLine(angle=0, movable=False,
                                   pen=pg.mkPen(colour, width=1.2, style=Qt.PenStyle.DashLine))
            item.addItem(line, ignoreBounds=True)
            self._means.append(line)

    def _show_cuts(self, spans: list[tuple[float, float]]) -> None:
        """Shade each cutting span in every plot; spare regions are hidden, not deleted."""
        for plot in self._plots.values():
            while len(plot.cuts) < len(spans):
                region = pg.LinearRegionItem((0, 1), movable=False, brush=CUT_FILL,
                                             pen=pg.mkPen(None))
                region.setZValue(-10)
                plot.item.addItem(region, ignoreBounds=True)
                plot.cuts.append(region)
            for i, region in enumerate(plot.cuts):
                region.setVisible(i < len(spans))
                if i < len(spans):
                    region.setRegion(spans[i])
        self._cut_text.setVisible(bool(spans))

    def _fill_speed_combo(self) -> None:
        """List the speeds; keep the chosen speed selected while it still exists."""
        rpms = [float(r) for r in self._model.dynamics.rpm]
        combo = self._speed_combo
        if [combo.itemData(i) for i in range(combo.count())] == rpms:
            return
        chosen = combo.currentData()
        combo.blockSignals(True)
        combo.clear()
        for rpm in rpms:
            combo.addItem(self._speed_name(rpm), rpm)
        combo.setCurrentIndex(rpms.index(chosen) if chosen in rpms else 0)
        combo.blockSignals(False)

    def _draw_forces(self) -> None:
        speed = min(self.selected_speed(), self._model.dynamics.rpm.size - 1)
        degrees = np.degrees(self._model.dynamics.crank_angle)
        for joint, values in joint_forces(self._model.dynamics, speed).items():
            curve = self._force_curves[joint]
            if values is None:
                curve.setData([], [])
            else:
                curve.setData(degrees, values)
        self._force_title.setText(self.tr("Joint forces at {0}").format(
            self._speed_name(float(self._model.dynamics.rpm[speed]))))
        self._fit_y(("force",))

    def _fit_y(self, names: tuple[str, ...] = PLOT_NAMES) -> None:
        """Fit y to the curves now, then hold it, so moving the cursor never re-ranges."""
        for name in names:
            vb = self._plots[name].item.vb
            vb.enableAutoRange(axis=pg.ViewBox.YAxis)
            vb.updateAutoRange()
            vb.disableAutoRange()
            vb.updateMatrix()

    def _place_cut_text(self, *_: object) -> None:
        """Label the longest cutting span at the top of the torque plot, or at the bottom
        when the torque fills the upper half there (it usually peaks while cutting)."""
        spans = self.cut_spans()
        if not spans:
            return
        start, end = max(spans, key=lambda s: s[1] - s[0])
        (_, _), (y_low, y_top) = self._plots["torque"].item.vb.viewRange()
        lowest = math.inf
        for x, y in self.curve_data("torque"):
            inside = y[(x >= start) & (x <= end)]
            if inside.size:
                lowest = min(lowest, float(inside.min()))
        bottom = lowest > (y_low + y_top) / 2.0
        self._cut_text.setAnchor((0.5, 1.0) if bottom else (0.5, 0.0))
        self._cut_text.setPos((start + end) / 2.0, y_low if bottom else y_top)

    def _on_angle(self, index: int) -> None:
        x = math.degrees(float(self._model.motion.crank_angle[index]))
        for plot in self._plots.values():
            plot.cursor.setValue(x)

    # ---- inputs --------------------------------------------------------
    def _value(self, name: str) -> object:
        """What the field means in model units: float, None (empty centre of mass) or the
        text itself when it is not a number."""
        text = self._fields[name].edit.text()
        if name == "lever_cg_mm" and not text.strip():
            return None
        if name == "delta":
            return parse_ratio(text)
        value = parse_number(text)
        if name == "idle_percent" and isinstance(value, float):
            return value / 100.0
        return value

    @staticmethod
    def _text(name: str, value: object) -> str:
        if value is None:
            return ""
        if isinstance(value, str):
            return value
        if name == "idle_percent":
            return format_number(float(value) * 100.0)
        if name == "delta":
            return f"{float(value):.{DELTA_DIGITS}g}"
        return format_number(float(value))

    def _model_values(self) -> dict[str, object]:
        """The model's inputs (as last typed, valid or not) keyed like the fields."""
        inputs = self._model.mass_inputs
        pair = inputs["ram_cg_mm"]
        dx, dy = pair if isinstance(pair, tuple) and len(pair) == 2 else (pair, pair)
        values = {name: inputs.get(name) for name in self._fields}
        values.update(ram_cg_dx=dx, ram_cg_dy=dy, idle_percent=inputs["idle_fraction"])
        values["gravity"] = inputs["gravity"]
        return values

    def _show_inputs(self) -> None:
        """Mirror the model into the fields, leaving alone what is being typed."""
        values = self._model_values()
        for name, number in self._fields.items():
            if name in self._pending:
                continue
            wanted = values[name]
            text = self._text(name, wanted)
            if number.edit.text() != text and self._value(name) != wanted:
                number.edit.setText(text)
        self._gravity.blockSignals(True)
        self._gravity.setChecked(bool(values["gravity"]))
        self._gravity.blockSignals(False)

    def _on_edited(self, name: str) -> None:
        self._pending.add(name)
        self._timer.start()

    def _commit(self) -> None:
        """Send the typed fields; the model validates and says which one is wrong."""
        self._timer.stop()
        if not self._pending:
            return
        changes: dict[str, object] = {}
        for name in self._pending:
            if name in ("ram_cg_dx", "ram_cg_dy"):
                changes["ram_cg_mm"] = (self._value("ram_cg_dx"), self._value("ram_cg_dy"))
            elif name == "idle_percent":
                changes["idle_fraction"] = self._value(name)
            else:
                changes[name] = self._value(name)
        self._pending.clear()
        current = self._model.mass_inputs
        changes = {key: value for key, value in changes.items() if current.get(key) != value}
        if changes:
            self._model.set_masses(**changes)

    def _error_fields(self, error: DesignError) -> list[str]:
        """Fields to mark for ``error``: the ram offset names its component by value."""
        if error.parameter == "idle_fraction":
            return ["idle_percent"]
        if error.parameter == "ram_cg_mm":
            values = self._model_values()
            for name in ("ram_cg_dx", "ram_cg_dy"):
                if values[name] == error.value or (
                        isinstance(values[name], float) and isinstance(error.value, float)
                        and math.isnan(values[name]) and math.isnan(error.value)):
                    return [name]
            return ["ram_cg_dx", "ram_cg_dy"]
        return [error.parameter] if error.parameter in self._fields else []

    def _show_error(self) -> None:
        for number in self._fields.values():
            number.set_error(False)
        self._show_inputs()      # an invalid value set from elsewhere shows as typed
        error = self._model.forces_error
        if error is None:
            self._error_label.clear()
            self._error_label.hide()
            return
        for name in self._error_fields(error):
            self._fields[name].set_error(True)
        self._error_label.setText("⚠ " + describe(error) + "\n" +
                                  self.tr("The last valid results stay on screen."))
        self._error_label.show()

    # ---- mouse ---------------------------------------------------------
    def _plot_at(self, scene_pos: QPointF) -> tuple[str, float] | None:
        return plot_under({n: p.item for n, p in self._plots.items()}, scene_pos)

    def _on_click(self, event: MouseClickEvent) -> None:
        """A left click in a plot moves the mechanism to that crank angle."""
        if event.button() != Qt.MouseButton.LeftButton or event.isAccepted():
            return
        hit = self._plot_at(event.scenePos())
        if hit is not None:
            self._model.set_angle_deg(hit[1])

    def _on_mouse_moved(self, args: tuple) -> None:
        hit = self._plot_at(args[0])
        if hit is not None:
            self._readout.setText(self._readout_for(*hit))

    def _readout_for(self, name: str, x: float) -> str:
        """The angle, then each curve's value at the nearest grid point, in its colour."""
        parts = [f"<b>{self._plot_names()[name]}</b>", self.tr("φ = {0}°").format(f"{x:.1f}")]
        if name == "force":
            names = self._joint_names()
            series = [(names[j], JOINT_COLOURS[j], self.curve_data(f"force:{j}")) for j in JOINTS]
            parts.append(self._speed_combo.currentText() + ":")
        else:
            rpms = self._model.dynamics.rpm
            series = [(self._speed_name(float(rpm)), speed_colour(i), [data])
                      for i, (rpm, data) in enumerate(zip(rpms, self.curve_data(name)))]
        for label, colour, data in series:
            if not data:
                continue
            xs, ys = data[0]
            value = "—" if x < xs[0] or x > xs[-1] else \
                f"{ys[int(np.argmin(np.abs(xs - x)))]:.4g} {UNITS[name]}"
            parts.append(f"<span style='color:{colour.name()}'>{label}:</span> {value}")
        return "&nbsp;&nbsp; ".join(parts)
