"""Animation controls: play/pause, step, loop, speed, a crank-angle slider and a read-out.

The bar only moves ``model.angle_index``; every widget that draws the
mechanism follows the model's ``angleChanged``. Playback runs on wall-clock
time (QElapsedTimer), so a slow frame skips grid angles instead of slowing
the motion down: the crank advances by elapsed time × ω × speed factor,
where ω is the first crank speed, and the result is rounded to the grid.
"""
from __future__ import annotations

import math

import numpy as np
from PySide6.QtCore import QElapsedTimer, QEvent, Qt, QTimer, Signal
from PySide6.QtGui import QAction
from PySide6.QtWidgets import (QCheckBox, QComboBox, QFrame, QGridLayout, QHBoxLayout, QLabel,
                               QScrollArea, QSlider, QStyle, QToolButton, QVBoxLayout, QWidget)

from shaperapp.design.model import DesignModel
from shaperapp.widgets.style import crank_text, fmt, speed_colour

TICK_MS = 16                       # ~60 frames per second
SPEED_FACTORS = (0.1, 0.25, 0.5, 1.0, 2.0)
DEFAULT_FACTOR = 0.25
MAX_ROWS = 4                       # speed rows shown in the read-out before it scrolls


class AnimationBar(QWidget):
    """Plays the crank cycle in real time and shows the values at the current angle."""

    playingChanged = Signal(bool)

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._phase = 0.0              # crank angle being played, rad (continuous)
        self._last_index = -1          # the index this bar set last, to notice outside moves
        self._clock = QElapsedTimer()
        self._timer = QTimer(self)
        self._timer.setInterval(TICK_MS)
        self._timer.setTimerType(Qt.PreciseTimer)
        self._timer.timeout.connect(self._tick)

        style = self.style()
        self._play_icon = style.standardIcon(QStyle.SP_MediaPlay)
        self._pause_icon = style.standardIcon(QStyle.SP_MediaPause)
        self.play_action = QAction(self._play_icon, "", self)
        self.play_action.setCheckable(True)
        self.play_action.toggled.connect(self._set_playing)
        self.step_back_action = QAction(style.standardIcon(QStyle.SP_MediaSeekBackward), "", self)
        self.step_back_action.triggered.connect(self.step_back)
        self.step_forward_action = QAction(style.standardIcon(QStyle.SP_MediaSeekForward), "", self)
        self.step_forward_action.triggered.connect(self.step_forward)

        self._back_button, self._play_button, self._forward_button = (
            QToolButton(), QToolButton(), QToolButton())
        self._back_button.setDefaultAction(self.step_back_action)
        self._play_button.setDefaultAction(self.play_action)
        self._forward_button.setDefaultAction(self.step_forward_action)
        self._slider = QSlider(Qt.Horizontal)
        self._slider.setMinimumWidth(100)
        self._slider.valueChanged.connect(self._model.set_angle_index)
        self._loop = QCheckBox()
        self._loop.setChecked(True)
        self._speed = QComboBox()
        for factor in SPEED_FACTORS:
            self._speed.addItem("", factor)
        self._speed.setCurrentIndex(SPEED_FACTORS.index(DEFAULT_FACTOR))
        self._speed_label = QLabel()
        self._speed_label.setBuddy(self._speed)

        controls = QHBoxLayout()
        controls.setContentsMargins(0, 0, 0, 0)
        for w in (self._back_button, self._play_button, self._forward_button):
            controls.addWidget(w)
        controls.addWidget(self._slider, 1)
        controls.addWidget(self._loop)
        controls.addWidget(self._speed_label)
        controls.addWidget(self._speed)

        # Read-out: positions on the left, one row per crank speed on the right.
        self._heads: dict[str, QLabel] = {}
        self._values: dict[str, QLabel] = {}
        self._positions = QGridLayout()
        for row, key in enumerate(("crank", "lever", "ram_x")):
            self._heads[key], self._values[key] = QLabel(), self._value_label()
            self._positions.addWidget(self._heads[key], row, 0)
            self._positions.addWidget(self._values[key], row, 1)
        self._speeds = QGridLayout()
        for col, key in enumerate(("time", "v", "a"), start=1):
            self._heads[key] = QLabel()
            self._heads[key].setAlignment(Qt.AlignRight | Qt.AlignVCenter)
            self._speeds.addWidget(self._heads[key], 0, col)
        self._speed_rows: list[tuple[QLabel, QLabel, QLabel, QLabel]] = []
        self._rows_for: tuple[float, ...] | None = None     # the speeds the rows were made for
        for grid in (self._positions, self._speeds):
            grid.setHorizontalSpacing(12)
            grid.setVerticalSpacing(0)
        readout = QHBoxLayout()
        readout.setContentsMargins(0, 0, 0, 0)
        readout.addLayout(self._positions)
        readout.addSpacing(24)
        # Many speeds scroll inside a few rows instead of pushing the mechanism off screen.
        speeds = QWidget()
        speeds.setLayout(self._speeds)
        self._speeds_area = QScrollArea()
        self._speeds_area.setWidget(speeds)
        self._speeds_area.setWidgetResizable(True)
        self._speeds_area.setFrameShape(QFrame.Shape.NoFrame)
        self._speeds_area.setHorizontalScrollBarPolicy(Qt.ScrollBarAlwaysOff)
        self._speeds_area.setAlignment(Qt.AlignLeft | Qt.AlignTop)
        self._speeds.setContentsMargins(0, 0, 0, 0)
        readout.addWidget(self._speeds_area)
        readout.addStretch(1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 2, 4, 2)
        layout.setSpacing(2)
        layout.addLayout(controls)
        layout.addLayout(readout)

        self._retranslate()
        model.resultsChanged.connect(self._on_results)
        model.angleChanged.connect(self._on_angle)
        self._on_results()

    # ---- public ------------------------------------------------------
    def is_playing(self) -> bool:
        return self._timer.isActive()

    def toggle_play(self) -> None:
        self.play_action.setChecked(not self.play_action.isChecked())

    def play(self) -> None:
        self.play_action.setChecked(True)

    def pause(self) -> None:
        self.play_action.setChecked(False)

    def step_forward(self) -> None:
        """One grid angle on; wraps from the end of the cycle to its start."""
        self._model.set_angle_index(self._model.angle_index + 1)

    def step_back(self) -> None:
        self._model.set_angle_index(self._model.angle_index - 1)

    def set_loop(self, loop: bool) -> None:
        self._loop.setChecked(loop)

    def loop(self) -> bool:
        return self._loop.isChecked()

    def speed_factor(self) -> float:
        return float(self._speed.currentData())

    def set_speed_factor(self, factor: float) -> None:
        self._speed.setCurrentIndex(int(np.argmin(np.abs(np.array(SPEED_FACTORS) - factor))))

    # ---- playback ----------------------------------------------------
    def _set_playing(self, playing: bool) -> None:
        if playing == self._timer.isActive():
            return
        if playing:
            last = self._model.angle_count - 1
            if not self.loop() and self._model.angle_index >= last:
                self._model.set_angle_index(0)     # replay a finished cycle from its start
            self._sync_phase()
            self._clock.start()
            self._timer.start()
        else:
            self._timer.stop()
        self.play_action.setIcon(self._pause_icon if playing else self._play_icon)
        self._retranslate_play()
        self.playingChanged.emit(playing)

    def _sync_phase(self) -> None:
        index = self._model.angle_index
        self._phase = float(self._model.motion.crank_angle[index])
        self._last_index = index

    def _tick(self) -> None:
        """Advance by the real time since the last tick; only cheap work here."""
        model = self._model
        if model.angle_index != self._last_index:
            self._sync_phase()          # someone scrubbed or stepped meanwhile
        elapsed = self._clock.nsecsElapsed() * 1e-9
        self._clock.restart()
        omega = float(model.motion.omega[0])
        self._phase += elapsed * omega * self.speed_factor()
        grid = model.motion.crank_angle
        end = float(grid[-1])
        if self._phase >= end:
            if not self.loop():
                self._last_index = grid.size - 1
                model.set_angle_index(grid.size - 1)
                self.pause()
                return
            self._phase = math.fmod(self._phase - end, end) + float(grid[0])
        index = int(np.searchsorted(grid, self._phase))
        if index > 0 and (index == grid.size or self._phase - grid[index - 1] < grid[index] - self._phase):
            index -= 1
        self._last_index = index
        model.set_angle_index(index)

    # ---- model → widgets ---------------------------------------------
    def _on_results(self) -> None:
        """New grid or new speeds: resize the slider and rebuild the per-speed rows."""
        self._slider.blockSignals(True)
        self._slider.setRange(0, self._model.angle_count - 1)
        self._slider.setSingleStep(1)
        self._slider.setPageStep(max(1, (self._model.angle_count - 1) // 12))
        self._slider.blockSignals(False)
        rpms = self._model.rpms
        if rpms == self._rows_for:           # same speeds: no relayout of the read-out
            self._sync_phase()
            self._on_angle(self._model.angle_index)
            return
        self._rows_for = rpms
        while len(self._speed_rows) > len(rpms):
            for w in self._speed_rows.pop():
                self._speeds.removeWidget(w)
                w.hide()
                w.deleteLater()
        while len(self._speed_rows) < len(rpms):
            i = len(self._speed_rows)
            row = (QLabel(), self._value_label(), self._value_label(), self._value_label())
            row[0].setStyleSheet(f"color: {speed_colour(i).name()}; font-weight: 600")
            for col, w in enumerate(row):
                self._speeds.addWidget(w, 1 + i, col)
                w.show()               # now, not on the next event-loop turn
            self._speed_rows.append(row)
        self._retranslate_rows()
        self._fit_speeds_area()
        self._sync_phase()
        self._on_angle(self._model.angle_index)

    def _on_angle(self, index: int) -> None:
        """Move the slider (signals blocked) and refresh the read-out."""
        if self._slider.value() != index:
            self._slider.blockSignals(True)
            self._slider.setValue(index)
            self._slider.blockSignals(False)
        m = self._model.motion
        if index >= m.crank_angle.size:
            return
        # fmt: a value at a limit position (±1e-17) reads 0.000, never -0.000
        self._values["crank"].setText(crank_text(math.degrees(float(m.crank_angle[index]))))
        self._values["lever"].setText(fmt(math.degrees(float(m.lever_angle[index])), ".2f"))
        self._values["ram_x"].setText(fmt(float(m.ram_x[index]), ".1f"))
        for i, row in enumerate(self._speed_rows[: m.rpm.size]):
            row[1].setText(fmt(float(m.time[i, index]), ".3f"))
            row[2].setText(fmt(float(m.ram_v[i, index]), ".3f"))
            row[3].setText(fmt(float(m.ram_a[i, index]), ".2f"))

    def _fit_speeds_area(self) -> None:
        """As tall as the heading and all rows, at most MAX_ROWS rows; wide enough for them
        and a scroll bar."""
        inner = self._speeds_area.widget()
        inner.adjustSize()
        # each row as tall as its tallest cell: in Chinese the heading is taller than the
        # rows of numbers, and the heading's height for every row showed a sixth row cut
        # in half under the fifth
        heading = max(_height(self._heads[key]) for key in ("time", "v", "a"))
        rows = [max(_height(cell) for cell in row) for row in self._speed_rows[:MAX_ROWS]]
        self._speeds_area.setFixedHeight(max(heading + sum(rows), 1))
        bar = self._speeds_area.verticalScrollBar().sizeHint().width()
        self._speeds_area.setMinimumWidth(inner.sizeHint().width() + bar + 4)

    def _value_label(self) -> QLabel:
        """A right-aligned number cell of a fixed size: wide enough that the layout does not
        jump, and fixed so that a new number does not ask the window to lay out again (at
        every frame that took about 2 ms of 9)."""
        value = QLabel()
        value.setAlignment(Qt.AlignRight | Qt.AlignVCenter)
        _fix_size(value)
        return value

    # ---- translation -------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.FontChange:
            for value in [*self._values.values(), *(w for row in self._speed_rows for w in row[1:])]:
                _fix_size(value)
        if event.type() == QEvent.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self._retranslate_play()
        self.step_back_action.setText(self.tr("Step back"))
        self.step_back_action.setToolTip(self.tr("One crank-angle step back"))
        self.step_forward_action.setText(self.tr("Step forward"))
        self.step_forward_action.setToolTip(self.tr("One crank-angle step forward"))
        self._slider.setToolTip(self.tr("Crank angle φ, 0…360°: drag to scrub"))
        self._loop.setText(self.tr("Loop"))
        self._loop.setToolTip(self.tr("Repeat the cycle; when off, playback stops at 360°"))
        self._speed_label.setText(self.tr("Speed"))
        self._speed.setToolTip(self.tr("Playback speed relative to real time at the first crank speed"))
        for i, factor in enumerate(SPEED_FACTORS):
            self._speed.setItemText(i, self.tr("{0:g}×").format(factor))
        self._heads["crank"].setText(self.tr("Crank φ (°)"))
        self._heads["lever"].setText(self.tr("Lever ψ (°)"))
        self._heads["ram_x"].setText(self.tr("Ram x (mm)"))
        self._heads["time"].setText(self.tr("Time t (s)"))
        self._heads["v"].setText(self.tr("Ram v (m/s)"))
        self._heads["a"].setText(self.tr("Ram a (m/s²)"))
        for key in ("crank", "lever", "ram_x"):
            self._values[key].setToolTip(self._heads[key].text())
        self._retranslate_rows()
        if hasattr(self, "_speeds_area"):
            self._fit_speeds_area()        # headings change width with the language

    def _retranslate_play(self) -> None:
        playing = self.play_action.isChecked()
        self.play_action.setText(self.tr("Pause") if playing else self.tr("Play"))
        self.play_action.setToolTip(self.tr("Pause the animation") if playing
                                    else self.tr("Play the crank cycle"))

    def _retranslate_rows(self) -> None:
        for rpm, row in zip(self._model.rpms, self._speed_rows):
            row[0].setText(self.tr("{0:g} r/min").format(rpm))
        if self._speed_rows:
            self._on_angle(self._model.angle_index)


def _height(widget: QWidget) -> int:
    """The height a grid gives ``widget``: its size hint within its least and most size."""
    return widget.sizeHint().expandedTo(widget.minimumSize()).boundedTo(widget.maximumSize()).height()


def _fix_size(value: QLabel) -> None:
    value.setFixedSize(value.fontMetrics().horizontalAdvance("-00000.000"),
                       value.fontMetrics().height() + 2 * value.margin())
