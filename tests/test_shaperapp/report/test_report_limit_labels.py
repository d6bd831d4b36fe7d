"""The report's scheme at both limit positions (§3), as the report draws it: each joint's
name reads as its own joint's, and L1 names the crank drawn in that position (issue 40).

At the end limit of 方案 I (`--dims 110,380,540 --rod-ratio 0.25`) "C" stood above the
ram between C and B, 0.71 of its distance to B from C, with no leader, and read as B's;
and L1's dimension ran from O2 to the start limit's crank pin, along the other position's
lever (dashed), not along the crank drawn.

A name with no leader must lie within half its distance to any other joint from its own
joint (box to point); one with a leader is tied to its joint by it. At a limit position the
crank is perpendicular to the lever (the lever touches the crank circle), so the crank pin
A is the tangent point that L1's line runs to: L1's leader starts at the drawn A.
"""
from __future__ import annotations

import numpy as np
import pytest

from core.linkage.spec import Spec
from scheme_shots import limit_frames

SPECS = [Spec(mode="dimensions", crank=110.0, frame=380.0, lever=540.0, variant="rod", rod_ratio=0.25),
         Spec(crank=100.0, time_ratio=1.4, stroke=300.0)]


def box_distance(box, point) -> float:
    """Distance from a box (left, right, bottom, top) to a point: 0 inside."""
    left, right = sorted(box[:2])
    bottom, top = sorted(box[2:])
    return float(np.hypot(max(left - point[0], 0.0, point[0] - right),
                          max(bottom - point[1], 0.0, point[1] - top)))


def led(scheme, box, joint) -> bool:
    """A leader runs from near ``joint`` to the edge of ``box``."""
    drawn = scheme._labels._leaders
    pairs = np.column_stack([drawn.x, drawn.y]).reshape(-1, 2, 2)
    return any(box_distance(box, end) < 1e-6 * (1.0 + abs(end).max())
               and np.hypot(*(start - joint)) < box_distance(box, joint)
               for start, end in pairs)


@pytest.mark.parametrize("spec", SPECS, ids=["scheme-I", "default"])
def test_limit_positions_name_their_own_joints_and_crank(qapp, spec):
    for scheme, index in limit_frames(spec):
        joints = {name: np.array(p) for name, p in scheme.drawn_joints().items()}
        for name, item in scheme._mechanism.labels.items():
            if not item.isVisible():
                continue
            box = scheme._screen_box(item)
            own = box_distance(box, joints[name])
            other, nearest = min((box_distance(box, p), n) for n, p in joints.items() if n != name)
            if not led(scheme, box, joints[name]):      # a leader says whose it is
                assert own <= 0.5 * other, (index, name, own, nearest, other)
        start = scheme._dimensions.leader_line()[0, 0]
        assert np.hypot(*(start - joints["A"])) < 1e-6 * spec.crank, (index, start, joints["A"])


@pytest.mark.parametrize("spec", SPECS, ids=["scheme-I", "default"])
def test_limit_positions_name_the_crank_pin_beside_it(qapp, spec):
    """At a limit position L1's leader starts at the crank pin A and runs out across the
    lever, A's own first direction: at the end limit of the default design "A" went out on
    a 128 mm leader (8.5 mm on the page), every near spot refused for L1's leader. A's name
    stands within one text height of A (box to point, on screen), with or without a leader."""
    for scheme, index in limit_frames(spec):
        a = np.array(scheme.drawn_joints()["A"])
        box = scheme._screen_box(scheme._mechanism.labels["A"])
        height = abs(box[3] - box[2])
        assert box_distance(box, a) <= height, (index, box_distance(box, a), height)
