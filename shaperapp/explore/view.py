"""The Explore tab: how two design choices trade one figure against the others.

It maps a chosen figure over two chosen parameters (the rest fixed by the
current design), greys out invalid designs and names their reason on hover,
marks the current design, loads a clicked cell through the model's setters,
and optimizes the chosen objective over the free parameters within the
map's ranges. The work runs on a worker thread (``explore_jobs``) with a
progress bar and Cancel; every number comes from ``core``.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from PySide6.QtCore import QEvent, Qt, QTimer
from PySide6.QtGui import QColor
from PySide6.QtWidgets import (QComboBox, QDoubleSpinBox, QGridLayout, QHBoxLayout, QLabel,
                               QProgressBar, QPushButton, QSpinBox, QVBoxLayout, QWidget)

from core.space.optimize import on_bounds, tidy_optimum
from core.space.sweep import default_range, design_value, spec_changes, varied_parameters
from shaperapp.design.model import DesignModel
from shaperapp.widgets.combos import fill_combo
from shaperapp.widgets.image_export import export_scene_captioned
from shaperapp.widgets.messages import describe
from shaperapp.widgets.worker import JobRunner

from . import names as explore_names
from .cells import cell_text, clicked_changes
from .jobs import FIGURES, MapJob, MapResult, OptimizeJob
from .map import HeatMap
from .optimize_box import OptimizeBox

REFRESH_MS = 300
REQUIREMENTS = ("time_ratio", "stroke")      # K and H: given by the user, fixed by default


class ExploreView(QWidget):
    """Heat map, its controls, and the Optimize action."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.model = model
        self.runner = JobRunner(self)
        self.runner.ended.connect(self._ended)
        self.runner.progress.connect(self._progress)
        self.runner.finished.connect(self._finished)
        self.runner.failed.connect(self._failed)
        self.runner.cancelled.connect(self._cancelled)
        self.result: MapResult | None = None
        self._basis = None
        self._stale = False          # the map no longer matches the model (refreshed when shown)
        self._opened = False         # shown once: the first map is computed then, unasked
        self.figure = QComboBox()
        self.axis_names = [QComboBox(), QComboBox()]
        self.lows = [self._spin(), self._spin()]
        self.highs = [self._spin(), self._spin()]
        self.count = QSpinBox()
        self.count.setRange(3, 200)
        self.count.setValue(40)
        self.compute = QPushButton()
        self.progress = QProgressBar()
        self.cancel = QPushButton()
        self.status = QLabel()
        self.status.setWordWrap(True)
        self.map = HeatMap(self)
        self.hover = QLabel()
        self.hover.setWordWrap(True)
        for label in (self.status, self.hover):      # two lines, beside each other above the map
            label.setMinimumHeight(2 * label.fontMetrics().lineSpacing() + 4)
            label.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        self.box = OptimizeBox(model)
        self._layout()
        self._refresh_timer = QTimer(self, singleShot=True, interval=REFRESH_MS)
        self._refresh_timer.timeout.connect(self.start_map)
        self.compute.clicked.connect(self.start_map)
        self.cancel.clicked.connect(self.stop)
        self.box.optimize.clicked.connect(self.start_optimize)
        self.figure.currentIndexChanged.connect(self._figure_changed)
        for i, combo in enumerate(self.axis_names):
            combo.currentIndexChanged.connect(lambda _=0, i=i: self._axis_changed(i))
        for spin in (*self.lows, *self.highs):      # the empty map spans the ranges typed
            spin.valueChanged.connect(lambda _=0: self.map.show_extent(*self._ends()))
        self.map.cellHovered.connect(self._hovered)
        self.map.cellClicked.connect(self._clicked)
        model.resultsChanged.connect(self._model_changed)
        model.forcesChanged.connect(self._model_changed)
        self._retranslate()
        self._fill_axes()
        self._set_busy(False)

    # ---- layout and texts -------------------------------------------------
    @staticmethod
    def _spin() -> QDoubleSpinBox:
        spin = QDoubleSpinBox()
        spin.setRange(0.001, 100_000.0)
        spin.setDecimals(3)
        spin.setKeyboardTracking(False)
        return spin

    def _layout(self) -> None:
        grid = QGridLayout()
        self._labels = [QLabel() for _ in range(4)]
        grid.addWidget(self._labels[0], 0, 0)
        grid.addWidget(self.figure, 0, 1, 1, 3)
        for row, i in ((1, 0), (2, 1)):
            grid.addWidget(self._labels[row], row, 0)
            grid.addWidget(self.axis_names[i], row, 1)
            grid.addWidget(self.lows[i], row, 2)
            grid.addWidget(self.highs[i], row, 3)
        grid.addWidget(self._labels[3], 3, 0)
        grid.addWidget(self.count, 3, 1)
        grid.addWidget(self.compute, 3, 2)
        grid.addWidget(self.cancel, 3, 3)         # beside Compute: no row of its own
        bar = QHBoxLayout()
        bar.addWidget(self.progress, 1)           # shown only while a job runs
        layout = QVBoxLayout(self)
        layout.addLayout(grid)
        layout.addLayout(bar)
        # the read-out of the cell under the mouse beside the status, not in a band of its own
        # under the map: the map had some 150 px of a 1366×768 screen
        texts = QHBoxLayout()
        texts.addWidget(self.status, 1)
        texts.addWidget(self.hover, 2)
        layout.addLayout(texts)
        layout.addWidget(self.map, 1)
        layout.addWidget(self.box)

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    # the names live in names.py (context "ExploreView", as before)
    figure_names = staticmethod(explore_names.figure_names)
    figure_titles = staticmethod(explore_names.figure_titles)
    parameter_names = staticmethod(explore_names.parameter_names)

    def _retranslate(self) -> None:
        for label, text in zip(self._labels, (self.tr("Figure"), self.tr("Across"), self.tr("Up"),
                                              self.tr("Points per axis"))):
            label.setText(text)
        self.compute.setText(self.tr("Compute map"))
        self.cancel.setText(self.tr("Cancel"))
        self.box.retranslate()
        self._fill_figures()
        names = self.parameter_names()
        for combo in self.axis_names:
            for i in range(combo.count()):
                combo.setItemText(i, names[combo.itemData(i)])
        self._show_labels()
        if self.runner.job is None:
            self._show_count()

    def _fill_figures(self) -> None:
        """The figures (and objectives) this design's variant has: no pressure angle
        without a rod."""
        rod = self.model.valid_spec.variant == "rod"
        names = {k: v for k, v in self.figure_names().items() if rod or not FIGURES[k][2]}
        fill_combo(self.figure, names)
        fill_combo(self.box.objective, {k: v for k, v in names.items() if FIGURES[k][0]})

    def _fill_axes(self) -> None:
        names = varied_parameters(self.model.valid_spec)
        preferred = (["rod_ratio", "guide"] if "rod_ratio" in names else
                     ["rod", "guide"] if "rod" in names else [names[0], names[1]])
        texts = self.parameter_names()
        for i, (combo, want) in enumerate(zip(self.axis_names, preferred)):
            fill_combo(combo, {name: texts[name] for name in names}, want)
            self._axis_changed(i)

    def _axis_changed(self, i: int) -> None:
        name = self.axis_names[i].currentData()
        # Optimize starts from the user's requirements: K and H are varied only when freed.
        self.box.free[i].setChecked(name not in REQUIREMENTS)
        low, high = default_range(self.model.design, name)
        self.lows[i].setValue(low)
        self.highs[i].setValue(high)
        self._show_labels()

    def _ends(self) -> list[tuple[float, float]]:
        """Each axis's range as typed, low to high."""
        return [tuple(sorted((self.lows[i].value(), self.highs[i].value()))) for i in (0, 1)]

    def _show_labels(self) -> None:
        names = self.parameter_names()
        x, y = (c.currentData() for c in self.axis_names)
        if x and y:
            self.map.set_labels(names[x], names[y], self.figure_titles().get(self.figure.currentData(), ""))

    # ---- the map ------------------------------------------------------------
    def axes(self) -> tuple[tuple[str, np.ndarray], tuple[str, np.ndarray]]:
        n = self.count.value()
        ends = self._ends()
        return tuple((self.axis_names[i].currentData(),  # type: ignore[return-value]
                      np.linspace(ends[i][0], ends[i][1], n)) for i in (0, 1))

    def start_map(self) -> None:
        self._stale = False
        (x_name, x), (y_name, y) = self.axes()
        if x_name == y_name:
            self.status.setText(self.tr("Choose two different parameters."))
            return
        if any(high <= low for low, high in self._ends()):
            # a range of one value drew no cell (a map of zero height under the old axes),
            # and its status counted 40 × 40 designs
            self.status.setText(self.tr("Give each axis a range with two different ends."))
            return
        masses = self.model.masses if FIGURES[self.figure.currentData()][1] else None
        job = MapJob(self.model.valid_spec, x_name, x, y_name, y, self.model.rpms, masses)
        self._start(job, self.tr("Computing %1 designs…").replace("%1", str(x.size * y.size)))

    def _map_done(self, result: MapResult) -> None:
        self.result = result
        self._basis = self._current_basis()
        self._show_count()
        self._show_figure()

    def _show_count(self) -> None:
        """The status line says how many designs of the map are valid, on one line: the
        label has a third of the row, and "1600 个设计中有 664 个有效。" broke after 664
        in it at 1280 × 720. It takes the width the count needs; the hover read-out
        beside it, the rest."""
        text = self._map_status()
        self.status.setText(text)
        self.status.setMinimumWidth(math.ceil(self.status.fontMetrics().horizontalAdvance(text)) + 2
                                    if text else 0)

    def _map_status(self) -> str:
        """What the status line says of the map shown (empty before the first)."""
        r = self.result
        return "" if r is None else self.tr("%1 of %2 designs are valid.").replace(
            "%1", str(int(r.valid.sum()))).replace("%2", str(r.valid.size))

    def _figure_changed(self) -> None:
        self._show_labels()                  # the colour bar's title
        key = self.figure.currentData()
        if self.result is None or key not in self.result.figures:
            self.start_map()
        else:
            self._show_figure()

    def _show_figure(self) -> None:
        result = self.result
        if result is None:
            return
        key = self.figure.currentData()
        values = result.figures.get(key)
        if values is None:
            values = np.full(result.valid.shape, np.nan)
        self.map.set_grid(result.x, result.y, values)
        self._show_labels()
        self._mark_current()

    def _mark_current(self) -> None:
        if self.result is None:
            return
        design = self.model.design
        self.map.set_marker(design_value(design, self.result.x_name),
                            design_value(design, self.result.y_name))

    def _hovered(self, row: int, column: int) -> None:
        text = "" if self.result is None or row < 0 else cell_text(self.result, row, column)
        self.hover.setText(text)
        self.map.setToolTip(text)

    def _clicked(self, row: int, column: int) -> None:
        """Load the clicked design through the model (an ordinary, undoable edit)."""
        if self.result is not None:
            self.model.set_spec(**clicked_changes(self.result, row, column, self.model.valid_spec))

    # ---- optimize -----------------------------------------------------------
    def start_optimize(self) -> None:
        (x_name, x), (y_name, y) = self.axes()
        bounds = {name: (float(v[0]), float(v[-1])) for name, v, box in
                  ((x_name, x, self.box.free[0]), (y_name, y, self.box.free[1])) if box.isChecked()}
        if not bounds or x_name == y_name:
            self.box.say(lambda: self.tr("Choose one or two different free parameters."))
            return
        objective = self.box.objective.currentData()
        masses = self.model.masses if FIGURES[objective][1] else None
        job = OptimizeJob(self.model.valid_spec, bounds, objective, self.model.rpms, masses)
        self.box.say(str)
        self._start(job, self.tr("Optimizing…"), busy=True)

    def _optimum_done(self, job: OptimizeJob, best) -> None:
        """Load the optimum, rounded as a person would type it (core.space.optimize.tidy_optimum),
        only when it beats the design on screen by more than the objective's tolerance
        (core.space.optimize.improves); else say why there is no proposal and load nothing."""
        self._show_count()       # no longer "Optimizing…"
        ends = on_bounds(best, job.bounds)
        if not best.improves:                         # nothing better: the design stays
            self.box.say(lambda: explore_names.no_gain_text(best, ends))
            return
        values, value = tidy_optimum(job.spec, best, job.bounds, job.rpms, job.masses)
        self.box.say(lambda: explore_names.proposal_text(values, value, best, ends))
        self.model.set_spec(**spec_changes(values))   # one step on the undo stack
        self.box.proposal_loaded()

    # ---- jobs -----------------------------------------------------------------
    def _start(self, job, text: str, busy: bool = False) -> None:
        self._refresh_timer.stop()       # a job started now supersedes a pending refresh
        self.status.setText(text)
        self.progress.setRange(0, 0 if busy else 1)
        self.progress.setValue(0)
        self._set_busy(True)
        self.runner.start(job)

    # Reports of a job that a newer one has replaced are ignored.
    def _progress(self, job, done: int, total: int) -> None:
        if job is self.runner.job:
            self.progress.setRange(0, total)
            self.progress.setValue(done)

    def _finished(self, job, result) -> None:
        if job is self.runner.job and isinstance(result, MapResult):
            self._map_done(result)
        elif job is self.runner.job:
            self._optimum_done(job, result)

    def _failed(self, job, error) -> None:
        if job is self.runner.job:
            reason = describe(error) if error is not None else self.tr("not enough memory")
            self.status.setText(self.tr("Could not compute: %1").replace("%1", reason))

    def _cancelled(self, job) -> None:
        if job is self.runner.job:
            self.status.setText(self.tr("Cancelled."))

    def _ended(self, job) -> None:
        if self.runner.job is None:
            self._set_busy(False)

    def stop(self) -> None:
        if self.runner.job is not None:
            self.runner.cancel()
            self.status.setText(self.tr("Cancelled."))
        self._set_busy(False)

    def _set_busy(self, on: bool) -> None:
        self.cancel.setEnabled(on)
        self.progress.setVisible(on)
        self.compute.setEnabled(not on)
        self.box.optimize.setEnabled(not on)

    # ---- following the model ------------------------------------------------
    def _current_basis(self):
        """What a map depends on besides its own two parameters."""
        spec = self.model.valid_spec
        if self.result is not None:
            spec = replace(spec, **spec_changes({self.result.x_name: 1.0, self.result.y_name: 1.0}))
        return spec, self.model.rpms, self.model.masses

    def _model_changed(self) -> None:
        if varied_parameters(self.model.valid_spec) != [self.axis_names[0].itemData(i)
                                      for i in range(self.axis_names[0].count())]:
            self._fill_axes()
            self._fill_figures()
        self._mark_current()
        if self.result is not None and self._current_basis() != self._basis:
            # The fixed parameters changed: the map is stale. Recomputed shortly if the tab
            # is shown, else when it is shown (no worker competing with the edits).
            self._stale = True
            if self.isVisible():
                self._refresh_timer.start()

    def showEvent(self, event) -> None:
        super().showEvent(event)
        first = not self._opened and self.result is None and self.runner.job is None
        self._opened = True
        if first or self._stale:
            self._refresh_timer.start()     # the map a user expects on opening the tab

    def export_image(self, path: str) -> None:
        """Write the heat map with its colour bar to ``path``: SVG for ``.svg``, else a raster
        image (errors as ``image_export.export_scene``'s; written atomically). ValueError
        before a map has been computed: there is nothing to draw."""
        if self.result is None:
            raise ValueError(self.tr("There is no map to export yet: press Compute map on "
                                     "the Explore tab first."))
        # the whole view, as on screen: the top tick label reaches above the plot item
        source = self.map.mapToScene(self.map.viewport().rect()).boundingRect()
        caption = explore_names.map_caption(self.figure.currentData(), self._basis[1])
        export_scene_captioned(self.map.scene(), source, path, caption, self.tr("Design-space map"),
                               QColor("white"))

    def shutdown(self) -> None:
        """Stop any work and wait for it (the window is closing)."""
        self._refresh_timer.stop()
        self.runner.cancel()
        self.runner.wait()
