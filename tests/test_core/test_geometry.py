"""Synthesis against seed 003's worked example and the validation rules."""
import math

import pytest

from core.base.errors import DesignError
from core.linkage.geometry import Design, from_dimensions, guide_height, synthesize


def test_seed003_example():
    # Seed 003: L1 = 100 mm, K = 1.4, H = 300 mm → θ = 30°, L2 ≈ 386.37, L3 ≈ 579.56, h ≈ 173.44 mm.
    d = synthesize(100, 1.4, 300)
    assert math.degrees(d.theta) == pytest.approx(30.0)
    assert d.frame == pytest.approx(386.37, abs=0.005)
    assert d.lever == pytest.approx(579.56, abs=0.005)
    assert d.guide_above_crank == pytest.approx(173.44, abs=0.005)
    # Seed 003's own expression for h: H/(2 tan(θ/2)) − L2.
    assert d.guide_above_crank == pytest.approx(300 / (2 * math.tan(math.radians(15))) - d.frame)
    assert d.variant == "block" and d.rod is None


def test_implied_values_round_trip():
    d = synthesize(120, 1.7, 420, guide="sagitta", rod_ratio=0.35)
    assert d.time_ratio == pytest.approx(1.7)
    assert d.stroke == pytest.approx(420)
    again = from_dimensions(d.crank, d.frame, d.lever, guide=d.guide, rod=d.rod)
    assert again == d


def test_guide_rules():
    lever, theta = 600.0, math.radians(40)
    chord = guide_height("chord", lever, theta)
    sag = guide_height("sagitta", lever, theta)
    assert chord == pytest.approx(lever * math.cos(theta / 2))
    assert sag == pytest.approx((chord + lever) / 2)  # midway between chord and arc top
    assert guide_height(555.0, lever, theta) == 555.0
    assert guide_height("555", lever, theta) == 555.0


@pytest.mark.parametrize("kwargs, parameter", [
    (dict(crank=100, time_ratio=1.0, stroke=300), "time_ratio"),
    (dict(crank=100, time_ratio=0.8, stroke=300), "time_ratio"),
    (dict(crank=100, time_ratio=9.0, stroke=300), "time_ratio"),
    (dict(crank=0, time_ratio=1.4, stroke=300), "crank"),
    (dict(crank=-5, time_ratio=1.4, stroke=300), "crank"),
    (dict(crank=float("nan"), time_ratio=1.4, stroke=300), "crank"),
    (dict(crank=100, time_ratio=float("inf"), stroke=300), "time_ratio"),
    (dict(crank=100, time_ratio=1.4, stroke=0), "stroke"),
    (dict(crank=100, time_ratio=1.4, stroke=200), "stroke"),   # crank pin would leave the lever
    (dict(crank=100, time_ratio=1.4, stroke=300, guide="middle"), "guide"),
    (dict(crank=100, time_ratio=1.4, stroke=300, guide=300.0), "guide"),   # below the crank circle
    (dict(crank=100, time_ratio=1.4, stroke=300, guide=700.0), "guide"),   # above the lever tip (block)
    (dict(crank=100, time_ratio=1.4, stroke=300, rod=5.0), "rod"),         # rod cannot reach the guide
    (dict(crank=100, time_ratio=1.4, stroke=300, rod=-1.0), "rod"),
    (dict(crank=100, time_ratio=1.4, stroke=300, rod_ratio=0.0), "rod_ratio"),
    (dict(crank=100, time_ratio=1.4, stroke=300, rod=100.0, rod_ratio=0.3), "rod"),
])
def test_invalid_synthesis(kwargs, parameter):
    with pytest.raises(DesignError) as info:
        synthesize(**kwargs)
    assert info.value.parameter == parameter
    assert parameter in str(info.value)
    assert "must" in info.value.allowed


def test_crank_must_be_shorter_than_frame():
    with pytest.raises(DesignError) as info:
        from_dimensions(300, 250, 800)
    assert info.value.parameter == "crank"
    assert "250" in info.value.allowed


def test_design_itself_is_validated():
    with pytest.raises(DesignError):
        Design(crank=100, frame=386, lever=300, guide=500)  # lever shorter than L2 + L1
    with pytest.raises(DesignError):
        Design(crank=100, frame=386, lever=600, guide=560, rod=100, rod_side="sideways")


def test_rod_dead_centre_refused():
    # Guide at the top of the tip's arc: at the far extreme the rod drops by
    # d = L3(1 − cos θ/2); a rod barely longer than that stands square to the lever.
    d = synthesize(100, 1.4, 300)
    drop = d.lever * (1 - math.cos(d.theta / 2))
    for side in ("leading", "trailing"):
        with pytest.raises(DesignError) as info:
            synthesize(100, 1.4, 300, guide=d.lever, rod=drop + 0.5, rod_side=side)
        assert info.value.parameter == "rod"
        assert "dead-centre" in info.value.allowed
    # A longer rod on the same guide works.
    assert synthesize(100, 1.4, 300, guide=d.lever, rod=drop * 5, rod_side="leading").rod == drop * 5


def test_dimensions_imply_k_at_most_5():
    """seed 003 bounds K ≤ 5 in synthesis; direct dimensions are held to the same K."""
    from core.linkage.geometry import MAX_CRANK_RATIO
    ok = from_dimensions(86.6, 100.0, 400.0, guide=300.0)
    assert ok.time_ratio <= 5.0
    with pytest.raises(DesignError) as info:
        from_dimensions(100.0, 100.001, 400.0, guide=300.0)
    assert info.value.parameter == "crank" and "K stays ≤ 5" in info.value.allowed
    # The bound is the one synthesis reaches at K = 5, and synthesis at K = 5 passes it.
    edge = synthesize(100.0, 5.0, 1000.0)
    assert edge.crank / edge.frame == pytest.approx(MAX_CRANK_RATIO)
    assert edge.time_ratio == pytest.approx(5.0)


def test_k_too_close_to_one_names_k_with_a_minimum_that_passes():
    with pytest.raises(DesignError) as info:
        synthesize(100.0, 1.000000000001, 300.0)
    assert info.value.parameter == "time_ratio"
    minimum = float(info.value.allowed.split("≥ ")[1].split()[0])
    assert synthesize(100.0, minimum, 300.0).frame <= 100_000.0


def test_stated_crank_maximum_is_itself_allowed():
    with pytest.raises(DesignError) as info:
        from_dimensions(100.0, 100.001, 400.0, guide=300.0)
    maximum = float(info.value.allowed.split("≤ ")[1].split()[0])
    assert from_dimensions(maximum, 100.001, 400.0, guide=300.0).time_ratio <= 5.0


def test_lengths_have_a_floor():
    with pytest.raises(DesignError) as info:
        synthesize(1e-300, 1.4, 300.0)
    assert info.value.parameter == "crank"


@pytest.mark.parametrize("crank, stroke", [(100_000.0, 300.0), (90_000.0, 300.0), (86_700.0, 300.0)])
def test_no_k_fits_a_crank_or_stroke_near_the_length_limit(crank, stroke):
    """A crank over sin 60° of the 100 m limit needs θ > 120°, K > 5: the
    message says no K does, instead of a bound above 5 or an internal error (the bound was
    infinite at L1 = 100 m: OverflowError), and indeed K = 5 itself fails."""
    with pytest.raises(DesignError) as info:
        synthesize(crank, 1.4, stroke)
    assert info.value.parameter == "time_ratio"
    assert info.value.allowed.startswith("no K up to 5 keeps the frame and the lever ≤ 100000 mm")
    with pytest.raises(DesignError):
        synthesize(crank, 5.0, stroke)

