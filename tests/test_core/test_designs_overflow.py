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
