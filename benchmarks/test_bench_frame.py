"""One animation frame of the mechanism sketch: move the model's angle, update, repaint.

Budget: ≤ 8 ms per frame so that 60 frames/s leave room for the plots, with the
force arrows hidden (the default) and shown.
Run: python -m pytest benchmarks/test_bench_frame.py --benchmark-enable -n 0 -q
"""
from __future__ import annotations

import itertools

import pytest

from shaperapp.design.model import DesignModel
from shaperapp.scheme.view import SchemeWidget

FRAME_BUDGET_S = 0.008


@pytest.fixture(params=[("block", False), ("rod", False), ("block", True), ("rod", True)],
                ids=["block", "rod", "block-forces", "rod-forces"])
def shown_scheme(request, qtbot):
    """The scheme of one variant, with the force arrows hidden (default) or shown."""
    variant, forces = request.param
    model = DesignModel()
    if variant == "rod":
        model.set_spec(variant="rod", rod_ratio=0.3)
    widget = SchemeWidget(model)
    qtbot.addWidget(widget)
    widget.resize(800, 600)
    widget.show()
    qtbot.waitExposed(widget)
    widget.set_forces_visible(forces)
    assert bool(widget.drawn_forces()) == forces
    return model, widget


def test_frame_update_and_repaint(benchmark, shown_scheme):
    """set_angle_index → the scheme moves its items → the whole widget is rendered."""
    model, widget = shown_scheme
    indices = itertools.cycle(range(model.angle_count))

    def frame() -> None:
        model.set_angle_index(next(indices))
        widget.grab()

    benchmark(frame)
    assert widget.drawn_joints()["A"] == pytest.approx(
        tuple(model.motion.shape.crank_pin[:, model.angle_index]))
    if benchmark.enabled:
        assert benchmark.stats.stats.median < FRAME_BUDGET_S


def test_frame_update_only(benchmark, shown_scheme):
    """The scheme's own share of a frame: moving the items, without the repaint."""
    model, widget = shown_scheme
    indices = itertools.cycle(range(model.angle_count))
    benchmark(lambda: model.set_angle_index(next(indices)))
    assert widget.drawn_joints()["B"] == pytest.approx(
        tuple(model.motion.shape.lever_tip[:, model.angle_index]))
