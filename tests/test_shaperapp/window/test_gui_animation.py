"""The animation bar moves the model's angle in real time and shows core's values."""
from __future__ import annotations

import math
import time

import numpy as np
import pytest
from PySide6.QtCore import QEvent, Qt
from PySide6.QtWidgets import QApplication, QLabel, QSlider, QToolButton

from shaperapp.window.animation import AnimationBar


@pytest.fixture
def bar(qtbot, model) -> AnimationBar:
    widget = AnimationBar(model)
    qtbot.addWidget(widget)
    widget.show()
    return widget


def button_for(bar: AnimationBar, action) -> QToolButton:
    return next(b for b in bar.findChildren(QToolButton) if b.defaultAction() is action)


def texts(bar: AnimationBar) -> list[str]:
    return [label.text() for label in bar.findChildren(QLabel) if not label.isHidden()]


def play_for(qtbot, bar: AnimationBar, model, seconds: float) -> tuple[float, float, float]:
    """Plays until the crank has moved for at least ``seconds`` of real time, then pauses.
    Returns the crank angle played (degrees, summed over the moves, so a wrap at the end
    of the cycle counts whole) and the real time from pressing play to the move before
    the last and to the last (s). Each move is stamped as it happens and the bar read its
    clock between those two stamps, so a loaded machine's late or skipped ticks shift
    both sides of the comparison alike (a fixed 300 ms wait, compared with the time the
    whole wait took, did not: a tick held up past its end was not counted)."""
    grid = np.degrees(model.motion.crank_angle)
    moves: list[tuple[float, int]] = []
    model.angleChanged.connect(lambda index: moves.append((time.perf_counter(), index)))
    first = model.angle_index
    start = time.perf_counter()
    bar.toggle_play()
    started = time.perf_counter()
    assert bar.is_playing()
    qtbot.waitUntil(lambda: len(moves) >= 2 and moves[-1][0] - start >= seconds, timeout=10_000)
    bar.toggle_play()
    assert not bar.is_playing()
    indices = [first] + [index for _, index in moves]
    played = float(sum((grid[b] - grid[a]) % 360.0 for a, b in zip(indices, indices[1:])))
    return played, moves[-2][0] - started, moves[-1][0] - start


def test_play_advances_in_real_time(qtbot, bar, model):
    bar.set_speed_factor(1.0)
    assert model.angle_index == 0
    played, before_last, last = play_for(qtbot, bar, model, 0.3)
    omega = math.degrees(float(model.motion.omega[0]))      # 1× at the first speed, °/s
    assert omega * before_last - 2.0 <= played <= omega * last + 2.0, (played, before_last, last)
    stopped = model.angle_index
    qtbot.wait(100)
    assert model.angle_index == stopped


def test_speed_factor_scales_playback(qtbot, bar, model):
    bar.set_speed_factor(0.1)
    assert bar.speed_factor() == 0.1
    played, before_last, last = play_for(qtbot, bar, model, 0.3)
    # 0.1× of 40 r/min is 24°/s, whatever time the machine took (1× would be 240°/s).
    slow = 0.1 * math.degrees(float(model.motion.omega[0]))
    assert slow * before_last - 2.0 <= played <= slow * last + 2.0, (played, before_last, last)


def test_slider_sets_model_and_model_moves_slider(bar, model):
    slider = bar.findChild(QSlider)
    assert (slider.minimum(), slider.maximum()) == (0, model.angle_count - 1)
    slider.setValue(90)
    assert model.angle_index == 90
    seen = []
    model.angleChanged.connect(seen.append)
    model.set_angle_index(45)
    assert slider.value() == 45
    assert seen == [45]               # syncing the slider did not echo back into the model


def test_slider_range_follows_the_grid(bar, model):
    model.set_step(2.0)
    slider = bar.findChild(QSlider)
    assert slider.maximum() == model.angle_count - 1 == 180


def test_step_buttons_move_by_one(qtbot, bar, model):
    model.set_angle_index(10)
    qtbot.mouseClick(button_for(bar, bar.step_forward_action), Qt.LeftButton)
    assert model.angle_index == 11
    qtbot.mouseClick(button_for(bar, bar.step_back_action), Qt.LeftButton)
    qtbot.mouseClick(button_for(bar, bar.step_back_action), Qt.LeftButton)
    assert model.angle_index == 9
    model.set_angle_index(0)
    bar.step_back()
    assert model.angle_index == model.angle_count - 1


def test_no_loop_stops_at_the_end(qtbot, bar, model):
    bar.set_loop(False)
    bar.set_speed_factor(2.0)
    model.set_angle_index(model.angle_count - 20)
    bar.toggle_play()
    qtbot.waitUntil(lambda: not bar.is_playing(), timeout=10_000)
    assert model.angle_index == model.angle_count - 1
    assert not bar.play_action.isChecked()
    bar.toggle_play()                 # playing a finished cycle starts it again
    assert bar.is_playing() and model.angle_index < 5
    bar.toggle_play()


def test_loop_wraps_around(qtbot, bar, model):
    bar.set_loop(True)
    bar.set_speed_factor(2.0)
    model.set_angle_index(model.angle_count - 10)
    bar.toggle_play()
    qtbot.waitUntil(lambda: model.angle_index < 60, timeout=10_000)
    assert bar.is_playing()
    bar.toggle_play()


def test_readout_shows_core_values(bar, model):
    model.set_rpms([30.0, 60.0, 90.0])
    model.set_angle_index(77)
    m, shown = model.motion, texts(bar)
    assert f"{math.degrees(m.crank_angle[77]):.1f}" in shown
    assert f"{math.degrees(m.lever_angle[77]):.2f}" in shown
    assert f"{m.ram_x[77]:.1f}" in shown
    for i in range(3):
        assert f"{m.time[i, 77]:.3f}" in shown
        assert f"{m.ram_v[i, 77]:.3f}" in shown
        assert f"{m.ram_a[i, 77]:.2f}" in shown
    model.set_rpms([50.0])
    assert f"{model.motion.ram_v[0, 77]:.3f}" in texts(bar)


def test_language_change_keeps_texts(bar):
    QApplication.sendEvent(bar, QEvent(QEvent.LanguageChange))
    assert bar.play_action.text() and bar.play_action.toolTip()
    assert bar.step_forward_action.toolTip() and bar.step_back_action.toolTip()


@pytest.mark.parametrize("lang", ["en", "zh_CN"])
def test_speed_rows_shown_whole(qtbot, bar, model, lang):
    """With 16 speeds the read-out shows the heading and four whole rows and scrolls to the
    rest: in Chinese, sized by the (taller) heading for every row, it showed a fifth row
    and half of a sixth (issue 34 item 8, the sweep)."""
    from shaperapp.widgets import i18n
    from shaperapp.window.animation import MAX_ROWS
    i18n.set_language(lang)
    try:
        model.set_rpms([20.0 + 5.0 * i for i in range(16)])
        qtbot.wait(10)
        area = bar._speeds_area
        height = area.viewport().height()
        seen = []                     # (whole, top, bottom) of each row the area shows
        for label, *_ in bar._speed_rows:
            top = label.mapTo(area.viewport(), label.rect().topLeft()).y()
            bottom = top + label.height()
            if bottom > 0 and top < height:
                seen.append((top >= 0 and bottom <= height, top, bottom))
        assert len(seen) == MAX_ROWS, (seen, height)
        assert all(whole for whole, *_ in seen), (seen, height)
    finally:
        i18n.set_language("en")
