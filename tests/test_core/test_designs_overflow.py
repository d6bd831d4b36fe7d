"""Any finite inputs give a design or a DesignError, never a numpy warning on the way
(issue 33: GUI fuzzing logged "overflow encountered in add" in the sagitta guide rule)."""
import warnings

from hypothesis import example, given, settings
from hypothesis import strategies as st

from core.base.errors import DesignError
from core.linkage.spec import Spec

FINITE = st.floats(min_value=-1.7976931348623157e308, max_value=1.7976931348623157e308,
                   allow_nan=False, allow_infinity=False)


@settings(max_examples=200, deadline=None)
@given(crank=FINITE, frame=FINITE, lever=FINITE, rule=st.sampled_from(["chord", "sagitta"]))
@example(crank=100.0, frame=300.0, lever=1.7e308, rule="sagitta")
def test_direct_dimensions_never_warn(crank, frame, lever, rule):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            Spec(mode="dimensions", crank=crank, frame=frame, lever=lever, guide_rule=rule).design()
        except DesignError:
            pass


GUIDES = st.one_of(st.floats(allow_nan=True, allow_infinity=True),
                   st.sampled_from([float("inf"), -float("inf"), float("nan"), 1e306, 1.7976931348623157e308]))


@settings(max_examples=200, deadline=None)
@given(crank=st.floats(1.0, 1000.0), time_ratio=st.floats(1.05, 4.0), stroke=st.floats(10.0, 2000.0),
       guide=GUIDES)
@example(crank=469.46, time_ratio=2.094843, stroke=244.0, guide=float("inf"))
@example(crank=469.46, time_ratio=2.094843, stroke=244.0, guide=1e306)
@example(crank=469.46, time_ratio=2.094843, stroke=244.0, guide=1.7976931348623157e308)
def test_a_given_guide_height_out_of_range_is_refused_as_the_guide(crank, time_ratio, stroke, guide):
    """GUI fuzz (30 November): a guide height typed as 1e999 (inf) and then a switch to
    synthesis raised OverflowError in the stroke rule's text (the block's reach, 2 sin(θ/2)
    times the guide, rounded up with math.ceil), a traceback on screen; at 1e306 the refusal
    asked for a stroke of a 308-digit number of mm. A guide height outside its range is now
    the refusal, naming the guide, whatever else fails after it."""
    spec = Spec(mode="synthesis", crank=crank, time_ratio=time_ratio, stroke=stroke,
                guide_rule="height", guide_height=guide)
    in_range = 0.001 <= guide <= 100_000.0          # False for NaN too
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")          # nor a numpy warning on the way (1e308: overflow)
            spec.design()
    except DesignError as error:
        if not in_range:
            assert error.parameter == "guide", str(error)
        return
    assert in_range


def test_switching_to_synthesis_with_an_infinite_guide_height_typed_keeps_a_design():
    """The fuzz's state: direct dimensions with the guide height typed as 1e999, then the
    synthesis mode chosen. The switch keeps the design on screen's K and H (it raised)."""
    design = Spec().design()
    typed = Spec(mode="dimensions", crank=469.46, frame=386.37033051562736, lever=579.5554957734411,
              time_ratio=2.094843, stroke=244.0, guide_rule="height", guide_height=float("inf"))
    switched = typed.switch_mode("synthesis", design)
    assert switched.mode == "synthesis"
    assert switched.time_ratio == design.time_ratio and switched.stroke == design.stroke
